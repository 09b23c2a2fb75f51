//! The absolute paths of generated code, made to survive the user's scope.
//!
//! Generated code names the run-time crate `::planar_arm::...` and its primitive types
//! `::core::primitive::f64`. Two things in a user's crate would break shorter names: a
//! dependency renamed in Cargo.toml (`arm = { package = "planar_arm" }`, so that `::planar_arm`
//! does not exist), and a type of the user's own named like a primitive (`struct f64;` in scope
//! shadows the primitive, which is not a keyword). The engine writes the primitives by their
//! `::core` paths as it emits them ([`F64`] and [`STR`] in a `quote!`: `SVector<#F64, 2>`), and
//! [`qualify`] rewrites `::planar_arm` (and any primitive left bare) only when a user renamed
//! the crate: rewriting walks every token, which inside a procedural macro is a call into the
//! compiler per token (a quarter of a 6-link arm's expansion). The derive's tests check that,
//! without a rename, the rewrite would change nothing.

use proc_macro2::{Group, Ident, Punct, Spacing, TokenStream, TokenTree};

/// `::core::primitive::f64`, for `quote!`: `#F64`.
#[derive(Clone, Copy, Debug)]
pub struct F64;

/// `::core::primitive::str`, for `quote!`: `&'static #STR`.
#[derive(Clone, Copy, Debug)]
pub struct STR;

impl quote::ToTokens for F64 {
    fn to_tokens(&self, tokens: &mut TokenStream) {
        tokens.extend(quote::quote!(::core::primitive::f64));
    }
}

impl quote::ToTokens for STR {
    fn to_tokens(&self, tokens: &mut TokenStream) {
        tokens.extend(quote::quote!(::core::primitive::str));
    }
}

/// The name of the method through which generated code reads the run-time parameter in field
/// `field` (`self.__planar_arm_mass()` for `self.mass`, a raw `r#type` as `__planar_arm_type`).
/// The derive defines one per parameter field in an inherent `impl` of the arm, its body
/// `::planar_arm::__private::param(&self.field)`; code the engine emits for an arm with
/// parameters needs them.
#[must_use]
pub fn param_accessor(field: &str) -> Ident {
    let bare = field.strip_prefix("r#").unwrap_or(field);
    Ident::new(
        &format!("__planar_arm_{bare}"),
        proc_macro2::Span::call_site(),
    )
}

/// The primitive types generated code names.
const PRIMITIVES: &[&str] = &[
    "f64", "f32", "usize", "u8", "u16", "u32", "u64", "i32", "i64", "i128", "bool", "str",
];

/// Rewrites `::planar_arm` at the start of a path to `krate` (the tokens of the path a user
/// gave with `#[arm(crate = "...")]`; `None` keeps `::planar_arm`), and each primitive type
/// named bare (`f64`) to `::core::primitive::f64`. Identifiers after `::` or `.` are parts of
/// longer paths or members and are left alone.
#[must_use]
pub fn qualify(tokens: TokenStream, krate: Option<&TokenStream>) -> TokenStream {
    let trees: Vec<TokenTree> = tokens.into_iter().collect();
    let mut out = TokenStream::new();
    let mut i = 0;
    while i < trees.len() {
        let is = |k: usize, c: char| matches!(&trees[k], TokenTree::Punct(p) if p.as_char() == c);
        // After `::` (not the single `:` of a type annotation) or `.`.
        let follows_path_or_dot =
            i > 0 && (is(i - 1, '.') || (i > 1 && is(i - 1, ':') && is(i - 2, ':')));
        match &trees[i] {
            TokenTree::Group(g) => {
                let mut inner = Group::new(g.delimiter(), qualify(g.stream(), krate));
                inner.set_span(g.span());
                out.extend([TokenTree::Group(inner)]);
            }
            TokenTree::Punct(p) if p.as_char() == ':' && p.spacing() == Spacing::Joint => {
                // Generated code names `planar_arm` only as the root of a path.
                let is_root = matches!(
                    (trees.get(i + 1), trees.get(i + 2)),
                    (Some(TokenTree::Punct(q)), Some(TokenTree::Ident(name)))
                        if q.as_char() == ':' && name == "planar_arm"
                );
                match (is_root, krate) {
                    (true, Some(path)) => {
                        out.extend(path.clone());
                        i += 3;
                        continue;
                    }
                    _ => out.extend([trees[i].clone()]),
                }
            }
            TokenTree::Ident(id) if !follows_path_or_dot && is_primitive(id) => {
                out.extend(primitive_path(id));
            }
            other => out.extend([other.clone()]),
        }
        i += 1;
    }
    out
}

fn is_primitive(id: &Ident) -> bool {
    PRIMITIVES.iter().any(|p| id == p)
}

/// `::core::primitive::NAME`, spanned where the bare name was.
fn primitive_path(id: &Ident) -> TokenStream {
    let span = id.span();
    let colons = || {
        let mut first = Punct::new(':', Spacing::Joint);
        first.set_span(span);
        let mut second = Punct::new(':', Spacing::Alone);
        second.set_span(span);
        [TokenTree::Punct(first), TokenTree::Punct(second)]
    };
    let name = |s: &str| TokenTree::Ident(Ident::new(s, span));
    let mut out = TokenStream::new();
    out.extend(colons());
    out.extend([name("core")]);
    out.extend(colons());
    out.extend([name("primitive")]);
    out.extend(colons());
    out.extend([TokenTree::Ident(id.clone())]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::quote;

    fn show(t: &TokenStream) -> String {
        t.to_string().replace(' ', "")
    }

    #[test]
    fn primitives_become_core_paths_and_paths_stay() {
        let t = quote! {
            fn f(x: &::planar_arm::nalgebra::SVector<f64, 2>) -> f64 {
                let y: f64 = self.f64 + <f64 as ::core::ops::Add>::add(1.0, ::core::primitive::f64::EPSILON);
                __T::from_f64(y)
            }
        };
        assert_eq!(
            show(&qualify(t, None)),
            show(&quote! {
                fn f(x: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>) -> ::core::primitive::f64 {
                    let y: ::core::primitive::f64 = self.f64 + <::core::primitive::f64 as ::core::ops::Add>::add(1.0, ::core::primitive::f64::EPSILON);
                    __T::from_f64(y)
                }
            })
        );
    }

    #[test]
    fn the_crate_path_replaces_planar_arm() {
        let t =
            quote!(impl ::planar_arm::PlanarArm<2> for A { type B = <A as ::planar_arm::C>::D; });
        let krate = quote!(arm);
        assert_eq!(
            show(&qualify(t.clone(), Some(&krate))),
            "implarm::PlanarArm<2>forA{typeB=<Aasarm::C>::D;}"
        );
        assert_eq!(show(&qualify(t.clone(), None)), show(&t));
    }
}
