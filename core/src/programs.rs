//! The third stage: straight-line programs. The engine's formulas become hash-consed programs
//! ([`slp`]); recursions are unrolled into them for one arm (`unrolled`), differentiated
//! ([`derivative`]) and split at their parameter-only part ([`frozen`]).

pub mod christoffel;
pub mod derivative;
pub mod frozen;
pub mod method;
pub mod slp;
pub(crate) mod unrolled;
