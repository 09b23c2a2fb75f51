//! The `#[arm(...)]` attribute: keywords and parsing of one item's attribute lists.

use planar_arm_core::Poly;
use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::meta::ParseNestedMeta;
use syn::parse::ParseStream;
use syn::Token;

use crate::ctxt::Ctxt;
use crate::value;

pub const ARM: &str = "arm";
pub const GRAVITY: &str = "gravity";
pub const LENGTH: &str = "length";
pub const MASS: &str = "mass";
pub const INERTIA: &str = "inertia";
pub const COM: &str = "com";
pub const ARMATURE: &str = "armature";
pub const DAMPING: &str = "damping";
pub const FRICTIONLOSS: &str = "frictionloss";
pub const PAYLOAD: &str = "payload";
pub const PAYLOAD_INERTIA: &str = "payload_inertia";
pub const PAYLOAD_COM: &str = "payload_com";
pub const CRATE: &str = "crate";
pub const RANGE: &str = "range";
pub const OFFSET: &str = "offset";
pub const STIFFNESS: &str = "stiffness";
pub const SPRINGREF: &str = "springref";
pub const REVERSED: &str = "reversed";
pub const URDF: &str = "urdf";
pub const MJCF: &str = "mjcf";
pub const BASE: &str = "base";
pub const TIP: &str = "tip";

pub const STRUCT_KEYS: &[&str] = &[
    GRAVITY,
    PAYLOAD,
    PAYLOAD_INERTIA,
    PAYLOAD_COM,
    CRATE,
    URDF,
    MJCF,
    BASE,
    TIP,
];
pub const FIELD_KEYS: &[&str] = &[
    LENGTH,
    MASS,
    INERTIA,
    COM,
    ARMATURE,
    DAMPING,
    FRICTIONLOSS,
    RANGE,
    OFFSET,
    REVERSED,
    STIFFNESS,
    SPRINGREF,
];
/// Keys of `#[derive(SpatialArm)]`, which a planar arm writes otherwise.
const SPATIAL_KEYS: &[&str] = &["dh", "mdh", "origin", "axis", "tool"];
/// Keys whose value may be a pair `(x, y)`.
const PAIR_KEYS: &[&str] = &[COM, PAYLOAD_COM, GRAVITY];

/// A parsed value with the tokens it came from.
pub struct Value {
    /// The value (for a pair, its first component).
    pub value: Poly,
    /// The second component of a pair `(x, y)`; `None` for a scalar.
    pub y: Option<Poly>,
    /// The value's tokens, for errors about the value.
    pub tokens: TokenStream,
    /// The run-time parameters it names.
    pub params: Vec<value::ParamUse>,
}

/// Where an `#[arm(...)]` list appears.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Place {
    Struct,
    Field,
}

/// One `key = value` that parsed.
pub struct Entry {
    pub key: &'static str,
    pub value: Value,
}

/// Key-value pairs of all `#[arm(...)]` attributes on one item, each key at most once.
#[derive(Default)]
pub struct Attrs {
    pub entries: Vec<Entry>,
    /// Keys that were written (perhaps misspelt, perhaps with a bad value): a missing-key error
    /// for them would only repeat the error already reported.
    pub mentioned: Vec<&'static str>,
    /// Some `#[arm ...]` could not be read to its end; what it lacks is not reported.
    pub malformed: bool,
    /// The first `#[arm(...)]`, for errors about the list as a whole.
    pub tokens: TokenStream,
    /// `#[arm(crate = "path")]`: the path of `planar_arm` in the user's crate.
    pub krate: Option<syn::Path>,
    /// `#[arm(urdf = "..")]` or `#[arm(mjcf = "..")]`: the model file the links come from, and
    /// the chain's `base` and `tip`.
    pub model: Option<(crate::models::Format, syn::LitStr)>,
    pub base: Option<syn::LitStr>,
    pub tip: Option<syn::LitStr>,
    /// `#[arm(offset = pi/2)]` on a link: the joint's constant turn, exact where it is a
    /// rational multiple of `pi` or a number of radians.
    pub offset: Option<planar_arm_core::spatial::FixedAngle>,
    /// `#[arm(reversed)]` on a link: the joint turns (slides) the other way.
    pub reversed: bool,
}

impl Attrs {
    pub fn get(&self, key: &str) -> Option<&Value> {
        self.entries.iter().find(|e| e.key == key).map(|e| &e.value)
    }

    /// Whether an error about `key` has been reported already, or the key was given.
    pub fn accounted_for(&self, key: &str) -> bool {
        self.malformed || self.mentioned.contains(&key)
    }
}

/// Parses every `#[arm(...)]` in `attrs`. Returns `None` when there is none at all.
pub fn parse(cx: &Ctxt, attrs: &[syn::Attribute], place: Place) -> Option<Attrs> {
    let mut out = Attrs::default();
    let mut found = false;
    for attr in attrs.iter().filter(|a| a.path().is_ident(ARM)) {
        if !found {
            out.tokens = attr.to_token_stream();
        }
        found = true;
        let list = match &attr.meta {
            syn::Meta::List(list) => list,
            // #[arm] or #[arm = ...]
            _ => {
                cx.error_spanned_by(attr, expected_syntax(place));
                out.malformed = true;
                continue;
            }
        };
        // #[arm[...]] or #[arm{...}]
        if !matches!(list.delimiter, syn::MacroDelimiter::Paren(_)) {
            cx.error_spanned_by(
                attr,
                format!(
                    "use parentheses: {}",
                    expected_syntax(place).trim_start_matches("expected ")
                ),
            );
            out.malformed = true;
            continue;
        }
        // #[arm()] on the struct says nothing; on a field the missing keys are reported.
        if list.tokens.is_empty() && place == Place::Struct {
            cx.error_spanned_by(
                attr,
                "empty #[arm()]; give the arm's properties, e.g. #[arm(gravity = 9.81)], or remove it",
            );
            out.malformed = true;
            continue;
        }
        let result = attr.parse_nested_meta(|meta| {
            parse_entry(cx, &meta, place, &mut out);
            Ok(())
        });
        if let Err(err) = result {
            cx.syn_error(err);
            out.malformed = true;
        }
    }
    found.then_some(out)
}

fn expected_syntax(place: Place) -> &'static str {
    match place {
        Place::Struct => {
            "expected #[arm(gravity = ..., payload = ...)], for example #[arm(gravity = 9.81)]"
        }
        Place::Field => {
            "expected #[arm(length = ..., mass = ...)], for example #[arm(length = 0.5, mass = 2)]"
        }
    }
}

/// Skips the rest of a malformed `key = value` so parsing goes on with the next key.
pub(crate) fn skip_to_comma(input: ParseStream<'_>) {
    while !input.is_empty() && !input.peek(Token![,]) {
        if input.parse::<proc_macro2::TokenTree>().is_err() {
            break;
        }
    }
}

pub(crate) fn path_text(path: &syn::Path) -> String {
    path.segments
        .iter()
        .map(|s| s.ident.to_string())
        .collect::<Vec<_>>()
        .join("::")
}

fn parse_entry(cx: &Ctxt, meta: &ParseNestedMeta<'_>, place: Place, out: &mut Attrs) {
    let path = &meta.path;
    let key = path_text(path);
    if key == CRATE && place == Place::Struct {
        parse_crate(cx, meta, out);
        return;
    }
    if [URDF, MJCF, BASE, TIP].contains(&key.as_str()) && place == Place::Struct {
        parse_model_key(cx, meta, &key, out);
        return;
    }
    if [OFFSET, REVERSED].contains(&key.as_str()) && place == Place::Field {
        parse_joint_turn(cx, meta, &key, out);
        return;
    }
    // #[arm(inertia(zz = 0.1))], before the value is skipped
    let list = meta.input.peek(syn::token::Paren);
    // Consume the value first so that parsing can go on to the next key after an error.
    let value = match meta.value().and_then(|v| {
        let start = v.cursor();
        let expr = v.parse::<syn::Expr>()?;
        Ok((expr, tokens_between(start, v.cursor())))
    }) {
        Ok(parsed) => Some(parsed),
        Err(_) => {
            skip_to_comma(meta.input);
            None
        }
    };
    let (own, other) = match place {
        Place::Struct => (STRUCT_KEYS, FIELD_KEYS),
        Place::Field => (FIELD_KEYS, STRUCT_KEYS),
    };
    let Some(&known) = own.iter().find(|k| **k == key) else {
        let msg = if other.contains(&key.as_str()) {
            match place {
                // #[arm(length = 1)] on the struct
                Place::Struct => format!(
                    "`{key}` is a link parameter; it belongs in the #[arm(...)] of a link field, not on the struct"
                ),
                // #[arm(gravity = 9.81)] on a field
                Place::Field => format!(
                    "`{key}` is a property of the whole arm; it belongs in #[arm({key} = ...)] on the struct, not on a link field"
                ),
            }
        } else if key == "tool" {
            // #[arm(tool(xyz = (0.1, 0, 0)))] on a planar arm
            format!(
                "`tool` is a key of #[derive(SpatialArm)]: derive `SpatialArm` for a spatial arm; \
                 #[derive(PlanarArm)] takes {} on the struct",
                STRUCT_KEYS
                    .iter()
                    .map(|k| format!("`{k}`"))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        } else if key == "exact_dynamics" {
            // #[arm(exact_dynamics)] on a planar arm
            "`exact_dynamics` is a key of #[derive(SpatialArm)]; a planar arm's `EXACT` always \
             holds M and c multiplied out"
                .to_string()
        } else if SPATIAL_KEYS.contains(&key.as_str()) {
            // #[arm(dh(a = 0.4))] on a planar arm: no missing-`length` error on top
            if key != "axis" {
                out.mentioned.push(LENGTH);
            }
            format!(
                "`{key}` describes a joint of a spatial arm: derive `SpatialArm` for that; a planar \
                 arm's link takes `length`, `mass`, `inertia`, `com` and the joint keys"
            )
        } else if let Some(&lower) = own.iter().find(|k| k.eq_ignore_ascii_case(&key)) {
            // #[arm(MASS = 1)]
            out.mentioned.push(lower);
            format!("unknown key `{key}`; keys are lowercase: `{lower}`")
        } else if let Some(best) = nearest(&key, own) {
            out.mentioned.push(best);
            format!("unknown key `{key}`; did you mean `{best}`?")
        } else {
            format!(
                "unknown key `{key}`; expected {}",
                own.iter()
                    .map(|k| format!("`{k}`"))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        cx.error_spanned_by(path, msg);
        return;
    };
    out.mentioned.push(known);
    if out.get(known).is_some() {
        cx.error_spanned_by(path, format!("duplicate key `{key}`; give it once"));
        return;
    }
    // #[arm(length = 0.5)]
    let Some((expr, tokens)) = value else {
        if known == INERTIA && list {
            // #[arm(inertia(zz = 0.1))]
            cx.error_spanned_by(
                path,
                "a planar link's `inertia` is one number, its moment about the centre of mass \
                 (kg m²), for example `inertia = 0.5`; `inertia(xx = .., ..)` is a tensor, for \
                 #[derive(SpatialArm)]",
            );
            return;
        }
        cx.error_spanned_by(
            path,
            format!("expected `{key} = <number>`, for example `{key} = 0.5`"),
        );
        return;
    };
    let mut params = Vec::new();
    let parsed = match &expr {
        // #[arm(com = (0.11, 0.005))]
        // #[arm(range = (0, 0.6))]
        syn::Expr::Tuple(t) if known == RANGE && t.elems.len() == 2 => value::eval(&t.elems[0], &mut params)
            .and_then(|x| value::eval(&t.elems[1], &mut params).map(|y| (x, Some(y)))),
        _ if known == RANGE => Err(syn::Error::new_spanned(
            &tokens,
            "`range` takes a pair `(lower, upper)` of numbers, radians for a revolute joint and metres for a prismatic one, for example `range = (0, 0.6)`",
        )),
        syn::Expr::Tuple(t) if PAIR_KEYS.contains(&known) && t.elems.len() == 2 => {
            value::eval(&t.elems[0], &mut params)
                .and_then(|x| value::eval(&t.elems[1], &mut params).map(|y| (x, Some(y))))
        }
        syn::Expr::Tuple(t) if PAIR_KEYS.contains(&known) => Err(syn::Error::new_spanned(
            t,
            if known == GRAVITY {
                "`gravity` takes one number, its magnitude along -y (`gravity = 9.81`), or its \
                 acceleration as a pair `(gx, gy)` (`gravity = (0, -9.81)`)"
                    .to_string()
            } else {
                format!("`{key}` takes one number (along the link) or a pair `(x, y)`")
            },
        )),
        syn::Expr::Tuple(t) => Err(syn::Error::new_spanned(
            t,
            format!(
                "`{key}` takes one number; only `com`, `payload_com` and `gravity` take a pair \
                 `(x, y)`"
            ),
        )),
        _ => value::eval(&expr, &mut params).map(|x| (x, None)),
    };
    match parsed {
        Ok((v, y)) => out.entries.push(Entry {
            key: known,
            value: Value {
                value: v,
                y,
                tokens,
                params,
            },
        }),
        Err(err) => cx.syn_error(err),
    }
}

/// The tokens from `start` up to `end`, as written: printing the parsed expression instead
/// recurses once per operator, which a value of 20 000 terms turns into a stack overflow.
pub(crate) fn tokens_between(
    mut cursor: syn::buffer::Cursor<'_>,
    end: syn::buffer::Cursor<'_>,
) -> TokenStream {
    let mut tokens = Vec::new();
    while cursor != end {
        let Some((tree, next)) = cursor.token_tree() else {
            break;
        };
        tokens.push(tree);
        cursor = next;
    }
    tokens.into_iter().collect()
}

/// `#[arm(crate = "path")]`: the path of `planar_arm` where the user renamed the dependency.
// #[arm(mjcf = "models/acrobot.xml", tip = "lower_arm")]
fn parse_model_key(cx: &Ctxt, meta: &ParseNestedMeta<'_>, key: &str, out: &mut Attrs) {
    let known = STRUCT_KEYS
        .iter()
        .copied()
        .find(|k| *k == key)
        .unwrap_or(URDF);
    out.mentioned.push(known);
    let lit = match meta.value().and_then(|v| v.parse::<syn::LitStr>()) {
        Ok(lit) => lit,
        Err(_) => {
            skip_to_comma(meta.input);
            out.malformed = true;
            let example = if key == BASE || key == TIP {
                format!("{key} = \"link_name\"")
            } else {
                format!("{key} = \"models/arm.{key}\"")
            };
            cx.error_spanned_by(&meta.path, format!("expected `{example}`, a string"));
            return;
        }
    };
    match key {
        BASE => out.base = Some(lit),
        TIP => out.tip = Some(lit),
        _ => out.malformed |= !crate::models::set_file(cx, &mut out.model, key, lit),
    }
}

/// `offset = <angle>` (a number of radians or a multiple of `pi`) and the flag `reversed`.
fn parse_joint_turn(cx: &Ctxt, meta: &ParseNestedMeta<'_>, key: &str, out: &mut Attrs) {
    let known = if key == OFFSET { OFFSET } else { REVERSED };
    let again = out.mentioned.contains(&known);
    out.mentioned.push(known);
    if known == REVERSED {
        if meta.input.peek(Token![=]) {
            // #[arm(reversed = true)]
            let _ = meta.value().and_then(|v| v.parse::<syn::Expr>());
            skip_to_comma(meta.input);
            cx.error_spanned_by(
                &meta.path,
                "`reversed` is a flag and takes no value: write `reversed` for a joint that turns \
                 (slides) the other way, and nothing for one that does not",
            );
        } else if again {
            cx.error_spanned_by(&meta.path, "duplicate key `reversed`; give it once");
        } else {
            out.reversed = true;
        }
        return;
    }
    let angle = meta
        .value()
        .and_then(|v| v.parse::<syn::Expr>())
        .and_then(|e| crate::spatial::angle::eval(&e));
    match angle {
        // #[arm(offset = pi/2)]
        Ok(a) if !again => {
            out.offset = Some(planar_arm_core::spatial::FixedAngle {
                radians: a.radians,
                pi_multiple: a.pi_multiple,
            });
        }
        Ok(_) => cx.error_spanned_by(&meta.path, "duplicate key `offset`; give it once"),
        Err(e) => {
            skip_to_comma(meta.input);
            // #[arm(offset = "90")]
            cx.syn_error(syn::Error::new(
                e.span(),
                format!(
                    "{e}; `offset` is the joint's angle at q = 0 relative to the previous link, \
                     for example `offset = pi/2`"
                ),
            ));
        }
    }
}

fn parse_crate(cx: &Ctxt, meta: &ParseNestedMeta<'_>, out: &mut Attrs) {
    out.mentioned.push(CRATE);
    let lit = match meta.value().and_then(|v| v.parse::<syn::LitStr>()) {
        Ok(lit) => lit,
        Err(_) => {
            skip_to_comma(meta.input);
            cx.error_spanned_by(
                &meta.path,
                "expected `crate = \"path\"`, the path of planar_arm in this crate, for example `crate = \"arm\"`",
            );
            return;
        }
    };
    if out.krate.is_some() {
        cx.error_spanned_by(&meta.path, "duplicate key `crate`; give it once");
        return;
    }
    match lit.parse::<syn::Path>() {
        Ok(path) => out.krate = Some(path),
        Err(_) => cx.error_spanned_by(
            &lit,
            "expected a path such as \"arm\" or \"::my_deps::planar_arm\"",
        ),
    }
}

/// The known key closest to `key` by edit distance, if it is close enough to be a typo.
pub(crate) fn nearest<'a>(key: &str, known: &[&'a str]) -> Option<&'a str> {
    known
        .iter()
        .map(|k| (levenshtein(key, k), *k))
        .filter(|(d, k)| *d <= (k.len() / 2).max(2))
        .min()
        .map(|(_, k)| k)
}

pub(crate) fn levenshtein(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, &cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typos_find_their_key() {
        assert_eq!(nearest("lenght", FIELD_KEYS), Some("length"));
        assert_eq!(nearest("mas", FIELD_KEYS), Some("mass"));
        assert_eq!(nearest("inertial", FIELD_KEYS), Some("inertia"));
        assert_eq!(nearest("colour", FIELD_KEYS), None);
        assert_eq!(nearest("gravty", STRUCT_KEYS), Some("gravity"));
    }
}
