//! Joints that do not start along the previous link or turn the other way: `offset = angle`
//! and `reversed` on a link, as model files have them, and joint springs (a cart-pole whose pole stands up at
//! `q = 0`, a floating base of slides at right angles, a hinge about -y among +y ones).
//!
//! Each arm's generated methods against the numeric reference on its `model()` (which treats
//! offsets and reversed joints in its own code) and against the spatial reference on
//! `model().to_spatial()` (the arm as a spatial arm in the plane, offsets as turns about z,
//! reversed joints about -z: no code shared with the planar path). The cart-pole written with
//! an offset is also the same arm as one written without, turned: its pole's angle is the
//! plain arm's less a quarter turn.

mod common;

use common::assert_matrix_close as close;
use planar_arm::nalgebra::{SMatrix, SVector};
use planar_arm::prelude::*;
use planar_arm::reference;

/// A cart on a slide, its pole standing up at `q = 0` (a quarter turn from the slide) and
/// turning clockwise (reversed), under gravity along -y.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct CartPole {
    #[arm(length = 0, mass = 1, inertia = 0, damping = 0.1)]
    cart: Prismatic,
    #[arm(length = 1, mass = 0.1, com = 0.5, offset = pi/2, reversed)]
    pole: Revolute,
}

/// [`CartPole`] written plainly: its pole lies along the slide at `q = 0` and turns
/// counter-clockwise.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct PlainCartPole {
    #[arm(length = 0, mass = 1, inertia = 0, damping = 0.1)]
    cart: Prismatic,
    #[arm(length = 1, mass = 0.1, com = 0.5)]
    pole: Revolute,
}

/// A planar floating base (slide x, slide at a right angle, hinge, all at one point and
/// massless) carrying a two-link leg: the hopper's chain. The second hinge is reversed, the
/// last is bent by an angle whose cosine is not rational (a named constant); a slide and a
/// hinge have springs.
#[derive(PlanarArm, Default)]
#[arm(gravity = (0, -9.81), payload = 0.2, payload_com = (0.05, 0.02))]
struct Floating {
    #[arm(length = 0, mass = 0, inertia = 0, armature = 0.01, stiffness = 40, springref = -0.1)]
    x: Prismatic,
    #[arm(length = 0, mass = 0, inertia = 0, offset = pi/2, reversed, damping = 0.2)]
    z: Prismatic,
    #[arm(length = 0.4, mass = 3.5, inertia = 0.05, com = (0.2, 0.01), offset = -pi/2)]
    torso: Revolute,
    #[arm(
        length = 0.45,
        mass = 2,
        com = 0.2,
        reversed,
        frictionloss = 0.3,
        stiffness = 5,
        springref = 0.2
    )]
    thigh: Revolute,
    #[arm(length = 0.5, mass = 1, com = (0.25, -0.02), offset = 0.3, armature = 0.02)]
    leg: Revolute,
}

fn states<const N: usize>() -> Vec<[SVector<f64, N>; 3]> {
    common::states(&mut common::Rng(61), 8, 1.5)
}

/// Every dynamics and kinematics method against both references.
fn against_references<const N: usize, A: PlanarArm<N>>(arm: &A) {
    use reference::spatial as sp;
    let model = arm.model();
    let spatial = model.to_spatial();
    for [q, qd, qdd] in states::<N>() {
        let tau = reference::inverse_dynamics(&model, &q, &qd, &qdd);
        close(&arm.inverse_dynamics(&q, &qd, &qdd), &tau, "ID");
        close(
            &tau,
            &sp::inverse_dynamics(&spatial, &q, &qd, &qdd),
            "ID: planar vs spatial reference",
        );
        let m = sp::mass_matrix(&spatial, &q);
        close(&arm.mass_matrix(&q), &m, "M");
        close(&arm.gravity(&q), &sp::gravity(&spatial, &q), "g");
        close(
            &arm.bias(&q, &qd),
            &reference::bias_forces(&model, &q, &qd),
            "bias",
        );
        close(
            &arm.forward_dynamics(&q, &qd, &tau),
            &reference::forward_dynamics(&model, &q, &qd, &tau),
            "FD",
        );
        let (t, v) = (arm.kinetic_energy(&q, &qd), arm.potential_energy(&q));
        let t_ref = reference::kinetic_energy(&model, &q, &qd);
        let v_ref = sp::potential_energy(&spatial, &q);
        assert!(
            (t - t_ref).abs() <= 1e-12 * t_ref.abs().max(1.0),
            "T {t} {t_ref}"
        );
        assert!(
            (v - v_ref).abs() <= 1e-12 * v_ref.abs().max(1.0),
            "V {v} {v_ref}"
        );
        let pose = arm.tip_pose(&q);
        let tip = sp::tip_pose(&spatial, &q);
        let d = pose.translation.vector - tip.translation.vector.xy();
        assert!(d.norm() <= 1e-12, "tip {d}");
        let x = tip.rotation * planar_arm::nalgebra::Vector3::x();
        assert!(
            (pose.rotation.angle() - x.y.atan2(x.x)).sin().abs() <= 1e-12,
            "tip orientation"
        );
        close(
            &arm.jacobian(&q),
            &reference::jacobian(&model, &q),
            "Jacobian",
        );
        // The derivatives against central differences of the generated inverse dynamics.
        let (dq, _) = arm.inverse_dynamics_derivatives(&q, &qd, &qdd);
        let h = 1e-6;
        let fd = SMatrix::<f64, N, N>::from_fn(|i, j| {
            let mut up = q;
            let mut down = q;
            up[j] += h;
            down[j] -= h;
            (arm.inverse_dynamics(&up, &qd, &qdd)[i] - arm.inverse_dynamics(&down, &qd, &qdd)[i])
                / (2.0 * h)
        });
        assert!((dq - fd).amax() <= 1e-6 * fd.amax().max(1.0), "dID/dq");
    }
}

#[test]
fn turned_and_reversed_joints_have_the_references_dynamics() {
    against_references(&CartPole::default());
    against_references(&Floating::default());
}

#[test]
fn the_regressors_cover_turned_and_reversed_joints() {
    // Quarter turns keep the geometry rational: the base parameters are found exactly.
    let arm = CartPole::default();
    for [q, qd, qdd] in states::<2>() {
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let y = arm.regressor(&q, &qd, &qdd) * arm.standard_parameters();
        close(&y, &tau, "Y theta");
        let yb = arm.base_regressor(&q, &qd, &qdd) * arm.base_parameters();
        close(&yb, &tau, "Y_b theta_b");
    }
}

#[test]
fn an_offset_is_a_shifted_angle() {
    // The pole at q2 in CartPole is the plain pole at pi/2 - q2: M, g and the tip agree once
    // the angle is turned and the reversed joint's sign is applied to its row and column.
    let (turned, plain) = (CartPole::default(), PlainCartPole::default());
    let s = SVector::<f64, 2>::new(1.0, -1.0);
    for [q, qd, _] in states::<2>() {
        let p = SVector::<f64, 2>::new(q[0], core::f64::consts::FRAC_PI_2 - q[1]);
        let m = plain.mass_matrix(&p).component_mul(&(s * s.transpose()));
        close(&turned.mass_matrix(&q), &m, "M");
        close(
            &turned.gravity(&q),
            &plain.gravity(&p).component_mul(&s),
            "g",
        );
        let pd = qd.component_mul(&s);
        close(
            &turned.bias(&q, &qd),
            &plain.bias(&p, &pd).component_mul(&s),
            "bias",
        );
        let (a, b) = (turned.tip_pose(&q), plain.tip_pose(&p));
        assert!((a.translation.vector - b.translation.vector).norm() < 1e-12);
    }
    // Quarter turns stay exact: the pole stands up at q2 = 0 and falls as q2 grows
    // clockwise, its centre at height c cos(q2), so V = m g c cos(q2) and
    // g2 = -m g c sin(q2), with m g c = 0.1 * 9.81 * 0.5 = 981/2000.
    let exact = CartPole::EXACT.to_string();
    assert!(exact.contains("V = 981/2000 cos(q2)\n"), "{exact}");
    assert!(exact.contains("g2 = -981/2000 sin(q2)\n"), "{exact}");
    // An offset off the quarter turns enters as its named cosine and sine.
    let exact = Floating::EXACT.to_string();
    assert!(
        exact.contains("cos(3/10)") && exact.contains("sin(3/10)"),
        "{exact}"
    );
}

#[test]
fn a_turned_slide_moves_across_the_one_before() {
    // At q = 0 except the second slide, the base has moved along +y (a quarter turn, then
    // reversed: -q along the turned x, which is -y... so +y for a negative q).
    let arm = Floating::default();
    let q = SVector::<f64, 5>::new(0.0, -0.7, 0.0, 0.0, 0.0);
    let joints = arm.joint_positions(&q);
    assert!((joints[2].x).abs() < 1e-15 && (joints[2].y - 0.7).abs() < 1e-15);
    // The torso's offset -pi/2 undoes the slide's quarter turn: it points along +x.
    let torso_end = joints[3] - joints[2];
    assert!((torso_end.x - 0.4).abs() < 1e-15 && torso_end.y.abs() < 1e-15);
}
