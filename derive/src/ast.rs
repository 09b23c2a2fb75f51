//! The parsed struct: its links and gravity, each value with the tokens it came from.

use syn::{Data, DeriveInput, Fields};

use crate::attr::{self, Attrs, Place, Value};
use crate::ctxt::Ctxt;

/// A link field.
pub struct Link<'a> {
    pub field: &'a syn::Field,
    pub attrs: Attrs,
}

impl Link<'_> {
    pub fn name(&self) -> String {
        self.field
            .ident
            .as_ref()
            .map_or_else(|| "link".to_string(), ToString::to_string)
    }
}

/// The derive input, as far as it could be parsed.
pub struct Arm<'a> {
    pub gravity: Option<Value>,
    pub links: Vec<Link<'a>>,
}

impl<'a> Arm<'a> {
    /// Parses the struct, recording every problem in `cx`. `None` when the shape is so wrong
    /// (an enum, a tuple struct) that there are no links to speak of.
    pub fn from_ast(cx: &Ctxt, input: &'a DeriveInput) -> Option<Self> {
        let struct_attrs = attr::parse(cx, &input.attrs, Place::Struct).unwrap_or_default();
        let fields = match &input.data {
            Data::Struct(s) => &s.fields,
            Data::Enum(e) => {
                cx.error_spanned_by(
                    e.enum_token,
                    "#[derive(PlanarArm)] needs a struct with one named field per link, not an enum",
                );
                return None;
            }
            Data::Union(u) => {
                cx.error_spanned_by(
                    u.union_token,
                    "#[derive(PlanarArm)] needs a struct with one named field per link, not a union",
                );
                return None;
            }
        };
        let named = match fields {
            Fields::Named(named) => named,
            Fields::Unnamed(unnamed) => {
                cx.error_spanned_by(
                    unnamed,
                    "links must be named fields, not tuple fields: write `{ #[arm(length = 1, mass = 1)] upper: Revolute }`",
                );
                return None;
            }
            Fields::Unit => {
                cx.error_spanned_by(
                    &input.ident,
                    "an arm needs at least one link: add a field `#[arm(length = 1, mass = 1)] upper: Revolute`",
                );
                return None;
            }
        };
        if named.named.is_empty() {
            cx.error_spanned_by(
                named,
                "an arm needs at least one link: add a field `#[arm(length = 1, mass = 1)] upper: Revolute`",
            );
            return None;
        }
        let mut links = Vec::new();
        for field in &named.named {
            let attrs = attr::parse(cx, &field.attrs, Place::Field);
            if !is_revolute(&field.ty) {
                cx.error_spanned_by(
                    &field.ty,
                    "link fields must have type `planar_arm::Revolute`, the only joint kind so far; the link's parameters go in its #[arm(...)]",
                );
            }
            match attrs {
                Some(attrs) => links.push(Link { field, attrs }),
                None => cx.error_spanned_by(
                    &field.ident,
                    format!(
                        "link `{}` needs its parameters: add #[arm(length = ..., mass = ...)] to the field",
                        field
                            .ident
                            .as_ref()
                            .map_or_else(String::new, ToString::to_string)
                    ),
                ),
            }
        }
        Some(Self {
            gravity: struct_attrs
                .entries
                .into_iter()
                .find(|e| e.key == attr::GRAVITY)
                .map(|e| e.value),
            links,
        })
    }

    /// The number of link fields, whether or not each parsed.
    pub fn field_count(input: &DeriveInput) -> Option<usize> {
        match &input.data {
            Data::Struct(s) => match &s.fields {
                Fields::Named(n) if !n.named.is_empty() => Some(n.named.len()),
                _ => None,
            },
            _ => None,
        }
    }
}

fn is_revolute(ty: &syn::Type) -> bool {
    match ty {
        syn::Type::Path(p) => p
            .path
            .segments
            .last()
            .is_some_and(|s| s.ident == "Revolute" && s.arguments.is_empty()),
        syn::Type::Group(g) => is_revolute(&g.elem),
        syn::Type::Paren(p) => is_revolute(&p.elem),
        _ => false,
    }
}
