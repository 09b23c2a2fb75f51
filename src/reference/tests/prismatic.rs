//! Arms with prismatic joints against closed forms worked out by hand: the polar (RP) arm, a
//! cart carrying a two-link arm (PRR) and a single slider.

use super::revolute::two_link_closed_form;
use super::*;

use core::f64::consts::PI;
use nalgebra::{Matrix1, Matrix2, Matrix3, Matrix3x2, Vector1};

/// `sign(x)` with `sign(0) = 0`, for the Coulomb friction.
fn coulomb(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x.signum()
    }
}

/// A payload that is there, off the tip's axis or (`on_axis`) on it.
fn some_payload(rng: &mut Rng, on_axis: bool) -> Payload {
    let y = rng.uniform(-0.3, 0.3);
    Payload {
        mass: rng.uniform(0.1, 3.0),
        inertia: rng.uniform(0.0, 0.2),
        com: V2::new(rng.uniform(-0.3, 0.3), if on_axis { 0.0 } else { y }),
    }
}

/// The polar (RP) arm, worked by hand: `(M, c, g, f, V)`.
///
/// Joint 1 turns link 1 by `q1` about the origin; joint 2 slides link 2 along
/// `u = (cos q1, sin q1)`, its origin at `(l1 + q2) u`. A body fixed in link 2 with mass `m`,
/// inertia `I` and centre `(x, y)` in link 2's frame sits at `r = s u + y perp(u)` with
/// `s = l1 + q2 + x`, and since `du/dt = qd1 perp(u)`, `d perp(u)/dt = -qd1 u`:
///
/// ```text
/// dr/dt = (qd2 - y qd1) u + s qd1 perp(u)
/// T_B   = m/2 [(qd2 - y qd1)^2 + s^2 qd1^2] + I/2 qd1^2
/// M_B   = [[I + m (s^2 + y^2), -m y], [-m y, m]]
/// ```
///
/// Link 2 is such a body with `(x, y) = (a2, b2)`, the payload with `(l2 + px, py)`. Link 1
/// adds `I1 + m1 |c1|^2` to `M11`, the armatures their diagonals. Only `s` depends on `q`
/// (`ds/dq2 = 1`): with `K = sum m_B s_B`, `dM11/dq2 = 2K`, so the Christoffel symbols are
/// `G_112 = G_121 = K`, `G_211 = -K` and all others zero:
///
/// ```text
/// c = (2 K qd1 qd2, -K qd1^2)
/// ```
///
/// the Coriolis torque `2 m s sd w` on the turning joint and the centripetal pull `-m s w^2`
/// on the slider. Heights: link 1's centre `a1 sin q1 + b1 cos q1`, a body's
/// `s sin q1 + y cos q1`, so
///
/// ```text
/// V  = gravity [m1 (a1 sin q1 + b1 cos q1) + sum m_B (s_B sin q1 + y_B cos q1)]
/// g1 = gravity [m1 (a1 cos q1 - b1 sin q1) + sum m_B (s_B cos q1 - y_B sin q1)]
/// g2 = gravity sin q1 sum m_B
/// ```
fn polar_closed_form(
    model: &Model<2>,
    q: &V2<f64>,
    qd: &V2<f64>,
) -> (Matrix2<f64>, V2<f64>, V2<f64>, V2<f64>, f64) {
    let [l1, l2] = model.links;
    let p = model.payload;
    // The closed form is written for gravity along -y.
    assert_eq!(model.gravity.x, 0.0);
    let gravity = -model.gravity.y;
    let (s1, c1) = q[0].sin_cos();
    let (a1, b1) = (l1.com.x, l1.com.y);
    let bodies = [
        (l2.mass, l2.inertia, l2.com.x, l2.com.y),
        (p.mass, p.inertia, l2.length + p.com.x, p.com.y),
    ];
    let mut m11 = l1.inertia + l1.mass * (a1 * a1 + b1 * b1) + l1.armature;
    let (mut m12, mut m22, mut k) = (0.0, l2.armature, 0.0);
    let mut g1 = gravity * l1.mass * (a1 * c1 - b1 * s1);
    let mut g2 = 0.0;
    let mut v = gravity * l1.mass * (a1 * s1 + b1 * c1);
    for (m, inertia, x, y) in bodies {
        let s = l1.length + q[1] + x;
        m11 += inertia + m * (s * s + y * y);
        m12 -= m * y;
        m22 += m;
        k += m * s;
        g1 += gravity * m * (s * c1 - y * s1);
        g2 += gravity * m * s1;
        v += gravity * m * (s * s1 + y * c1);
    }
    let c = V2::new(2.0 * k * qd[0] * qd[1], -k * qd[0] * qd[0]);
    let f = V2::new(
        l1.damping * qd[0] + l1.frictionloss * coulomb(qd[0]),
        l2.damping * qd[1] + l2.frictionloss * coulomb(qd[1]),
    );
    (Matrix2::new(m11, m12, m12, m22), c, V2::new(g1, g2), f, v)
}

#[test]
fn polar_arm_matches_closed_form() {
    let mut rng = Rng(21);
    let mut worst = Worst::default();
    let tol = 1e-13;
    for case in 0..400 {
        let on_axis = case % 2 == 0;
        let mut model: Model<2> = rng.model();
        model.links[1].joint = Joint::Prismatic;
        if on_axis {
            model.links[1].com.y = 0.0;
        }
        model.payload = some_payload(&mut rng, on_axis);
        let q = V2::new(rng.uniform(-PI, PI), rng.uniform(-0.5, 1.0));
        let qd = rng.vector::<2>(3.0);
        let qdd = rng.vector::<2>(5.0);
        let (m, c, g, f, v) = polar_closed_form(&model, &q, &qd);
        let tau = m * qdd + c + g + f;
        worst.close(&mass_matrix(&model, &q), &m, tol, "M");
        worst.close(&coriolis(&model, &q, &qd), &c, tol, "c");
        worst.close(&gravity_torques(&model, &q), &g, tol, "g");
        worst.close(&friction(&model, &qd), &f, 0.0, "f");
        worst.close(&bias_forces(&model, &q, &qd), &(c + g + f), tol, "bias");
        worst.close(&inverse_dynamics(&model, &q, &qd, &qdd), &tau, tol, "tau");
        worst.close(&forward_dynamics(&model, &q, &qd, &tau), &qdd, 1e-11, "ABA");
        worst.close_f(
            kinetic_energy(&model, &q, &qd),
            0.5 * qd.dot(&(m * qd)),
            tol,
            "T",
        );
        worst.close_f(potential_energy(&model, &q), v, tol, "V");

        // The tip is `r u` with `r = l1 + q2 + l2`; joint 2 slides it along `u`.
        let [l1, l2] = model.links;
        let (s1, c1) = q[0].sin_cos();
        let r = l1.length + q[1] + l2.length;
        let tip = tip_position(&model, &q);
        worst.close(&tip.coords, &(V2::new(c1, s1) * r), tol, "tip");
        let jac = Matrix3x2::new(-r * s1, c1, r * c1, s1, 1.0, 0.0);
        worst.close(&jacobian(&model, &q), &jac, tol, "Jacobian");
        let joints = joint_positions(&model, &q);
        assert_eq!(joints[0], Point2::origin());
        worst.close(
            &joints[1].coords,
            &(V2::new(c1, s1) * (l1.length + q[1])),
            tol,
            "joint 2",
        );
        assert_eq!(tip_orientation(&model, &q), q[0]);
    }
    worst.print("polar_arm_matches_closed_form");
}

/// The polar arm of the crate's documentation: `tip = (0.2 + q2 + 0.5) (cos q1, sin q1)`.
#[test]
fn polar_arm_tip() {
    let model = Model::new(
        [
            Link::rod(0.2, 1.0),
            Link::rod(0.5, 1.0).with_joint(Joint::Prismatic),
        ],
        9.81,
    );
    for (q1, q2) in [(0.0, 0.0), (PI / 2.0, 0.3), (-2.0, -0.1), (3.0, 1.0)] {
        let tip = tip_position(&model, &V2::new(q1, q2));
        let expected = V2::new(q1.cos(), q1.sin()) * (0.2 + q2 + 0.5);
        assert_close(&tip.coords, &expected, 1e-15, "polar tip");
    }
    // Straight up, slid out 0.3 m: the tip 1 m above the base.
    let up = tip_position(&model, &V2::new(PI / 2.0, 0.3));
    assert_close(&up.coords, &V2::new(0.0, 1.0), 1e-15, "up");
}

/// A cart carrying a two-link arm (PRR), worked by hand: `(M, c, g, f, V)`.
///
/// Joint 1 slides link 1 along +x by `q1`; joints 2 and 3 turn links 2 and 3 about
/// `(q1 + l1, 0)` and the end of link 2. Link 1 only translates. Every body beyond moves with
/// `qd1 e_x` plus its velocity `v_k` in the same two-link arm on a fixed base, so
///
/// ```text
/// T = (m1 + m2 + m3 + A1) qd1^2 / 2 + qd1 dX/dt + T_2R(q2, q3, qd2, qd3)
/// X = m2 (a2 cos q2 - b2 sin q2) + m3 (l2 cos q2 + a3 cos q23 - b3 sin q23) = Q(q2) + P(q23)
/// ```
///
/// with `X = sum m_k x_k` the horizontal first moment of links 2 and 3 about the arm's base
/// and `sum m_k v_k.x = dX/dt`. So `M11 = m1 + m2 + m3 + A1`, `M1j = dX/dqj` (`j = 2, 3`):
///
/// ```text
/// dX/dq3 = P' = -m3 (a3 sin q23 + b3 cos q23)
/// dX/dq2 = Q' + P' = -m2 (a2 sin q2 + b2 cos q2) - m3 l2 sin q2 + P'
/// ```
///
/// and the lower block is the two-link arm's `M` ([`two_link_closed_form`]). Nothing depends
/// on `q1` and `M11` is constant, so the Christoffel symbols with a 1 are `G_1jk = d2X/dqj dqk`
/// (`j, k > 1`) and zero otherwise (`G_j1k = (d2X/dqj dqk - d2X/dqk dqj) / 2 = 0`): `Q` and `P`
/// are sinusoids with `Q'' = -Q`, `P'' = -P`, so
///
/// ```text
/// c1 = -Q qd2^2 - P (qd2 + qd3)^2        (the arm's horizontal centripetal forces)
/// ```
///
/// and `c2, c3` are the two-link arm's. The cart slides horizontally: `g1 = 0`, `g2, g3` are
/// the two-link arm's, and
/// `V = gravity [m1 b1 + m2 (a2 sin q2 + b2 cos q2) + m3 (l2 sin q2 + a3 sin q23 + b3 cos q23)]`.
fn cart_closed_form(
    model: &Model<3>,
    q: &Vector3<f64>,
    qd: &Vector3<f64>,
) -> (Matrix3<f64>, Vector3<f64>, Vector3<f64>, Vector3<f64>, f64) {
    let [l1, l2, l3] = model.links;
    let arm = Model::new([l2, l3], 0.0).with_gravity(model.gravity);
    let (m_arm, c_arm, g_arm, f_arm) =
        two_link_closed_form(&arm, &V2::new(q[1], q[2]), &V2::new(qd[1], qd[2]));
    let (a2, b2, a3, b3) = (l2.com.x, l2.com.y, l3.com.x, l3.com.y);
    let (s2, c2) = q[1].sin_cos();
    let (s23, c23) = (q[1] + q[2]).sin_cos();
    let big_q = l2.mass * (a2 * c2 - b2 * s2) + l3.mass * l2.length * c2;
    let big_p = l3.mass * (a3 * c23 - b3 * s23);
    let dp = -l3.mass * (a3 * s23 + b3 * c23);
    let dq = -l2.mass * (a2 * s2 + b2 * c2) - l3.mass * l2.length * s2;
    let m11 = l1.mass + l2.mass + l3.mass + l1.armature;
    let m = Matrix3::new(
        m11,
        dq + dp,
        dp,
        dq + dp,
        m_arm[(0, 0)],
        m_arm[(0, 1)],
        dp,
        m_arm[(1, 0)],
        m_arm[(1, 1)],
    );
    let w23 = qd[1] + qd[2];
    let c = Vector3::new(
        -big_q * qd[1] * qd[1] - big_p * w23 * w23,
        c_arm[0],
        c_arm[1],
    );
    let g = Vector3::new(0.0, g_arm[0], g_arm[1]);
    let f = Vector3::new(
        l1.damping * qd[0] + l1.frictionloss * coulomb(qd[0]),
        f_arm[0],
        f_arm[1],
    );
    let v = -model.gravity.y
        * (l1.mass * l1.com.y
            + l2.mass * (a2 * s2 + b2 * c2)
            + l3.mass * (l2.length * s2 + a3 * s23 + b3 * c23));
    (m, c, g, f, v)
}

#[test]
fn cart_with_two_link_arm_matches_closed_form() {
    let mut rng = Rng(22);
    let mut worst = Worst::default();
    let tol = 1e-13;
    for _ in 0..400 {
        let mut model: Model<3> = rng.model();
        model.links[0].joint = Joint::Prismatic;
        model.payload = Payload::NONE;
        let q = Vector3::new(
            rng.uniform(-0.5, 1.0),
            rng.uniform(-PI, PI),
            rng.uniform(-PI, PI),
        );
        let qd = rng.vector::<3>(3.0);
        let qdd = rng.vector::<3>(5.0);
        let (m, c, g, f, v) = cart_closed_form(&model, &q, &qd);
        let tau = m * qdd + c + g + f;
        worst.close(&mass_matrix(&model, &q), &m, tol, "M");
        worst.close(&coriolis(&model, &q, &qd), &c, tol, "c");
        worst.close(&gravity_torques(&model, &q), &g, tol, "g");
        worst.close(&friction(&model, &qd), &f, 0.0, "f");
        worst.close(&inverse_dynamics(&model, &q, &qd, &qdd), &tau, tol, "tau");
        worst.close(&forward_dynamics(&model, &q, &qd, &tau), &qdd, 1e-11, "ABA");
        worst.close_f(
            kinetic_energy(&model, &q, &qd),
            0.5 * qd.dot(&(m * qd)),
            tol,
            "T",
        );
        worst.close_f(potential_energy(&model, &q), v, tol, "V");

        // Kinematics: the arm's base at (q1 + l1, 0).
        let [l1, l2, l3] = model.links;
        let (s2, c2) = q[1].sin_cos();
        let (s23, c23) = (q[1] + q[2]).sin_cos();
        let base = V2::new(q[0] + l1.length, 0.0);
        let elbow = base + V2::new(c2, s2) * l2.length;
        let tip = elbow + V2::new(c23, s23) * l3.length;
        let joints = joint_positions(&model, &q);
        assert_eq!(joints[0], Point2::new(q[0], 0.0));
        worst.close(&joints[1].coords, &base, tol, "joint 2");
        worst.close(&joints[2].coords, &elbow, tol, "joint 3");
        worst.close(&tip_position(&model, &q).coords, &tip, tol, "tip");
        let (r2, r3) = (tip - base, tip - elbow);
        let jac = Matrix3::new(1.0, -r2.y, -r3.y, 0.0, r2.x, r3.x, 0.0, 1.0, 1.0);
        worst.close(&jacobian(&model, &q), &jac, tol, "Jacobian");
        assert_eq!(tip_orientation(&model, &q), q[1] + q[2]);
    }
    worst.print("cart_with_two_link_arm_matches_closed_form");
}

/// A single slider along +x carrying a payload: it never turns, so neither its inertia nor
/// the centres' offsets reach the dynamics. `T = (m + m_p + A) qd^2 / 2`,
/// `V = gravity (m b + m_p p_y)` is constant (`b`, `p_y` the centres' heights), hence
/// `M = m + m_p + A`, `c = g = 0` and `tau = M qdd + damping qd + frictionloss sign(qd)`.
/// The tip is `(q + l, 0)`, moved at `(1, 0)` per unit `qd`, not turned.
#[test]
fn single_slider_matches_closed_form() {
    let mut rng = Rng(23);
    let mut worst = Worst::default();
    for case in 0..200 {
        let mut model: Model<1> = rng.model();
        model.links[0].joint = Joint::Prismatic;
        model.payload = some_payload(&mut rng, case % 2 == 0);
        let [link] = model.links;
        let p = model.payload;
        let inertia = link.mass + p.mass + link.armature;
        let q = Vector1::new(rng.uniform(-0.5, 1.0));
        let qd = rng.vector::<1>(3.0);
        let qdd = rng.vector::<1>(5.0);
        let f = link.damping * qd[0] + link.frictionloss * coulomb(qd[0]);
        let tau = Vector1::new(inertia * qdd[0] + f);
        let tol = 1e-14;
        worst.close(&mass_matrix(&model, &q), &Matrix1::new(inertia), tol, "M");
        worst.close(&coriolis(&model, &q, &qd), &Vector1::zeros(), tol, "c");
        worst.close(&gravity_torques(&model, &q), &Vector1::zeros(), tol, "g");
        worst.close(&inverse_dynamics(&model, &q, &qd, &qdd), &tau, tol, "tau");
        worst.close(&forward_dynamics(&model, &q, &qd, &tau), &qdd, tol, "ABA");
        worst.close(
            &forward_dynamics_crba(&model, &q, &qd, &tau),
            &qdd,
            tol,
            "CRBA",
        );
        worst.close_f(
            kinetic_energy(&model, &q, &qd),
            0.5 * inertia * qd[0] * qd[0],
            tol,
            "T",
        );
        worst.close_f(
            potential_energy(&model, &q),
            -model.gravity.y * (link.mass * link.com.y + p.mass * p.com.y),
            tol,
            "V",
        );
        let tip = tip_position(&model, &q);
        worst.close(&tip.coords, &V2::new(q[0] + link.length, 0.0), tol, "tip");
        assert_eq!(jacobian(&model, &q), Vector3::new(1.0, 0.0, 0.0));
        assert_eq!(joint_positions(&model, &q), [Point2::new(q[0], 0.0)]);
        assert_eq!(tip_orientation(&model, &q), 0.0);
    }
    worst.print("single_slider_matches_closed_form");
}
