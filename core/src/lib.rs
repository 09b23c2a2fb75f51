//! The symbolic engine of `planar_arm`: exact rationals, trigonometric polynomials,
//! Lagrangian mechanics of planar serial arms, straight-line programs and their emission as
//! Rust. The derive macro is a thin front on this crate; it is an ordinary library, usable and
//! tested on its own.
//!
//! - [`ring`]: the coefficient ring. [`Rational`] is a big-integer fraction (no overflow);
//!   [`Coefficient`] is the trait a later ring (named run-time parameters) would implement.
//! - [`trig`] and [`expr`]: the canonical form. An [`Expr`] is a sum of
//!   `coefficient x trig atom x monomial in rates`, with trig products linearised and angles
//!   normalised, so equal expressions are structurally equal. `diff_q`, `diff_var` and `dt`
//!   (the chain rule) act on it directly.
//! - [`mechanics`]: the paper's route. Centre-of-mass velocities by `dt` of their positions,
//!   kinetic energy (translation plus rotation about the centre of mass), potential energy;
//!   M as the Hessian of T, g = dV/dq, C from Christoffel symbols and c = C qd, equal to what
//!   Lagrange's equation gives (also derived, and compared, in the tests).
//! - [`poly`]: run-time parameters, polynomials in named parameters with exact rational
//!   coefficients, the coefficient ring of arms whose values are read at run time.
//! - [`slp`]: hash-consed straight-line programs; trig atoms of angle sums by angle addition
//!   from one sine-cosine pair per joint; operation counts.
//! - [`methods`]: which program computes each generated method (the expanded formulas, or a
//!   Newton-Euler or composite-rigid-body recursion unrolled for the arm, whichever is cheaper).
//! - [`frozen`]: methods of arms with run-time parameters split into a block of
//!   parameter-only values, evaluated once per parameter change, and the state-dependent rest.
//! - [`regressor`]: identification, the torques' columns per standard parameter and the base
//!   parameters by exact elimination.
//! - [`emit`] and [`generate`]: programs rendered as Rust, and the `impl PlanarArm<N>` the
//!   derive emits.
//!
//! # Example: the paper's three equal links
//!
//! ```
//! use planar_arm_core::{ArmSpec, Dynamics, Trig, Angle};
//! use planar_arm_core::ring::ratio;
//!
//! let d = Dynamics::derive(&ArmSpec::paper(3)); // unit rods, no gravity
//! // The paper prints 19/3 for the qd1 qd2 coefficient of L' = 2L; the derivation gives 10/3,
//! // i.e. M12 = 5/3 + 3/2 c2 + 1/2 c23 + c3.
//! assert_eq!(d.mass_matrix[0][1].constant_term(), Some(&ratio(5, 3)));
//! assert_eq!(d.mass_matrix[0][1].coefficient(&Trig::Cos(Angle::new(vec![0, 1]))), Some(&ratio(3, 2)));
//! assert_eq!(d.mass_matrix[0][1].to_string(), "5/3 + 3/2 c2 + 1/2 c23 + c3");
//! println!("{d}"); // T, V, L, M, c and g in readable notation
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

// The stages in pipeline order; each uses only the stages above it.
mod algebra;
mod emission;
pub mod mechanics;
pub mod methods;
mod programs;

pub use algebra::{expr, poly, ring, trig};
pub use emission::{closed_forms, compact, emit, generate, identification, paths};
pub use mechanics::planar::definite;
pub use methods::identification::regressor;
pub use programs::{christoffel, derivative, frozen, slp};

// Re-exports, not copies, in the docs: each item's page stays in its module.
#[doc(no_inline)]
pub use expr::{Expr, Monomial, Var};
pub use mechanics::{ArmSpec, Body, Dynamics, JointKind, Kinematics, LinkSpec, PayloadSpec};
#[doc(no_inline)]
pub use poly::{Param, Poly};
#[doc(no_inline)]
pub use ring::{Coefficient, Rational};
#[doc(no_inline)]
pub use trig::{Angle, Trig};
