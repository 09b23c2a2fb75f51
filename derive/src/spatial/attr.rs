//! The `#[arm(...)]` attribute of `#[derive(SpatialArm)]`: its keys and their parsing.
//!
//! On the struct: `gravity = (gx, gy, gz)`, `tool(xyz = (x, y, z), rpy = (r, p, y))`,
//! `crate = "..."`, a payload held by the tool (`payload = m`, `payload_com = (x, y, z)`,
//! `payload_inertia(xx, ..)` in the tool frame), and `urdf = ".."` or `mjcf = ".."` with
//! `base = ".."` and `tip = ".."` for an arm read from a model file. On each joint field: one of `dh(a, alpha, d, theta)`,
//! `mdh(a, alpha, d, theta)` or `origin(xyz = (..), rpy = (..))` with `axis = (x, y, z)`; the
//! link's `mass`, `com = (x, y, z)` and `inertia(xx, yy, zz, xy, xz, yz)`; the joint's `range`,
//! `armature`, `damping`, `frictionloss`, and a spring's `stiffness` and `springref`. Lengths and mass properties are exact numbers or
//! run-time parameters (`self.NAME`); angles are numbers and multiples of `pi`.

use planar_arm_core::ring::Rational;
use planar_arm_core::Poly;
use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::meta::ParseNestedMeta;
use syn::parse::Parser;

use super::angle::{self, Angle};
use crate::attr::{nearest, path_text, skip_to_comma, tokens_between};
use crate::ctxt::Ctxt;
use crate::value::{self, ParamUse};

/// A value with the tokens it came from.
pub struct Spanned<T> {
    pub value: T,
    pub tokens: TokenStream,
}

/// A length or mass property: exact, perhaps polynomial in run-time parameters.
pub type Scalar = Spanned<Poly>;
/// A triple `(x, y, z)` of them.
pub type Triple = Spanned<[Poly; 3]>;
/// An angle triple `(r, p, y)`.
pub type Angles = Spanned<[Angle; 3]>;

/// Which convention a joint is written in.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Convention {
    Dh,
    Mdh,
    Origin,
}

impl Convention {
    pub fn key(self) -> &'static str {
        match self {
            Self::Dh => "dh",
            Self::Mdh => "mdh",
            Self::Origin => "origin",
        }
    }
}

/// A joint's geometry as written (omitted entries are zero).
pub struct Geometry {
    pub convention: Convention,
    pub tokens: TokenStream,
    /// `dh`/`mdh`: `a`, `d`; `origin`: unused.
    pub a: Option<Scalar>,
    pub d: Option<Scalar>,
    /// `dh`/`mdh`: `alpha`, `theta`.
    pub alpha: Option<Spanned<Angle>>,
    pub theta: Option<Spanned<Angle>>,
    /// `origin`: `xyz`, `rpy`.
    pub xyz: Option<Triple>,
    pub rpy: Option<Angles>,
}

/// Every key of one item's `#[arm(...)]` lists.
#[derive(Default)]
pub struct SpatialAttrs {
    pub tokens: TokenStream,
    pub malformed: bool,
    pub params: Vec<ParamUse>,
    /// The keys given, for duplicates.
    pub seen: Vec<String>,
    // On a field.
    pub geometry: Option<Geometry>,
    /// A geometry was written (perhaps unreadable, perhaps a planar `length`): its error is
    /// reported, so a missing-geometry error would only repeat it.
    pub geometry_written: bool,
    pub axis: Option<Spanned<[Rational; 3]>>,
    pub mass: Option<Scalar>,
    pub com: Option<Triple>,
    /// xx, yy, zz, xy, xz, yz.
    pub inertia: [Option<Scalar>; 6],
    pub range: Option<Spanned<(Rational, Rational)>>,
    pub armature: Option<Scalar>,
    pub damping: Option<Scalar>,
    pub frictionloss: Option<Scalar>,
    pub stiffness: Option<Scalar>,
    pub springref: Option<Scalar>,
    // On the struct.
    pub gravity: Option<Triple>,
    pub tool_xyz: Option<Triple>,
    pub tool_rpy: Option<Angles>,
    pub krate: Option<syn::Path>,
    /// The payload at the tool frame: mass, centre, tensor (xx, yy, zz, xy, xz, yz).
    pub payload: Option<Scalar>,
    pub payload_com: Option<Triple>,
    pub payload_inertia: [Option<Scalar>; 6],
    /// Where `payload_com` or `payload_inertia` was written, for an error without `payload`.
    pub payload_extras: Vec<TokenStream>,
    /// A model file the joints come from: `urdf = ".."` or `mjcf = ".."`, with the chain's
    /// `base` and `tip`.
    pub model: Option<(ModelFormat, syn::LitStr)>,
    pub model_written: bool,
    pub base: Option<syn::LitStr>,
    pub tip: Option<syn::LitStr>,
    /// `exact_dynamics` (where it was written): M and c multiplied out for `EXACT` whatever
    /// their size.
    pub exact_dynamics: Option<TokenStream>,
}

pub use crate::models::Format as ModelFormat;

/// Where a list appears.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Place {
    Struct,
    Field,
}

const FIELD_KEYS: &[&str] = &[
    "dh",
    "mdh",
    "origin",
    "axis",
    "mass",
    "com",
    "inertia",
    "range",
    "armature",
    "damping",
    "frictionloss",
    "stiffness",
    "springref",
];
const STRUCT_KEYS: &[&str] = &[
    "gravity",
    "tool",
    "crate",
    "payload",
    "payload_com",
    "payload_inertia",
    "urdf",
    "mjcf",
    "base",
    "tip",
    "exact_dynamics",
];
pub const INERTIA_KEYS: [&str; 6] = ["xx", "yy", "zz", "xy", "xz", "yz"];

/// Parses every `#[arm(...)]` of `attrs`.
pub fn parse(cx: &Ctxt, attrs: &[syn::Attribute], place: Place) -> SpatialAttrs {
    let mut out = SpatialAttrs::default();
    let mut found = false;
    for attr in attrs.iter().filter(|a| a.path().is_ident("arm")) {
        if !found {
            out.tokens = attr.to_token_stream();
        }
        found = true;
        let syn::Meta::List(_) = &attr.meta else {
            let example = match place {
                Place::Struct => "#[arm(gravity = (0, 0, -9.81))]",
                Place::Field => "#[arm(dh(a = 0.4, alpha = pi/2))]",
            };
            cx.error_spanned_by(attr, format!("expected #[arm(...)], for example {example}"));
            out.malformed = true;
            continue;
        };
        if let Err(err) = attr.parse_nested_meta(|meta| {
            entry(cx, &meta, place, &mut out);
            Ok(())
        }) {
            cx.syn_error(err);
            out.malformed = true;
        }
    }
    out
}

fn entry(cx: &Ctxt, meta: &ParseNestedMeta<'_>, place: Place, out: &mut SpatialAttrs) {
    let key = path_text(&meta.path);
    let (own, other) = match place {
        Place::Field => (FIELD_KEYS, STRUCT_KEYS),
        Place::Struct => (STRUCT_KEYS, FIELD_KEYS),
    };
    if !own.contains(&key.as_str()) {
        let message = if other.contains(&key.as_str()) {
            match place {
                // #[arm(dh(..))] on the struct
                Place::Struct => format!("`{key}` describes a joint; it belongs in a joint field's #[arm(...)], not on the struct"),
                // #[arm(gravity = ..)] on a field
                Place::Field => format!("`{key}` is a property of the whole arm; it belongs in the struct's #[arm(...)]"),
            }
        } else if key == "length" {
            // #[arm(length = 0.4)]: the planar geometry; no missing-geometry error on top.
            out.geometry_written = true;
            "`length` is a key of #[derive(PlanarArm)]; a spatial joint's geometry is \
             `dh(a = .., alpha = .., d = .., theta = ..)`, `mdh(...)`, or `origin(xyz = .., rpy = ..)` \
             with `axis`"
                .to_string()
        } else if let Some(best) = nearest(&key, own) {
            format!("unknown key `{key}`; did you mean `{best}`?")
        } else {
            format!("unknown key `{key}`; expected one of {}", own.join(", "))
        };
        cx.error_spanned_by(&meta.path, message);
        skip_rest(meta);
        return;
    }
    let is_geometry = matches!(key.as_str(), "dh" | "mdh" | "origin");
    let is_list = is_geometry || key == "inertia" || key == "payload_inertia" || key == "tool";
    let message = if let Some(g) = out.geometry.as_ref().filter(|_| is_geometry) {
        // #[arm(dh(..), mdh(..))]
        Some(format!(
            "this joint is already written with `{}`; a joint has one geometry",
            g.convention.key()
        ))
    } else if out.seen.contains(&key) {
        // #[arm(mass = 1, mass = 2)]
        Some(format!("duplicate key `{key}`; give it once"))
    } else if (key == "inertia" || key == "payload_inertia") && !meta.input.peek(syn::token::Paren)
    {
        // #[arm(inertia = 0.1)], as a planar link's
        Some(format!(
            "{} inertia is a tensor, not one number: write `{}` (kg m², about the centre of \
             mass in the {} axes; omitted entries are 0)",
            if key == "inertia" {
                "a spatial link's"
            } else {
                "a payload's"
            },
            form(&key),
            if key == "inertia" {
                "link's"
            } else {
                "tool frame's"
            }
        ))
    } else if key == "exact_dynamics" {
        // #[arm(exact_dynamics = true)]
        (meta.input.peek(syn::Token![=]) || meta.input.peek(syn::token::Paren)).then(|| {
            "`exact_dynamics` is a flag: write `#[arm(exact_dynamics)]`, without a value"
                .to_string()
        })
    } else if is_list != meta.input.peek(syn::token::Paren)
        || !is_list && !meta.input.peek(syn::Token![=])
    {
        // #[arm(dh = (0.4, 0))], #[arm(mass(1))], #[arm(mass)]
        Some(format!("expected `{}`", form(&key)))
    } else {
        None
    };
    out.seen.push(key.clone());
    out.geometry_written |= is_geometry;
    if let Some(message) = message {
        cx.error_spanned_by(&meta.path, message);
        skip_rest(meta);
        return;
    }
    let result = match key.as_str() {
        "dh" | "mdh" | "origin" => geometry(cx, meta, &key, out),
        "inertia" | "payload_inertia" => inertia(cx, meta, &key, out),
        "tool" => tool(cx, meta, out),
        "crate" => krate(meta, out),
        "exact_dynamics" => {
            out.exact_dynamics = Some(meta.path.to_token_stream());
            Ok(())
        }
        "urdf" | "mjcf" | "base" | "tip" => model_key(cx, meta, &key, out),
        _ => keyed_value(cx, meta, &key, out),
    };
    if let Err(err) = result {
        cx.syn_error(err);
        out.malformed = true;
        skip_rest(meta);
    }
}

/// How `key` is written, for errors.
fn form(key: &str) -> String {
    match key {
        "dh" | "mdh" => format!("{key}(a = .., alpha = .., d = .., theta = ..)"),
        "origin" | "tool" => format!("{key}(xyz = (x, y, z), rpy = (roll, pitch, yaw))"),
        "inertia" | "payload_inertia" => {
            format!("{key}(xx = .., yy = .., zz = .., xy = .., xz = .., yz = ..)")
        }
        "axis" | "com" | "payload_com" => format!("{key} = (x, y, z)"),
        "gravity" => "gravity = (0, 0, -9.81)".to_string(),
        "range" => "range = (lower, upper)".to_string(),
        "crate" => "crate = \"path\"".to_string(),
        "urdf" | "mjcf" => format!("{key} = \"models/arm.{key}\""),
        "base" | "tip" => format!("{key} = \"link_name\""),
        _ => format!("{key} = <number>"),
    }
}

/// Skips the rest of an entry that could not be read, so that parsing goes on with the next
/// entry and reports no error of its own.
fn skip_rest(meta: &ParseNestedMeta<'_>) {
    skip_to_comma(meta.input);
}

/// Reads the list `(...)` after `key` entry by entry with `f`, which reports its own errors.
/// An entry that is not `name = value` is one error, at it.
fn nested(
    meta: &ParseNestedMeta<'_>,
    key: &str,
    f: impl FnMut(ParseNestedMeta<'_>) -> syn::Result<()>,
) -> syn::Result<()> {
    let group: proc_macro2::Group = meta.input.parse()?;
    syn::meta::parser(f).parse2(group.stream()).map_err(|e| {
        syn::Error::new(
            e.span(),
            format!(
                "expected `{}`: entries `name = value`, separated by commas",
                form(key)
            ),
        )
    })
}

/// The expression after `=` and its tokens as written.
fn expr(meta: &ParseNestedMeta<'_>) -> syn::Result<(syn::Expr, TokenStream)> {
    if !meta.input.peek(syn::Token![=]) {
        // dh(a 0.4), dh(a)
        let key = path_text(&meta.path);
        return Err(syn::Error::new_spanned(
            &meta.path,
            format!("expected `{key} = <value>`"),
        ));
    }
    let v = meta.value()?;
    let start = v.cursor();
    let e = v.parse::<syn::Expr>()?;
    Ok((e, tokens_between(start, v.cursor())))
}

fn scalar(meta: &ParseNestedMeta<'_>, params: &mut Vec<ParamUse>) -> syn::Result<Scalar> {
    let (e, tokens) = expr(meta)?;
    Ok(Spanned {
        value: value::eval(&e, params)?,
        tokens,
    })
}

fn triple(
    meta: &ParseNestedMeta<'_>,
    params: &mut Vec<ParamUse>,
    what: &str,
) -> syn::Result<Triple> {
    let (e, tokens) = expr(meta)?;
    let t = match &e {
        syn::Expr::Tuple(t) if t.elems.len() == 3 => t,
        // #[arm(gravity = 9.81)], as a planar arm's
        _ if what == "gravity" => {
            return Err(syn::Error::new_spanned(
                tokens,
                "`gravity` takes the vector `(x, y, z)` in the base frame, for example \
                 `gravity = (0, 0, -9.81)` (the default)",
            ))
        }
        _ => {
            return Err(syn::Error::new_spanned(
                tokens,
                format!("`{what}` takes three numbers `(x, y, z)`"),
            ))
        }
    };
    let v: Vec<Poly> = t
        .elems
        .iter()
        .map(|x| value::eval(x, params))
        .collect::<syn::Result<_>>()?;
    Ok(Spanned {
        value: [v[0].clone(), v[1].clone(), v[2].clone()],
        tokens,
    })
}

fn angles(meta: &ParseNestedMeta<'_>) -> syn::Result<Angles> {
    let (e, tokens) = expr(meta)?;
    let syn::Expr::Tuple(t) = &e else {
        return Err(syn::Error::new_spanned(
            tokens,
            "`rpy` takes three angles `(roll, pitch, yaw)`",
        ));
    };
    if t.elems.len() != 3 {
        return Err(syn::Error::new_spanned(
            tokens,
            "`rpy` takes three angles `(roll, pitch, yaw)`",
        ));
    }
    let v: Vec<Angle> = t
        .elems
        .iter()
        .map(angle::eval)
        .collect::<syn::Result<_>>()?;
    Ok(Spanned {
        value: [v[0].clone(), v[1].clone(), v[2].clone()],
        tokens,
    })
}

fn duplicate(path: &syn::Path, key: &str) -> syn::Error {
    syn::Error::new_spanned(path, format!("duplicate key `{key}`; give it once"))
}

/// `dh(a = .., alpha = .., d = .., theta = ..)`, `mdh(...)`, `origin(xyz = .., rpy = ..)`.
fn geometry(
    cx: &Ctxt,
    meta: &ParseNestedMeta<'_>,
    key: &str,
    out: &mut SpatialAttrs,
) -> syn::Result<()> {
    let convention = match key {
        "dh" => Convention::Dh,
        "mdh" => Convention::Mdh,
        _ => Convention::Origin,
    };
    let mut g = Geometry {
        convention,
        tokens: meta.path.to_token_stream(),
        a: None,
        d: None,
        alpha: None,
        theta: None,
        xyz: None,
        rpy: None,
    };
    let subkeys: &[&str] = match convention {
        Convention::Origin => &["xyz", "rpy"],
        _ => &["a", "alpha", "d", "theta"],
    };
    let params = &mut out.params;
    nested(meta, key, |m| {
        let sub = path_text(&m.path);
        let result = (|| -> syn::Result<()> {
            match sub.as_str() {
                "a" | "d" if convention != Convention::Origin => {
                    let slot = if sub == "a" { &mut g.a } else { &mut g.d };
                    if slot.is_some() {
                        return Err(duplicate(&m.path, &sub));
                    }
                    *slot = Some(scalar(&m, params)?);
                }
                "alpha" | "theta" if convention != Convention::Origin => {
                    let slot = if sub == "alpha" {
                        &mut g.alpha
                    } else {
                        &mut g.theta
                    };
                    if slot.is_some() {
                        return Err(duplicate(&m.path, &sub));
                    }
                    let (e, tokens) = expr(&m)?;
                    *slot = Some(Spanned {
                        value: angle::eval(&e)?,
                        tokens,
                    });
                }
                "xyz" | "rpy" if convention == Convention::Origin => {
                    if (sub == "xyz" && g.xyz.is_some()) || (sub == "rpy" && g.rpy.is_some()) {
                        return Err(duplicate(&m.path, &sub));
                    }
                    if sub == "xyz" {
                        g.xyz = Some(triple(&m, params, "xyz")?);
                    } else {
                        g.rpy = Some(angles(&m)?);
                    }
                }
                _ => {
                    let hint = nearest(&sub, subkeys)
                        .map_or_else(String::new, |b| format!("; did you mean `{b}`?"));
                    return Err(syn::Error::new_spanned(
                        &m.path,
                        format!("`{key}` takes {}{hint}", subkeys.join(", ")),
                    ));
                }
            }
            Ok(())
        })();
        if let Err(e) = result {
            cx.syn_error(e);
            skip_rest(&m);
        }
        Ok(())
    })?;
    out.geometry = Some(g);
    Ok(())
}

/// `inertia(xx = .., yy = .., zz = .., xy = .., xz = .., yz = ..)`, or `payload_inertia(..)`.
fn inertia(
    cx: &Ctxt,
    meta: &ParseNestedMeta<'_>,
    key: &str,
    out: &mut SpatialAttrs,
) -> syn::Result<()> {
    let params = &mut out.params;
    let (slots, axes) = if key == "inertia" {
        (&mut out.inertia, "the link's axes")
    } else {
        out.payload_extras.push(meta.path.to_token_stream());
        (&mut out.payload_inertia, "the tool frame's axes")
    };
    nested(meta, key, |m| {
        let sub = path_text(&m.path);
        let result = match INERTIA_KEYS.iter().position(|k| *k == sub) {
            Some(i) if slots[i].is_some() => Err(duplicate(&m.path, &sub)),
            Some(i) => scalar(&m, params).map(|v| slots[i] = Some(v)),
            None => {
                let hint = inertia_entry(&sub)
                    .map_or_else(String::new, |k| format!(" (did you mean `{k}`?)"));
                Err(syn::Error::new_spanned(
                    &m.path,
                    format!(
                        "unknown inertia entry `{sub}`{hint}; the entries are xx, yy, zz, xy, xz, yz \
                         (kg m², about the centre of mass in {axes})"
                    ),
                ))
            }
        };
        if let Err(e) = result {
            cx.syn_error(e);
            skip_rest(&m);
        }
        Ok(())
    })
}

/// The entry meant by URDF's `ixx` or by `yx` (the tensor is symmetric).
fn inertia_entry(sub: &str) -> Option<&'static str> {
    let sub = sub.to_ascii_lowercase();
    let sub = sub.strip_prefix('i').unwrap_or(&sub);
    let mut sorted: Vec<char> = sub.chars().collect();
    sorted.sort_unstable();
    let sorted: String = sorted.into_iter().collect();
    INERTIA_KEYS.iter().copied().find(|k| *k == sorted)
}

/// `tool(xyz = .., rpy = ..)`.
fn tool(cx: &Ctxt, meta: &ParseNestedMeta<'_>, out: &mut SpatialAttrs) -> syn::Result<()> {
    let params = &mut out.params;
    let (xyz, rpy) = (&mut out.tool_xyz, &mut out.tool_rpy);
    nested(meta, "tool", |m| {
        let sub = path_text(&m.path);
        let result = match sub.as_str() {
            "xyz" if xyz.is_some() => Err(duplicate(&m.path, &sub)),
            "rpy" if rpy.is_some() => Err(duplicate(&m.path, &sub)),
            "xyz" => triple(&m, params, "xyz").map(|v| *xyz = Some(v)),
            "rpy" => angles(&m).map(|v| *rpy = Some(v)),
            _ => Err(syn::Error::new_spanned(
                &m.path,
                "`tool` takes `xyz = (x, y, z)` and `rpy = (roll, pitch, yaw)`",
            )),
        };
        if let Err(e) = result {
            cx.syn_error(e);
            skip_rest(&m);
        }
        Ok(())
    })
}

/// `crate = "path"`.
fn krate(meta: &ParseNestedMeta<'_>, out: &mut SpatialAttrs) -> syn::Result<()> {
    let value = meta.value()?;
    let lit = value.parse::<syn::LitStr>().map_err(|e| {
        syn::Error::new(
            e.span(),
            "expected `crate = \"path\"`, the path of planar_arm in this crate, for example \
             `crate = \"arm\"`",
        )
    })?;
    out.krate = Some(lit.parse::<syn::Path>().map_err(|_| {
        syn::Error::new_spanned(
            &lit,
            "expected a path such as \"arm\" or \"::my_deps::planar_arm\"",
        )
    })?);
    Ok(())
}

// #[arm(urdf = "models/ur5.urdf", base = "base_link", tip = "tool0")]
fn model_key(
    cx: &Ctxt,
    meta: &ParseNestedMeta<'_>,
    key: &str,
    out: &mut SpatialAttrs,
) -> syn::Result<()> {
    // Known to be an arm from a file even when the path cannot be read, so that no
    // missing-joint error follows.
    out.model_written |= key == "urdf" || key == "mjcf";
    let lit = meta
        .value()?
        .parse::<syn::LitStr>()
        .map_err(|e| syn::Error::new(e.span(), format!("expected `{}`, a string", form(key))))?;
    match key {
        "base" => out.base = Some(lit),
        "tip" => out.tip = Some(lit),
        _ => out.malformed |= !crate::models::set_file(cx, &mut out.model, key, lit),
    }
    Ok(())
}

/// `axis`, `mass`, `com`, `range`, `armature`, `damping`, `frictionloss`, `gravity`,
/// `payload`, `payload_com`.
fn keyed_value(
    cx: &Ctxt,
    meta: &ParseNestedMeta<'_>,
    key: &str,
    out: &mut SpatialAttrs,
) -> syn::Result<()> {
    let params = &mut out.params;
    match key {
        "axis" => {
            let mut uses = Vec::new();
            let t = triple(meta, &mut uses, "axis")?;
            let numbers: Option<Vec<Rational>> = t.value.iter().map(Poly::as_rational).collect();
            match numbers {
                Some(v) if uses.is_empty() => {
                    out.axis = Some(Spanned {
                        value: [v[0].clone(), v[1].clone(), v[2].clone()],
                        tokens: t.tokens,
                    });
                }
                _ => cx.error_spanned_by(
                    &t.tokens,
                    "an axis is three numbers, not run-time parameters",
                ),
            }
        }
        "mass" => out.mass = Some(scalar(meta, params)?),
        "payload" => out.payload = Some(scalar(meta, params)?),
        "payload_com" => {
            let t = triple(meta, params, "payload_com")?;
            out.payload_extras.push(t.tokens.clone());
            out.payload_com = Some(t);
        }
        "com" => out.com = Some(triple(meta, params, "com")?),
        "gravity" => out.gravity = Some(triple(meta, params, "gravity")?),
        "armature" => out.armature = Some(scalar(meta, params)?),
        "damping" => out.damping = Some(scalar(meta, params)?),
        "frictionloss" => out.frictionloss = Some(scalar(meta, params)?),
        "stiffness" => out.stiffness = Some(scalar(meta, params)?),
        "springref" => out.springref = Some(scalar(meta, params)?),
        "range" => {
            let mut uses = Vec::new();
            let (e, tokens) = expr(meta)?;
            let pair = match &e {
                syn::Expr::Tuple(t) if t.elems.len() == 2 => Some((
                    value::eval(&t.elems[0], &mut uses)?.as_rational(),
                    value::eval(&t.elems[1], &mut uses)?.as_rational(),
                )),
                _ => None,
            };
            match pair {
                Some((Some(lo), Some(hi))) => {
                    out.range = Some(Spanned {
                        value: (lo, hi),
                        tokens,
                    })
                }
                _ => cx.error_spanned_by(
                    &tokens,
                    "`range` takes two numbers `(lower, upper)`, radians or metres",
                ),
            }
        }
        _ => {}
    }
    Ok(())
}
