//! The symbolic engine of `planar_arm`. Crate docs are written at the end.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod expr;
pub mod mechanics;
pub mod ring;
pub mod trig;

pub use expr::{Expr, Monomial, Var};
pub use mechanics::{ArmSpec, Dynamics, Kinematics, LinkSpec};
pub use ring::{Coefficient, Rational};
pub use trig::{Angle, Trig};
pub mod emit;
pub mod generate;
pub mod slp;
