//! The struct `#[derive(SpatialArm)]` reads: its joint fields and their attributes.

use planar_arm_core::JointKind;
use syn::{Data, DeriveInput, Fields};

use super::attr::{self, Place, SpatialAttrs};
use crate::ast::{joint_kind, param_field};
use crate::ctxt::Ctxt;

/// A joint field (type `Revolute` or `Prismatic`).
pub struct SpatialJoint<'a> {
    pub field: &'a syn::Field,
    pub attrs: SpatialAttrs,
    pub kind: JointKind,
}

impl SpatialJoint<'_> {
    pub fn name(&self) -> String {
        self.field
            .ident
            .as_ref()
            .map_or_else(|| "joint".to_string(), ToString::to_string)
    }
}

const NO_JOINT: &str = "a spatial arm needs at least one joint: add a field \
                        `#[arm(dh(a = 0.4))] shoulder: Revolute` (or `Prismatic`)";

/// The derive input.
pub struct SpatialArm<'a> {
    pub attrs: SpatialAttrs,
    pub joints: Vec<SpatialJoint<'a>>,
    pub others: Vec<&'a syn::Field>,
}

impl<'a> SpatialArm<'a> {
    /// Parses the struct, recording every problem in `cx`.
    pub fn from_ast(cx: &Ctxt, input: &'a DeriveInput) -> Option<Self> {
        let attrs = attr::parse(cx, &input.attrs, Place::Struct);
        for param in input.generics.type_params() {
            if param.ident == "__T" {
                cx.error_spanned_by(
                    &param.ident,
                    "the generic parameter name `__T` is taken by the methods #[derive(SpatialArm)] \
                     generates (their scalar type); rename this one",
                );
            }
        }
        if attrs.model_written {
            return Self::from_file(cx, input, attrs);
        }
        let fields = match &input.data {
            Data::Struct(s) => match &s.fields {
                Fields::Named(named) if !named.named.is_empty() => named,
                Fields::Named(named) => {
                    cx.error_spanned_by(named, NO_JOINT);
                    return None;
                }
                Fields::Unnamed(unnamed) => {
                    cx.error_spanned_by(
                        unnamed,
                        "joints must be named fields, not tuple fields: write \
                         `{ #[arm(dh(a = 0.4))] shoulder: Revolute }`",
                    );
                    return None;
                }
                Fields::Unit => {
                    cx.error_spanned_by(&input.ident, NO_JOINT);
                    return None;
                }
            },
            Data::Enum(e) => {
                cx.error_spanned_by(
                    e.enum_token,
                    "#[derive(SpatialArm)] needs a struct with one named field per joint, not an enum",
                );
                return None;
            }
            Data::Union(u) => {
                cx.error_spanned_by(
                    u.union_token,
                    "#[derive(SpatialArm)] needs a struct with one named field per joint, not a union",
                );
                return None;
            }
        };
        let (mut joints, mut others) = (Vec::new(), Vec::new());
        let mut mistyped = false;
        for field in &fields.named {
            let listed = field.attrs.iter().any(|a| a.path().is_ident("arm"));
            match joint_kind(&field.ty) {
                Some(kind) => joints.push(SpatialJoint {
                    field,
                    attrs: attr::parse(cx, &field.attrs, Place::Field),
                    kind,
                }),
                None if listed => {
                    cx.error_spanned_by(
                        &field.ty,
                        "joint fields must have type `planar_arm::Revolute` or `planar_arm::Prismatic`; \
                         their geometry goes in #[arm(...)]",
                    );
                    mistyped = true;
                }
                None => others.push(field),
            }
        }
        if joints.is_empty() {
            // A joint of the wrong type has had its error.
            if !mistyped {
                cx.error_spanned_by(fields, NO_JOINT);
            }
            return None;
        }
        Some(Self {
            attrs,
            joints,
            others,
        })
    }

    /// An arm whose joints come from a model file: a struct of no joint fields.
    fn from_file(cx: &Ctxt, input: &'a DeriveInput, attrs: SpatialAttrs) -> Option<Self> {
        let others = crate::models::other_fields(cx, input, "SpatialArm", "joint")?;
        Some(Self {
            attrs,
            joints: Vec::new(),
            others,
        })
    }

    /// Whether `self.name` may be read as a run-time parameter.
    pub fn f64_field(&self, name: &str) -> Result<(), String> {
        let joints: Vec<&syn::Field> = self.joints.iter().map(|j| j.field).collect();
        param_field(&joints, &self.others, name)
    }
}
