//! The `#[arm(...)]` attribute: keywords and parsing of one attribute list.

use planar_arm_core::ring::Rational;
use syn::meta::ParseNestedMeta;
use syn::spanned::Spanned;

use crate::ctxt::Ctxt;
use crate::value;

pub const ARM: &str = "arm";
pub const GRAVITY: &str = "gravity";
pub const LENGTH: &str = "length";
pub const MASS: &str = "mass";
pub const INERTIA: &str = "inertia";
pub const COM: &str = "com";

pub const STRUCT_KEYS: &[&str] = &[GRAVITY];
pub const FIELD_KEYS: &[&str] = &[LENGTH, MASS, INERTIA, COM];

/// A parsed value with the tokens it came from.
pub struct Value {
    pub value: Rational,
    /// The value's tokens, for errors about the value.
    pub tokens: proc_macro2::TokenStream,
}

/// Where an `#[arm(...)]` list appears.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Place {
    Struct,
    Field,
}

/// Key-value pairs of all `#[arm(...)]` attributes on one item, each key at most once.
#[derive(Default)]
pub struct Attrs {
    pub entries: Vec<(String, proc_macro2::Span, Value)>,
}

impl Attrs {
    pub fn get(&self, key: &str) -> Option<&Value> {
        self.entries.iter().find(|e| e.0 == key).map(|e| &e.2)
    }
}

/// Parses every `#[arm(...)]` in `attrs`. Returns `None` when there is none at all.
pub fn parse(cx: &Ctxt, attrs: &[syn::Attribute], place: Place) -> Option<Attrs> {
    let mut out = Attrs::default();
    let mut found = false;
    for attr in attrs.iter().filter(|a| a.path().is_ident(ARM)) {
        found = true;
        if let syn::Meta::Path(_) = attr.meta {
            cx.error_spanned_by(attr, expected_syntax(place));
            continue;
        }
        let result = attr.parse_nested_meta(|meta| {
            parse_entry(cx, &meta, place, &mut out);
            Ok(())
        });
        if let Err(err) = result {
            cx.syn_error(err);
        }
    }
    found.then_some(out)
}

fn expected_syntax(place: Place) -> &'static str {
    match place {
        Place::Struct => "expected #[arm(gravity = ...)]",
        Place::Field => "expected #[arm(length = ..., mass = ...)]",
    }
}

fn parse_entry(cx: &Ctxt, meta: &ParseNestedMeta<'_>, place: Place, out: &mut Attrs) {
    let path = &meta.path;
    let key = path
        .get_ident()
        .map(ToString::to_string)
        .unwrap_or_else(|| quote::quote!(#path).to_string());
    // Consume the value first so that parsing can go on to the next key after an error.
    let value = match meta.value().and_then(|v| v.parse::<syn::Expr>()) {
        Ok(expr) => Some(expr),
        Err(err) => {
            cx.syn_error(syn::Error::new(
                err.span(),
                format!("expected `{key} = <number>`"),
            ));
            None
        }
    };
    let (own, other) = match place {
        Place::Struct => (STRUCT_KEYS, FIELD_KEYS),
        Place::Field => (FIELD_KEYS, STRUCT_KEYS),
    };
    if !own.contains(&key.as_str()) {
        let msg = if other.contains(&key.as_str()) {
            match place {
                // #[arm(length = 1)] on the struct
                Place::Struct => format!(
                    "`{key}` is a link parameter; it belongs on a link field, not on the struct"
                ),
                // #[arm(gravity = 9.81)] on a field
                Place::Field => format!(
                    "`{key}` is a property of the whole arm; it belongs in #[arm({key} = ...)] on the struct, not on a link field"
                ),
            }
        } else {
            match nearest(&key, own) {
                Some(best) => format!("unknown key `{key}`; did you mean `{best}`?"),
                None => format!(
                    "unknown key `{key}`; expected one of: {}",
                    own.iter()
                        .map(|k| format!("`{k}`"))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            }
        };
        cx.error_spanned_by(path, msg);
        return;
    }
    if out.get(&key).is_some() {
        cx.error_spanned_by(path, format!("duplicate key `{key}`"));
        return;
    }
    let Some(expr) = value else { return };
    match value::eval(&expr) {
        Ok(v) => out.entries.push((
            key,
            path.span(),
            Value {
                value: v,
                tokens: quote::quote!(#expr),
            },
        )),
        Err(err) => cx.syn_error(err),
    }
}

/// The known key closest to `key` by edit distance, if it is close enough to be a typo.
fn nearest<'a>(key: &str, known: &[&'a str]) -> Option<&'a str> {
    known
        .iter()
        .map(|k| (levenshtein(key, k), *k))
        .filter(|(d, k)| *d <= (k.len() / 2).max(2))
        .min()
        .map(|(_, k)| k)
}

fn levenshtein(a: &str, b: &str) -> usize {
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
