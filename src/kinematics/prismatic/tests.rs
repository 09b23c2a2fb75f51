//! Unit tests of the closed forms with a prismatic joint: the test kinematics against the
//! joint rules, then each arm's round trip, branches and ranges against its own brute force.

use super::*;
use crate::kinematics::test_support::{fk_joints as fk, Rng};
use crate::kinematics::REACH_TOLERANCE;
use crate::Joint;
use core::f64::consts::TAU;

const RP: [Joint; 2] = [Joint::Revolute, Joint::Prismatic];
const PR: [Joint; 2] = [Joint::Prismatic, Joint::Revolute];
const PRR: [Joint; 3] = [Joint::Prismatic, Joint::Revolute, Joint::Revolute];

fn within(value: f64, range: Range) -> bool {
    range.is_none_or(|(lo, hi)| lo <= value && value <= hi)
}

fn close(a: (f64, f64), b: (f64, f64), scale: f64) -> bool {
    (a.0 - b.0).hypot(a.1 - b.1) <= 1e-12 * scale
}

fn gap(a: f64, b: f64) -> f64 {
    wrap_angle(a - b).abs()
}

#[test]
fn the_fk_of_the_tests_follows_the_rules() {
    // The brief's polar arm: tip = (0.2 + q2 + 0.5)(cos q1, sin q1).
    let (x, y, phi) = fk(&RP, &[0.2, 0.5], &[0.7, 0.1]);
    assert!(close(
        (x, y),
        (0.8 * 0.7_f64.cos(), 0.8 * 0.7_f64.sin()),
        1.0
    ));
    assert_eq!(phi, 0.7);
    // A slider carrying a link: carriage at (q1 + l1, 0).
    let (x, y, _) = fk(&PR, &[0.3, 0.5], &[0.4, 1.0]);
    assert!(close(
        (x, y),
        (0.7 + 0.5 * 1.0_f64.cos(), 0.5 * 1.0_f64.sin()),
        1.0
    ));
    // Two sliders in a row: along +x, then on along the first.
    let (x, y, _) = fk(&[Joint::Prismatic; 2], &[0.3, 0.5], &[0.4, 0.1]);
    assert!(close((x, y), (1.3, 0.0), 1.0));
}

/// `[(lengths, range1, range2)]` for the two-joint arms.
const TWO: [(f64, f64, Range, Range); 5] = [
    (0.2, 0.5, None, None),
    (0.2, 0.5, None, Some((0.1, 0.6))),
    (1.0, 0.5, Some((-1.0, 2.0)), Some((-2.5, 0.5))),
    (0.5, 1.5, Some((2.0, 5.0)), None),
    (-0.3, 0.8, Some((-4.0, -3.0)), Some((-1.0, 1.0))),
];

#[test]
fn ik_rp_round_trip_and_ranges() {
    let mut rng = Rng(21);
    for (l1, l2, r1, r2) in TWO {
        let (mut solved, mut refused, mut single) = (0, 0, 0);
        for _ in 0..5000 {
            let r = rng.range(0.0, 3.5);
            let theta = rng.angle();
            let (x, y) = (r * theta.cos(), r * theta.sin());
            // Reachable exactly when some signed reach (a representative of the angle
            // in range1) lies in range2.
            let ok = |s: f64, angle: f64| {
                within(s - l1 - l2, r2)
                    && r1.is_none_or(|(lo, hi)| {
                        let k = ((lo - angle) / TAU).ceil();
                        angle + k * TAU <= hi
                    })
            };
            let expected = [ok(r, theta), ok(-r, theta + PI)];
            match ik_rp(l1, l2, r1, r2, &Point2::new(x, y)) {
                Ok(qs) => {
                    solved += 1;
                    for q in qs {
                        let (tx, ty, _) = fk(&RP, &[l1, l2], q.as_slice());
                        assert!(close((tx, ty), (x, y), 3.5), "{q} misses ({x}, {y})");
                        assert!(within(q[0], r1) && within(q[1], r2), "{q} outside");
                    }
                    // Branch 0 points at the target, branch 1 away.
                    if expected[0] {
                        assert!((qs[0][1] - (r - l1 - l2)).abs() < 1e-12);
                        assert!(gap(qs[0][0], theta) < 1e-12);
                    }
                    if expected[0] && expected[1] {
                        assert!((qs[1][1] - (-r - l1 - l2)).abs() < 1e-12);
                        assert!(gap(qs[1][0], theta + PI) < 1e-12);
                    } else {
                        single += 1;
                        assert_eq!(qs[0], qs[1]);
                    }
                    assert!(expected[0] || expected[1]);
                }
                Err(ArmError::BeyondJointRange { excess, .. }) => {
                    refused += 1;
                    assert!(!expected[0] && !expected[1], "({x}, {y}) refused");
                    assert!(excess > 0.0);
                }
                Err(e) => panic!("{e:?}"),
            }
        }
        if r1.is_none() && r2.is_none() {
            assert_eq!(refused, 0);
        } else {
            assert!(refused > 100 && solved > 100, "{solved}, {refused}");
        }
        if r2.is_some() {
            assert!(single > 100, "{single} with one branch");
        }
    }
}

#[test]
fn ik_rp_special_cases() {
    // The origin: q2 = -(l1 + l2), any q1.
    let [a, b] = ik_rp(0.2, 0.5, None, None, &Point2::origin()).unwrap();
    assert_eq!((a, b), (Vector2::new(0.0, -0.7), Vector2::new(0.0, -0.7)));
    // Only if the slide reaches back that far.
    assert!(matches!(
        ik_rp(0.2, 0.5, None, Some((0.1, 0.6)), &Point2::origin()),
        Err(ArmError::BeyondJointRange { joint: 1, kind: Joint::Prismatic, excess, .. })
            if (excess - 0.8).abs() < 1e-15
    ));
    // q1 free but ranged: a representative of 0, else the lower bound.
    let [a, _] = ik_rp(0.2, 0.5, Some((6.0, 7.0)), None, &Point2::origin()).unwrap();
    assert_eq!(a[0], TAU);
    let [a, _] = ik_rp(0.2, 0.5, Some((1.0, 2.0)), None, &Point2::origin()).unwrap();
    assert_eq!(a[0], 1.0);
    // Too far, by 0.2 m of slide.
    assert!(matches!(
        ik_rp(0.2, 0.5, None, Some((0.1, 0.6)), &Point2::new(0.0, 1.5)),
        Err(ArmError::BeyondJointRange { joint: 1, excess, .. }) if (excess - 0.2).abs() < 1e-12
    ));
    // Outside the angle range by 0.5 rad on one side, pi - 0.5 - 1 on the other.
    let e = ik_rp(
        0.2,
        0.5,
        Some((0.0, 1.0)),
        None,
        &Point2::new(0.5_f64.cos(), -0.5_f64.sin()),
    );
    assert!(
        matches!(e, Err(ArmError::BeyondJointRange { joint: 0, kind: Joint::Revolute, excess, .. }) if (excess - 0.5).abs() < 1e-12)
    );
    // Just beyond the slide's end, within the tolerance: clamped onto it.
    let edge = 1.3 * (1.0 + 0.5 * REACH_TOLERANCE);
    let [q, _] = ik_rp(0.2, 0.5, None, Some((0.1, 0.6)), &Point2::new(edge, 0.0)).unwrap();
    assert_eq!(q[1], 0.6);
    for bad in [f64::NAN, f64::INFINITY] {
        let t = Point2::new(bad, 0.0);
        assert_eq!(
            ik_rp(0.2, 0.5, None, None, &t),
            Err(ArmError::NonFinite { argument: "target" })
        );
        let p = Point2::new(1.0, 0.0);
        assert_eq!(
            ik_rp(bad, 0.5, None, None, &p),
            Err(ArmError::NonFinite {
                argument: "lengths"
            })
        );
        assert_eq!(
            ik_rp(0.2, 0.5, Some((0.0, f64::NAN)), None, &p),
            Err(ArmError::NonFinite { argument: "ranges" })
        );
    }
    assert!(matches!(
        ik_rp(0.2, 0.5, None, Some((1.0, 0.0)), &Point2::new(1.0, 0.0)),
        Err(ArmError::OutOfRange {
            what: "range",
            link: Some(1),
            ..
        })
    ));
}

#[test]
fn ik_pr_round_trip_and_ranges() {
    let mut rng = Rng(22);
    for (l1, l2, r2, r1) in TWO {
        let (mut solved, mut refused, mut single) = (0, 0, 0);
        let scale = l1.abs() + l2.abs() + 4.0;
        for _ in 0..5000 {
            let (x, y) = (rng.range(-4.0, 4.0), rng.range(-1.2, 1.2) * l2.abs());
            let a2 = l2.abs();
            let result = ik_pr(l1, l2, r1, r2, &Point2::new(x, y));
            if y.abs() > a2 {
                assert!(matches!(result, Err(ArmError::Unreachable { distance, .. })
                    if (distance - (y.abs() - a2)).abs() < 1e-15));
                continue;
            }
            // The two carriage positions, and whether each fits the ranges.
            let h = (a2 * a2 - y * y).sqrt();
            let fits = |q1: f64, cx: f64| {
                let angle = (y / l2).atan2((x - cx) / l2);
                within(q1, r1)
                    && r2.is_none_or(|(lo, hi)| {
                        let k = ((lo - angle) / TAU).ceil();
                        angle + k * TAU <= hi
                    })
            };
            let expected = [fits(x - h - l1, x - h), fits(x + h - l1, x + h)];
            match result {
                Ok(qs) => {
                    solved += 1;
                    for q in qs {
                        let (tx, ty, _) = fk(&PR, &[l1, l2], q.as_slice());
                        assert!(close((tx, ty), (x, y), scale), "{q} misses ({x}, {y})");
                        assert!(within(q[0], r1) && within(q[1], r2));
                    }
                    if expected[0] {
                        assert!((qs[0][0] - (x - h - l1)).abs() < 1e-12 * scale);
                        assert!(l2 * qs[0][1].cos() >= -1e-12);
                    }
                    if expected[0] && expected[1] {
                        assert!((qs[1][0] - (x + h - l1)).abs() < 1e-12 * scale);
                        assert!(l2 * qs[1][1].cos() <= 1e-12);
                    } else {
                        single += 1;
                        assert_eq!(qs[0], qs[1]);
                    }
                }
                Err(
                    ArmError::Unreachable { distance: miss, .. }
                    | ArmError::BeyondJointRange { excess: miss, .. },
                ) => {
                    refused += 1;
                    assert!(!expected[0] && !expected[1], "({x}, {y}) refused");
                    assert!(miss > 0.0);
                }
                Err(e) => panic!("{e:?}"),
            }
        }
        assert!(solved > 300, "{solved}");
        if r1.is_some() || r2.is_some() {
            assert!(
                refused > 50 && single > 50,
                "{refused} refused, {single} single"
            );
        }
    }
    // No second link: the tip is the carriage; any angle.
    let [a, b] = ik_pr(0.3, 0.0, None, Some((1.0, 2.0)), &Point2::new(1.0, 0.0)).unwrap();
    assert_eq!((a, b), (Vector2::new(0.7, 1.0), Vector2::new(0.7, 1.0)));
    assert!(ik_pr(0.3, 0.0, None, None, &Point2::new(1.0, 1e-3)).is_err());
    assert_eq!(
        ik_pr(0.3, 0.5, None, None, &Point2::new(f64::NAN, 0.0)),
        Err(ArmError::NonFinite { argument: "target" })
    );
}

#[test]
fn ik_prr_round_trip_and_ranges() {
    let mut rng = Rng(23);
    let arms: [(f64, f64, f64, [Range; 3]); 4] = [
        (0.2, 0.5, 0.3, [None; 3]),
        (0.2, 0.5, 0.3, [Some((0.0, 1.0)), None, None]),
        (
            0.4,
            0.6,
            0.25,
            [Some((-1.0, 1.0)), Some((-1.0, 2.0)), Some((-2.0, 2.0))],
        ),
        (0.4, -0.6, 0.25, [None, Some((3.0, 4.0)), Some((-1.0, 1.0))]),
    ];
    for (l1, l2, l3, ranges) in arms {
        let scale = l1.abs() + l2.abs() + l3.abs() + 3.0;
        let (mut solved, mut refused, mut single) = (0, 0, 0);
        for _ in 0..6000 {
            let (x, y, phi) = (
                rng.range(-2.0, 3.0),
                rng.range(-1.0, 1.0),
                rng.range(-7.0, 7.0),
            );
            let target = Isometry2::new(Vector2::new(x, y), phi);
            let w = (x - l3 * phi.cos(), y - l3 * phi.sin());
            match ik_prr(l1, l2, l3, ranges, &target) {
                Ok(qs) => {
                    solved += 1;
                    assert!(w.1.abs() <= l2.abs() * (1.0 + 1e-9));
                    for q in qs {
                        let (tx, ty, tphi) = fk(&PRR, &[l1, l2, l3], q.as_slice());
                        assert!(close((tx, ty), (x, y), scale), "{q} misses ({x}, {y})");
                        assert!(gap(tphi, phi) < 1e-12);
                        for k in 0..3 {
                            assert!(within(q[k], ranges[k]), "{q} outside {ranges:?}");
                        }
                    }
                    let carriage = |q: &SVector<f64, 3>| q[0] + l1;
                    if qs[0] == qs[1] {
                        single += 1;
                    } else {
                        assert!(carriage(&qs[0]) <= w.0 + 1e-12 && carriage(&qs[1]) >= w.0 - 1e-12);
                    }
                }
                Err(ArmError::Unreachable {
                    target: asked,
                    orientation,
                    radius,
                    distance,
                    ..
                }) => {
                    refused += 1;
                    assert_eq!(asked, [x, y]);
                    assert!(gap(orientation.unwrap(), phi) < 1e-15);
                    assert!((radius - w.0.hypot(w.1)).abs() < 1e-12 && distance > 0.0);
                    // Only beyond the band the wrist can reach.
                    assert!(w.1.abs() > l2.abs());
                }
                Err(ArmError::BeyondJointRange { excess, .. }) => {
                    refused += 1;
                    assert!(excess > 0.0);
                    {
                        // Reachable without ranges: check that the ranges exclude both.
                        let free = ik_prr(l1, l2, l3, [None; 3], &target).unwrap();
                        for q in free {
                            let fits = (0..3).all(|k| match ranges[k] {
                                None => true,
                                Some((lo, hi)) if k == 0 => lo <= q[0] && q[0] <= hi,
                                Some((lo, hi)) => {
                                    let a = q[k] + TAU * ((lo - q[k]) / TAU).ceil();
                                    a <= hi
                                }
                            });
                            assert!(!fits, "{q} fits {ranges:?}");
                        }
                    }
                }
                Err(e) => panic!("{e:?}"),
            }
        }
        assert!(
            solved > 300 && refused > 500,
            "{solved} solved, {refused} refused"
        );
        if ranges.iter().any(Option::is_some) {
            assert!(single > 50, "{single}");
        }
    }
    let nan = Isometry2::new(Vector2::new(0.5, f64::NAN), 0.0);
    assert_eq!(
        ik_prr(0.2, 0.5, 0.3, [None; 3], &nan),
        Err(ArmError::NonFinite { argument: "target" })
    );
}
