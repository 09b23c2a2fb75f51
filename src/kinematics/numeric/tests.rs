//! Unit tests of the numeric inverse kinematics: convergence for four to eight links, agreement
//! with the closed forms, joint ranges on prismatic arms, and a reach check that never refuses a
//! reachable target.

use super::*;
use crate::kinematics::test_support::{
    angle_gap, any_f64, clean, fk_joints, jacobian, pose_of, Rng,
};
use crate::kinematics::{ik3, tip_pose_of, Workspace};
use crate::{Joint, Link};
use core::f64::consts::PI;
use nalgebra::Vector2;
use proptest::prelude::*;

fn dls_case<const N: usize>(rng: &mut Rng) {
    let lengths: [f64; N] = core::array::from_fn(|_| rng.range(0.3, 1.2));
    let options = DlsOptions::default();
    for pose in [false, true] {
        for _ in 0..30 {
            let truth = SVector::<f64, N>::from_fn(|_, _| rng.angle());
            let seed = truth + SVector::<f64, N>::from_fn(|_, _| rng.range(-0.2, 0.2));
            let goal = pose_of(&lengths, &truth);
            let target = if pose {
                IkTarget::Pose(goal)
            } else {
                IkTarget::Position(Point2::from(goal.translation.vector))
            };
            let q = solve_dls(
                |q| pose_of(&lengths, q),
                |q| jacobian(&lengths, q),
                &target,
                &seed,
                &options,
            )
            .unwrap_or_else(|e| panic!("N = {N}, pose {pose}: {e:?}"));
            let reached = pose_of(&lengths, &q);
            assert!((reached.translation.vector - goal.translation.vector).norm() <= 1e-10);
            if pose {
                assert!(angle_gap(reached.rotation.angle(), goal.rotation.angle()) <= 1e-10);
            }
            // Reached from the seed: no farther from it than the configuration used.
            assert!(
                (q - seed).norm() <= 1.25 * (truth - seed).norm() + 1e-9,
                "N = {N}: |q - seed| = {}, |truth - seed| = {}",
                (q - seed).norm(),
                (truth - seed).norm()
            );
        }
    }
    // Beyond reach: the best is the stretched arm, short by 0.5.
    let reach: f64 = lengths.iter().sum();
    let far = IkTarget::Position(Point2::new(0.0, reach + 0.5));
    let seed = SVector::<f64, N>::from_fn(|i, _| if i == 0 { 1.2 } else { 0.1 });
    match solve_dls(
        |q| pose_of(&lengths, q),
        |q| jacobian(&lengths, q),
        &far,
        &seed,
        &options,
    ) {
        Err(ArmError::NoConvergence {
            iterations,
            residual,
        }) => {
            assert!(iterations <= options.max_iterations);
            assert!((residual - 0.5).abs() < 1e-6, "residual {residual}");
        }
        other => panic!("expected NoConvergence, got {other:?}"),
    }
}

#[test]
fn dls_converges_for_four_to_eight_links() {
    let mut rng = Rng(12);
    dls_case::<4>(&mut rng);
    dls_case::<5>(&mut rng);
    dls_case::<6>(&mut rng);
    dls_case::<7>(&mut rng);
    dls_case::<8>(&mut rng);
}

#[test]
fn dls_agrees_with_the_closed_forms() {
    let mut rng = Rng(13);
    let lengths = [1.0, 0.7, 0.3];
    for _ in 0..200 {
        let q = Vector3::new(rng.angle(), rng.range(0.3, 2.8), rng.angle());
        let target = pose_of(&lengths, &q);
        let [up, _] = ik3(lengths[0], lengths[1], lengths[2], &target).unwrap();
        let seed = up + Vector3::new(0.1, -0.1, 0.1);
        let solved = solve_dls(
            |q| pose_of(&lengths, q),
            |q| jacobian(&lengths, q),
            &IkTarget::Pose(target),
            &seed,
            &DlsOptions::default(),
        )
        .unwrap();
        for k in 0..3 {
            assert!(angle_gap(solved[k], up[k]) < 1e-8);
        }
    }
    // No iterations allowed: only an exact seed is accepted.
    let none = DlsOptions {
        max_iterations: 0,
        ..DlsOptions::default()
    };
    let q = Vector3::new(0.1, 0.2, 0.3);
    let at = IkTarget::Pose(pose_of(&lengths, &q));
    let run = |seed: &Vector3<f64>| {
        solve_dls(
            |q| pose_of(&lengths, q),
            |q| jacobian(&lengths, q),
            &at,
            seed,
            &none,
        )
    };
    assert_eq!(run(&q), Ok(q));
    assert!(matches!(
        run(&(q * 2.0)),
        Err(ArmError::NoConvergence { iterations: 0, .. })
    ));
}

fn within<const N: usize>(q: &SVector<f64, N>, limits: &[(f64, f64); N]) -> bool {
    (0..N).all(|i| limits[i].0 <= q[i] && q[i] <= limits[i].1)
}

/// Random configurations within the ranges, their poses as targets, seeds near them:
/// converged within the ranges (and within the narrower limits of `options`, if any).
fn ranged_case<const N: usize>(
    links: &[Link; N],
    options: &DlsOptions<N>,
    rng: &mut Rng,
) -> (usize, usize) {
    let kinds = links.map(|l| l.joint);
    let lengths = links.map(|l| l.length);
    let limits: [(f64, f64); N] = core::array::from_fn(|i| {
        let (lo, hi) = links[i].range.unwrap_or((-PI, PI));
        let (olo, ohi) = options.limits.map_or((lo, hi), |l| l[i]);
        (lo.max(olo), hi.min(ohi))
    });
    let (mut converged, mut tried) = (0, 0);
    for pose in [false, true] {
        for _ in 0..200 {
            let truth = SVector::<f64, N>::from_fn(|i, _| rng.range(limits[i].0, limits[i].1));
            let (x, y, phi) = fk_joints(&kinds, &lengths, truth.as_slice());
            let target = if pose {
                IkTarget::Pose(Isometry2::new(Vector2::new(x, y), phi))
            } else {
                IkTarget::Position(Point2::new(x, y))
            };
            // Never refused: the configuration is within the ranges.
            assert_eq!(reachable_target_of(links, &target), Ok(target));
            let seed = truth + SVector::<f64, N>::from_fn(|_, _| rng.range(-0.15, 0.15));
            tried += 1;
            match inverse_kinematics_of(links, &target, &seed, options) {
                Ok(q) => {
                    converged += 1;
                    assert!(within(&q, &limits), "{q} outside {limits:?}");
                    let (qx, qy, qphi) = fk_joints(&kinds, &lengths, q.as_slice());
                    assert!((qx - x).hypot(qy - y) <= 1e-10);
                    if pose {
                        assert!(angle_gap(qphi, phi) <= 1e-10);
                    }
                }
                Err(ArmError::NoConvergence { .. }) => {}
                Err(e) => panic!("{e:?}"),
            }
        }
    }
    (converged, tried)
}

#[test]
fn numeric_ik_on_prismatic_arms_respects_the_ranges() {
    let mut rng = Rng(28);
    let polar = [
        Link::rod(0.2, 1.0).with_range(-1.0, 2.0),
        Link::rod(0.5, 1.0)
            .with_joint(Joint::Prismatic)
            .with_range(0.1, 0.6),
    ];
    let prr = [
        Link::rod(0.2, 1.0)
            .with_joint(Joint::Prismatic)
            .with_range(-0.5, 0.6),
        Link::rod(0.6, 1.0).with_range(-2.0, 2.0),
        Link::rod(0.3, 1.0).with_range(-1.5, 1.5),
    ];
    let (c, t) = ranged_case(&polar, &DlsOptions::default(), &mut rng);
    let free = DlsOptions::<3>::default();
    assert!(c * 100 >= 98 * t, "RP: {c} of {t} converged");
    let (c, t) = ranged_case(&prr, &free, &mut rng);
    assert!(c * 100 >= 95 * t, "PRR: {c} of {t} converged");
    // Options narrow the ranges further: the intersection holds.
    let narrow = DlsOptions {
        limits: Some([(0.0, 0.4), (-1.0, 1.0), (f64::NEG_INFINITY, 0.5)]),
        ..free
    };
    let (c, t) = ranged_case(&prr, &narrow, &mut rng);
    assert!(c * 100 >= 95 * t, "PRR, narrower: {c} of {t} converged");
    // Limits that miss a range: refused.
    let apart = DlsOptions {
        limits: Some([(1.0, 2.0), (-1.0, 1.0), (-1.0, 1.0)]),
        ..free
    };
    let at = IkTarget::Position(Point2::new(0.8, 0.3));
    assert!(matches!(
        inverse_kinematics_of(&prr, &at, &Vector3::zeros(), &apart),
        Err(ArmError::OutOfRange {
            what: "joint limits",
            link: Some(0),
            ..
        })
    ));
    // A target that needs the slide beyond its end: no solution inside the ranges, and
    // the closed form agrees.
    let far = IkTarget::Position(Point2::new(0.0, 1.5));
    assert!(
        matches!(reachable_target_of(&polar, &far), Err(ArmError::BeyondJointRange { joint: 1, kind: Joint::Prismatic, excess, .. }) if (excess - 0.2).abs() < 1e-12)
    );
    // The polar arm's angle range: reachable only pointing away, which the range forbids.
    let behind = IkTarget::Position(Point2::new(-0.9, -0.1));
    assert!(reachable_target_of(&polar, &behind).is_err());
    // Sliders without a range reach far; the check lets them through.
    let unbounded = [
        Link::rod(0.3, 1.0).with_joint(Joint::Prismatic),
        Link::rod(0.5, 1.0),
    ];
    let target = IkTarget::Position(Point2::new(25.0, 0.4));
    let q = inverse_kinematics_of(
        &unbounded,
        &target,
        &Vector2::new(0.0, 0.5),
        &DlsOptions::default(),
    )
    .unwrap();
    assert!((pose_of_links(&unbounded, &q) - Vector2::new(25.0, 0.4)).norm() < 1e-10);
    assert!(reachable_target_of(&unbounded, &IkTarget::Position(Point2::new(3.0, 0.6))).is_err());
}

fn pose_of_links<const N: usize>(links: &[Link; N], q: &SVector<f64, N>) -> Vector2<f64> {
    tip_pose_of(links, q).translation.vector
}

#[test]
fn the_reach_check_never_refuses_a_reachable_target() {
    let mut rng = Rng(29);
    let p = Joint::Prismatic;
    let mixes: [[Link; 3]; 4] = [
        [
            Link::rod(1.0, 1.0),
            Link::rod(0.5, 1.0),
            Link::rod(0.3, 1.0).with_joint(p).with_range(0.0, 0.4),
        ],
        [
            Link::rod(0.4, 1.0),
            Link::rod(1.0, 1.0).with_joint(p).with_range(0.5, 1.0),
            Link::rod(0.3, 1.0),
        ],
        [
            Link::rod(0.5, 1.0).with_joint(p).with_range(0.0, 1.0),
            Link::rod(0.2, 1.0).with_joint(p),
            Link::rod(0.3, 1.0).with_range(0.0, 1.0),
        ],
        [
            Link::rod(0.2, 1.0).with_joint(p).with_range(-0.5, 0.6),
            Link::rod(0.6, 1.0).with_range(0.0, 1.0),
            Link::rod(0.3, 1.0),
        ],
    ];
    for links in mixes {
        let kinds = links.map(|l| l.joint);
        let lengths = links.map(|l| l.length);
        let mut refused = 0;
        for _ in 0..3000 {
            let q: [f64; 3] = core::array::from_fn(|i| {
                let (lo, hi) = links[i].range.unwrap_or((-3.0, 3.0));
                rng.range(lo, hi)
            });
            let (x, y, phi) = fk_joints(&kinds, &lengths, &q);
            for target in [
                IkTarget::Position(Point2::new(x, y)),
                IkTarget::Pose(Isometry2::new(Vector2::new(x, y), phi)),
            ] {
                assert_eq!(
                    reachable_target_of(&links, &target),
                    Ok(target),
                    "{kinds:?} at {q:?}"
                );
            }
            let far = 1.1 * Workspace::of_links(&links).outer_radius() + 0.1;
            let beyond = IkTarget::Position(Point2::new(far * phi.cos(), far * phi.sin()));
            refused += usize::from(reachable_target_of(&links, &beyond).is_err());
        }
        assert_eq!(refused, 3000, "{kinds:?}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn dls_never_panics_or_returns_nan(
        p in proptest::array::uniform3(any_f64()),
        seed in proptest::array::uniform3(any_f64()),
        tolerance in any_f64(),
        damping in any_f64(),
        max_iterations in 0..60_usize,
        pose in any::<bool>(),
    ) {
        let lengths = [1.0, 0.7, 0.3];
        let target = if pose {
            IkTarget::Pose(Isometry2::new(Vector2::new(p[0], p[1]), p[2]))
        } else {
            IkTarget::Position(Point2::new(p[0], p[1]))
        };
        let options = DlsOptions { max_iterations, tolerance, damping, limits: None };
        let r = solve_dls(
            |q| pose_of(&lengths, q),
            |q| jacobian(&lengths, q),
            &target,
            &Vector3::from(seed),
            &options,
        );
        prop_assert!(clean(&r));
        if let Ok(q) = r {
            prop_assert!(q.iter().all(|a| a.is_finite()));
        }
    }
}
