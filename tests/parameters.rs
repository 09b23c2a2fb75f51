//! Run-time parameters, payload, armature and friction, through the derive.
//!
//! Each parameterised arm is checked, for random parameter values and random states, against
//! the numeric reference fed with `arm.model()` (the reference shares no code with the
//! symbolic path), and against the same arm written with literals.

mod common;

use common::Rng;

use planar_arm::nalgebra::{SVector, Vector2};
use planar_arm::prelude::*;
use planar_arm::{reference, Model, Payload};

/// The SCARA: parameters, a fixed link with an off-axis centre of mass, armature,
/// damping, Coulomb friction, a payload, and a field that is not a link.
#[derive(PlanarArm, Debug, Clone)]
#[arm(gravity = 9.81, payload = self.payload)]
struct Scara {
    #[arm(length = 0.35, mass = self.m1, inertia = self.i1, com = self.c1, armature = 0.02, damping = 0.1)]
    shoulder: Revolute,
    #[arm(length = 0.25, mass = 1.2, com = (0.11, 0.005), frictionloss = self.f2)]
    elbow: Revolute,
    m1: f64,
    i1: f64,
    c1: f64,
    f2: f64,
    payload: f64,
    #[allow(dead_code)] // fields that are not links are left alone
    label: String,
}

/// The same arm with the parameters' values written as literals.
#[derive(PlanarArm, Debug, Default)]
#[arm(gravity = 9.81, payload = 0.4)]
struct ScaraLiteral {
    #[arm(
        length = 0.35,
        mass = 2.5,
        inertia = 0.03,
        com = 0.16,
        armature = 0.02,
        damping = 0.1
    )]
    shoulder: Revolute,
    #[arm(length = 0.25, mass = 1.2, com = (0.11, 0.005), frictionloss = 0.3)]
    elbow: Revolute,
}

fn scara() -> Scara {
    Scara {
        shoulder: Revolute,
        elbow: Revolute,
        m1: 2.5,
        i1: 0.03,
        c1: 0.16,
        f2: 0.3,
        payload: 0.4,
        label: "bench arm".into(),
    }
}

/// Every value a parameter, including lengths, gravity, the payload's inertia and offset,
/// and the defaults (`inertia`, `com`) computed from parameters.
#[derive(PlanarArm, Debug, Clone, Default)]
#[arm(gravity = self.g, payload = self.pm, payload_inertia = self.pi, payload_com = (self.px, self.py))]
struct Three {
    #[arm(length = self.l1, mass = self.m1, armature = self.a1, damping = self.b1, frictionloss = self.f1)]
    a: Revolute,
    #[arm(length = self.l2, mass = self.m2, inertia = self.i2, com = (self.cx2, self.cy2), armature = self.a2, damping = self.b2)]
    b: Revolute,
    #[arm(length = self.l3 / 2 + 0.1, mass = 2 * self.m3 - self.m1 * 0, inertia = self.i3, com = self.cx3, frictionloss = self.f3)]
    c: Revolute,
    g: f64,
    pm: f64,
    pi: f64,
    px: f64,
    py: f64,
    l1: f64,
    m1: f64,
    a1: f64,
    b1: f64,
    f1: f64,
    l2: f64,
    m2: f64,
    i2: f64,
    cx2: f64,
    cy2: f64,
    a2: f64,
    b2: f64,
    l3: f64,
    m3: f64,
    i3: f64,
    cx3: f64,
    f3: f64,
}

fn random_three(rng: &mut Rng) -> Three {
    Three {
        g: rng.range(0.0, 12.0),
        pm: rng.range(0.0, 2.0),
        pi: rng.range(0.0, 0.1),
        px: rng.range(-0.2, 0.2),
        py: rng.range(-0.2, 0.2),
        l1: rng.range(0.1, 1.5),
        m1: rng.range(0.1, 4.0),
        a1: rng.range(0.0, 0.2),
        b1: rng.range(0.0, 1.0),
        f1: rng.range(0.0, 1.0),
        l2: rng.range(0.1, 1.5),
        m2: rng.range(0.1, 4.0),
        i2: rng.range(0.0, 0.5),
        cx2: rng.range(-0.5, 1.5),
        cy2: rng.range(-0.3, 0.3),
        a2: rng.range(0.0, 0.2),
        b2: rng.range(0.0, 1.0),
        l3: rng.range(0.1, 1.5),
        m3: rng.range(0.1, 4.0),
        i3: rng.range(0.01, 0.5),
        cx3: rng.range(-0.5, 1.5),
        f3: rng.range(0.0, 1.0),
        ..Three::default()
    }
}

#[test]
fn scara_matches_the_reference_and_its_literal_twin() {
    let arm = scara();
    let twin = ScaraLiteral::default();
    assert!(arm.model().check().is_ok());
    assert_eq!(arm.model(), twin.model());
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for _ in 0..200 {
        let (q, qd, qdd) = (
            rng.vector::<2>(3.0),
            rng.vector::<2>(3.0),
            rng.vector::<2>(5.0),
        );
        common::check_state(&arm, &q, &qd, &qdd);
        let rel = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0);
        let pairs = [
            (
                arm.inverse_dynamics(&q, &qd, &qdd),
                twin.inverse_dynamics(&q, &qd, &qdd),
            ),
            (
                arm.forward_dynamics(&q, &qd, &qdd),
                twin.forward_dynamics(&q, &qd, &qdd),
            ),
            (arm.coriolis(&q, &qd), twin.coriolis(&q, &qd)),
            (arm.gravity(&q), twin.gravity(&q)),
            (arm.friction(&qd), twin.friction(&qd)),
        ];
        for (a, b) in pairs {
            assert!(
                a.iter().zip(b.iter()).all(|(x, y)| rel(*x, *y)),
                "{a} vs {b}"
            );
        }
        let (m, mt) = (arm.mass_matrix(&q), twin.mass_matrix(&q));
        assert!(m.iter().zip(mt.iter()).all(|(x, y)| rel(*x, *y)));
        assert!(rel(
            arm.kinetic_energy(&q, &qd),
            twin.kinetic_energy(&q, &qd)
        ));
        assert!(rel(arm.potential_energy(&q), twin.potential_energy(&q)));
    }
}

#[test]
fn every_value_a_parameter_matches_the_reference() {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    for _ in 0..64 {
        let arm = random_three(&mut rng);
        for _ in 0..8 {
            let (q, qd, qdd) = (
                rng.vector::<3>(3.0),
                rng.vector::<3>(3.0),
                rng.vector::<3>(5.0),
            );
            common::check_state(&arm, &q, &qd, &qdd);
        }
        // The defaults follow the parameters: a uniform rod for link 1.
        let l = arm.links();
        assert!((l[0].inertia - arm.m1 * arm.l1 * arm.l1 / 12.0).abs() < 1e-12);
        assert!((l[0].com - Vector2::new(arm.l1 / 2.0, 0.0)).norm() < 1e-15);
        assert!((l[2].length - (arm.l3 / 2.0 + 0.1)).abs() < 1e-15);
        assert!((l[2].mass - 2.0 * arm.m3).abs() < 1e-15);
        // Closed-form kinematics follow the run-time lengths.
        let q = rng.vector::<3>(3.0);
        let pose = arm.tip_pose(&q);
        for sol in arm.inverse_kinematics(&pose).expect("reachable") {
            assert!(
                (arm.tip_pose(&sol).translation.vector - pose.translation.vector).norm() < 1e-9
            );
        }
        let outer: f64 = l.iter().map(|l| l.length).sum();
        assert!((arm.workspace().outer_radius() - outer).abs() < 1e-12);
    }
}

#[test]
fn changing_a_parameter_changes_every_method() {
    let mut arm = random_three(&mut Rng(7));
    let (q, qd, qdd) = (
        SVector::<f64, 3>::new(0.3, -0.7, 1.1),
        SVector::<f64, 3>::new(0.5, 1.5, -0.9),
        SVector::<f64, 3>::new(-0.2, 0.4, 0.8),
    );
    let snapshot = |a: &Three| {
        (
            a.mass_matrix(&q),
            a.coriolis(&q, &qd),
            a.gravity(&q),
            a.friction(&qd),
            a.inverse_dynamics(&q, &qd, &qdd),
            a.forward_dynamics(&q, &qd, &qdd),
            a.kinetic_energy(&q, &qd),
            a.potential_energy(&q),
            a.tip_pose(&q),
            a.jacobian(&q),
        )
    };
    let before = snapshot(&arm);
    // Each parameter changes what it must change, read at the next call: nothing is cached.
    arm.m2 *= 1.5;
    arm.l1 *= 1.25;
    arm.b1 += 0.5;
    arm.f3 += 0.5;
    arm.pm += 1.0;
    let after = snapshot(&arm);
    assert_ne!(before.0, after.0, "mass_matrix");
    assert_ne!(before.1, after.1, "coriolis");
    assert_ne!(before.2, after.2, "gravity");
    assert_ne!(before.3, after.3, "friction");
    assert_ne!(before.4, after.4, "inverse_dynamics");
    assert_ne!(before.5, after.5, "forward_dynamics");
    assert_ne!(before.6, after.6, "kinetic_energy");
    assert_ne!(before.7, after.7, "potential_energy");
    assert_ne!(before.8, after.8, "tip_pose");
    assert_ne!(before.9, after.9, "jacobian");
    // And the new answers are the reference's for the new values.
    common::check_state(&arm, &q, &qd, &qdd);
}

/// The payload against the last link combined with it by hand: mass 1.5 + 0.5 = 2,
/// first moment 1.5 (0.5, 0) + 0.5 (1 + 0.2, 0.1) = (1.35, 0.05), so the centre of mass is
/// (0.675, 0.025); inertia about it by the parallel-axis theorem:
/// 0.125 + 1.5 ((0.5 - 0.675)^2 + 0.025^2) + 0.01 + 0.5 ((1.2 - 0.675)^2 + (0.1 - 0.025)^2)
/// = 0.125 + 0.046875 + 0.01 + 0.140625 = 0.3225.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81, payload = 0.5, payload_inertia = 0.01, payload_com = (0.2, 0.1))]
struct Carrying {
    #[arm(length = 0.8, mass = 2)]
    upper: Revolute,
    #[arm(length = 1, mass = 1.5, inertia = 0.125, com = 0.5)]
    fore: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Combined {
    #[arm(length = 0.8, mass = 2)]
    upper: Revolute,
    #[arm(length = 1, mass = 2, inertia = 0.3225, com = (0.675, 0.025))]
    fore: Revolute,
}

/// A zero payload is exactly no payload.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81, payload = 0)]
struct Empty {
    #[arm(length = 0.8, mass = 2)]
    upper: Revolute,
    #[arm(length = 1, mass = 1.5, inertia = 0.125, com = 0.5)]
    fore: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Bare {
    #[arm(length = 0.8, mass = 2)]
    upper: Revolute,
    #[arm(length = 1, mass = 1.5, inertia = 0.125, com = 0.5)]
    fore: Revolute,
}

#[test]
fn payload_is_the_parallel_axis_combination() {
    let (a, b) = (Carrying::default(), Combined::default());
    let mut rng = Rng(11);
    for _ in 0..100 {
        let (q, qd, qdd) = (
            rng.vector::<2>(3.0),
            rng.vector::<2>(3.0),
            rng.vector::<2>(5.0),
        );
        let close =
            |x: SVector<f64, 2>, y: SVector<f64, 2>| (x - y).amax() <= 1e-12 * (1.0 + y.amax());
        assert!(close(
            a.inverse_dynamics(&q, &qd, &qdd),
            b.inverse_dynamics(&q, &qd, &qdd)
        ));
        assert!(close(
            a.forward_dynamics(&q, &qd, &qdd),
            b.forward_dynamics(&q, &qd, &qdd)
        ));
        assert!((a.mass_matrix(&q) - b.mass_matrix(&q)).amax() < 1e-12);
        assert!((a.kinetic_energy(&q, &qd) - b.kinetic_energy(&q, &qd)).abs() < 1e-12);
        assert!((a.potential_energy(&q) - b.potential_energy(&q)).abs() < 1e-12);
        common::check_state(&a, &q, &qd, &qdd);
    }
    // The reference merges the payload itself; it must agree with the hand combination too.
    let merged = Model::new(
        [Link::rod(0.8, 2.0), Link::rod(1.0, 1.5).with_inertia(0.125)],
        9.81,
    )
    .with_payload(Payload::point(0.5).with_inertia(0.01).with_com(0.2, 0.1))
    .rigid_links();
    assert!((merged[1].mass - 2.0).abs() < 1e-15);
    assert!((merged[1].com - Vector2::new(0.675, 0.025)).norm() < 1e-15);
    assert!((merged[1].inertia - 0.3225).abs() < 1e-15);
    // EXACT: the same derivation, exactly (M11 constant term, both arms).
    assert_eq!(
        planar_arm::exact::constant_term(<Carrying as PlanarArm<2>>::EXACT.mass_matrix[0][0]),
        planar_arm::exact::constant_term(<Combined as PlanarArm<2>>::EXACT.mass_matrix[0][0]),
    );
}

#[test]
fn zero_payload_is_no_payload() {
    let (a, b) = (Empty::default(), Bare::default());
    assert_eq!(
        format!("{:?}", <Empty as PlanarArm<2>>::EXACT.mass_matrix),
        format!("{:?}", <Bare as PlanarArm<2>>::EXACT.mass_matrix)
    );
    let q = SVector::<f64, 2>::new(0.4, -1.3);
    let qd = SVector::<f64, 2>::new(1.0, 2.0);
    assert_eq!(
        a.inverse_dynamics(&q, &qd, &qd),
        b.inverse_dynamics(&q, &qd, &qd)
    );
}

/// `d/dt (T + V) = qd . (tau - f)`: with no friction and no torque the energy is conserved;
/// with damping alone it falls at the rate `sum B qd_i^2`.
fn energy_change(arm: &Three, steps: usize, dt: f64) -> (f64, f64) {
    let mut q = SVector::<f64, 3>::new(0.4, -0.9, 1.3);
    let mut qd = SVector::<f64, 3>::new(1.0, -0.5, 0.8);
    let zero = SVector::<f64, 3>::zeros();
    let energy = |q: &SVector<f64, 3>, qd: &SVector<f64, 3>| {
        arm.kinetic_energy(q, qd) + arm.potential_energy(q)
    };
    let dissipation =
        |qd: &SVector<f64, 3>| -> f64 { arm.b1 * qd[0] * qd[0] + arm.b2 * qd[1] * qd[1] };
    let e0 = energy(&q, &qd);
    let mut dissipated = 0.0;
    for _ in 0..steps {
        // RK4 on (q, qd) and on the dissipated energy alongside.
        let f =
            |q: &SVector<f64, 3>, qd: &SVector<f64, 3>| (*qd, arm.forward_dynamics(q, qd, &zero));
        let (k1q, k1v) = f(&q, &qd);
        let (k2q, k2v) = f(&(q + k1q * (dt / 2.0)), &(qd + k1v * (dt / 2.0)));
        let (k3q, k3v) = f(&(q + k2q * (dt / 2.0)), &(qd + k2v * (dt / 2.0)));
        let (k4q, k4v) = f(&(q + k3q * dt), &(qd + k3v * dt));
        let d1 = dissipation(&qd);
        let d2 = dissipation(&(qd + k1v * (dt / 2.0)));
        let d3 = dissipation(&(qd + k2v * (dt / 2.0)));
        let d4 = dissipation(&(qd + k3v * dt));
        dissipated += dt / 6.0 * (d1 + 2.0 * d2 + 2.0 * d3 + d4);
        q += (k1q + k2q * 2.0 + k3q * 2.0 + k4q) * (dt / 6.0);
        qd += (k1v + k2v * 2.0 + k3v * 2.0 + k4v) * (dt / 6.0);
    }
    (energy(&q, &qd) - e0, dissipated)
}

#[test]
fn energy_is_conserved_without_friction_and_damping_dissipates_it() {
    let mut arm = random_three(&mut Rng(99));
    arm.g = 9.81;
    arm.pm = 0.7;
    arm.a1 = 0.05;
    arm.a2 = 0.03;
    arm.f1 = 0.0;
    arm.f3 = 0.0;
    arm.b1 = 0.0;
    arm.b2 = 0.0;
    let (change, _) = energy_change(&arm, 2000, 1e-3);
    let scale = 1.0
        + arm.kinetic_energy(
            &SVector::<f64, 3>::new(0.4, -0.9, 1.3),
            &SVector::<f64, 3>::new(1.0, -0.5, 0.8),
        );
    assert!(
        change.abs() < 1e-7 * scale,
        "free arm: energy changed by {change}"
    );
    arm.b1 = 0.3;
    arm.b2 = 0.2;
    let (change, dissipated) = energy_change(&arm, 2000, 1e-3);
    assert!(dissipated > 1e-2, "the test must dissipate: {dissipated}");
    assert!(
        (change + dissipated).abs() < 1e-7 * scale,
        "energy fell by {} but damping dissipated {dissipated}",
        -change
    );
    // Negative control: the damping torque left out of the balance is seen.
    assert!((change).abs() > 1e-3);
}

#[test]
fn friction_is_viscous_plus_coulomb_with_sign_zero_at_rest() {
    let arm = scara();
    let f = arm.friction(&SVector::<f64, 2>::new(2.0, -3.0));
    assert!((f[0] - 0.1 * 2.0).abs() < 1e-15);
    assert!((f[1] - (-0.3)).abs() < 1e-15);
    let rest = arm.friction(&SVector::<f64, 2>::zeros());
    assert_eq!(rest, SVector::<f64, 2>::zeros());
    let model = arm.model();
    let r = reference::friction(&model, &SVector::<f64, 2>::new(2.0, -3.0));
    assert!((r - f).amax() < 1e-15);
}

#[test]
fn parameters_out_of_range_do_not_panic() {
    let mut arm = scara();
    arm.m1 = f64::NAN;
    let q = SVector::<f64, 2>::new(0.3, 0.2);
    assert!(arm.try_inverse_dynamics(&q, &q, &q).is_err());
    assert!(matches!(
        arm.model().check(),
        Err(ArmError::OutOfRange {
            what: "mass",
            link: Some(0),
            ..
        })
    ));
    arm.m1 = -1.0;
    assert!(arm.model().check().is_err());
    let _ = arm.forward_dynamics(&q, &q, &q);
    let _ = arm.inverse_kinematics(&Point2::new(0.3, 0.1));
}

/// Two links whose lengths are run-time parameters: the closed-form inverse kinematics and
/// inverse statics use the current lengths (the equal-link formula when both name one field).
#[derive(PlanarArm, Debug)]
#[arm(gravity = 0)]
struct Telescope {
    #[arm(length = self.l1, mass = 1)]
    upper: Revolute,
    #[arm(length = self.l2, mass = 1)]
    fore: Revolute,
    l1: f64,
    l2: f64,
}

#[derive(PlanarArm, Debug)]
#[arm(gravity = 0)]
struct EqualParam {
    #[arm(length = self.l, mass = 1)]
    upper: Revolute,
    #[arm(length = self.l, mass = 1)]
    fore: Revolute,
    l: f64,
}

#[test]
fn closed_forms_follow_run_time_lengths() {
    let mut rng = Rng(5);
    for _ in 0..200 {
        let arm = Telescope {
            upper: Revolute,
            fore: Revolute,
            l1: rng.range(0.2, 2.0),
            l2: rng.range(0.2, 2.0),
        };
        let q = rng.vector::<2>(3.0);
        let tip = Point2::from(arm.tip_pose(&q).translation.vector);
        let [a, b] = arm.inverse_kinematics(&tip).expect("reachable");
        for sol in [a, b] {
            let reached = Point2::from(arm.tip_pose(&sol).translation.vector);
            assert!((reached - tip).norm() < 1e-9, "{reached} vs {tip}");
        }
        let force = Vector2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
        let tau = arm.joint_torques(&q, &force, 0.0);
        if let Ok(back) = arm.tip_force(&q, &tau) {
            assert!((back - force).norm() < 1e-6 * (1.0 + force.norm()));
        }
        let outside = Point2::new(arm.l1 + arm.l2 + 0.1, 0.0);
        assert!(matches!(
            arm.inverse_kinematics(&outside),
            Err(ArmError::Unreachable { .. })
        ));
        let equal = EqualParam {
            upper: Revolute,
            fore: Revolute,
            l: arm.l1,
        };
        let tip = Point2::from(equal.tip_pose(&q).translation.vector);
        for sol in equal.inverse_kinematics(&tip).expect("reachable") {
            let reached = Point2::from(equal.tip_pose(&sol).translation.vector);
            assert!((reached - tip).norm() < 1e-9);
        }
    }
}
