//! Ten links: the generated code agrees with the numeric reference and its forward dynamics
//! inverts its inverse dynamics.
use planar_arm::prelude::*;
use planar_arm::reference;

#[derive(PlanarArm, Default)]
struct Ten {
    #[arm(length = 1, mass = 1)]
    l1: Revolute,
    #[arm(length = 0.9, mass = 0.9)]
    l2: Revolute,
    #[arm(length = 0.8, mass = 0.8, com = 0.3)]
    l3: Revolute,
    #[arm(length = 0.7, mass = 0.7, inertia = 0.01)]
    l4: Revolute,
    #[arm(length = 0.6, mass = 0.6, inertia = 0, com = 0.6)]
    l5: Revolute,
    #[arm(length = 0.5, mass = 0.5, com = -0.1)]
    l6: Revolute,
    #[arm(length = 0.4, mass = 0.4)]
    l7: Revolute,
    #[arm(length = 0.3, mass = 0.3)]
    l8: Revolute,
    #[arm(length = 0.2, mass = 0.2)]
    l9: Revolute,
    #[arm(length = 0.1, mass = 0.1)]
    l10: Revolute,
}

fn main() {
    let arm = Ten::default();
    for k in 0..10 {
        let t = f64::from(k);
        let q = SVector::<f64, 10>::from_fn(|i, _| (t + 1.0) * 0.37 * (i as f64 + 1.0).sin());
        let qd = SVector::<f64, 10>::from_fn(|i, _| (t - 4.0) * 0.2 * (i as f64).cos());
        let qdd = SVector::<f64, 10>::from_fn(|i, _| 0.3 * t - 0.1 * i as f64);
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let tau_ref =
            reference::inverse_dynamics(&arm.model(), &q, &qd, &qdd);
        assert!(
            (tau - tau_ref).amax() <= 1e-9 * (1.0 + tau_ref.amax()),
            "{tau} {tau_ref}"
        );
        let back = arm.forward_dynamics(&q, &qd, &tau);
        assert!(
            (back - qdd).amax() <= 1e-7 * (1.0 + qdd.amax()),
            "{back} {qdd}"
        );
        assert!(arm.mass_matrix(&q).cholesky().is_some());
        assert_eq!(arm.joint_positions(&q).len(), 10);
    }
    let reach: f64 = arm.links().iter().map(|l| l.length).sum();
    assert!((arm.workspace().outer_radius() - reach).abs() < 1e-12);
}
