//! The symbolic engine of `planar_arm`: exact rationals, trigonometric polynomials,
//! Lagrangian mechanics of planar serial arms, straight-line programs and their emission as
//! Rust. The derive macro is a thin front on this crate; it is an ordinary library, usable and
//! tested on its own.
//!
//! The engine is a pipeline of five stages, one folder of `core/src/` each; a stage uses only
//! the stages before it. Every module keeps its path at the crate root (`planar_arm_core::slp`,
//! not `programs::slp`), so the folders are the source's layout, not the API's.
//!
//! 1. Algebra (`algebra/`).
//!    - [`ring`]: the coefficient ring. [`Rational`] is a big-integer fraction (no overflow);
//!      [`Coefficient`] is the trait every coefficient ring implements.
//!    - [`poly`]: run-time parameters, polynomials in named parameters with exact rational
//!      coefficients, the coefficient ring of arms whose values are read at run time.
//!    - [`trig`] and [`expr`]: the canonical form. An [`Expr`] is a sum of
//!      `coefficient x trig atom x monomial in rates`, with trig products linearised and angles
//!      normalised, so equal expressions are structurally equal. `diff_q`, `diff_var` and `dt`
//!      (the chain rule) act on it directly.
//! 2. Mechanics (`mechanics/`, one part per geometry: `mechanics/planar/`).
//!    - [`mechanics`]: the paper's route. Centre-of-mass velocities by `dt` of their positions,
//!      kinetic energy (translation plus rotation about the centre of mass), potential energy;
//!      M as the Hessian of T (or summed from the metric in absolute angles), g = dV/dq, C from
//!      Christoffel symbols and c = C qd, equal to what Lagrange's equation gives (also
//!      derived, and compared, in the tests).
//!    - [`definite`]: whether an arm's mass matrix is positive definite, exactly.
//! 3. Programs (`programs/`).
//!    - [`slp`]: hash-consed straight-line programs; trig atoms of angle sums by angle
//!      addition from one sine-cosine pair per joint; operation counts.
//!    - The Newton-Euler and composite-rigid-body recursions and an `L D L^T` solve, unrolled
//!      for one arm; [`christoffel`], the Coriolis matrix summed in absolute angles.
//!    - [`derivative`]: programs differentiated at compile time.
//!    - [`frozen`]: methods of arms with run-time parameters split into a block of
//!      parameter-only values, evaluated once per parameter change, and the state-dependent
//!      rest.
//! 4. Methods (`methods/`).
//!    - [`methods`]: which program computes each generated method (the expanded formulas, or a
//!      recursion unrolled for the arm, whichever is cheaper).
//!    - [`regressor`]: identification, the torques' columns per standard parameter and the base
//!      parameters by exact elimination.
//! 5. Emission (`emission/`).
//!    - [`emit`]: programs rendered as Rust.
//!    - [`generate`], [`closed_forms`] and [`identification`]: the impls the derive emits.
//!    - [`compact`] and [`paths`]: the exact `const` data's encoding and the paths the
//!      generated code names.
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

// The stages, in pipeline order: each uses only the ones above it.
mod algebra;

pub mod mechanics;

mod programs;

pub mod methods;

mod emission;

pub use algebra::{expr, poly, ring, trig};
pub use emission::{closed_forms, compact, emit, generate, identification, paths};
pub use mechanics::planar::definite;
pub use methods::identification::regressor;
pub use programs::{adjoint, christoffel, derivative, frozen, packed, slp};

/// Spatial arms, from their specification to the emitted `impl SpatialArm<N>`: the exact frames,
/// the decoupling their geometry allows, the chosen programs and the emission.
pub mod spatial {
    pub use crate::emission::spatial::generate_spatial;
    pub use crate::mechanics::spatial::*;
    pub use crate::methods::identification::spatial::{
        exact_geometry, identification, SpatialIdentification,
    };
    pub use crate::methods::spatial::{SpatialDerived, SpatialForm};
    pub use crate::programs::spatial_regressor::{
        packed_regressor, regressor, standard_parameters, standard_values, Entry, SpatialParameter,
        BODY_ENTRIES,
    };
}

// Re-exports, not copies, in the docs: each item's page stays in its module.
#[doc(no_inline)]
pub use expr::{Expr, Monomial, Var};
pub use mechanics::{
    down, ArmSpec, Body, Dynamics, JointKind, Kinematics, LinkSpec, Offset, PayloadSpec,
};
#[doc(no_inline)]
pub use poly::{Param, Poly};
#[doc(no_inline)]
pub use ring::{Coefficient, Rational};
#[doc(no_inline)]
pub use trig::{Angle, Trig};
