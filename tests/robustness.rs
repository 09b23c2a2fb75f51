//! Run-time robustness of derived arms, over random states of arms with extreme parameters.
//!
//! The promises checked here:
//!
//! - No generated method panics, whatever the input (NaN, infinities, 1e300 included).
//! - For an arm with positive masses, every generated method returns finite values for every
//!   state with `|q| <= 1e6`, `|qd| <= 1e6`, `|qdd| <= 1e6`, `|tau| <= 1e12` (and tip forces
//!   up to 1e12); forward dynamics in particular. Beyond that the answer is still IEEE
//!   arithmetic on the exact formulas: where a torque or an energy exceeds `f64::MAX` (for
//!   instance `qd ~ 1e160`, since velocity terms grow as `qd^2`) it is infinite, and NaN can
//!   follow (`inf - inf`). The `try_` methods turn that into `Err(NonFinite { argument:
//!   "result" })`.
//! - The fallible methods (`try_forward_dynamics`, `try_inverse_dynamics`, inverse
//!   kinematics, inverse statics) answer NaN or infinite input with `Err(NonFinite)` naming
//!   the argument, and never return `Ok` holding NaN or an infinity.

use planar_arm::prelude::*;
use proptest::prelude::*;

/// A simple pendulum.
#[derive(PlanarArm, Default)]
struct Pendulum {
    #[arm(length = 1, mass = 1)]
    rod: Revolute,
}

/// Three millimetre, one gram links.
#[derive(PlanarArm, Default)]
struct Tiny {
    #[arm(length = 1e-3, mass = 1e-3)]
    a: Revolute,
    #[arm(length = 1e-3, mass = 1e-3)]
    b: Revolute,
    #[arm(length = 1e-3, mass = 1e-3)]
    c: Revolute,
}

/// Three kilometre, tonne links.
#[derive(PlanarArm, Default)]
struct Big {
    #[arm(length = 1e3, mass = 1e3)]
    a: Revolute,
    #[arm(length = 1e3, mass = 1e3)]
    b: Revolute,
    #[arm(length = 1e3, mass = 1e3)]
    c: Revolute,
}

/// A big link carrying a tiny one, and the reverse.
#[derive(PlanarArm, Default)]
struct BigThenTiny {
    #[arm(length = 1e3, mass = 1e3)]
    a: Revolute,
    #[arm(length = 1e-3, mass = 1e-3)]
    b: Revolute,
}

#[derive(PlanarArm, Default)]
struct TinyThenBig {
    #[arm(length = 1e-3, mass = 1e-3)]
    a: Revolute,
    #[arm(length = 1e3, mass = 1e3)]
    b: Revolute,
}

/// Centres of mass far outside their links, on both sides.
#[derive(PlanarArm, Default)]
struct FarCom {
    #[arm(length = 0.1, mass = 1, com = 10)]
    a: Revolute,
    #[arm(length = 1, mass = 2, com = -5)]
    b: Revolute,
    #[arm(length = 0.5, mass = 0.5, inertia = 0.001, com = 3)]
    c: Revolute,
}

/// Point masses at the link ends: the textbook double pendulum.
#[derive(PlanarArm, Default)]
struct PointMasses {
    #[arm(length = 1, mass = 1, inertia = 0, com = 1)]
    a: Revolute,
    #[arm(length = 1, mass = 1, inertia = 0, com = 1)]
    b: Revolute,
}

/// Point masses with extreme ratios, one behind its joint.
#[derive(PlanarArm, Default)]
struct PointMassesExtreme {
    #[arm(length = 1e-3, mass = 1e3, inertia = 0, com = 1e-3)]
    a: Revolute,
    #[arm(length = 1e3, mass = 1e-3, inertia = 0, com = 1e3)]
    b: Revolute,
    #[arm(length = 1, mass = 1, inertia = 0, com = -0.5)]
    c: Revolute,
    #[arm(length = 1e-3, mass = 1e-3, inertia = 0, com = 1e-3)]
    d: Revolute,
}

/// Valid arms whose mass matrices, stretched or folded, are too ill-conditioned for `f64`
/// (found by search over parameters in 1e-3 ..= 1e3): there `M11 M22 - M12^2`, or a pivot of
/// `L D L^T`, computed naively, rounds to zero or below although it is positive.
#[derive(PlanarArm, Default)]
struct IllConditioned2 {
    #[arm(length = 500, mass = 0.01, inertia = 0, com = 0.001)]
    a: Revolute,
    #[arm(length = 1, mass = 500, inertia = 0, com = 0.01)]
    b: Revolute,
}

#[derive(PlanarArm, Default)]
struct IllConditioned3 {
    #[arm(length = 500, mass = 0.003, inertia = 0, com = -0.001)]
    a: Revolute,
    #[arm(length = 10, mass = 1000, inertia = 0, com = 0.01)]
    b: Revolute,
    #[arm(length = 0.003, mass = 100, inertia = 0, com = -500)]
    c: Revolute,
}

#[derive(PlanarArm, Default)]
struct IllConditionedRods {
    #[arm(length = 1000, mass = 0.1, com = -10)]
    a: Revolute,
    #[arm(length = 0.001, mass = 0.001, inertia = 8.3e-11, com = 0.003)]
    b: Revolute,
    #[arm(length = 1, mass = 100, com = 1000)]
    c: Revolute,
}

/// Six links, the longest arm checked here.
#[derive(PlanarArm, Default)]
#[arm(gravity = 0)]
struct Six {
    #[arm(length = 1, mass = 1)]
    a: Revolute,
    #[arm(length = 0.9, mass = 0.9, com = 0)]
    b: Revolute,
    #[arm(length = 0.8, mass = 0.8, inertia = 0, com = 0.8)]
    c: Revolute,
    #[arm(length = 0.7, mass = 0.7)]
    d: Revolute,
    #[arm(length = 0.6, mass = 0.6, com = -0.3)]
    e: Revolute,
    #[arm(length = 0.5, mass = 0.5)]
    f: Revolute,
}

/// The largest state magnitudes for which finiteness is promised.
const ANGLE: f64 = 1e6;
const RATE: f64 = 1e6;
const TORQUE: f64 = 1e12;

fn finite<const R: usize, const C: usize>(m: &SMatrix<f64, R, C>) -> bool {
    m.iter().all(|x| x.is_finite())
}

/// A finite value in `[-limit, limit]`, biased towards the edges and the special points.
fn bounded(limit: f64) -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -limit..=limit,
        2 => -10.0..10.0_f64,
        1 => Just(0.0),
        1 => Just(-0.0),
        1 => Just(limit),
        1 => Just(-limit),
        1 => Just(std::f64::consts::PI),
        1 => Just(1e-300),
    ]
}

/// Any `f64` at all, NaN and the infinities included.
fn anything() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => any::<f64>(),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => Just(f64::MAX),
        1 => Just(1e160),
        1 => -1e3..1e3_f64,
    ]
}

fn vector<const N: usize>(values: &[f64]) -> SVector<f64, N> {
    SVector::from_column_slice(&values[..N])
}

/// Every method, in the promised range: finite, and forward dynamics solves `M qdd = tau - c - g`
/// (`tau - h` from three joints).
fn check_bounded<A: PlanarArm<N>, const N: usize>(arm: &A, s: &[f64]) -> Result<(), TestCaseError> {
    let q = vector::<N>(&s[0..N]);
    let qd = vector::<N>(&s[N..2 * N]);
    let qdd = vector::<N>(&s[2 * N..3 * N]);
    let tau = vector::<N>(&s[3 * N..4 * N]) * (TORQUE / RATE);
    let force = Vector2::new(s[4 * N], s[4 * N + 1]) * (TORQUE / RATE);
    let torque = s[4 * N + 2] * (TORQUE / RATE);

    let m = arm.mass_matrix(&q);
    let c = arm.coriolis(&q, &qd);
    let g = arm.gravity(&q);
    prop_assert!(
        finite(&m) && finite(&c) && finite(&g),
        "M, c, g at {q}, {qd}"
    );
    prop_assert!(finite(&arm.coriolis_matrix(&q, &qd)));
    prop_assert!(finite(&arm.inverse_dynamics(&q, &qd, &qdd)));
    let accel = arm.forward_dynamics(&q, &qd, &tau);
    prop_assert!(
        finite(&accel),
        "forward dynamics {accel} at q {q}, qd {qd}, tau {tau}"
    );
    // Accurate to the conditioning of M (an ill-conditioned M gets only finiteness), for the
    // system the method solves: with one or two joints M, c and g as `mass_matrix`,
    // `coriolis` and `gravity` return them; from three joints M and h as
    // `mass_matrix_and_bias` returns them. (They differ by rounding, which at the extreme
    // rates here is far above the solve's: at q = (0, pi, 1e6), qd = (-1e6, 0, 1e6) the `Big`
    // arm's c + g is 2.8e4 off `bias` and off the Newton-Euler reference, which agree to 1e-5.)
    let (m, rhs) = if N <= 2 {
        (m, tau - c - g)
    } else {
        let (m, h) = arm.mass_matrix_and_bias(&q, &qd);
        (m, tau - h)
    };
    if let Some(cholesky) = m.cholesky() {
        #[allow(clippy::cast_precision_loss)]
        let condition = m.amax() * cholesky.inverse().amax() * N as f64;
        let residual = (m * accel - rhs).amax();
        let scale = m.amax() * accel.amax() + rhs.amax();
        prop_assert!(
            residual <= 1e-13 * condition.max(1.0) * scale,
            "M qdd - (tau - c - g) = {residual} at scale {scale}, condition {condition}"
        );
    }
    prop_assert!(arm.kinetic_energy(&q, &qd).is_finite());
    prop_assert!(arm.potential_energy(&q).is_finite());
    let pose = arm.tip_pose(&q);
    prop_assert!(pose.translation.vector.iter().all(|x| x.is_finite()));
    prop_assert!(pose.rotation.re.is_finite() && pose.rotation.im.is_finite());
    prop_assert!(finite(&arm.jacobian(&q)));
    prop_assert!(arm
        .joint_positions(&q)
        .iter()
        .all(|p| p.coords.iter().all(|x| x.is_finite())));
    let (r, theta) = arm.tip_polar(&q);
    prop_assert!(r.is_finite() && r >= 0.0 && theta.is_finite());
    prop_assert!(finite(&arm.joint_torques(&q, &force, torque)));
    prop_assert!(arm.manipulability(&q).is_finite());

    prop_assert_eq!(arm.try_forward_dynamics(&q, &qd, &tau), Ok(accel));
    prop_assert!(arm.try_inverse_dynamics(&q, &qd, &qdd).is_ok());
    Ok(())
}

/// Any input at all: no panic, and the checked methods keep their promise.
fn check_anything<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    s: &[f64],
) -> Result<(), TestCaseError> {
    let q = vector::<N>(&s[0..N]);
    let qd = vector::<N>(&s[N..2 * N]);
    let qdd = vector::<N>(&s[2 * N..3 * N]);
    let tau = vector::<N>(&s[3 * N..4 * N]);
    let force = Vector2::new(s[4 * N], s[4 * N + 1]);
    let _ = arm.mass_matrix(&q);
    let _ = arm.coriolis(&q, &qd);
    let _ = arm.coriolis_matrix(&q, &qd);
    let _ = arm.gravity(&q);
    let _ = arm.inverse_dynamics(&q, &qd, &qdd);
    let _ = arm.forward_dynamics(&q, &qd, &tau);
    let _ = arm.kinetic_energy(&q, &qd);
    let _ = arm.potential_energy(&q);
    let _ = arm.tip_pose(&q);
    let _ = arm.jacobian(&q);
    let _ = arm.joint_positions(&q);
    let _ = arm.tip_polar(&q);
    let _ = arm.joint_torques(&q, &force, s[4 * N + 2]);
    let _ = arm.manipulability(&q);
    let _ = arm.is_singular(&q, 1e-9);

    let all_finite = |v: &SVector<f64, N>| v.iter().all(|x| x.is_finite());
    let first_bad = |named: [(&'static str, &SVector<f64, N>); 3]| {
        named
            .into_iter()
            .find(|(_, v)| !all_finite(v))
            .map(|(n, _)| n)
    };
    match (
        first_bad([("q", &q), ("qd", &qd), ("tau", &tau)]),
        arm.try_forward_dynamics(&q, &qd, &tau),
    ) {
        (Some(name), result) => {
            prop_assert_eq!(result, Err(ArmError::NonFinite { argument: name }));
        }
        (None, Ok(qdd)) => prop_assert!(all_finite(&qdd)),
        (None, Err(e)) => prop_assert_eq!(e, ArmError::NonFinite { argument: "result" }),
    }
    match (
        first_bad([("q", &q), ("qd", &qd), ("qdd", &qdd)]),
        arm.try_inverse_dynamics(&q, &qd, &qdd),
    ) {
        (Some(name), result) => {
            prop_assert_eq!(result, Err(ArmError::NonFinite { argument: name }));
        }
        (None, Ok(tau)) => prop_assert!(all_finite(&tau)),
        (None, Err(e)) => prop_assert_eq!(e, ArmError::NonFinite { argument: "result" }),
    }
    Ok(())
}

/// The closed forms of a two-link arm: `Err` for bad input, finite and correct `Ok`s.
fn check_two<A: PlanarArm<2> + ClosedFormIk<2, Target = Point2<f64>> + TipForce>(
    arm: &A,
    s: &[f64],
) -> Result<(), TestCaseError> {
    let target = Point2::new(s[0], s[1]);
    let q = SVector::<f64, 2>::new(s[2], s[3]);
    let tau = SVector::<f64, 2>::new(s[4], s[5]);
    let reach = arm.workspace().outer_radius();
    match arm.inverse_kinematics(&target) {
        Ok(solutions) => {
            for sol in solutions {
                prop_assert!(sol.iter().all(|a| a.is_finite()));
                let tip = arm.tip_pose(&sol).translation.vector;
                prop_assert!((tip - target.coords).norm() <= 1e-6 * reach.max(1.0));
            }
        }
        Err(ArmError::NonFinite { argument }) => {
            prop_assert!(!(s[0].is_finite() && s[1].is_finite()), "{argument}");
        }
        Err(ArmError::Unreachable { .. }) => {
            prop_assert!(s[0].is_finite() && s[1].is_finite());
        }
        Err(other) => prop_assert!(false, "unexpected {other}"),
    }
    let inputs_finite = q.iter().chain(tau.iter()).all(|x| x.is_finite());
    match arm.tip_force(&q, &tau) {
        Ok(f) => {
            prop_assert!(inputs_finite);
            prop_assert!(f.iter().all(|x| !x.is_nan()));
        }
        Err(ArmError::NonFinite { argument }) => {
            prop_assert!(!inputs_finite || argument == "result")
        }
        Err(ArmError::Singular { .. }) => prop_assert!(inputs_finite),
        Err(other) => prop_assert!(false, "unexpected {other}"),
    }
    Ok(())
}

fn check_three<A: PlanarArm<3> + ClosedFormIk<3, Target = Isometry2<f64>> + TipWrench>(
    arm: &A,
    s: &[f64],
) -> Result<(), TestCaseError> {
    let target = Isometry2::new(Vector2::new(s[0], s[1]), s[2]);
    let finite_target = s[0].is_finite() && s[1].is_finite() && s[2].is_finite();
    let q = SVector::<f64, 3>::new(s[3], s[4], s[5]);
    let tau = SVector::<f64, 3>::new(s[6], s[7], s[8]);
    let reach = arm.workspace().outer_radius();
    match arm.inverse_kinematics(&target) {
        Ok(solutions) => {
            prop_assert!(finite_target);
            for sol in solutions {
                prop_assert!(sol.iter().all(|a| a.is_finite()));
                let tip = arm.tip_pose(&sol).translation.vector;
                prop_assert!((tip - target.translation.vector).norm() <= 1e-6 * reach.max(1.0));
            }
        }
        Err(ArmError::NonFinite { .. }) => prop_assert!(!finite_target),
        Err(ArmError::Unreachable { .. }) => prop_assert!(finite_target),
        Err(other) => prop_assert!(false, "unexpected {other}"),
    }
    let inputs_finite = q.iter().chain(tau.iter()).all(|x| x.is_finite());
    match arm.tip_wrench(&q, &tau) {
        Ok(w) => {
            let (f, t) = (w.force, w.torque);
            prop_assert!(inputs_finite);
            prop_assert!(f.iter().all(|x| !x.is_nan()) && !t.is_nan());
        }
        Err(ArmError::NonFinite { argument }) => {
            prop_assert!(!inputs_finite || argument == "result")
        }
        Err(ArmError::Singular { .. }) => prop_assert!(inputs_finite),
        Err(other) => prop_assert!(false, "unexpected {other}"),
    }
    Ok(())
}

/// A state of `4 N + 3` numbers: q, qd, qdd, tau / 1e6, then a tip force and torque / 1e6.
fn bounded_state(n: usize) -> impl Strategy<Value = Vec<f64>> {
    (
        proptest::collection::vec(bounded(ANGLE), n),
        proptest::collection::vec(bounded(RATE), 3 * n + 3),
    )
        .prop_map(|(mut q, rest)| {
            q.extend(rest);
            q
        })
}

macro_rules! robustness {
    ($($name:ident: $ty:ty, $n:literal;)*) => {
        $(
            mod $name {
                use super::*;

                proptest! {
                    #![proptest_config(ProptestConfig::with_cases(512))]

                    #[test]
                    fn finite_in_the_promised_range(s in bounded_state($n)) {
                        check_bounded::<$ty, $n>(&<$ty>::default(), &s)?;
                    }

                    #[test]
                    fn no_panic_and_checked_errors_for_any_input(
                        s in proptest::collection::vec(anything(), 4 * $n + 3),
                    ) {
                        check_anything::<$ty, $n>(&<$ty>::default(), &s)?;
                    }
                }
            }
        )*
    };
}

robustness! {
    pendulum: Pendulum, 1;
    tiny: Tiny, 3;
    big: Big, 3;
    big_then_tiny: BigThenTiny, 2;
    tiny_then_big: TinyThenBig, 2;
    far_com: FarCom, 3;
    point_masses: PointMasses, 2;
    point_masses_extreme: PointMassesExtreme, 4;
    ill_conditioned2: IllConditioned2, 2;
    ill_conditioned3: IllConditioned3, 3;
    ill_conditioned_rods: IllConditionedRods, 3;
    six: Six, 6;
}

fn closed_form_input() -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(
        prop_oneof![3 => -3e3..3e3_f64, 2 => -2.0..2.0_f64, 1 => anything()],
        9,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1024))]

    #[test]
    fn closed_forms_of_two_links(s in closed_form_input()) {
        check_two(&BigThenTiny::default(), &s)?;
        check_two(&TinyThenBig::default(), &s)?;
        check_two(&PointMasses::default(), &s)?;
    }

    #[test]
    fn closed_forms_of_three_links(s in closed_form_input()) {
        check_three(&Tiny::default(), &s)?;
        check_three(&Big::default(), &s)?;
        check_three(&FarCom::default(), &s)?;
    }
}

/// Every stretched and folded pose of the ill-conditioned arms, where they are worst.
#[test]
fn ill_conditioned_arms_have_finite_forward_dynamics_when_stretched_or_folded() {
    fn sweep<A: PlanarArm<N> + Default, const N: usize>(name: &str) {
        let arm = A::default();
        let tau = SVector::<f64, N>::from_fn(|i, _| [1.0, -2.0, 3.0][i % 3]);
        for k in 0..(1 << (N - 1)) * 16 {
            let q = SVector::<f64, N>::from_fn(|i, _| match i {
                0 => f64::from(k) * 0.4,
                _ if k >> (i + 3) & 1 == 1 => std::f64::consts::PI,
                _ => 0.0,
            });
            let qdd = arm.forward_dynamics(&q, &SVector::zeros(), &tau);
            assert!(qdd.iter().all(|x| x.is_finite()), "{name} at {q}: {qdd}");
        }
    }
    sweep::<IllConditioned2, 2>("IllConditioned2");
    sweep::<IllConditioned3, 3>("IllConditioned3");
    sweep::<IllConditionedRods, 3>("IllConditionedRods");
}

#[test]
fn huge_rates_overflow_to_infinity_and_the_checked_methods_say_so() {
    let arm = Big::default();
    let q = SVector::<f64, 3>::new(0.1, 0.2, 0.3);
    let qd = SVector::<f64, 3>::repeat(1e160);
    let c = arm.coriolis(&q, &qd);
    assert!(c.iter().any(|x| x.is_infinite() || x.is_nan()));
    assert_eq!(
        arm.try_inverse_dynamics(&q, &qd, &SVector::zeros()),
        Err(ArmError::NonFinite { argument: "result" })
    );
    assert_eq!(
        arm.try_forward_dynamics(&q, &qd, &SVector::zeros()),
        Err(ArmError::NonFinite { argument: "result" })
    );
    assert_eq!(
        arm.try_forward_dynamics(&q, &SVector::repeat(f64::NAN), &SVector::zeros()),
        Err(ArmError::NonFinite { argument: "qd" })
    );
}

#[test]
fn arm_error_is_a_std_error() {
    fn assert_error<E: std::error::Error + Send + Sync + 'static>(e: E) -> String {
        e.to_string()
    }
    let message = assert_error(ArmError::NonFinite { argument: "q" });
    assert!(message.contains("`q`"), "{message}");
    let boxed: Box<dyn std::error::Error> = Box::new(ArmError::Singular {
        measure: 0.0,
        threshold: 1e-9,
    });
    assert!(!boxed.to_string().is_empty());
}

/// Two links whose masses are read at run time.
#[derive(PlanarArm)]
#[arm(gravity = 9.81)]
struct Heavy2 {
    #[arm(length = 1, mass = self.m1)]
    a: Revolute,
    #[arm(length = 0.5, mass = self.m2)]
    b: Revolute,
    m1: f64,
    m2: f64,
}

#[test]
fn enormous_masses_keep_two_link_forward_dynamics_finite() {
    // Cramer's determinant of a two-link arm is a product of two masses: 1e154 squared
    // overflowed to inf, and the accelerations to NaN. The solve works within M's own range.
    for m in [1.0, 1e100, 1e154, 1e160, 1e300] {
        let arm = Heavy2 {
            a: Revolute,
            b: Revolute,
            m1: m,
            m2: 0.5 * m,
        };
        let (q, qd) = (Vector2::new(0.3, 1.1), Vector2::new(0.2, -0.4));
        let tau = Vector2::new(2.0, -1.0) * m;
        let qdd = arm.forward_dynamics(&q, &qd, &tau);
        assert!(qdd.iter().all(|x| x.is_finite()), "m = {m}: {qdd}");
        let back = arm.inverse_dynamics(&q, &qd, &qdd);
        assert!(
            (back - tau).amax() <= 1e-12 * tau.amax(),
            "m = {m}: {back} vs {tau}"
        );
        let frozen = arm.freeze().forward_dynamics(&q, &qd, &tau);
        assert!((frozen - qdd).amax() <= 1e-12 * qdd.amax(), "m = {m}");
    }
}
