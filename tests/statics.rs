//! Inverse statics of derived arms of every size, checked against the statics written out
//! independently here (`tau_i = T + (tip - joint_i) x F`), virtual work and least-squares
//! optimality; and its accuracy at large angles and on overflow.

use core::f64::consts::PI;

use planar_arm::kinematics::{
    inverse_statics, InverseStatics, RedundantTipWrench, SINGULAR_THRESHOLD, UNBALANCED_TOLERANCE,
};
use planar_arm::nalgebra::{SMatrix, Vector3};
use planar_arm::prelude::*;

mod common;

#[path = "common/arms.rs"]
mod arms;

use arms::Six;
use common::Rng;

#[derive(PlanarArm, Default)]
struct One {
    #[arm(length = 3/4, mass = 1)]
    only: Revolute,
}

#[derive(PlanarArm, Default)]
struct Two {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1/2, mass = 1)]
    fore: Revolute,
}

#[derive(PlanarArm, Default)]
struct Three {
    #[arm(length = 1, mass = 2)]
    upper: Revolute,
    #[arm(length = 7/10, mass = 1)]
    fore: Revolute,
    #[arm(length = 3/10, mass = 1/2)]
    hand: Revolute,
}

#[derive(PlanarArm, Default)]
struct Four {
    #[arm(length = 2, mass = 3)]
    l1: Revolute,
    #[arm(length = 1/2, mass = 1)]
    l2: Revolute,
    #[arm(length = 3/10, mass = 1/2)]
    l3: Revolute,
    #[arm(length = 2/5, mass = 1/2)]
    l4: Revolute,
}

/// A six-link arm whose lengths are run-time parameters.
#[derive(PlanarArm)]
struct SixParam {
    #[arm(length = self.a, mass = 1)]
    l1: Revolute,
    #[arm(length = 1, mass = 1)]
    l2: Revolute,
    #[arm(length = self.b, mass = 1)]
    l3: Revolute,
    #[arm(length = 1, mass = 1)]
    l4: Revolute,
    #[arm(length = 1, mass = 1)]
    l5: Revolute,
    #[arm(length = self.a, mass = 1)]
    l6: Revolute,
    a: f64,
    b: f64,
}

fn lengths<A: PlanarArm<N>, const N: usize>(arm: &A) -> [f64; N] {
    arm.links().map(|l| l.length)
}

/// The absolute angles' sines and cosines, composed by angle sums (exact in the reals), and the
/// joint positions and tip from them: the statics written out without the crate.
fn geometry<const N: usize>(
    lengths: &[f64; N],
    absolute: &[(f64, f64); N],
) -> ([Vector2<f64>; N], Vector2<f64>) {
    let mut joints = [Vector2::zeros(); N];
    let mut at = Vector2::zeros();
    for k in 0..N {
        joints[k] = at;
        at += Vector2::new(absolute[k].1, absolute[k].0) * lengths[k];
    }
    (joints, at)
}

fn absolute_angles<const N: usize>(q: &SVector<f64, N>) -> [(f64, f64); N] {
    let mut phi = 0.0;
    core::array::from_fn(|k| {
        phi += q[k];
        phi.sin_cos()
    })
}

/// `tau_i = T + (tip - joint_i) x F`.
fn torques<const N: usize>(
    joints: &[Vector2<f64>; N],
    tip: Vector2<f64>,
    force: Vector2<f64>,
    torque: f64,
) -> SVector<f64, N> {
    SVector::from_fn(|i, _| {
        let d = tip - joints[i];
        torque + d.x * force.y - d.y * force.x
    })
}

/// `J^T` of the statics above (columns: F_x, F_y, T).
fn jt<const N: usize>(joints: &[Vector2<f64>; N], tip: Vector2<f64>) -> SMatrix<f64, N, 3> {
    SMatrix::from_fn(|i, c| {
        let d = tip - joints[i];
        [-d.y, d.x, 1.0][c]
    })
}

fn redundant<A, const N: usize>(arm: &A, rng: &mut Rng) -> (usize, f64)
where
    A: PlanarArm<N> + RedundantTipWrench<N>,
{
    let l = lengths(arm);
    let (mut checked, mut worst) = (0, 0.0_f64);
    for _ in 0..400 {
        let q = rng.vector::<N>(PI);
        let (joints, tip) = geometry(&l, &absolute_angles(&q));
        let jt = jt(&joints, tip);
        let manipulability = (jt.transpose() * jt).determinant().sqrt();
        if manipulability < 1e-3 {
            continue;
        }
        checked += 1;
        // A wrench, its torques by the statics above, and back.
        let force = Vector2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
        let torque = rng.range(-5.0, 5.0);
        let tau = torques(&joints, tip, force, torque);
        let w = arm.tip_wrench(&q, &tau).unwrap();
        let (f, t) = (w.force, w.torque);
        let error = (f - force).norm().max((t - torque).abs()) / force.norm().max(1.0);
        worst = worst.max(error * manipulability);
        assert!(error <= 1e-11 / manipulability, "N = {N}: error {error}");
        let w = arm.inverse_statics(&q, &tau).unwrap();
        assert!(w.residual.norm() <= 1e-12 * tau.norm().max(1.0));
        // The same torques by the generated joint_torques (virtual work of the tip wrench).
        let generated = arm.joint_torques(&q, &force, torque);
        assert!((generated - tau).norm() <= 1e-12 * tau.norm().max(1.0));

        // Arbitrary torques: the least-squares wrench. The residual is orthogonal to the range
        // of J^T (normal equations) and J^T w + residual = tau.
        let tau = rng.vector::<N>(5.0);
        let w = arm.inverse_statics(&q, &tau).unwrap();
        let fitted = jt * Vector3::new(w.force.x, w.force.y, w.torque);
        assert!((fitted + w.residual - tau).norm() <= 1e-12 * tau.norm());
        let normal = jt.transpose() * w.residual;
        assert!(normal.norm() <= 1e-11 * tau.norm() * jt.norm(), "{normal}");
        // No other wrench comes closer.
        let best = w.residual.norm();
        for _ in 0..5 {
            let other = Vector3::new(w.force.x, w.force.y, w.torque)
                + Vector3::from_fn(|_, _| rng.range(-1e-3, 1e-3));
            assert!((jt * other - tau).norm() >= best);
        }
        // Generic torques of N > 3 joints are not balanced by any wrench.
        if best > 10.0 * UNBALANCED_TOLERANCE * tau.norm() {
            assert!(matches!(
                arm.tip_wrench(&q, &tau),
                Err(ArmError::Unbalanced { residual, .. }) if (residual - best).abs() <= 1e-12 * tau.norm()
            ));
        }
    }
    (checked, worst)
}

#[test]
fn tip_wrench_of_four_and_six_links_inverts_the_statics() {
    let mut rng = Rng(21);
    let (n4, w4) = redundant(&Four::default(), &mut rng);
    let (n6, w6) = redundant(&Six::default(), &mut rng);
    let param = SixParam {
        l1: Revolute,
        l2: Revolute,
        l3: Revolute,
        l4: Revolute,
        l5: Revolute,
        l6: Revolute,
        a: 0.7,
        b: 1.3,
    };
    let (np, wp) = redundant(&param, &mut rng);
    assert!(n4 > 300 && n6 > 300 && np > 300, "{n4} {n6} {np}");
    // Measured: the worst relative error times the manipulability.
    println!(
        "worst error x manipulability: 4 links {w4:.1e}, 6 links {w6:.1e}, parameters {wp:.1e}"
    );
}

#[test]
fn three_links_agree_with_the_closed_form() {
    let arm = Three::default();
    let mut rng = Rng(22);
    for _ in 0..1000 {
        let q = rng.vector::<3>(PI);
        if q[1].sin().abs() < 0.05 {
            continue;
        }
        let tau = rng.vector::<3>(5.0);
        let w = arm.tip_wrench(&q, &tau).unwrap();
        let (f, t) = (w.force, w.torque);
        let w = arm.inverse_statics(&q, &tau).unwrap();
        let scale = 1e-12 / q[1].sin().abs();
        assert!(
            (w.force - f).norm() <= scale * f.norm().max(1.0)
                && (w.torque - t).abs() <= scale * t.abs().max(1.0)
        );
        assert!(w.residual.norm() <= 1e-12 * tau.norm());
    }
    // Singular exactly where tip_wrench3 is: |sin q2| < SINGULAR_THRESHOLD.
    for q2 in [0.0, PI, 1e-12, PI - 1e-10] {
        let q = Vector3::new(0.3, q2, 1.0);
        let tau = Vector3::new(1.0, 2.0, 3.0);
        assert!(
            matches!(
                arm.inverse_statics(&q, &tau),
                Err(ArmError::Singular { .. })
            ),
            "{q2}"
        );
        assert!(matches!(
            arm.tip_wrench(&q, &tau),
            Err(ArmError::Singular { .. })
        ));
    }
    let q = Vector3::new(0.3, 1e-6, 1.0);
    assert!(arm
        .inverse_statics(&q, &Vector3::new(1.0, 2.0, 3.0))
        .is_ok());
}

#[test]
fn one_and_two_links_exert_no_tip_torque() {
    let two = Two::default();
    let mut rng = Rng(23);
    for _ in 0..500 {
        let q = rng.vector::<2>(PI);
        if q[1].sin().abs() < 0.05 {
            continue;
        }
        let force = Vector2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
        let tau = two.joint_torques(&q, &force, 0.0);
        let w = two.inverse_statics(&q, &tau).unwrap();
        assert!((w.force - force).norm() <= 1e-10 * force.norm().max(1.0) && w.torque == 0.0);
        assert_eq!(w.force, two.tip_force(&q, &tau).unwrap());
    }
    let one = One::default();
    for _ in 0..100 {
        let q = rng.vector::<1>(PI);
        let tau = rng.vector::<1>(5.0);
        let w = one.inverse_statics(&q, &tau).unwrap();
        // It balances the torque and is the shortest force that does: perpendicular to the link.
        assert!((one.joint_torques(&q, &w.force, 0.0) - tau).norm() <= 1e-12 * tau.norm());
        let link = Vector2::new(q[0].cos(), q[0].sin());
        assert!(w.force.dot(&link).abs() <= 1e-12 * w.force.norm());
    }
}

#[test]
fn collinear_joints_are_singular() {
    let six = Six::default();
    let tau = SVector::<f64, 6>::from_fn(|i, _| 1.0 + i as f64);
    // Stretched, folded back and forth: every joint on one line.
    for q in [
        SVector::<f64, 6>::zeros(),
        SVector::<f64, 6>::new(0.4, PI, 0.0, -PI, PI, 0.0),
        SVector::<f64, 6>::new(-2.0, 0.0, 0.0, 0.0, 0.0, 1.3), // the last link does not count
    ] {
        match six.inverse_statics(&q, &tau) {
            Err(ArmError::Singular { measure, threshold }) => {
                assert!(measure.abs() < threshold, "{measure} {threshold}");
                // sum_{i<j<6} l_i l_j of the lengths 1, 0.8, 0.6, 0.5, 0.4 is
                // ((sum l)^2 - sum l^2) / 2 = (3.3^2 - 2.41) / 2 = 4.24.
                assert!((threshold - SINGULAR_THRESHOLD * 4.24).abs() < 1e-15 * threshold);
            }
            other => panic!("{q}: {other:?}"),
        }
        assert!(matches!(
            six.tip_wrench(&q, &tau),
            Err(ArmError::Singular { .. })
        ));
    }
    // Off the line by a little: regular, and the measure is sqrt(det J J^T).
    let q = SVector::<f64, 6>::new(0.4, 1e-3, 0.0, 0.0, 0.0, 0.0);
    let force = Vector2::new(1.0, -1.0);
    let tau = six.joint_torques(&q, &force, 0.5);
    let w = six.tip_wrench(&q, &tau).unwrap();
    let (f, t) = (w.force, w.torque);
    assert!(
        (f - force).norm() < 1e-7 && (t - 0.5).abs() < 1e-7,
        "{f} {t}"
    );
    // Just inside the threshold: the measure reported is sqrt(det J J^T), here by Cauchy-Binet
    // from the joints alone: the sum over joint triples of (twice the triangle's area)^2.
    let q = SVector::<f64, 6>::new(0.4, 1e-10, 0.0, 0.0, 0.0, 0.0);
    let (joints, _) = geometry(&lengths(&six), &absolute_angles(&q));
    let mut sum = 0.0;
    for a in 0..6 {
        for b in a + 1..6 {
            for c in b + 1..6 {
                let (u, v) = (joints[b] - joints[a], joints[c] - joints[a]);
                sum += (u.x * v.y - u.y * v.x).powi(2);
            }
        }
    }
    match six.inverse_statics(&q, &tau) {
        Err(ArmError::Singular { measure, .. }) => {
            assert!(
                (measure - sum.sqrt()).abs() <= 1e-4 * measure,
                "{measure} vs {}",
                sum.sqrt()
            );
        }
        other => panic!("{other:?}"),
    }
}

/// The numbers: at |q| = 1.6e6 the wrapped angles cost 4.9e-10, at 1e15 0.39.
#[test]
fn large_angles_lose_no_accuracy() {
    let two = Two::default();
    let three = Three::default();
    let six = Six::default();
    let force = Vector2::new(1.5, -0.5);
    let torque = 0.25;
    for big in [1.6e6_f64, 1e15, -1e15] {
        // q1 + q2 = 0.75 exactly in the reals (big - 0.75 is an f64), so the reference below
        // takes the absolute angle of link 2 as 0.75, from no big number.
        let q = Vector2::new(big, -(big - 0.75));
        assert_eq!(q[0] + q[1], 0.75);
        let absolute = [big.sin_cos(), 0.75_f64.sin_cos()];
        let (joints, tip) = geometry(&lengths(&two), &absolute);
        let tau = torques(&joints, tip, force, 0.0);
        let back = two.tip_force(&q, &tau).unwrap();
        assert!((back - force).norm() <= 1e-14, "{big}: {back}");

        let q3 = Vector3::new(big, -(big - 0.75), 0.5);
        let absolute = [big.sin_cos(), 0.75_f64.sin_cos(), 1.25_f64.sin_cos()];
        let (joints, tip) = geometry(&lengths(&three), &absolute);
        let tau = torques(&joints, tip, force, torque);
        let w = three.tip_wrench(&q3, &tau).unwrap();
        let (f, t) = (w.force, w.torque);
        assert!(
            (f - force).norm() <= 1e-14 && (t - torque).abs() <= 1e-14,
            "{big}: {f} {t}"
        );
        let w = three.inverse_statics(&q3, &tau).unwrap();
        assert!((w.force - force).norm() <= 1e-14 && (w.torque - torque).abs() <= 1e-14);

        let q6 = SVector::<f64, 6>::new(big, -(big - 0.75), 0.5, big, -big, -0.25);
        let absolute = [
            big.sin_cos(),
            0.75_f64.sin_cos(),
            1.25_f64.sin_cos(),
            // 1.25 + big: composed here from big's own sine and cosine.
            {
                let ((sb, cb), (sa, ca)) = (big.sin_cos(), 1.25_f64.sin_cos());
                (sa * cb + ca * sb, ca * cb - sa * sb)
            },
            1.25_f64.sin_cos(),
            1.0_f64.sin_cos(),
        ];
        let (joints, tip) = geometry(&lengths(&six), &absolute);
        let tau = torques(&joints, tip, force, torque);
        let w = six.tip_wrench(&q6, &tau).unwrap();
        let (f, t) = (w.force, w.torque);
        assert!(
            (f - force).norm() <= 1e-13 && (t - torque).abs() <= 1e-13,
            "{big}: {f} {t}"
        );
    }
}

#[test]
fn overflow_is_an_error_not_an_infinity() {
    let result: Result<Vector2<f64>, ArmError> = Err(ArmError::NonFinite { argument: "result" });
    let overflowed = Err(ArmError::NonFinite { argument: "result" });
    // Finite torques near a singularity: the force exceeds f64::MAX.
    let q = Vector2::new(0.3, 1e-8);
    let tau = Vector2::new(1e301, -1e301);
    assert_eq!(Two::default().tip_force(&q, &tau), result);
    let q3 = Vector3::new(0.3, 1e-8, 0.2);
    let tau3 = Vector3::new(1e301, -1e301, 1e301);
    assert_eq!(
        Three::default().tip_wrench(&q3, &tau3).map(|_| ()),
        overflowed
    );
    assert_eq!(
        Three::default().inverse_statics(&q3, &tau3).map(|_| ()),
        overflowed
    );
    let six = Six::default();
    let q6 = SVector::<f64, 6>::new(0.3, 1e-8, 0.0, 0.0, 0.0, 0.0);
    let tau6 = SVector::<f64, 6>::from_fn(|i, _| if i % 2 == 0 { 1e301 } else { -1e301 });
    assert_eq!(six.inverse_statics(&q6, &tau6).map(|_| ()), overflowed);
    // The largest torques far from a singularity stay finite.
    let big = SVector::<f64, 6>::repeat(f64::MAX);
    let q = SVector::<f64, 6>::new(0.3, 1.0, -0.5, 0.8, 1.2, -0.7);
    let w = six.inverse_statics(&q, &big);
    assert!(w.is_ok() || w == Err(ArmError::NonFinite { argument: "result" }));
    if let Ok(w) = w {
        assert!(w.force.iter().all(|x| x.is_finite()) && w.torque.is_finite());
    }
}

#[test]
fn bad_input_is_an_error() {
    let six = Six::default();
    let q = SVector::<f64, 6>::repeat(0.3);
    for bad in [f64::NAN, f64::INFINITY] {
        let mut qb = q;
        qb[3] = bad;
        assert_eq!(
            six.inverse_statics(&qb, &q).map(|_| ()),
            Err(ArmError::NonFinite { argument: "q" })
        );
        assert_eq!(
            six.tip_wrench(&q, &qb).map(|_| ()),
            Err(ArmError::NonFinite { argument: "tau" })
        );
        assert_eq!(
            inverse_statics(
                &[1.0, bad, 1.0, 1.0],
                &SVector::repeat(0.3),
                &SVector::repeat(1.0)
            )
            .map(|_| ()),
            Err(ArmError::NonFinite {
                argument: "lengths"
            })
        );
    }
    // Zero torques: zero wrench, even next to a singularity.
    let w = six
        .inverse_statics(
            &SVector::<f64, 6>::new(0.0, 1e-6, 0.0, 0.0, 0.0, 0.0),
            &SVector::zeros(),
        )
        .unwrap();
    assert_eq!((w.force, w.torque), (Vector2::zeros(), 0.0));
    // All lengths zero: singular, not NaN.
    assert!(matches!(
        inverse_statics(&[0.0; 4], &SVector::repeat(0.3), &SVector::repeat(1.0)),
        Err(ArmError::Singular { .. })
    ));
}
