//! Exact Lagrangian dynamics, kinematics and statics of planar serial arms, derived at
//! compile time and emitted as straight-line Rust.
//!
//! You describe an arm as a struct; `#[derive(PlanarArm)]` builds its kinetic and potential
//! energy symbolically with exact rational coefficients, applies Lagrange's equation, reads
//! off the mass matrix M(q), the velocity-product (Coriolis and centrifugal) torques c(q, qd)
//! and the gravity torques g(q), and emits code specialised to that arm: no loops, no
//! allocation, no symbolic work at run time, one sine-cosine pair per joint angle it needs
//! (all of them from one call of [`trig::sin_cos`], four angles per SIMD vector). It also
//! generates the arm's tip pose, Jacobian, joint positions and statics, and for two and three
//! links the paper's closed-form inverse kinematics and inverse statics.
//!
//! The route is the one of B. K. P. Horn's MIT working paper *Kinematics, Statics, and
//! Dynamics of Two-D Manipulators*, which derives all of this by hand for two and three equal
//! links; here it is done for any arm, exactly, with the paper's misprints corrected
//! (`docs/errata.md`).
//!
//! # A worked example: the paper's two-link arm
//!
//! Two uniform rods of unit length and mass. Link 1 has its centre of mass at
//! `r1/2` and angular velocity `qd1`; link 2's centre is at `r1 + r2/2` and turns at
//! `qd1 + qd2`. Kinetic energy (translation of each centre plus rotation about it, inertia
//! `m l^2 / 12`) sums to
//!
//! ```text
//! T = 1/2 [(5/3 + cos q2) qd1^2 + (2/3 + cos q2) qd1 qd2 + 1/3 qd2^2]      (m = l = 1)
//! ```
//!
//! and Lagrange's equation `tau_i = d/dt dL/dqd_i - dL/dq_i` gives
//!
//! ```text
//! M = [[5/3 + c2, 1/3 + c2/2], [1/3 + c2/2, 1/3]]
//! c = (-s2 qd1 qd2 - 1/2 s2 qd2^2,  1/2 s2 qd1^2)
//! g = (g (3/2 c1 + 1/2 c12),  g 1/2 c12)
//! ```
//!
//! The derive does exactly this at compile time:
//!
//! ```
//! use planar_arm::prelude::*;
//!
//! /// The paper's two equal links: unit length, unit mass, uniform rods.
//! #[derive(PlanarArm, Default)]
//! #[arm(gravity = 9.81)]
//! struct TwoLink {
//!     #[arm(length = 1, mass = 1)] // inertia m l^2 / 12 and com l / 2 by default
//!     upper: Revolute,
//!     #[arm(length = 1, mass = 1)]
//!     fore: Revolute,
//! }
//!
//! let arm = TwoLink::default();
//! let q = Vector2::new(0.3_f64, 1.2);
//! let (s2, c2) = q[1].sin_cos();
//!
//! // The mass matrix is the paper's, evaluated.
//! let m = arm.mass_matrix(&q);
//! assert!((m[(0, 0)] - (5.0 / 3.0 + c2)).abs() < 1e-15);
//! assert!((m[(0, 1)] - (1.0 / 3.0 + c2 / 2.0)).abs() < 1e-15);
//! assert!((m[(1, 1)] - 1.0 / 3.0).abs() < 1e-15);
//!
//! // Velocity-product torques: c2 = 1/2 s2 qd1^2 (centrifugal on link 2).
//! let qd = Vector2::new(2.0, 0.0);
//! assert!((arm.coriolis(&q, &qd)[1] - 0.5 * s2 * 4.0).abs() < 1e-14);
//!
//! // Decoupled at cos q2 = -2/3: torque on joint 1 accelerates joint 1 only.
//! let q_dec = Vector2::new(0.0, (-2.0f64 / 3.0).acos());
//! let qdd = arm.forward_dynamics(&q_dec, &Vector2::zeros(), &(arm.gravity(&q_dec) + Vector2::new(1.0, 0.0)));
//! assert!(qdd[1].abs() < 1e-12);
//!
//! // tau = M qdd + c + g, and forward dynamics inverts it.
//! let qdd = Vector2::new(0.5, -1.0);
//! let tau = arm.inverse_dynamics(&q, &qd, &qdd);
//! assert!((arm.forward_dynamics(&q, &qd, &tau) - qdd).norm() < 1e-12);
//!
//! // The exact result is const data too: M11 = 5/3 + cos q2.
//! use planar_arm::exact::{constant_term, Rational};
//! const _: () = assert!(constant_term(<TwoLink as PlanarArm<2>>::EXACT.mass_matrix[0][0]).eq(Rational::new(5, 3)));
//!
//! // Kinematics and statics of the same arm.
//! let tip = arm.tip_pose(&q).translation.vector;
//! let [elbow_up, _elbow_down] = arm.inverse_kinematics(&Point2::from(tip)).unwrap();
//! assert!((elbow_up - q).norm() < 1e-12);
//! let tau = arm.joint_torques(&q, &Vector2::new(0.0, -2.0), 0.0); // push down with 2 N
//! assert!((arm.tip_force(&q, &tau).unwrap() - Vector2::new(0.0, -2.0)).norm() < 1e-12);
//! assert!(arm.workspace().inner_radius() == 0.0); // equal links reach a disk
//! ```
//!
//! # The attributes
//!
//! - `#[arm(gravity = G)]` on the struct (optional): gravity of magnitude `G` acts along -y;
//!   the default is standard gravity 9.80665; `gravity = 0` is a horizontal arm;
//!   `gravity = (gx, gy)` is gravity's acceleration in any direction of the plane. Also on the
//!   struct: `payload = P` (kg), a body rigidly held at the tip of the last link, with optional
//!   `payload_inertia = I` (kg m^2, about its own centre) and `payload_com = (x, y)` (m, its
//!   centre from the tip in the last link's frame).
//! - Each field of type [`Revolute`] or [`Prismatic`] is a link, base first, with
//!   `#[arm(length = L, mass = M, inertia = I, com = C)]`: `inertia` is the moment of inertia
//!   about the link's centre of mass (default: uniform rod, `M L^2 / 12`), `com` the centre of
//!   mass along the link from its own joint (default `L / 2`; it may be negative or beyond the
//!   link, a counterweight), or a pair `com = (x, y)` with `y` perpendicular to the link,
//!   counter-clockwise. `length` and `mass` are required. Joint keys with MuJoCo's names and
//!   meanings: `armature = A` (reflected rotor inertia, kg m^2, added to M's diagonal),
//!   `damping = B` (viscous torque `B qd_i`), `frictionloss = F` (Coulomb torque
//!   `F sign(qd_i)`, `sign(0) = 0`). `range = (lo, hi)` (optional, numbers) is the joint's
//!   travel, radians or metres: the work-spaces and inverse kinematics respect it, the
//!   dynamics never clamp to it. `offset = a` turns the joint: a hinge's link stands at angle
//!   `a` to the previous link at `q = 0`, a slide moves at angle `a` to it (and its frame turns
//!   with it); `reversed` makes the joint turn clockwise (slide backwards);
//!   `stiffness = K, springref = R` is a joint spring of energy `K (q_i - R)^2 / 2`, part of
//!   the potential (so of `gravity` and `bias`), as MuJoCo's. A link's `mass`
//!   may be 0 where later links keep the mass matrix definite (a floating base's slides).
//! - Values are exact: integers, decimals (`0.35` is `7/20`, not an `f64`), fractions `a/b`
//!   and `+ - * /` with parentheses. Nothing passes through a float before the final emission.
//! - Any value may be a run-time parameter, `self.NAME`: an `f64` field of the struct read when
//!   a method is called, for a payload that changes, identified or calibrated values, values
//!   loaded from a file. Values stay polynomial in the parameters (division by a parameter is a
//!   compile error), so the derivation stays exact over polynomials in them; each method's
//!   rustdoc shows its formulas with the parameters by name. Other fields are left alone.
//!   Between parameter changes, [`Dynamics::freeze`] evaluates the parameter-only values once
//!   and gives a [`Frozen`] view with the hot dynamics methods at the literal arm's speed; it
//!   borrows the arm, so a parameter cannot change under it.
//!
//! ```
//! use planar_arm::prelude::*;
//!
//! #[derive(PlanarArm)]
//! #[arm(gravity = 9.81, payload = self.load)]
//! struct Picker {
//!     #[arm(length = 0.4, mass = 3, armature = 0.05, damping = 0.2)]
//!     upper: Revolute,
//!     #[arm(length = 0.3, mass = self.fore_mass, com = (0.12, 0.01), frictionloss = 0.4)]
//!     fore: Revolute,
//!     fore_mass: f64,
//!     load: f64,
//! }
//!
//! let mut arm = Picker { upper: Revolute, fore: Revolute, fore_mass: 1.1, load: 0.0 };
//! let (q, qd) = (Vector2::new(0.2, 0.9), Vector2::new(0.5, -1.0));
//! let empty = arm.inverse_dynamics(&q, &qd, &Vector2::zeros());
//! arm.load = 2.0; // picked up: the next call sees it
//! let loaded = arm.inverse_dynamics(&q, &qd, &Vector2::zeros());
//! assert!(loaded[0] > empty[0]);
//! // tau = M qdd + bias, with bias = c + g + f (friction included).
//! let qdd = Vector2::new(1.0, -2.0);
//! let (m, h) = arm.mass_matrix_and_bias(&q, &qd);
//! assert!((arm.inverse_dynamics(&q, &qd, &qdd) - (m * qdd + h)).norm() < 1e-12);
//! assert_eq!(arm.friction(&qd)[1], -0.4);
//! ```
//!
//! # Prismatic joints
//!
//! A [`Prismatic`] link slides along the previous link's direction (the first along +x of the
//! base) by `q_i` metres without turning: its frame starts at the previous link's end plus
//! `q_i` along that direction. The derivation is the same, exactly: the expressions become
//! polynomials in the prismatic coordinates (trigonometric atoms still come only from the
//! revolute angles). The polar arm, a turret and a telescoping boom, by hand: the boom's centre
//! is `r = l1 + q2 + l2 / 2` from the axis and moves radially at `qd2` and sideways at
//! `r qd1`, so `M = [[I1 + m1 c1^2 + I2 + m2 r^2, 0], [0, m2]]`, and at `qdd = 0` the slide's
//! generalised force is the force `-m2 r qd1^2 + g m2 sin q1` (centrifugal and gravity):
//!
//! ```
//! use planar_arm::prelude::*;
//!
//! #[derive(PlanarArm)]
//! #[arm(gravity = 9.81)]
//! struct Polar {
//!     #[arm(length = 0.2, mass = 3)]
//!     turret: Revolute,
//!     #[arm(length = 0.5, mass = 1.5, range = (0, 0.6))]
//!     boom: Prismatic,
//! }
//!
//! let arm = Polar { turret: Revolute, boom: Prismatic };
//! let q = Vector2::new(0.4_f64, 0.25);
//! let r = 0.2 + q[1] + 0.25;
//! let m = arm.mass_matrix(&q);
//! let turret = 3.0 * 0.2 * 0.2 / 12.0 + 3.0 * 0.1 * 0.1;
//! assert!((m[(0, 0)] - (turret + 1.5 * 0.5 * 0.5 / 12.0 + 1.5 * r * r)).abs() < 1e-14);
//! assert!(m[(0, 1)] == 0.0 && m[(1, 1)] == 1.5);
//! let qd = Vector2::new(2.0, 0.0);
//! let tau = arm.inverse_dynamics(&q, &qd, &Vector2::zeros());
//! assert!((tau[1] - (-1.5 * r * 4.0 + 9.81 * 1.5 * q[0].sin())).abs() < 1e-13);
//! // The tip is (l1 + q2 + l2) (cos q1, sin q1); the Jacobian's last row is (1, 0).
//! let tip = arm.tip_pose(&q).translation.vector;
//! assert!((tip - 0.95 * Vector2::new(q[0].cos(), q[0].sin())).norm() < 1e-15);
//! assert_eq!(arm.jacobian(&q)[(2, 1)], 0.0);
//! assert_eq!(arm.links()[1].joint, Joint::Prismatic);
//! ```
//!
//! For a prismatic joint `tau_i` is a force (N), `armature` a reflected mass (kg), `damping`
//! N s/m and `frictionloss` N; the statics and the regressors speak of the same forces.
//!
//! # Conventions
//!
//! `q[0]` is link 1's angle from +x; `q[i]` (i > 0) is link i+1's angle relative to link i
//! (a prismatic joint's `q[i]` is its displacement, metres); all zeros is the arm stretched
//! along +x. The equations are `tau = M(q) qdd + c(q, qd) +
//! g(q)`, with c the velocity-product torques and g the torques that hold the arm against
//! gravity (`g = dV/dq`). Potential energy is measured from y = 0 at the base. Joint 1 is at
//! the origin; the tip is the end of the last link; the tip orientation is the last link's
//! absolute angle.
//!
//! # Scalars, batches and `no_std`
//!
//! The generated dynamics are generic over [`Real`]: `f64`, `f32`, SIMD batches with one
//! state per lane ([`simd`]), or your own number type (a dual number gives derivatives). An
//! `SVector<f32, N>` in gives an `SVector<f32, N>` out; `f64` calls compile and run as before.
//! Without its default features the crate is `#![no_std]` and needs no allocator. The
//! symbolic engine runs inside the derive; a program links it only with the `symbolic`
//! feature, which adds it as `planar_arm::symbolic`.
//!
//! # Seeing what was generated
//!
//! Each generated method's rustdoc shows the exact formulas it evaluates and its operation
//! count. `cargo expand` shows the code; without it, `cargo run --example expand -- 3` prints
//! the code for the paper's three-link arm, and `tests/expand/` holds the checked-in
//! expansions. With the `symbolic` feature, `planar_arm::symbolic` is the engine itself,
//! usable on its own: derive an `ArmSpec` and print its Lagrangian, M, c and g.
//!
//! # Checked against
//!
//! [`reference`](mod@reference) is a numeric recursive Newton-Euler, composite-rigid-body and
//! articulated-body implementation written apart from the symbolic path; property tests
//! compare every generated method with it for arms of 1 to 8 links with random rational
//! parameters. Energy is conserved under integration, `Mdot - 2C` is skew-symmetric, and the
//! paper's hand derivations are reproduced exactly where they are right.
#![cfg_attr(not(feature = "std"), no_std)]
// `unsafe` only in `dispatch`, `lanes` and `wide`: calling the AVX2 or AVX-512 copy of a
// generated method after the processor has said it runs them, the result it writes, and that
// copy's intrinsics.
#![deny(unsafe_code)]
#![warn(missing_docs)]

mod arm;
mod dispatch;
mod error;
pub mod exact;
mod frozen;
mod identification;
mod jet;
pub mod kinematics;
mod lanes;
mod ldlt;
mod linear;
mod link;
mod lqr;
mod mass_inverse;
mod model;
mod real;
pub mod reference;
/// Simulation and control: integrators, a simulation loop, trajectories, controllers.
pub mod sim;
#[cfg(feature = "std")]
pub mod simd;
pub mod spatial;
pub mod trig;
mod wide;

#[doc(hidden)]
pub mod __private;

/// The README's examples, compiled and run as doctests. Each is a complete program with its
/// own `fn main` (`tests/readme.rs` checks that), so that what a newcomer pastes compiles.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

pub use arm::{Dynamics, PlanarArm};
pub use error::ArmError;
pub use frozen::Frozen;
pub use identification::Identification;
pub use jet::Jet;
pub use kinematics::DynArm;
pub use linear::Linearize;
pub use link::{Joint, Link, Prismatic, Revolute};
pub use lqr::{dlqr, lqr, EigenSize, Lqr};
pub use model::{Model, Payload, RELATIVE_PIVOT};
pub use nalgebra;
// Inlined, so that the crate page's links to it resolve wherever planar_arm's docs are built
// alone (docs.rs, `cargo doc -p planar_arm`), not only beside planar_arm_core's.
#[cfg(feature = "symbolic")]
#[doc(inline)]
pub use planar_arm_core as symbolic;
pub use planar_arm_derive::PlanarArm;
pub use real::Real;
/// The spatial trait and its derive (also in [`spatial`] and the prelude), named as `PlanarArm` is.
pub use spatial::SpatialArm;

/// Everything a user of a derived arm needs: `use planar_arm::prelude::*;`.
pub mod prelude {
    pub use crate::kinematics::{
        ClosedFormIk, DexterousWorkspace, DlsOptions, IkTarget, TipForce, TipWrench, Workspace,
    };
    pub use crate::kinematics::{
        DexterousWorkspaceExt, DynArm, InverseStatics, RedundantTipWrench, Skeleton, StaticWrench,
    };
    pub use crate::spatial::{IkSolutions, SpatialArm};
    pub use crate::{
        ArmError, Dynamics, Frozen, Identification, Joint, Linearize, Link, Model, Payload,
        PlanarArm, Prismatic, Real, Revolute,
    };
    pub use nalgebra::{Isometry2, Isometry3, Point2, Point3, SMatrix, SVector, Vector2, Vector3};
}
