//! `#[derive(PlanarArm)]`: the thin procedural-macro front of `planar_arm`.
//!
//! Three steps, as in thiserror: `ast` parses the struct and its `#[arm(...)]` attributes
//! (collecting every error with its span), `check` validates the physics, and `expand`
//! hands a valid arm to the symbolic engine in `planar_arm_core`. After any error a stub impl
//! is emitted so the user sees the real error and not a cascade. Use it through the
//! `planar_arm` crate, which documents the attribute syntax.

mod ast;
mod attr;
mod check;
mod ctxt;
mod expand;
mod models;
mod spatial;
mod value;

use proc_macro::TokenStream;
use syn::{parse_macro_input, DeriveInput};

/// Derives `planar_arm::PlanarArm<N>` for a struct whose `N` fields are links
/// (`#[arm(length = L, mass = M, inertia = I, com = C)]`, type `planar_arm::Revolute`); an
/// optional `#[arm(gravity = G)]` on the struct sets gravity along -y (default 9.80665), or
/// `#[arm(gravity = (gx, gy))]` in any direction of the plane.
/// See the `planar_arm` crate documentation.
#[proc_macro_derive(PlanarArm, attributes(arm))]
pub fn derive_planar_arm(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    expand::derive(&input).into()
}

/// Derives `planar_arm::spatial::SpatialArm<N>` for a struct whose `N` fields are joints
/// (`#[arm(dh(a = .., alpha = .., d = .., theta = ..))]`, `mdh(...)`, or
/// `origin(xyz = .., rpy = ..), axis = ..`, type `planar_arm::Revolute` or `Prismatic`). See
/// the `planar_arm` crate documentation.
#[proc_macro_derive(SpatialArm, attributes(arm))]
pub fn derive_spatial_arm(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    spatial::expand::derive(&input).into()
}
