//! A derived arm compiles without a single warning under strict lints: rustc's pedantic
//! groups, clippy's `all`, `pedantic` and `nursery` (CI runs clippy on this file with
//! `-D warnings`), and the lints of the 2024 edition migration.
#![deny(
    warnings,
    unused_qualifications,
    unused_results,
    unused_parens,
    unused_extern_crates,
    unreachable_pub,
    trivial_casts,
    trivial_numeric_casts,
    single_use_lifetimes,
    rust_2018_idioms,
    rust_2024_compatibility,
    missing_debug_implementations,
    clippy::all,
    clippy::pedantic,
    clippy::nursery
)]

use planar_arm::kinematics::{ClosedFormIk, TipForce, TipWrench};
use planar_arm::nalgebra::{Isometry2, Point2, SMatrix, SVector, Vector2};
use planar_arm::{ArmError, Dynamics, Link, PlanarArm, Revolute};

#[derive(PlanarArm, Debug, Default)]
#[arm(gravity = 9.81)]
struct One {
    #[arm(length = 0.5, mass = 2)]
    upper: Revolute,
}

#[derive(PlanarArm, Debug, Default)]
struct Two {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

#[derive(PlanarArm, Debug, Default)]
#[arm(gravity = 0)]
struct Three {
    #[arm(length = 0.4, mass = 2, inertia = 0, com = 0.2)]
    upper: Revolute,
    #[arm(length = 0.3, mass = 1)]
    fore: Revolute,
    #[arm(length = 0.1, mass = 0.5, com = -0.05)]
    hand: Revolute,
}

#[derive(PlanarArm, Debug, Default)]
struct Four {
    #[arm(length = 1, mass = 1)]
    a: Revolute,
    #[arm(length = 1, mass = 1)]
    b: Revolute,
    #[arm(length = 1, mass = 1)]
    c: Revolute,
    #[arm(length = 1, mass = 1)]
    d: Revolute,
}

#[test]
fn strict_lints_accept_derived_arms() {
    let q1: SVector<f64, 1> = SVector::from_element(0.0);
    let g: SVector<f64, 1> = One::default().gravity(&q1);
    // The holding torque of a 2 kg rod 0.5 m long: 2 * 9.81 * 0.25 N m.
    assert!((g[0] - 4.905).abs() < 1e-12);

    let two = Two::default();
    let q2 = SVector::<f64, 2>::new(0.4, 0.9);
    let m: SMatrix<f64, 2, 2> = two.mass_matrix(&q2);
    assert!(m.cholesky().is_some());
    let target: Point2<f64> = two.tip_pose(&q2).translation.vector.into();
    let solutions: Result<[SVector<f64, 2>; 2], ArmError> = two.inverse_kinematics(&target);
    assert!(solutions.is_ok());
    let force: Result<Vector2<f64>, ArmError> = two.tip_force(&q2, &q2);
    assert!(force.is_ok());

    let three = Three::default();
    let q3 = SVector::<f64, 3>::new(0.1, 0.2, 0.3);
    let pose: Isometry2<f64> = three.tip_pose(&q3);
    assert!(three.inverse_kinematics(&pose).is_ok());
    assert!(three.tip_wrench(&q3, &q3).is_ok());
    let links: [Link; 3] = three.links();
    assert!(links.iter().all(|l| l.mass > 0.0));

    let four = Four::default();
    let q4 = SVector::<f64, 4>::new(0.1, 0.2, 0.3, 0.4);
    let qdd = four.forward_dynamics(&q4, &q4, &q4);
    let tau = four.inverse_dynamics(&q4, &q4, &qdd);
    assert!((tau - q4).amax() < 1e-9);
}
