//! Revolute arms against closed forms worked out by hand.

use super::*;

use nalgebra::Matrix2;

#[test]
fn pendulum_by_hand() {
    let link = Link {
        length: 1.3,
        mass: 2.1,
        inertia: 0.37,
        com: V2::new(0.55, -0.2),
        armature: 0.05,
        damping: 0.3,
        frictionloss: 0.4,
        stiffness: 0.0,
        springref: 0.0,
        joint: crate::Joint::Revolute,
        range: None,
        offset: 0.0,
        reversed: false,
    };
    let model = Model::new([link], 9.81);
    let (cx, cy) = (0.55, -0.2);
    let mut rng = Rng(1);
    for _ in 0..50 {
        let q = rng.uniform(-4.0, 4.0);
        let qd = rng.uniform(-5.0, 5.0);
        let qdd = rng.uniform(-5.0, 5.0);
        // Joint inertia by the parallel-axis theorem, plus the armature; the centre of mass
        // is at angle q + atan2(cy, cx), so its height is cx sin q + cy cos q and the
        // gravity torque m g (cx cos q - cy sin q).
        let inertia = 0.37 + 2.1 * (cx * cx + cy * cy) + 0.05;
        let gravity = 2.1 * 9.81 * (cx * q.cos() - cy * q.sin());
        let friction = 0.3 * qd + 0.4 * qd.signum();
        let expected = inertia * qdd + gravity + friction;
        let (q, qd, qdd) = (
            SVector::from([q]),
            SVector::from([qd]),
            SVector::from([qdd]),
        );
        assert_close_f(
            inverse_dynamics(&model, &q, &qd, &qdd)[0],
            expected,
            1e-13,
            "pendulum tau",
        );
        assert_close_f(mass_matrix(&model, &q)[(0, 0)], inertia, 1e-15, "M");
        assert_close_f(gravity_torques(&model, &q)[0], gravity, 1e-13, "g");
        assert_close_f(coriolis(&model, &q, &qd)[0], 0.0, 1e-13, "c");
        assert_close_f(
            potential_energy(&model, &q),
            2.1 * 9.81 * (cx * q[0].sin() + cy * q[0].cos()),
            1e-13,
            "V",
        );
    }
}

/// The textbook closed form of the general two-link arm, with the centres of mass off the
/// links' axes (`c2 = (a, b)` in link 2's frame), armature and friction.
pub(super) fn two_link_closed_form(
    model: &Model<2>,
    q: &V2<f64>,
    qd: &V2<f64>,
) -> (Matrix2<f64>, V2<f64>, V2<f64>, V2<f64>) {
    let [l1, l2] = model.links;
    let (m1, m2, len1, c1, c2) = (l1.mass, l2.mass, l1.length, l1.com, l2.com);
    let (a, b) = (c2.x, c2.y);
    // The closed form is written for gravity along -y.
    assert_eq!(model.gravity.x, 0.0);
    let g = -model.gravity.y;
    let (s2, cos2) = q[1].sin_cos();
    // Link 2's centre seen from joint 1 is `len1 e_x + R(q2) c2`: its dot product with
    // `len1 e_x` is `len1 (a cos q2 - b sin q2)`.
    let p = len1 * (a * cos2 - b * s2);
    let m22 = l2.inertia + m2 * c2.norm_squared();
    let m11 = l1.inertia + m1 * c1.norm_squared() + m22 + m2 * (len1 * len1 + 2.0 * p);
    let m12 = m22 + m2 * p;
    // h = -dM12/dq2 = m2 len1 (a sin q2 + b cos q2).
    let h = m2 * len1 * (a * s2 + b * cos2);
    let c = V2::new(
        -h * qd[1] * qd[1] - 2.0 * h * qd[0] * qd[1],
        h * qd[0] * qd[0],
    );
    let (s1, cos1) = q[0].sin_cos();
    let (s12, cos12) = (q[0] + q[1]).sin_cos();
    let grav2 = g * m2 * (a * cos12 - b * s12);
    let grav = V2::new(
        g * m1 * (c1.x * cos1 - c1.y * s1) + g * m2 * len1 * cos1 + grav2,
        grav2,
    );
    let sign = |x: f64| if x == 0.0 { 0.0 } else { x.signum() };
    let f = V2::new(
        l1.damping * qd[0] + l1.frictionloss * sign(qd[0]),
        l2.damping * qd[1] + l2.frictionloss * sign(qd[1]),
    );
    let m = Matrix2::new(m11 + l1.armature, m12, m12, m22 + l2.armature);
    (m, c, grav, f)
}

#[test]
fn two_link_matches_closed_form() {
    let mut rng = Rng(2);
    for _ in 0..200 {
        let model = Model::new(rng.links::<2>(), rng.uniform(0.0, 15.0));
        let q = rng.vector::<2>(4.0);
        let qd = rng.vector::<2>(5.0);
        let qdd = rng.vector::<2>(5.0);
        let (m, c, grav, f) = two_link_closed_form(&model, &q, &qd);
        assert_close(&mass_matrix(&model, &q), &m, 1e-13, "M");
        assert_close(&coriolis(&model, &q, &qd), &c, 1e-13, "c");
        assert_close(&gravity_torques(&model, &q), &grav, 1e-13, "g");
        assert_close(&friction(&model, &qd), &f, 1e-15, "f");
        assert_close(
            &bias_forces(&model, &q, &qd),
            &(c + grav + f),
            1e-13,
            "c + g + f",
        );
        assert_close(
            &inverse_dynamics(&model, &q, &qd, &qdd),
            &(m * qdd + c + grav + f),
            1e-13,
            "tau",
        );
    }
}

#[test]
fn paper_equal_rods_mass_matrix() {
    let model = Model::new([Link::rod(1.0, 1.0); 2], 9.81);
    for q2 in [0.0_f64, 0.4, 1.0, -2.5, 3.0] {
        let q = SVector::from([0.7, q2]);
        let c = q2.cos();
        let expected = Matrix2::new(
            5.0 / 3.0 + c,
            1.0 / 3.0 + c / 2.0,
            1.0 / 3.0 + c / 2.0,
            1.0 / 3.0,
        );
        assert_close(&mass_matrix(&model, &q), &expected, 1e-15, "paper M");
    }
}

#[test]
fn kinematics_by_hand() {
    let model = Model::new(
        [
            Link::rod(1.0, 1.0),
            Link::rod(2.0, 1.0),
            Link::rod(0.5, 1.0),
        ],
        9.81,
    );
    let q = SVector::from([
        std::f64::consts::FRAC_PI_2,
        -std::f64::consts::FRAC_PI_2,
        0.0,
    ]);
    let joints = joint_positions(&model, &q);
    assert_close(&joints[1].coords, &V2::new(0.0, 1.0), 1e-15, "joint 2");
    assert_close(&joints[2].coords, &V2::new(2.0, 1.0), 1e-15, "joint 3");
    assert_close(
        &tip_position(&model, &q).coords,
        &V2::new(2.5, 1.0),
        1e-15,
        "tip",
    );
    assert_close_f(tip_angle(&q), 0.0, 0.0, "tip angle");
    // Joint 3 rotates only the last link: tip velocity perp((0.5, 0)) = (0, 0.5).
    let jac = jacobian(&model, &q);
    assert_close(
        &jac.column(2).into_owned(),
        &Vector3::new(0.0, 0.5, 1.0),
        1e-15,
        "J col 3",
    );
    assert_close(
        &jac.column(0).into_owned(),
        &Vector3::new(-1.0, 2.5, 1.0),
        1e-15,
        "J col 1",
    );
}

#[test]
fn energies_by_hand() {
    // A single rod spinning about its joint at rate w, held horizontal then raised.
    let rod = Model::new([Link::rod(2.0, 3.0)], 9.81);
    let w = 1.5;
    let joint_inertia = 3.0 * 4.0 / 3.0;
    let (flat, up) = (
        SVector::from([0.3]),
        SVector::from([std::f64::consts::FRAC_PI_2]),
    );
    assert_close_f(
        kinetic_energy(&rod, &flat, &SVector::from([w])),
        0.5 * joint_inertia * w * w,
        1e-15,
        "rod T",
    );
    assert_close_f(potential_energy(&rod, &up), 9.81 * 3.0, 1e-15, "rod V");
    // With a rotor of armature 0.5, a 2 kg point at the tip (2 m from the joint) and the
    // centre of mass moved 1 m to the rod's right: (1, 1) when the rod points up.
    let geared = Model::new(
        [Link::rod(2.0, 3.0).with_com(1.0, -1.0).with_armature(0.5)],
        9.81,
    )
    .with_payload(Payload::point(2.0));
    assert_close_f(
        kinetic_energy(&geared, &flat, &SVector::from([w])),
        0.5 * (1.0 + 3.0 * 2.0 + 0.5 + 2.0 * 4.0) * w * w,
        1e-15,
        "geared T",
    );
    assert_close_f(
        potential_energy(&geared, &up),
        9.81 * (3.0 * (1.0 + 0.0) + 2.0 * 2.0),
        1e-15,
        "geared V",
    );
}
