//! Values with as many digits as model files carry (URDF's and MuJoCo's 17-digit decimals):
//! the exact equations of motion of such an arm have coefficients too long for the `i128` of
//! `EXACT`, so those values enter as named constants, exact in that symbol, and the arm
//! derives. Its methods against the numeric reference, which uses the same `f64` values.

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;
use planar_arm::reference;

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct FromAFile {
    #[arm(length = 0.40000000000000002, mass = 1.3999999999999999,
          inertia = 3.9175660390264734e-05, com = (0.19999999999999998, 0.0))]
    upper: Revolute,
    #[arm(
        length = 0.29999999999999999,
        mass = 0.80000000000000004,
        inertia = 2.1175660390264734e-05,
        damping = 0.10000000000000001
    )]
    fore: Revolute,
}

#[test]
fn seventeen_digit_values_enter_as_named_constants() {
    let arm = FromAFile::default();
    let model = arm.model();
    let mut worst: f64 = 0.0;
    for k in 0..20 {
        let t = f64::from(k);
        let q = SVector::<f64, 2>::new((0.7 * t).sin() * 3.0, (0.3 * t).cos() * 2.0);
        let qd = SVector::<f64, 2>::new((1.1 * t).cos(), -(0.5 * t).sin() * 2.0);
        let qdd = SVector::<f64, 2>::new(1.0 - 0.1 * t, (0.9 * t).sin());
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let want = reference::inverse_dynamics(&model, &q, &qd, &qdd);
        worst = worst.max((tau - want).amax() / want.amax().max(1.0));
        let m = arm.mass_matrix(&q);
        worst = worst.max((m - reference::mass_matrix(&model, &q)).amax());
    }
    assert!(worst < 1e-13, "{worst:e}");
    // The long values are symbols of EXACT, named by their shortest decimals.
    let exact = FromAFile::EXACT.to_string();
    assert!(exact.contains("0.000039175660390264734"), "{exact}");
}

/// Magnitudes far from 1, whose exact coefficients overflowed `i128` and were refused before:
/// named constants too.
#[derive(PlanarArm, Default)]
struct Huge {
    #[arm(length = 1e30, mass = 1)]
    upper: Revolute,
    #[arm(length = 1e30, mass = 1)]
    fore: Revolute,
}

#[derive(PlanarArm, Default)]
struct Tiny {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1/1000000000000000000000000000000, mass = 1)]
    fore: Revolute,
}

#[test]
fn extreme_magnitudes_derive_too() {
    let q = SVector::<f64, 2>::new(0.3, -0.8);
    let (huge, tiny) = (Huge::default(), Tiny::default());
    let m = huge.mass_matrix(&q);
    let want = reference::mass_matrix(&huge.model(), &q);
    assert!((m - want).amax() <= 1e-13 * want.amax(), "{m} {want}");
    let m = tiny.mass_matrix(&q);
    let want = reference::mass_matrix(&tiny.model(), &q);
    assert!((m - want).amax() <= 1e-13 * want.amax(), "{m} {want}");
}

/// A spatial arm whose exact tool pose and potential energy would overflow `EXACT`.
#[derive(SpatialArm, Default)]
struct FarReach {
    #[arm(dh(a = 1e30, alpha = pi/2), mass = 1.3999999999999999, com = (-0.19999999999999998, 0, 0))]
    shoulder: Revolute,
    #[arm(dh(a = 1e30), mass = 1)]
    elbow: Revolute,
}

#[test]
fn a_spatial_arm_with_extreme_values_derives() {
    use planar_arm::reference::spatial as spatial_reference;
    use planar_arm::spatial::SpatialArm;
    let arm = FarReach::default();
    let model = arm.model();
    let q = SVector::<f64, 2>::new(0.3, -0.8);
    let (qd, qdd) = (
        SVector::<f64, 2>::new(0.2, 0.5),
        SVector::<f64, 2>::new(-1.0, 0.4),
    );
    let tau = arm.inverse_dynamics(&q, &qd, &qdd);
    let want = spatial_reference::inverse_dynamics(&model, &q, &qd, &qdd);
    assert!((tau - want).amax() <= 1e-12 * want.amax(), "{tau} {want}");
    let pose = arm.tip_pose(&q).translation.vector;
    let want = spatial_reference::tip_pose(&model, &q).translation.vector;
    assert!((pose - want).amax() <= 1e-12 * want.amax());
}
