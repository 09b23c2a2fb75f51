//! Unit tests of the revolute closed forms: round trips over the work-space, boundaries and
//! unreachable targets, signed and zero lengths, and the branches kept within joint ranges.

use super::*;
use crate::kinematics::test_support::{angle_gap, fk, in_range, pose_of, Rng, PAIRS, TRIPLES};
use crate::kinematics::REACH_TOLERANCE;
use core::f64::consts::TAU;
use nalgebra::Vector3;
use proptest::prelude::*;

fn check_two_link_solutions(l1: f64, l2: f64, target: Point2<f64>, q: &[SVector<f64, 2>; 2]) {
    let scale = l1.abs() + l2.abs();
    for (branch, qb) in q.iter().enumerate() {
        let (x, y, _) = fk(&[l1, l2], qb.as_slice());
        assert!(
            (x - target.x).hypot(y - target.y) <= 1e-12 * scale,
            "l = ({l1}, {l2}), target {target}, branch {branch}: reached ({x}, {y})"
        );
        assert!(qb.iter().all(|a| in_range(*a)), "{qb} not in (-pi, pi]");
        let s2 = qb[1].sin();
        if branch == 0 {
            assert!(s2 >= -1e-15, "branch 0 has sin q2 = {s2}");
        } else {
            assert!(s2 <= 1e-15, "branch 1 has sin q2 = {s2}");
        }
    }
}

#[test]
fn ik2_round_trip_over_dense_workspace() {
    for (l1, l2) in PAIRS {
        let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
        for i in 0..=48 {
            let r = inner + (outer - inner) * f64::from(i) / 48.0;
            for j in 0..72 {
                let theta = f64::from(j) * TAU / 72.0;
                let target = Point2::new(r * theta.cos(), r * theta.sin());
                let q = ik2(l1, l2, &target).unwrap();
                check_two_link_solutions(l1, l2, target, &q);
                if l1 == l2 {
                    let qe = ik2_equal(l1, &target).unwrap();
                    check_two_link_solutions(l1, l2, target, &qe);
                    for (a, b) in q.iter().zip(&qe) {
                        assert!(angle_gap(a[0], b[0]) < 1e-6 && angle_gap(a[1], b[1]) < 1e-6);
                    }
                }
            }
        }
    }
}

#[test]
fn ik2_recovers_sampled_configurations() {
    let mut rng = Rng(1);
    for (l1, l2) in PAIRS {
        for _ in 0..2000 {
            let q = Vector2::new(rng.angle(), rng.angle());
            if q[1].sin().abs() < 1e-3 {
                continue;
            }
            let (x, y, _) = fk(&[l1, l2], q.as_slice());
            let target = Point2::new(x, y);
            let solutions = ik2(l1, l2, &target).unwrap();
            check_two_link_solutions(l1, l2, target, &solutions);
            let same = &solutions[usize::from(q[1].sin() < 0.0)];
            assert!(
                angle_gap(same[0], q[0]) < 1e-8 && angle_gap(same[1], q[1]) < 1e-8,
                "l = ({l1}, {l2}): {q} came back as {same}"
            );
        }
    }
}

#[test]
fn signed_and_zero_lengths() {
    let mut rng = Rng(2);
    for (l1, l2) in [(-1.0, 0.5), (1.0, -0.5), (-0.7, -1.3), (-1.0, -1.0)] {
        for _ in 0..500 {
            let q = Vector2::new(rng.angle(), rng.angle());
            let (x, y, _) = fk(&[l1, l2], q.as_slice());
            let target = Point2::new(x, y);
            check_two_link_solutions(l1, l2, target, &ik2(l1, l2, &target).unwrap());
            if l1 == l2 {
                check_two_link_solutions(l1, l2, target, &ik2_equal(l1, &target).unwrap());
            }
        }
    }
    // One link of length zero: the work-space is a circle.
    let on_circle = Point2::new(0.6, 0.8);
    check_two_link_solutions(0.0, 1.0, on_circle, &ik2(0.0, 1.0, &on_circle).unwrap());
    check_two_link_solutions(1.0, 0.0, on_circle, &ik2(1.0, 0.0, &on_circle).unwrap());
    assert!(ik2(0.0, 1.0, &Point2::new(0.5, 0.0)).is_err());
    // Both zero: only the origin.
    assert_eq!(
        ik2(0.0, 0.0, &Point2::origin()).unwrap(),
        [Vector2::zeros(); 2]
    );
    assert!(ik2_equal(0.0, &Point2::new(1e-300, 0.0)).is_err());
}

#[test]
fn boundary_targets_give_one_configuration() {
    for (l1, l2) in PAIRS {
        let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
        for j in 0..36 {
            let (s, c) = (f64::from(j) * TAU / 36.0).sin_cos();
            // On the outer circle: stretched, q2 = 0.
            let [a, b] = ik2(l1, l2, &Point2::new(outer * c, outer * s)).unwrap();
            assert!(
                a[1].abs() < 1e-6 && angle_gap(a[0], b[0]) < 1e-6 && angle_gap(a[1], b[1]) < 1e-6
            );
            // Just outside, within the tolerance: clamped onto the circle, identical branches.
            let out = outer * (1.0 + 0.5 * REACH_TOLERANCE);
            let [a, b] = ik2(l1, l2, &Point2::new(out * c, out * s)).unwrap();
            assert_eq!(a, b);
            assert_eq!(a[1], 0.0);
            // On the inner circle: folded, q2 = pi.
            if inner > 0.0 {
                let [a, b] = ik2(l1, l2, &Point2::new(inner * c, inner * s)).unwrap();
                assert!(angle_gap(a[1], PI) < 1e-6 && angle_gap(a[0], b[0]) < 1e-6);
                let inside = inner - 0.25 * REACH_TOLERANCE * outer;
                let [a, b] = ik2(l1, l2, &Point2::new(inside * c, inside * s)).unwrap();
                assert_eq!(a, b);
                assert_eq!(a[1], PI);
            }
        }
    }
}

#[test]
fn unreachable_targets_report_the_distance() {
    for (l1, l2) in PAIRS {
        let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
        for d in [3.0 * REACH_TOLERANCE, 1e-6, 0.1, 10.0] {
            let r = outer * (1.0 + d);
            match ik2(l1, l2, &Point2::new(0.0, -r)) {
                Err(ArmError::Unreachable {
                    target,
                    orientation,
                    radius,
                    inner: i,
                    outer: o,
                    distance,
                }) => {
                    assert_eq!((target, orientation), ([0.0, -r], None));
                    assert_eq!((radius, i, o), (r, inner, outer));
                    assert!((distance - (r - outer)).abs() <= 1e-15 * r && distance > 0.0);
                }
                other => panic!("expected Unreachable, got {other:?}"),
            }
            let r = inner - outer * d;
            if r > 0.0 {
                match ik2(l1, l2, &Point2::new(-r, 0.0)) {
                    Err(ArmError::Unreachable { distance, .. }) => {
                        assert!((distance - outer * d).abs() <= 1e-12 * outer);
                    }
                    other => panic!("expected Unreachable, got {other:?}"),
                }
            }
        }
        if l1 != l2 {
            assert_eq!(
                ik2(l1, l2, &Point2::origin()),
                Err(ArmError::Unreachable {
                    target: [0.0, 0.0],
                    orientation: None,
                    radius: 0.0,
                    inner,
                    outer,
                    distance: inner
                })
            );
        }
    }
    assert!(matches!(
        ik2_equal(1.0, &Point2::new(3.0, 0.0)),
        Err(ArmError::Unreachable { distance, .. }) if distance == 1.0
    ));
}

#[test]
fn origin_with_equal_links() {
    for l in [1.0, 0.25, 7.0] {
        let expected = [Vector2::new(0.0, PI); 2];
        for origin in [Point2::origin(), Point2::new(-0.0, -0.0)] {
            assert_eq!(ik2_equal(l, &origin).unwrap(), expected);
            assert_eq!(ik2(l, l, &origin).unwrap(), expected);
            let (x, y, _) = fk(&[l, l], &[0.0, PI]);
            assert!(x.hypot(y) < 1e-15 * l);
        }
        // Three links whose wrist must sit at the origin.
        let (l3, phi) = (0.3 * l, 2.0_f64);
        let target = Isometry2::new(Vector2::new(l3 * phi.cos(), l3 * phi.sin()), phi);
        for q in ik3(l, l, l3, &target).unwrap() {
            assert_eq!((q[0], q[1]), (0.0, PI));
            assert!(angle_gap(q[2], phi - PI) < 1e-15);
        }
    }
}

#[test]
fn ik3_round_trip_and_reachability() {
    let mut rng = Rng(3);
    for (l1, l2, l3) in TRIPLES {
        let reach = l1 + l2 + l3;
        let (mut solved, mut refused) = (0, 0);
        for _ in 0..20_000 {
            let r = reach * rng.range(0.0, 1.05);
            let (theta, phi) = (rng.angle(), rng.range(-10.0, 10.0));
            let (x, y) = (r * theta.cos(), r * theta.sin());
            let target = Isometry2::new(Vector2::new(x, y), phi);
            let wrist = (x - l3 * phi.cos()).hypot(y - l3 * phi.sin());
            let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
            let margin = 1e-9 * outer;
            match ik3(l1, l2, l3, &target) {
                Ok(solutions) => {
                    solved += 1;
                    assert!(wrist >= inner - 2.0 * margin && wrist <= outer + 2.0 * margin);
                    for (branch, q) in solutions.iter().enumerate() {
                        let (tx, ty, tphi) = fk(&[l1, l2, l3], q.as_slice());
                        assert!((tx - x).hypot(ty - y) < 1e-12 * reach);
                        assert!(angle_gap(tphi, phi) < 1e-12);
                        assert!(q.iter().all(|a| in_range(*a)));
                        let s2 = q[1].sin();
                        assert!(if branch == 0 {
                            s2 >= -1e-15
                        } else {
                            s2 <= 1e-15
                        });
                    }
                }
                Err(ArmError::Unreachable {
                    target: asked,
                    orientation,
                    radius,
                    inner: i,
                    outer: o,
                    distance,
                }) => {
                    refused += 1;
                    // The error names the tip pose asked for, not the wrist.
                    assert_eq!(asked, [x, y]);
                    assert!(angle_gap(orientation.unwrap(), phi) < 1e-15);
                    assert!(wrist < inner || wrist > outer);
                    assert!((radius - wrist).abs() < 1e-12 * reach);
                    assert_eq!((i, o), (inner, outer));
                    let expected = if wrist > outer {
                        wrist - outer
                    } else {
                        inner - wrist
                    };
                    assert!((distance - expected).abs() < 1e-12 * reach && distance > 0.0);
                }
                Err(e) => panic!("unexpected {e:?}"),
            }
        }
        assert!(
            solved > 1000 && refused > 500,
            "{solved} solved, {refused} refused"
        );
    }
}

#[test]
fn ik3_recovers_sampled_configurations() {
    let mut rng = Rng(4);
    for (l1, l2, l3) in TRIPLES {
        for _ in 0..2000 {
            let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
            if q[1].sin().abs() < 1e-3 {
                continue;
            }
            let target = pose_of(&[l1, l2, l3], &q);
            let solutions = ik3(l1, l2, l3, &target).unwrap();
            let same = &solutions[usize::from(q[1].sin() < 0.0)];
            for k in 0..3 {
                assert!(angle_gap(same[k], q[k]) < 1e-8, "{q} came back as {same}");
            }
        }
    }
}

/// Whether some `a + 2 pi k` lies in `range`, by the test's own rule.
fn turns_into(a: f64, range: Option<(f64, f64)>) -> bool {
    range.is_none_or(|(lo, hi)| a + TAU * ((lo - a) / TAU).ceil() <= hi)
}

fn within(a: f64, range: Option<(f64, f64)>) -> bool {
    range.is_none_or(|(lo, hi)| lo <= a && a <= hi)
}

#[test]
fn ik2_and_ik3_in_ranges() {
    let mut rng = Rng(24);
    let two: [[Option<(f64, f64)>; 2]; 3] = [
        [None, Some((0.0, PI))],
        [Some((-1.0, 2.0)), Some((-2.5, 0.5))],
        [Some((3.0, 5.0)), None],
    ];
    for (l1, l2) in PAIRS {
        for ranges in two {
            let (mut single, mut refused) = (0, 0);
            for _ in 0..2000 {
                let q = Vector2::new(rng.angle(), rng.angle());
                let (x, y, _) = fk(&[l1, l2], q.as_slice());
                let target = Point2::new(x, y);
                let free = ik2(l1, l2, &target).unwrap();
                let fits = free.map(|b| (0..2).all(|k| turns_into(b[k], ranges[k])));
                match ik2_in_ranges(l1, l2, ranges, &target) {
                    Ok(qs) => {
                        if fits[0] && fits[1] {
                            assert!(qs[0][1].sin() >= -1e-15 && qs[1][1].sin() <= 1e-15);
                        }
                        for b in &qs {
                            let (tx, ty, _) = fk(&[l1, l2], b.as_slice());
                            assert!((tx - x).hypot(ty - y) <= 1e-12 * (l1 + l2));
                            assert!(within(b[0], ranges[0]) && within(b[1], ranges[1]));
                        }
                        // Branch order kept; a lone survivor fills both entries.
                        for (b, free) in qs.iter().zip(&free) {
                            if fits[0] && fits[1] {
                                assert!(angle_gap(b[0], free[0]) < 1e-12);
                            }
                        }
                        if fits[0] != fits[1] {
                            single += 1;
                            assert_eq!(qs[0], qs[1]);
                            let kept = &free[usize::from(fits[1])];
                            assert!(angle_gap(qs[0][1], kept[1]) < 1e-12);
                        }
                    }
                    Err(ArmError::BeyondJointRange { joint, excess, .. }) => {
                        refused += 1;
                        assert!(!fits[0] && !fits[1] && excess > 0.0);
                        assert!(ranges[joint].is_some());
                    }
                    Err(e) => panic!("{e:?}"),
                }
            }
            assert!(single > 100, "{ranges:?}: {single} with one branch");
            if ranges[0].is_some() {
                assert!(refused > 50, "{ranges:?}: {refused} refused");
            }
        }
    }
    // Outside the annulus: the annulus error, whatever the ranges.
    assert_eq!(
        ik2_in_ranges(1.0, 0.5, two[0], &Point2::new(2.0, 0.0)),
        ik2(1.0, 0.5, &Point2::new(2.0, 0.0))
    );
    assert!(matches!(
        ik2_in_ranges(1.0, 0.5, [Some((1.0, 0.0)), None], &Point2::new(1.0, 0.0)),
        Err(ArmError::OutOfRange {
            what: "range",
            link: Some(0),
            ..
        })
    ));
    let three = [Some((-1.0, 1.0)), Some((0.0, PI)), Some((-1.0, 1.0))];
    let (mut solved, mut refused) = (0, 0);
    for (l1, l2, l3) in TRIPLES {
        for _ in 0..2000 {
            let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
            let target = pose_of(&[l1, l2, l3], &q);
            let free = ik3(l1, l2, l3, &target).unwrap();
            let fits = free.map(|b| (0..3).all(|k| turns_into(b[k], three[k])));
            match ik3_in_ranges(l1, l2, l3, three, &target) {
                Ok(qs) => {
                    solved += 1;
                    assert!(fits[0] || fits[1]);
                    for b in &qs {
                        let (x, y, phi) = fk(&[l1, l2, l3], b.as_slice());
                        let t = target.translation.vector;
                        assert!((x - t.x).hypot(y - t.y) < 1e-12 * (l1 + l2 + l3));
                        assert!(angle_gap(phi, target.rotation.angle()) < 1e-12);
                        assert!((0..3).all(|k| within(b[k], three[k])));
                    }
                }
                Err(ArmError::BeyondJointRange { excess, joint, .. }) => {
                    refused += 1;
                    assert!(!fits[0] && !fits[1] && excess > 0.0);
                    assert!(three[joint].is_some());
                }
                Err(e) => panic!("{e:?}"),
            }
        }
    }
    assert!(
        solved > 1000 && refused > 1000,
        "{solved} solved, {refused} refused"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn ik2_round_trip_for_random_lengths(
        l1 in 1e-3..1e3_f64,
        l2 in 1e-3..1e3_f64,
        u in 0.0..=1.0_f64,
        theta in -PI..PI,
    ) {
        let (inner, outer) = ((l1 - l2).abs(), l1 + l2);
        let r = inner + (outer - inner) * u;
        let target = Point2::new(r * theta.cos(), r * theta.sin());
        let q = ik2(l1, l2, &target).unwrap();
        check_two_link_solutions(l1, l2, target, &q);
    }
}
