//! The `#[arm(...)]` attribute of `#[derive(SpatialArm)]`: its keys and their parsing.
//!
//! On the struct: `gravity = (gx, gy, gz)`, `tool(xyz = (x, y, z), rpy = (r, p, y))`,
//! `crate = "..."`. On each joint field: one of `dh(a, alpha, d, theta)`,
//! `mdh(a, alpha, d, theta)` or `origin(xyz = (..), rpy = (..))` with `axis = (x, y, z)`; the
//! link's `mass`, `com = (x, y, z)` and `inertia(xx, yy, zz, xy, xz, yz)`; the joint's `range`,
//! `armature`, `damping`, `frictionloss`. Lengths and mass properties are exact numbers or
//! run-time parameters (`self.NAME`); angles are numbers and multiples of `pi`.

use planar_arm_core::ring::Rational;
use planar_arm_core::Poly;
use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::meta::ParseNestedMeta;

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
    // On a field.
    pub geometry: Option<Geometry>,
    pub axis: Option<Spanned<[Rational; 3]>>,
    pub mass: Option<Scalar>,
    pub com: Option<Triple>,
    /// xx, yy, zz, xy, xz, yz.
    pub inertia: [Option<Scalar>; 6],
    pub inertia_tokens: Option<TokenStream>,
    pub range: Option<Spanned<(Rational, Rational)>>,
    pub armature: Option<Scalar>,
    pub damping: Option<Scalar>,
    pub frictionloss: Option<Scalar>,
    // On the struct.
    pub gravity: Option<Triple>,
    pub tool_xyz: Option<Triple>,
    pub tool_rpy: Option<Angles>,
    pub krate: Option<syn::Path>,
}

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
];
const STRUCT_KEYS: &[&str] = &["gravity", "tool", "crate"];
/// A planar arm's keys, which a spatial arm writes otherwise.
const PLANAR_KEYS: &[&str] = &["length", "payload", "payload_com", "payload_inertia"];
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
            cx.error_spanned_by(
                attr,
                "expected #[arm(...)], for example #[arm(dh(a = 0.4, alpha = pi/2))]",
            );
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
        } else if PLANAR_KEYS.contains(&key.as_str()) {
            format!(
                "`{key}` is a key of #[derive(PlanarArm)]; a spatial joint is written `dh(...)`, \
                 `mdh(...)` or `origin(...)` with `axis`, its link with `mass`, `com` and `inertia(...)`"
            )
        } else if let Some(best) = nearest(&key, own) {
            format!("unknown key `{key}`; did you mean `{best}`?")
        } else {
            format!("unknown key `{key}`; expected one of {}", own.join(", "))
        };
        cx.error_spanned_by(&meta.path, message);
        skip_value(meta);
        return;
    }
    let result = match key.as_str() {
        "dh" | "mdh" | "origin" => geometry(cx, meta, &key, out),
        "inertia" => inertia(cx, meta, out),
        "tool" => tool(cx, meta, out),
        "crate" => krate(meta, out),
        _ => keyed_value(cx, meta, &key, out),
    };
    if let Err(err) = result {
        cx.syn_error(err);
        out.malformed = true;
    }
}

/// Skips `= value` or `(...)` after an unknown key.
fn skip_value(meta: &ParseNestedMeta<'_>) {
    if meta.input.peek(syn::token::Paren) {
        let _ = meta.parse_nested_meta(|m| {
            skip_value(&m);
            Ok(())
        });
    } else if meta.input.peek(syn::Token![=]) {
        let _ = meta.value();
        skip_to_comma(meta.input);
    }
}

/// The expression after `=` and its tokens as written.
fn expr(meta: &ParseNestedMeta<'_>) -> syn::Result<(syn::Expr, TokenStream)> {
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
    let syn::Expr::Tuple(t) = &e else {
        return Err(syn::Error::new_spanned(
            tokens,
            format!("`{what}` takes three numbers `(x, y, z)`"),
        ));
    };
    if t.elems.len() != 3 {
        return Err(syn::Error::new_spanned(
            tokens,
            format!("`{what}` takes three numbers `(x, y, z)`"),
        ));
    }
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
    if let Some(g) = &out.geometry {
        return Err(syn::Error::new_spanned(
            &meta.path,
            format!(
                "this joint is already written with `{}`; a joint has one geometry",
                g.convention.key()
            ),
        ));
    }
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
    meta.parse_nested_meta(|m| {
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
                "xyz" if convention == Convention::Origin => {
                    g.xyz = Some(triple(&m, params, "xyz")?)
                }
                "rpy" if convention == Convention::Origin => g.rpy = Some(angles(&m)?),
                _ => {
                    let hint = nearest(&sub, subkeys)
                        .map_or_else(String::new, |b| format!("; did you mean `{b}`?"));
                    skip_value(&m);
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
        }
        Ok(())
    })?;
    out.geometry = Some(g);
    Ok(())
}

/// `inertia(xx = .., yy = .., zz = .., xy = .., xz = .., yz = ..)`.
fn inertia(cx: &Ctxt, meta: &ParseNestedMeta<'_>, out: &mut SpatialAttrs) -> syn::Result<()> {
    if out.inertia_tokens.is_some() {
        return Err(duplicate(&meta.path, "inertia"));
    }
    out.inertia_tokens = Some(meta.path.to_token_stream());
    let params = &mut out.params;
    let slots = &mut out.inertia;
    meta.parse_nested_meta(|m| {
        let sub = path_text(&m.path);
        match INERTIA_KEYS.iter().position(|k| *k == sub) {
            Some(i) if slots[i].is_some() => cx.syn_error(duplicate(&m.path, &sub)),
            Some(i) => match scalar(&m, params) {
                Ok(v) => slots[i] = Some(v),
                Err(e) => cx.syn_error(e),
            },
            None => {
                let hint = nearest(&sub, &INERTIA_KEYS).map_or_else(String::new, |b| format!("; did you mean `{b}`?"));
                skip_value(&m);
                cx.error_spanned_by(
                    &m.path,
                    format!(
                        "unknown inertia entry `{sub}`{hint}; the entries are xx, yy, zz, xy, xz, yz (kg m², about the centre of mass in the link's axes)"
                    ),
                );
            }
        }
        Ok(())
    })
}

/// `tool(xyz = .., rpy = ..)`.
fn tool(cx: &Ctxt, meta: &ParseNestedMeta<'_>, out: &mut SpatialAttrs) -> syn::Result<()> {
    let params = &mut out.params;
    let (xyz, rpy) = (&mut out.tool_xyz, &mut out.tool_rpy);
    meta.parse_nested_meta(|m| {
        let sub = path_text(&m.path);
        let result = match sub.as_str() {
            "xyz" => triple(&m, params, "xyz").map(|v| *xyz = Some(v)),
            "rpy" => angles(&m).map(|v| *rpy = Some(v)),
            _ => {
                skip_value(&m);
                Err(syn::Error::new_spanned(
                    &m.path,
                    "`tool` takes `xyz = (x, y, z)` and `rpy = (roll, pitch, yaw)`",
                ))
            }
        };
        if let Err(e) = result {
            cx.syn_error(e);
        }
        Ok(())
    })
}

fn krate(meta: &ParseNestedMeta<'_>, out: &mut SpatialAttrs) -> syn::Result<()> {
    let lit = meta.value()?.parse::<syn::LitStr>()?;
    out.krate = Some(lit.parse::<syn::Path>()?);
    Ok(())
}

/// `axis`, `mass`, `com`, `range`, `armature`, `damping`, `frictionloss`, `gravity`.
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
        "com" => out.com = Some(triple(meta, params, "com")?),
        "gravity" => out.gravity = Some(triple(meta, params, "gravity")?),
        "armature" => out.armature = Some(scalar(meta, params)?),
        "damping" => out.damping = Some(scalar(meta, params)?),
        "frictionloss" => out.frictionloss = Some(scalar(meta, params)?),
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
