//! The parsed struct: its links and gravity, each value with the tokens it came from.

use planar_arm_core::JointKind;
use syn::{Data, DeriveInput, Fields};

use crate::attr::{self, Attrs, Place, Value};
use crate::ctxt::Ctxt;

/// A link field.
pub struct Link<'a> {
    pub field: &'a syn::Field,
    pub attrs: Attrs,
    /// Read from the type's name: `Prismatic`, else revolute (the compiler checks the type).
    pub joint: JointKind,
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
    /// The struct's own `#[arm(...)]`: gravity and payload.
    pub attrs: Attrs,
    pub links: Vec<Link<'a>>,
    /// The named fields that are not links, which `self.NAME` may read.
    pub others: Vec<&'a syn::Field>,
}

impl<'a> Arm<'a> {
    /// Parses the struct, recording every problem in `cx`. `None` when the shape is so wrong
    /// (an enum, a tuple struct) that there are no links to speak of.
    pub fn from_ast(cx: &Ctxt, input: &'a DeriveInput) -> Option<Self> {
        let struct_attrs = attr::parse(cx, &input.attrs, Place::Struct).unwrap_or_default();
        // The generated methods are generic over `__T`, the scalar: a generic of the struct's
        // own with that name would clash with it.
        for param in input.generics.type_params() {
            if param.ident == "__T" {
                cx.error_spanned_by(
                    &param.ident,
                    "the generic parameter name `__T` is taken by the methods #[derive(PlanarArm)] \
                     generates (their scalar type); rename this one",
                );
            }
        }
        if struct_attrs.mentioned.contains(&attr::URDF)
            || struct_attrs.mentioned.contains(&attr::MJCF)
        {
            return Self::from_file(cx, input, struct_attrs);
        }
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
        let mut others = Vec::new();
        for field in &named.named {
            let attrs = attr::parse(cx, &field.attrs, Place::Field);
            if attrs.is_none() && joint_kind(&field.ty).is_none() {
                // Not a link: a parameter, a label, anything the user keeps in the struct.
                others.push(field);
                continue;
            }
            // A path type (an alias, a re-export) may still be `Revolute`: the generated code
            // asserts it (`__private::LinkField`). Anything else cannot be.
            if !matches!(strip(&field.ty), syn::Type::Path(_)) || is_primitive(&field.ty) {
                cx.error_spanned_by(
                    &field.ty,
                    "link fields must have type `planar_arm::Revolute` or `planar_arm::Prismatic`; the link's parameters go in its #[arm(...)]",
                );
            }
            match attrs {
                Some(attrs) => links.push(Link {
                    field,
                    attrs,
                    joint: joint_kind(&field.ty).unwrap_or_default(),
                }),
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
        if links.is_empty() {
            cx.error_spanned_by(
                named,
                "an arm needs at least one link: add a field `#[arm(length = 1, mass = 1)] upper: Revolute`",
            );
            return None;
        }
        Some(Self {
            attrs: struct_attrs,
            links,
            others,
        })
    }

    /// A struct-level value.
    pub fn get(&self, key: &str) -> Option<&Value> {
        self.attrs.get(key)
    }

    /// Every value with a description of where it stands, struct first.
    pub fn values(&self) -> Vec<(String, &Value)> {
        let mut out: Vec<(String, &Value)> = self
            .attrs
            .entries
            .iter()
            .map(|e| (format!("this {}", e.key), &e.value))
            .collect();
        for link in &self.links {
            for e in &link.attrs.entries {
                out.push((format!("link `{}`: this {}", link.name(), e.key), &e.value));
            }
        }
        out
    }

    /// Whether the field `name` is a plain `f64` (what a run-time parameter must be).
    pub fn f64_field(&self, name: &str) -> Result<(), String> {
        let links: Vec<&syn::Field> = self.links.iter().map(|l| l.field).collect();
        param_field(&links, &self.others, name)
    }

    /// The number of link fields, whether or not each parsed.
    pub fn field_count(input: &DeriveInput) -> Option<usize> {
        match &input.data {
            Data::Struct(s) => match &s.fields {
                Fields::Named(n) => {
                    let links = n.named.iter().filter(|f| is_link_field(f)).count();
                    (links > 0).then_some(links)
                }
                _ => None,
            },
            _ => None,
        }
    }
}

/// Whether a field is a link: of type `Revolute` or `Prismatic`, or carrying `#[arm(...)]`.
pub fn is_link_field(f: &syn::Field) -> bool {
    joint_kind(&f.ty).is_some() || f.attrs.iter().any(|a| a.path().is_ident(attr::ARM))
}

fn is_f64(ty: &syn::Type) -> bool {
    match ty {
        // f64, or the primitive by its path (core::primitive::f64), for crates that shadow it
        syn::Type::Path(p) => {
            let names: Vec<String> = p
                .path
                .segments
                .iter()
                .map(|s| s.ident.to_string())
                .collect();
            p.qself.is_none()
                && (p.path.is_ident("f64")
                    || matches!(names.as_slice(), [root, prim, f] if (root == "core" || root == "std") && prim == "primitive" && f == "f64"))
        }
        syn::Type::Group(g) => is_f64(&g.elem),
        syn::Type::Paren(p) => is_f64(&p.elem),
        _ => false,
    }
}

/// Whether the field `name` is a plain `f64` (what a run-time parameter must be), not one of the
/// `links`, among the `others`.
pub fn param_field(
    links: &[&syn::Field],
    others: &[&syn::Field],
    name: &str,
) -> Result<(), String> {
    if links
        .iter()
        .any(|f| f.ident.as_ref().is_some_and(|i| i == name))
    {
        return Err(format!(
            "`self.{name}` is a link, not a run-time parameter; a parameter is an `f64` field of this struct"
        ));
    }
    match others.iter().find(|f| f.ident.as_ref().is_some_and(|i| i == name)) {
        Some(f) if is_f64(&f.ty) => Ok(()),
        Some(_) => Err(format!(
            "`self.{name}` must be an `f64` field to serve as a run-time parameter; change its type to `f64`"
        )),
        None => {
            let names: Vec<String> = others
                .iter()
                .filter(|f| is_f64(&f.ty))
                .filter_map(|f| f.ident.as_ref().map(ToString::to_string))
                .collect();
            Err(if names.is_empty() {
                format!("no field `{name}`: a run-time parameter is an `f64` field of this struct; add `{name}: f64`")
            } else {
                format!(
                    "no field `{name}`: a run-time parameter is an `f64` field of this struct (it has {}); or add `{name}: f64`",
                    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
                )
            })
        }
    }
}

/// Whether the type is a primitive's bare name (`f64`), which no alias of `Revolute` takes.
pub(crate) fn is_primitive(ty: &syn::Type) -> bool {
    const PRIMITIVES: &[&str] = &[
        "f64", "f32", "i8", "i16", "i32", "i64", "i128", "isize", "u8", "u16", "u32", "u64",
        "u128", "usize", "bool", "char", "str",
    ];
    matches!(strip(ty), syn::Type::Path(p) if p.qself.is_none()
        && PRIMITIVES.iter().any(|name| p.path.is_ident(name)))
}

/// The type inside invisible groups and parentheses.
pub(crate) fn strip(ty: &syn::Type) -> &syn::Type {
    match ty {
        syn::Type::Group(g) => strip(&g.elem),
        syn::Type::Paren(p) => strip(&p.elem),
        other => other,
    }
}

/// The joint kind a type names by its last segment, `Revolute` or `Prismatic`: the derive
/// cannot resolve names, so an alias of either is a revolute link if it carries
/// `#[arm(...)]`, and the compiler's check (`__private::LinkField`) says so if it is not.
pub fn joint_kind(ty: &syn::Type) -> Option<JointKind> {
    match ty {
        syn::Type::Path(p) => p.path.segments.last().and_then(|s| {
            if !s.arguments.is_empty() {
                None
            } else if s.ident == "Revolute" {
                Some(JointKind::Revolute)
            } else if s.ident == "Prismatic" {
                Some(JointKind::Prismatic)
            } else {
                None
            }
        }),
        syn::Type::Group(g) => joint_kind(&g.elem),
        syn::Type::Paren(p) => joint_kind(&p.elem),
        _ => None,
    }
}

impl<'a> Arm<'a> {
    /// An arm whose links come from a model file: a struct of no link fields.
    fn from_file(cx: &Ctxt, input: &'a DeriveInput, attrs: Attrs) -> Option<Self> {
        let others = crate::models::other_fields(cx, input, "PlanarArm", "link")?;
        Some(Self {
            attrs,
            links: Vec::new(),
            others,
        })
    }
}
