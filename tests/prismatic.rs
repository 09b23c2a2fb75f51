//! Arms with prismatic joints, derived at compile time: against closed forms worked out by hand
//! in this file (the polar arm of the issue, the cart-pole), the numeric reference for mixed
//! chains of 1 to 8 links (with run-time parameters, friction and payloads), conservation of
//! energy, the statics, the derivatives and the identification regressors.

mod common;

use common::{check_state, Rng};
use planar_arm::nalgebra::{SMatrix, SVector, Vector2, Vector3};
use planar_arm::prelude::*;
use planar_arm::reference;
use planar_arm::sim::{Integrator, Rk4};

/// The polar arm of the issue, with its boom's centre of mass off the axis, a slide with a
/// reflected rotor mass and friction, and a payload held off the boom's end.
#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.81, payload = 0.4, payload_com = (0.05, 0.02), payload_inertia = 0.001)]
struct Polar {
    #[arm(length = 0.2, mass = 3, inertia = 0.02, com = (0.1, 0.01))]
    turret: Revolute,
    #[arm(length = 0.5, mass = 1.5, inertia = 0.03, com = (0.25, 0.03), armature = 0.2,
          damping = 0.5, frictionloss = 0.1, range = (0, 0.6))]
    boom: Prismatic,
}

/// `tau = M qdd + c + g + f` of [`Polar`] worked out by hand. With `u = (cos q1, sin q1)` and
/// `perp(u) = (-sin q1, cos q1)`, a body on the boom sits at `r u + e perp(u)`, `r` its
/// distance along the boom's axis from the turret's axis (`l1 + q2 + cx`), `e` its offset
/// across it. Its velocity is `(qd2 - e qd1) u + r qd1 perp(u)`, so it adds
/// `m ((qd2 - e qd1)^2 + r^2 qd1^2) / 2 + I qd1^2 / 2` to T and `g m (r sin q1 + e cos q1)`
/// to V. Hence `M11 = I1 + m1 |c1|^2 + sum (I + m (r^2 + e^2))`, `M12 = -sum m e`,
/// `M22 = sum m + armature`; M depends on q2 alone through `r`, `dM11/dq2 = 2 sum m r`, so
/// `c = (2 sum m r qd1 qd2, -sum m r qd1^2)`; `g1 = g (m1 (c1x cos q1 - c1y sin q1) + sum m (r
/// cos q1 - e sin q1))`, `g2 = g sum m sin q1`; and the slide's friction `0.5 qd2 + 0.1
/// sign(qd2)`.
fn polar_by_hand(q: &Vector2<f64>, qd: &Vector2<f64>, qdd: &Vector2<f64>) -> Vector2<f64> {
    let (g, l1, l2) = (9.81, 0.2, 0.5);
    let (m1, i1, c1x, c1y) = (3.0, 0.02, 0.1, 0.01);
    // (mass, inertia, r, e) of the boom and the payload.
    let bodies = [
        (1.5, 0.03, l1 + q[1] + 0.25, 0.03),
        (0.4, 0.001, l1 + q[1] + l2 + 0.05, 0.02),
    ];
    let (s1, c1) = q[0].sin_cos();
    let mut m11 = i1 + m1 * (c1x * c1x + c1y * c1y);
    let (mut m12, mut m22, mut mr) = (0.0, 0.2, 0.0);
    let mut g1 = g * m1 * (c1x * c1 - c1y * s1);
    let mut mass = 0.0;
    for (m, i, r, e) in bodies {
        m11 += i + m * (r * r + e * e);
        m12 -= m * e;
        m22 += m;
        mr += m * r;
        g1 += g * m * (r * c1 - e * s1);
        mass += m;
    }
    let g2 = g * mass * s1;
    let friction = 0.5 * qd[1] + 0.1 * qd[1].signum();
    Vector2::new(
        m11 * qdd[0] + m12 * qdd[1] + 2.0 * mr * qd[0] * qd[1] + g1,
        m12 * qdd[0] + m22 * qdd[1] - mr * qd[0] * qd[0] + g2 + friction,
    )
}

/// The textbook cart-pole: a point cart sliding along x, a pole hinged on it (its angle from
/// +x). The cart has no length, no inertia and its mass at its joint: it only slides.
#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.81)]
struct CartPole {
    #[arm(length = 0, mass = 2)]
    cart: Prismatic,
    #[arm(length = 0.6, mass = 0.3, inertia = 0.009, com = (0.3, 0))]
    pole: Revolute,
}

/// The cart-pole by hand: the pole's centre is at `(q1 + c cos q2, c sin q2)`, so
/// `M = [[mc + mp, -mp c sin q2], [-mp c sin q2, Ip + mp c^2]]`, `c = (-mp c cos q2 qd2^2, 0)`,
/// `g = (0, g mp c cos q2)`: the cart's height never changes.
fn cart_pole_by_hand(q: &Vector2<f64>, qd: &Vector2<f64>, qdd: &Vector2<f64>) -> Vector2<f64> {
    let (g, mc, mp, ip, c) = (9.81, 2.0, 0.3, 0.009, 0.3);
    let (s2, c2) = q[1].sin_cos();
    let m = SMatrix::<f64, 2, 2>::new(mc + mp, -mp * c * s2, -mp * c * s2, ip + mp * c * c);
    m * qdd + Vector2::new(-mp * c * c2 * qd[1] * qd[1], g * mp * c * c2)
}

#[test]
fn the_polar_arm_and_the_cart_pole_match_their_closed_forms() {
    let (polar, cart) = (Polar::default(), CartPole::default());
    let mut rng = Rng(7);
    for _ in 0..200 {
        let (q, qd, qdd) = (rng.vector(2.0), rng.vector(3.0), rng.vector(5.0));
        for (got, want) in [
            (
                polar.inverse_dynamics(&q, &qd, &qdd),
                polar_by_hand(&q, &qd, &qdd),
            ),
            (
                cart.inverse_dynamics(&q, &qd, &qdd),
                cart_pole_by_hand(&q, &qd, &qdd),
            ),
        ] {
            assert!(
                (got - want).amax() <= 1e-12 * (1.0 + want.amax()),
                "{got} vs {want}"
            );
        }
        // The tip of the polar arm: (l1 + q2 + l2) u.
        let tip = polar.tip_pose(&q);
        let reach = 0.2 + q[1] + 0.5;
        let (s1, c1) = q[0].sin_cos();
        assert!((tip.translation.vector - Vector2::new(reach * c1, reach * s1)).amax() < 1e-12);
        assert!((tip.rotation.angle() - q[0].sin().atan2(q[0].cos())).abs() < 1e-12);
        let (r, theta) = polar.tip_polar(&q);
        assert!((r - reach.abs()).abs() < 1e-12);
        assert!((theta.sin_cos().0 * reach.signum() - s1).abs() < 1e-9);
    }
    // The joint kinds and the range reach the model.
    let links = polar.links();
    assert_eq!(
        (links[0].joint, links[1].joint),
        (Joint::Revolute, Joint::Prismatic)
    );
    assert_eq!((links[0].range, links[1].range), (None, Some((0.0, 0.6))));
}

/// Eight literal arms mixing the kinds, checked by the shared checks against the reference.
#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.81)]
struct Slide1 {
    #[arm(length = 0.4, mass = 1.3, com = (0.1, 0.05), armature = 0.1, damping = 0.2)]
    a: Prismatic,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.81, payload = 0.5)]
struct Mixed3 {
    #[arm(length = 0.3, mass = 2, damping = 0.4)]
    a: Prismatic,
    #[arm(length = 0.4, mass = 1, com = (0.15, -0.02), frictionloss = 0.2)]
    b: Revolute,
    #[arm(length = 0.3, mass = 0.5, inertia = 0.01)]
    c: Prismatic,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 1.625)]
struct Mixed4 {
    #[arm(length = 3/4, mass = 19/4)]
    a: Revolute,
    #[arm(length = 5/3, mass = 9/8, inertia = 28/36, com = 2/2)]
    b: Prismatic,
    #[arm(length = 13/4, mass = 4.89, inertia = 49/22, com = (1.3, 0.2), armature = 0.3)]
    c: Prismatic,
    #[arm(length = 1, mass = 7.83, com = -10/4)]
    d: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.81, payload = 0.3, payload_com = (0.1, 0))]
struct Mixed6 {
    #[arm(length = 0.5, mass = 4)]
    a: Revolute,
    #[arm(length = 0.5, mass = 3, damping = 1)]
    b: Prismatic,
    #[arm(length = 0.4, mass = 2, com = (0.2, 0.05))]
    c: Revolute,
    #[arm(length = 0.4, mass = 1.5)]
    d: Revolute,
    #[arm(length = 0.3, mass = 1, frictionloss = 0.3)]
    e: Prismatic,
    #[arm(length = 0.2, mass = 0.5, inertia = 0.004)]
    f: Revolute,
}

#[derive(PlanarArm, Default, Debug)]
#[arm(gravity = 9.81)]
struct Mixed8 {
    #[arm(length = 0.5, mass = 2)]
    a: Prismatic,
    #[arm(length = 0.5, mass = 2)]
    b: Revolute,
    #[arm(length = 0.4, mass = 1.5, com = (0.2, 0.1))]
    c: Prismatic,
    #[arm(length = 0.4, mass = 1.5)]
    d: Revolute,
    #[arm(length = 0.3, mass = 1)]
    e: Revolute,
    #[arm(length = 0.3, mass = 1, armature = 0.1)]
    f: Prismatic,
    #[arm(length = 0.2, mass = 0.5)]
    g: Revolute,
    #[arm(length = 0.2, mass = 0.5, damping = 0.1)]
    h: Revolute,
}

planar_arm_tests_check_arms! {
    slide1: Slide1, 1;
    polar: Polar, 2;
    cart_pole: CartPole, 2;
    mixed3: Mixed3, 3;
    mixed4: Mixed4, 4;
    mixed6: Mixed6, 6;
    mixed8: Mixed8, 8;
}

/// A slider carrying two links, with run-time carriage mass, centre of mass, damping and
/// payload: the parameters enter the same exact derivation.
#[derive(PlanarArm, Clone, Debug)]
#[arm(gravity = 9.81, payload = self.load)]
struct Gantry {
    #[arm(length = 0.1, mass = self.carriage, inertia = 0, com = 0, damping = self.rail_damping,
          range = (-1, 1))]
    rail: Prismatic,
    #[arm(length = 0.4, mass = 1, com = (self.c2, 0.01), frictionloss = 0.2)]
    upper: Revolute,
    #[arm(length = 0.3, mass = 0.5)]
    fore: Revolute,
    carriage: f64,
    rail_damping: f64,
    c2: f64,
    load: f64,
}

fn gantry(rng: &mut Rng) -> Gantry {
    Gantry {
        rail: Prismatic,
        upper: Revolute,
        fore: Revolute,
        carriage: rng.range(1.0, 6.0),
        rail_damping: rng.range(0.0, 3.0),
        c2: rng.range(0.05, 0.35),
        load: rng.range(0.0, 1.0),
    }
}

#[test]
fn run_time_parameters_of_a_mixed_arm_against_the_reference() {
    let mut rng = Rng(11);
    for _ in 0..40 {
        let arm = gantry(&mut rng);
        let (q, qd, qdd) = (rng.vector(1.5), rng.vector(3.0), rng.vector(5.0));
        check_state(&arm, &q, &qd, &qdd);
    }
}

#[test]
fn a_free_polar_arm_conserves_energy_under_rk4() {
    #[derive(PlanarArm, Default)]
    #[arm(gravity = 9.81, payload = 0.4)]
    struct Free {
        #[arm(length = 0.2, mass = 3, com = (0.1, 0.01))]
        turret: Revolute,
        #[arm(length = 0.5, mass = 1.5, com = (0.25, 0.03), armature = 0.2)]
        boom: Prismatic,
    }
    let arm = Free::default();
    let energy =
        |q: &Vector2<f64>, qd: &Vector2<f64>| arm.kinetic_energy(q, qd) + arm.potential_energy(q);
    let (mut q, mut qd) = (Vector2::new(0.4, 0.1), Vector2::new(1.5, 0.8));
    let start = energy(&q, &qd);
    let mut drift: f64 = 0.0;
    for _ in 0..5000 {
        (q, qd) = Rk4
            .step(&arm, &q, &qd, &Vector2::zeros(), 1e-3)
            .expect("finite");
        drift = drift.max((energy(&q, &qd) - start).abs());
    }
    // The boom swings out and back: a real exchange of energy, not a resting arm.
    assert!(q[1].abs() > 0.2 || qd[1].abs() > 0.5, "{q} {qd}");
    assert!(
        drift <= 1e-9 * start.abs().max(1.0),
        "energy drift {drift:e} of {start}"
    );
}

#[test]
fn the_statics_of_mixed_arms_invert_the_jacobian() {
    let mut rng = Rng(3);
    let (polar, cart, arm) = (Polar::default(), CartPole::default(), gantry(&mut rng));
    for _ in 0..100 {
        let q: Vector2<f64> = rng.vector(1.5);
        let force: Vector2<f64> = rng.vector(10.0);
        for (name, j, got) in [
            ("polar", polar.jacobian(&q), &polar as &dyn TipForce),
            ("cart-pole", cart.jacobian(&q), &cart as &dyn TipForce),
        ] {
            let jp = j.fixed_rows::<2>(0).into_owned();
            let tau = jp.transpose() * force;
            let back = got.tip_force(&q, &tau).expect("regular");
            assert!(
                (back - force).amax() <= 1e-10 * force.amax(),
                "{name}: {back} vs {force}"
            );
        }
        let q3: Vector3<f64> = rng.vector(1.5);
        let wrench: Vector3<f64> = rng.vector(10.0);
        let tau = arm.jacobian(&q3).transpose() * wrench;
        match arm.tip_wrench(&q3, &tau) {
            Ok(w) => {
                let (f, t) = (w.force, w.torque);
                assert!((Vector3::new(f.x, f.y, t) - wrench).amax() <= 1e-8 * wrench.amax());
            }
            // Only where the two revolute links line up (sin q3 = 0).
            Err(ArmError::Singular { .. }) => assert!(q3[2].sin().abs() < 1e-6, "{q3}"),
            Err(e) => panic!("{e}"),
        }
    }
    // The polar arm's tip on the turret's axis: no joint force can push it sideways.
    let on_axis = Vector2::new(0.3, -0.7);
    assert!(matches!(
        polar.tip_force(&on_axis, &Vector2::new(1.0, 0.0)),
        Err(ArmError::Singular { .. })
    ));
    assert!(matches!(
        polar.tip_force(&Vector2::new(f64::NAN, 0.0), &Vector2::zeros()),
        Err(ArmError::NonFinite { .. })
    ));
}

/// Central differences of `f` along each coordinate of `x`.
fn central<const N: usize>(
    f: impl Fn(&SVector<f64, N>) -> SVector<f64, N>,
    x: &SVector<f64, N>,
) -> SMatrix<f64, N, N> {
    let h = 1e-6;
    let mut d = SMatrix::<f64, N, N>::zeros();
    for k in 0..N {
        let mut e = SVector::<f64, N>::zeros();
        e[k] = h;
        d.set_column(k, &((f(&(x + e)) - f(&(x - e))) / (2.0 * h)));
    }
    d
}

fn check_derivatives<A: PlanarArm<N>, const N: usize>(arm: &A, rng: &mut Rng) {
    let model = arm.model();
    for _ in 0..20 {
        // Rates away from zero: Coulomb friction's jump is not differentiable.
        let q: SVector<f64, N> = rng.vector(1.5);
        let qd = rng
            .vector::<N>(3.0)
            .map(|x| if x.abs() < 0.1 { 0.5 } else { x });
        let qdd = rng.vector(5.0);
        let (dq, dqd) = arm.inverse_dynamics_derivatives(&q, &qd, &qdd);
        let id = |q: &SVector<f64, N>, qd: &SVector<f64, N>| {
            reference::inverse_dynamics(&model, q, qd, &qdd)
        };
        let (fq, fqd) = (central(|x| id(x, &qd), &q), central(|x| id(&q, x), &qd));
        let scale = 1.0 + fq.amax() + fqd.amax();
        assert!((dq - fq).amax() <= 1e-6 * scale, "dtau/dq {dq} vs {fq}");
        assert!(
            (dqd - fqd).amax() <= 1e-6 * scale,
            "dtau/dqd {dqd} vs {fqd}"
        );
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let (aq, aqd, atau) = arm.forward_dynamics_derivatives(&q, &qd, &tau);
        let fd = |q: &SVector<f64, N>, qd: &SVector<f64, N>, tau: &SVector<f64, N>| {
            reference::forward_dynamics(&model, q, qd, tau)
        };
        let (gq, gqd, gtau) = (
            central(|x| fd(x, &qd, &tau), &q),
            central(|x| fd(&q, x, &tau), &qd),
            central(|x| fd(&q, &qd, x), &tau),
        );
        let scale = 1.0 + gq.amax() + gqd.amax() + gtau.amax();
        for (got, want, what) in [
            (aq, gq, "dqdd/dq"),
            (aqd, gqd, "dqdd/dqd"),
            (atau, gtau, "dqdd/dtau"),
        ] {
            assert!(
                (got - want).amax() <= 1e-5 * scale,
                "{what}: {got} vs {want}"
            );
        }
    }
}

#[test]
fn derivatives_of_mixed_arms_match_central_differences_of_the_reference() {
    let mut rng = Rng(5);
    check_derivatives(&Polar::default(), &mut rng);
    check_derivatives(&CartPole::default(), &mut rng);
    check_derivatives(&gantry(&mut rng), &mut rng);
    check_derivatives(&Mixed6::default(), &mut rng);
    check_derivatives(&Mixed8::default(), &mut rng);
}

fn check_identification<A, const N: usize, const P: usize, const B: usize>(arm: &A, rng: &mut Rng)
where
    A: Identification<N, P, B> + PlanarArm<N>,
{
    let (theta, base) = (arm.standard_parameters(), arm.base_parameters());
    for _ in 0..30 {
        let (q, qd, qdd) = (
            rng.vector::<N>(1.5),
            rng.vector::<N>(3.0),
            rng.vector::<N>(5.0),
        );
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let scale = 1.0 + tau.amax();
        assert!((arm.regressor(&q, &qd, &qdd) * theta - tau).amax() <= 1e-12 * scale);
        assert!((arm.base_regressor(&q, &qd, &qdd) * base - tau).amax() <= 1e-12 * scale);
        let numeric = reference::regressor(&arm.model(), &q, &qd, &qdd);
        let y = arm.regressor(&q, &qd, &qdd);
        for (k, name) in A::PARAMETERS.iter().enumerate() {
            let col = numeric.column(name).expect("a standard parameter's name");
            let d = (y.column(k) - col).amax();
            assert!(d <= 1e-12 * (1.0 + col.amax()), "column {name}: {d:e}");
        }
    }
    assert!(B < P);
}

#[test]
fn identification_of_mixed_arms() {
    let mut rng = Rng(9);
    check_identification(&Polar::default(), &mut rng);
    check_identification(&CartPole::default(), &mut rng);
    check_identification(&Mixed4::default(), &mut rng);
    check_identification(&gantry(&mut rng), &mut rng);
    // The polar arm by hand: with the boom and payload one body on link 2 (mass m, first
    // moment h about its frame origin, inertia J there), L has the terms qd1^2 (zz1 + J + m l1^2
    // + 2 hx l1) / 2, qd1^2 q2 (m l1 + hx), qd1^2 q2^2 m / 2, qd2^2 (m + ia2) / 2, -hy qd1 qd2,
    // and g sin q1 (mx1 + m l1 + hx), g q2 sin q1 m, g cos q1 (my1 + hy); m1 never moves. So
    // seven inertial combinations are identifiable, plus the slide's two friction values, out
    // of 15 standard parameters.
    let names = <Polar as Identification<2, 15, 9>>::BASE_PARAMETERS;
    assert_eq!(names.len(), 9, "{names:?}");
    assert!(names.iter().all(|b| !b.contains("m1")), "{names:?}");
}

#[test]
fn f32_evaluates_mixed_arms_within_its_precision() {
    let mut rng = Rng(13);
    let arm = Mixed6::default();
    for _ in 0..50 {
        let (q, qd, qdd) = (
            rng.vector::<6>(1.5),
            rng.vector::<6>(2.0),
            rng.vector::<6>(3.0),
        );
        let tau = arm.inverse_dynamics(&q, &qd, &qdd);
        let single = arm.inverse_dynamics(&q.cast::<f32>(), &qd.cast::<f32>(), &qdd.cast::<f32>());
        let scale =
            arm.mass_matrix(&q).amax() * (1.0 + qd.amax().powi(2) + qdd.amax()) + tau.amax();
        let err = (single.cast::<f64>() - tau).amax();
        assert!(
            err <= 64.0 * f64::from(f32::EPSILON) * scale,
            "{err:e} of {scale}"
        );
    }
}

/// The generated closed-form inverse kinematics: every branch reaches the target (by the
/// generated forward kinematics) and lies within the ranges; out-of-range targets are refused.
#[test]
fn closed_form_inverse_kinematics_of_mixed_arms() {
    let mut rng = Rng(17);
    let (polar, cart) = (Polar::default(), CartPole::default());
    let arm = gantry(&mut rng);
    let within = |links: &[Link], q: &[f64]| {
        links.iter().zip(q).all(|(l, &x)| {
            l.range.is_none_or(|(lo, hi)| {
                let tol = 1e-12 * (1.0 + x.abs());
                (lo - tol..=hi + tol).contains(&x)
            })
        })
    };
    let (mut polar_hits, mut gantry_hits) = (0, 0);
    for _ in 0..2000 {
        // Polar: any configuration within the ranges gives a reachable target.
        let q = Vector2::new(rng.range(-3.0, 3.0), rng.range(0.0, 0.6));
        let tip = Point2::from(polar.tip_pose(&q).translation.vector);
        for sol in polar.inverse_kinematics(&tip).expect("reachable") {
            let back = polar.tip_pose(&sol).translation.vector;
            assert!(
                (back - tip.coords).amax() < 1e-12,
                "{sol} -> {back} vs {tip}"
            );
            assert!(within(&polar.links(), sol.as_slice()), "{sol}");
        }
        polar_hits += 1;
        // The cart-pole has no ranges: both branches.
        let q = Vector2::new(rng.range(-2.0, 2.0), rng.range(-3.0, 3.0));
        let tip = Point2::from(cart.tip_pose(&q).translation.vector);
        let [a, b] = cart.inverse_kinematics(&tip).expect("reachable");
        for sol in [a, b] {
            let back = cart.tip_pose(&sol).translation.vector;
            assert!((back - tip.coords).amax() < 1e-12);
        }
        // The gantry, for a pose.
        let q3 = Vector3::new(
            rng.range(-1.0, 1.0),
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
        );
        let pose = arm.tip_pose(&q3);
        for sol in arm.inverse_kinematics(&pose).expect("reachable") {
            let back = arm.tip_pose(&sol);
            assert!((back.translation.vector - pose.translation.vector).amax() < 1e-11);
            assert!((back.rotation.angle() - pose.rotation.angle()).sin().abs() < 1e-11);
            assert!(within(&arm.links(), sol.as_slice()), "{sol}");
        }
        gantry_hits += 1;
    }
    assert_eq!((polar_hits, gantry_hits), (2000, 2000));
    // Beyond the boom's travel (reach 0.7 to 1.3 m) and on the wrong side of its range.
    for target in [Point2::new(1.5, 0.0), Point2::new(0.3, 0.2)] {
        assert!(matches!(
            polar.inverse_kinematics(&target),
            Err(ArmError::BeyondJointRange {
                joint: 1,
                kind: Joint::Prismatic,
                ..
            })
        ));
    }
    assert!(matches!(
        polar.inverse_kinematics(&Point2::new(f64::NAN, 0.0)),
        Err(ArmError::NonFinite { .. })
    ));
    // The work-space agrees: an annulus 0.7 ..= 1.3 about the base.
    let w = polar.workspace();
    assert!(
        w.is_exact() && w.contains(&Point2::new(0.0, 1.0)) && !w.contains(&Point2::new(0.3, 0.2))
    );
    let area = std::f64::consts::PI * (1.3f64.powi(2) - 0.7f64.powi(2));
    assert!((w.area() - area).abs() < 1e-12, "{} vs {area}", w.area());
}

/// Numeric inverse kinematics keeps a slide within its range.
#[test]
fn numeric_inverse_kinematics_respects_the_ranges() {
    let mut rng = Rng(19);
    let polar = Polar::default();
    for _ in 0..200 {
        let q = Vector2::new(rng.range(-3.0, 3.0), rng.range(0.0, 0.6));
        let target = IkTarget::Position(Point2::from(polar.tip_pose(&q).translation.vector));
        let seed = Vector2::new(rng.range(-3.0, 3.0), rng.range(0.0, 0.6));
        let sol = polar
            .inverse_kinematics_near(&target, &seed, &DlsOptions::default())
            .expect("converges");
        assert!((-1e-12..=0.6 + 1e-12).contains(&sol[1]), "{sol}");
        let back = polar.tip_pose(&sol).translation.vector;
        assert!((back - polar.tip_pose(&q).translation.vector).amax() < 1e-8);
    }
}

/// A revolute arm with an elbow that bends one way only: the generated closed form keeps the
/// branch within the range, in both entries.
#[test]
fn a_ranged_elbow_keeps_one_branch() {
    #[derive(PlanarArm, Default)]
    struct Elbow {
        #[arm(length = 0.5, mass = 1)]
        upper: Revolute,
        #[arm(length = 0.4, mass = 1, range = (0, 3))]
        fore: Revolute,
    }
    let arm = Elbow::default();
    let mut rng = Rng(23);
    for _ in 0..500 {
        let q = Vector2::new(rng.range(-3.0, 3.0), rng.range(0.05, 2.95));
        let tip = Point2::from(arm.tip_pose(&q).translation.vector);
        let [a, b] = arm.inverse_kinematics(&tip).expect("reachable");
        assert_eq!(a, b);
        assert!((a - q).amax() < 1e-9, "{a} vs {q}");
    }
}
