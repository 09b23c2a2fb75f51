//! The third stage: straight-line programs. The engine's formulas become hash-consed programs
//! ([`slp`]), a generated method's body is one with named outputs ([`method`]); recursions are
//! unrolled into them for one arm (`unrolled`), the Coriolis matrix is summed in absolute
//! angles ([`christoffel`]), and programs are differentiated ([`derivative`]) and split at
//! their parameter-only part ([`frozen`]), forward four directions at a time ([`packed`]) or
//! backward several weighted rows at a time ([`adjoint`]).

pub mod adjoint;
pub mod christoffel;
pub mod derivative;
pub mod frozen;
pub mod method;
pub mod packed;
pub mod slp;
pub(crate) mod spatial;
pub(crate) mod spatial_composite;
pub(crate) mod spatial_newton_euler;
pub mod spatial_regressor;
pub(crate) mod unrolled;
