//! `#[derive(SpatialArm)]`: parse, check, expand, as for planar arms.

pub(crate) mod angle;
mod ast;
mod attr;
mod check;
pub mod expand;
