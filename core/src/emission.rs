//! The last stage: Rust. Programs rendered as statements ([`emit`]), the impls the derive
//! emits ([`generate`], [`closed_forms`], [`identification`]), the exact `const` data
//! ([`compact`]) and the paths the generated code names ([`paths`]).

mod chunks;
pub mod closed_forms;
pub mod compact;
pub mod emit;
mod error;
mod formulas;
mod function;
pub mod generate;
mod header;
pub mod identification;
mod packed;
pub mod paths;
pub(crate) mod spatial;
mod spatial_identification;
mod tokens;
mod traits;
