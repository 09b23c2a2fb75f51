//! The generated regressor and base parameters: `Y theta` and `Y_b theta_b` are the generated
//! inverse dynamics (itself checked against the numeric reference elsewhere) at random states,
//! for arms with run-time parameters, armature, damping, Coulomb friction and a payload; and a
//! change of the standard parameters that leaves every base parameter unchanged leaves the
//! torques unchanged.

mod common;

use common::Rng;

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;

#[derive(PlanarArm, Clone)]
#[arm(gravity = 9.81, payload = self.load, payload_com = (0.03, -0.01))]
struct Scara {
    #[arm(length = 0.35, mass = self.m1, inertia = self.i1, com = self.c1, armature = 0.02, damping = 0.1)]
    shoulder: Revolute,
    #[arm(length = 0.25, mass = 1.2, com = (0.11, 0.005), frictionloss = self.f2)]
    elbow: Revolute,
    m1: f64,
    i1: f64,
    c1: f64,
    f2: f64,
    load: f64,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 0)]
struct Flat {
    #[arm(length = 3/4, mass = 3/2, inertia = 1/7, com = (1/5, 1/9))]
    a: Revolute,
    #[arm(length = 1, mass = 5/2, inertia = 1/8, com = (2/5, 0))]
    b: Revolute,
    #[arm(length = 5/4, mass = 7/2, inertia = 1/9, com = (3/5, -1/9), armature = 1/10)]
    c: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.80665)]
struct Six {
    #[arm(length = 1/2, mass = 2)]
    a: Revolute,
    #[arm(length = 3/4, mass = 3/2, damping = 1/5)]
    b: Revolute,
    #[arm(length = 1, mass = 1, com = (1/3, 1/20))]
    c: Revolute,
    #[arm(length = 1/2, mass = 3/4, frictionloss = 1/4)]
    d: Revolute,
    #[arm(length = 3/4, mass = 1/2, armature = 1/50)]
    e: Revolute,
    #[arm(length = 1/2, mass = 1/4)]
    f: Revolute,
}

fn check<A, const N: usize, const P: usize, const B: usize>(arm: &A, rng: &mut Rng)
where
    A: Identification<N, P, B>,
{
    let (theta, base) = (arm.standard_parameters(), arm.base_parameters());
    for _ in 0..50 {
        let (q, qd, qdd) = (
            rng.vector::<N>(3.0),
            rng.vector::<N>(3.0),
            rng.vector::<N>(5.0),
        );
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let scale = 1.0 + tau.amax();
        let y = arm.regressor(&q, &qd, &qdd);
        assert!((y * theta - tau).amax() <= 1e-12 * scale, "Y theta");
        let yb = arm.base_regressor(&q, &qd, &qdd);
        assert!((yb * base - tau).amax() <= 1e-12 * scale, "Y_b theta_b");
    }
    assert!(B <= P);
}

#[test]
fn regressor_and_base_regressor_give_the_inverse_dynamics() {
    let mut rng = Rng(0x1d_e471_f1ca);
    for _ in 0..10 {
        let arm = Scara {
            shoulder: Revolute,
            elbow: Revolute,
            m1: rng.range(0.5, 4.0),
            i1: rng.range(0.01, 0.1),
            c1: rng.range(0.05, 0.3),
            f2: rng.range(0.0, 0.5),
            load: rng.range(0.0, 2.0),
        };
        check(&arm, &mut rng);
    }
    check(&Flat::default(), &mut rng);
    check(&Six::default(), &mut rng);
}

#[test]
fn parameter_lists_and_counts() {
    // Two links with payload, armature on joint 1, damping on 1, friction on 2:
    // 3 x 2 + 3 (payload) + 3 masses + ia1 + fv1 + fc2 = 15 standard parameters; base: zz, mx,
    // my per link (the payload and masses grouped, ia1 into zz1) plus fv1 and fc2 = 8.
    assert_eq!(
        <Scara as Identification<2, 15, 8>>::PARAMETERS,
        [
            "zz1", "mx1", "my1", "zz2", "mx2", "my2", "zzp", "mxp", "myp", "m1", "m2", "mp", "ia1",
            "fv1", "fc2"
        ]
    );
    // zz1 gathers l1^2 = 0.35^2 = 49/400 of each mass beyond link 1 and the armature.
    assert_eq!(
        <Scara as Identification<2, 15, 8>>::BASE_PARAMETERS[0],
        "zz1 + 49/400 m2 + 49/400 mp + ia1"
    );
    // No gravity: mx1 and my1 are not identifiable, ia1 joins zz1; ia3 is its own.
    assert_eq!(<Flat as Identification<3, 13, 8>>::BASE_PARAMETERS.len(), 8);
    // Six links with gravity: 18 + fv2 + fc4 + ia5 = 21.
    assert_eq!(
        <Six as Identification<6, 27, 21>>::BASE_PARAMETERS.len(),
        21
    );
}

#[test]
fn moving_along_a_grouping_leaves_the_torques_unchanged() {
    // m2 enters the base parameters only through zz1 + l1^2 m2 + ... and mx1 + l1 m2 + ...:
    // adding dm to m2 and subtracting l1^2 dm from zz1 and l1 dm from mx1 changes no base
    // parameter, so no torque. In standard parameters: theta + d.
    let arm = Six::default();
    let mut rng = Rng(5);
    let theta = arm.standard_parameters();
    let names = <Six as Identification<6, 27, 21>>::PARAMETERS;
    let at = |name: &str| names.iter().position(|n| *n == name).expect("name");
    let mut d = SVector::<f64, 27>::zeros();
    let (dm, l1) = (0.3, 0.5);
    d[at("m2")] = dm;
    d[at("zz1")] = -l1 * l1 * dm;
    d[at("mx1")] = -l1 * dm;
    for _ in 0..20 {
        let (q, qd, qdd) = (
            rng.vector::<6>(3.0),
            rng.vector::<6>(3.0),
            rng.vector::<6>(5.0),
        );
        let y = arm.regressor(&q, &qd, &qdd);
        let (a, b) = (y * theta, y * (theta + d));
        assert!((a - b).amax() <= 1e-12 * (1.0 + a.amax()));
        // And a change that moves a base parameter changes the torques.
        let mut e = SVector::<f64, 27>::zeros();
        e[at("zz1")] = 0.3;
        let c = y * (theta + e);
        assert!((a - c).amax() > 1e-6 || qdd[0].abs() < 1e-3);
    }
}
