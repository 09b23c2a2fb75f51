//! `#[derive(SpatialArm)]`: parse, check, expand, as for planar arms.

mod angle;
mod ast;
mod attr;
mod check;
pub mod expand;
