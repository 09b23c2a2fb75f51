//! Closed-form inverse kinematics of arms with a prismatic joint: the polar arm (revolute then
//! prismatic), a slider carrying a link (prismatic then revolute) and a slider carrying two
//! links for a full pose.
//!
//! A prismatic joint `i` slides link `i` along the previous link's direction (for the first
//! link, +x of the base) by `q_i` metres without turning it. So the polar arm's tip is
//! `(l1 + q2 + l2) (cos q1, sin q1)`, and a slider's carriage, the joint after the first
//! link, sits at `(q1 + l1, 0)`.

use core::f64::consts::PI;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::{Isometry2, Point2, SVector, Vector2, Vector3};

use super::closed_form::target_coordinates;
use super::range::{check_ranges, finite, fit, fit_branches, slide_slack, Range};
use super::workspace::{polar_radii, swept_radii};
#[cfg(doc)]
use super::REACH_TOLERANCE;
use super::{check_lengths, wrap_angle};
use crate::{ArmError, Joint};

/// The error for a target that only joint values outside the ranges reach.
pub(super) fn excluded(
    target: [f64; 2],
    orientation: Option<f64>,
    radius: f64,
    (inner, outer): (f64, f64),
    excess: f64,
) -> ArmError {
    ArmError::Unreachable {
        target,
        orientation,
        radius,
        inner,
        outer,
        distance: excess,
    }
}

/// `(lower, upper)` of `l + q` for `q` in `range` (all of the line without one).
fn shifted(l: f64, range: Range) -> (f64, f64) {
    range.map_or((f64::NEG_INFINITY, f64::INFINITY), |(lo, hi)| {
        (l + lo, l + hi)
    })
}

/// Closed-form inverse kinematics of the polar arm: a revolute joint turning a first link of
/// length `l1`, then a prismatic joint sliding the second link (length `l2`) along it, so
/// that the tip is at `(l1 + q2 + l2) (cos q1, sin q1)`. Both solutions for the tip position
/// `target`, within the joint ranges `range1` (radians) and `range2` (metres).
///
/// Index 0 points the arm at the target, `(atan2(y, x), r - l1 - l2)` with `r = |target|`;
/// index 1 points it away and slides back through the base,
/// `(atan2(y, x) + pi, -r - l1 - l2)`. Angles are in (-pi, pi] unless the range asks for
/// another turn: an angle `q1` satisfies `range1` when some `q1 + 2 pi k` lies in it, and that
/// representative is returned. When only one branch lies within the ranges both entries hold
/// it. A slide outside `range2` by at most [`REACH_TOLERANCE`] times the arm's scale (`|l1| +
/// |l2|` plus the larger finite bound of `range2`), or an angle outside `range1` by at most
/// [`REACH_TOLERANCE`] radians, is clamped onto the range.
///
/// The origin is reached with `q2 = -(l1 + l2)` and any `q1`: both entries are then
/// `(0, -(l1 + l2))` (with `q1` the representative of 0 in `range1`, or its lower bound if it
/// holds none).
///
/// # Errors
/// [`ArmError::NonFinite`] (`"lengths"`, `"target"`, `"ranges"`) for NaN or infinite
/// arguments (an infinite bound is allowed: no bound), `"result"` when finite arguments
/// overflow a joint value; [`ArmError::OutOfRange`] (`"range"`)
/// for a range with `lower > upper`; [`ArmError::Unreachable`] when neither branch lies within
/// the ranges, with `radius = |target|`, `inner ..= outer` the radii `|l1 + l2 + q2|` that
/// `range2` allows (`0 ..= inf` without it) and `distance` how far the nearer branch's joint
/// value lies outside its range (radians or metres: the branch's larger excess, the smaller
/// over the branches).
///
/// # Example
/// ```
/// use planar_arm::kinematics::ik_rp;
/// use planar_arm::nalgebra::Point2;
///
/// // A 0.2 m arm carrying a 0.5 m slide that travels 0.1 ..= 0.6 m.
/// let target = Point2::new(0.6, 0.8);
/// let [q, same] = ik_rp(0.2, 0.5, None, Some((0.1, 0.6)), &target).unwrap();
/// assert_eq!(q, same); // pointing away would need a negative slide
/// let reach = 0.2 + q[1] + 0.5;
/// assert!((reach * q[0].cos() - 0.6).abs() < 1e-12 && (reach * q[0].sin() - 0.8).abs() < 1e-12);
/// // Free ranges: both branches.
/// let [toward, away] = ik_rp(0.2, 0.5, None, None, &target).unwrap();
/// assert!((toward[1] - 0.3).abs() < 1e-12 && (away[1] + 1.7).abs() < 1e-12);
/// ```
#[inline]
pub fn ik_rp(
    l1: f64,
    l2: f64,
    range1: Option<(f64, f64)>,
    range2: Option<(f64, f64)>,
    target: &Point2<f64>,
) -> Result<[SVector<f64, 2>; 2], ArmError> {
    check_lengths(&[l1, l2])?;
    check_ranges(&[range1, range2])?;
    let (x, y) = target_coordinates(target)?;
    let r = x.hypot(y);
    let reach = l1 + l2;
    let branches = if r == 0.0 {
        let q1 = free_angle(range1);
        [[q1, -reach]; 2]
    } else {
        let theta = y.atan2(x);
        [[theta, r - reach], [wrap_angle(theta + PI), -r - reach]]
    };
    let kinds = [Joint::Revolute, Joint::Prismatic];
    let ranges = [range1, range2];
    let slack = slide_slack(&[l1, l2], &[range2]);
    let branches = finite(branches)?;
    fit_branches(&kinds, &ranges, slack, branches)
        .map(|b| b.map(SVector::from))
        .map_err(|excess| {
            let (lo, hi) = shifted(reach, range2);
            excluded([x, y], None, r, polar_radii(lo, hi), excess)
        })
}

/// The angle a joint takes when any angle will do: the representative of 0 in `range`, or its
/// lower bound (which a checked range always has finite when 0 has no representative in it).
fn free_angle(range: Range) -> f64 {
    fit(Joint::Revolute, 0.0, range, 0.0).unwrap_or_else(|_| range.map_or(0.0, |r| r.0))
}

/// Both slider-and-link solutions `[q1, q2]` for the point `(x, y)`, the ranges not yet
/// applied but for a free `q2` (when `l2 == 0`): carriage behind the point first. `Err` with
/// the distance beyond the band `|y| <= |l2|` when that exceeds `slack`.
fn slider_branches(
    l1: f64,
    l2: f64,
    x: f64,
    y: f64,
    range2: Range,
    slack: f64,
) -> Result<[[f64; 2]; 2], f64> {
    let a2 = l2.abs();
    let beyond = y.abs() - a2;
    if beyond > slack {
        return Err(beyond);
    }
    if l2 == 0.0 {
        return Ok([[x - l1, free_angle(range2)]; 2]);
    }
    let y = y.max(-a2).min(a2);
    // sqrt(l2^2 - y^2) in factored form, accurate near |y| = |l2|.
    let h = ((a2 - y.abs()) * (a2 + y.abs())).max(0.0).sqrt();
    let sign = l2.signum();
    // `+ 0.0` turns a negative zero into 0, so that atan2 answers pi rather than -pi.
    let (sy, sh) = (sign * y + 0.0, sign * h + 0.0);
    Ok([
        [x - h - l1, sy.atan2(sh)],
        [x + h - l1, sy.atan2(-sh + 0.0)],
    ])
}

/// Closed-form inverse kinematics of a slider carrying a link: a prismatic joint moving the
/// first link (length `l1`) along +x, then a revolute joint turning the second (length `l2`)
/// about the carriage at `(q1 + l1, 0)`, so that the tip is at
/// `(q1 + l1 + l2 cos q2, l2 sin q2)`. Both solutions for the tip position `target`, within
/// the ranges `range1` (metres) and `range2` (radians).
///
/// The tip must lie in the band `|y| <= |l2|` (up to [`REACH_TOLERANCE`] times the arm's
/// scale, `|l1| + |l2|` plus the larger finite bound of `range1`); then
/// `sin q2 = y / l2` and the carriage sits `sqrt(l2^2 - y^2)` behind the tip (index 0, `q1 =
/// x - l1 - sqrt(l2^2 - y^2)`, so `l2 cos q2 >= 0`) or ahead of it (index 1). On the band's
/// edges both are the same configuration. Ranges, their tolerances and the choice of
/// representative angle as in [`ik_rp`]; when only one branch lies within them both entries
/// hold it. With `l2 == 0` the angle is free: both entries hold `q2 = 0` (the representative
/// of 0 in `range2`, or its lower bound).
///
/// # Errors
/// [`ArmError::NonFinite`] and [`ArmError::OutOfRange`] as [`ik_rp`];
/// [`ArmError::Unreachable`] with `radius = |target|`, `inner ..= outer` the radii about the
/// base between which the reachable region lies (see
/// [`Workspace::of_links`](super::Workspace::of_links); `0 ..= inf` without `range1`) and
/// `distance` either `|y| - |l2|` beyond the band or, inside it, how far the nearer branch's
/// joint value lies outside its range (metres or radians).
///
/// # Example
/// ```
/// use planar_arm::kinematics::ik_pr;
/// use planar_arm::nalgebra::Point2;
///
/// let (l1, l2) = (0.3, 0.5);
/// let [behind, ahead] = ik_pr(l1, l2, None, None, &Point2::new(1.0, 0.3)).unwrap();
/// for q in [behind, ahead] {
///     let x = q[0] + l1 + l2 * q[1].cos();
///     let y = l2 * q[1].sin();
///     assert!((x - 1.0).abs() < 1e-12 && (y - 0.3).abs() < 1e-12);
/// }
/// assert!((behind[0] - 0.3).abs() < 1e-12 && (ahead[0] - 1.1).abs() < 1e-12);
/// // The slider stops at 1 m: only the carriage behind the tip remains.
/// let [q, same] = ik_pr(l1, l2, Some((0.0, 1.0)), None, &Point2::new(1.0, 0.3)).unwrap();
/// assert_eq!((q, same), (behind, behind));
/// ```
#[inline]
pub fn ik_pr(
    l1: f64,
    l2: f64,
    range1: Option<(f64, f64)>,
    range2: Option<(f64, f64)>,
    target: &Point2<f64>,
) -> Result<[SVector<f64, 2>; 2], ArmError> {
    check_lengths(&[l1, l2])?;
    check_ranges(&[range1, range2])?;
    let (x, y) = target_coordinates(target)?;
    let ranges = [range1, range2];
    let slack = slide_slack(&[l1, l2], &[range1]);
    let radii = || {
        let (a, b) = shifted(l1, range1);
        swept_radii(a, b, l2.abs(), l2.abs())
    };
    let error = |distance| excluded([x, y], None, x.hypot(y), radii(), distance);
    let branches = finite(slider_branches(l1, l2, x, y, range2, slack).map_err(error)?)?;
    let kinds = [Joint::Prismatic, Joint::Revolute];
    fit_branches(&kinds, &ranges, slack, branches)
        .map(|b| b.map(SVector::from))
        .map_err(error)
}

/// Closed-form inverse kinematics of a slider carrying two links: a prismatic joint moving
/// the first link (length `l1`) along +x, then revolute joints turning the second (`l2`, about
/// the carriage at `(q1 + l1, 0)`) and the third (`l3`). Both solutions that put the tip at
/// `target.translation` with the last link at the absolute angle `phi = target.rotation`,
/// within the ranges (metres, radians, radians).
///
/// The wrist, the third joint, must be at `w = p - l3 (cos phi, sin phi)`; the slider and the
/// second link reach it as [`ik_pr`] does (`sin q2 = w_y / l2`, `q1 = w_x - l1 - l2 cos q2`),
/// and `q3 = phi - q2`. Index 0 has the carriage behind the wrist (`l2 cos q2 >= 0`), index 1
/// ahead of it. Ranges, tolerances and representative angles as in [`ik_rp`]; when only one
/// branch lies within the ranges both entries hold it.
///
/// # Errors
/// [`ArmError::NonFinite`] and [`ArmError::OutOfRange`] as [`ik_rp`];
/// [`ArmError::Unreachable`] with `target` and `orientation` the pose asked for, `radius` the
/// wrist's distance from the base, `inner ..= outer` the radii about the base between which
/// the wrist positions of the first two links lie, and `distance` either `|w_y| - |l2|` beyond
/// the band the wrist can reach or, inside it, how far the nearer branch's joint value lies
/// outside its range (metres or radians).
///
/// # Example
/// ```
/// use planar_arm::kinematics::ik_prr;
/// use planar_arm::nalgebra::{Isometry2, Vector2};
///
/// let (l1, l2, l3) = (0.2, 0.5, 0.3);
/// let target = Isometry2::new(Vector2::new(0.9, 0.4), 0.5);
/// let [q, _] = ik_prr(l1, l2, l3, [None; 3], &target).unwrap();
/// let (s2, c2) = q[1].sin_cos();
/// let (s23, c23) = (q[1] + q[2]).sin_cos();
/// assert!((q[0] + l1 + l2 * c2 + l3 * c23 - 0.9).abs() < 1e-12);
/// assert!((l2 * s2 + l3 * s23 - 0.4).abs() < 1e-12);
/// assert!((q[1] + q[2] - 0.5).abs() < 1e-12);
/// ```
#[inline]
pub fn ik_prr(
    l1: f64,
    l2: f64,
    l3: f64,
    ranges: [Option<(f64, f64)>; 3],
    target: &Isometry2<f64>,
) -> Result<[SVector<f64, 3>; 2], ArmError> {
    check_lengths(&[l1, l2, l3])?;
    check_ranges(&ranges)?;
    let t = target.translation.vector;
    let rotation = target.rotation.complex();
    if !(t.x.is_finite() && t.y.is_finite() && rotation.re.is_finite() && rotation.im.is_finite()) {
        return Err(ArmError::NonFinite { argument: "target" });
    }
    let phi = target.rotation.angle();
    let (s, c) = phi.sin_cos();
    let wrist = Vector2::new(t.x - l3 * c, t.y - l3 * s);
    let radii = || {
        let (a, b) = shifted(l1, ranges[0]);
        swept_radii(a, b, l2.abs(), l2.abs())
    };
    let error = |radius, distance| excluded([t.x, t.y], Some(phi), radius, radii(), distance);
    if !(wrist.x.is_finite() && wrist.y.is_finite()) {
        return Err(error(f64::INFINITY, f64::INFINITY));
    }
    let radius = wrist.norm();
    let slack = slide_slack(&[l1, l2, l3], &ranges[..1]);
    let [a, b] = slider_branches(l1, l2, wrist.x, wrist.y, ranges[1], slack)
        .map_err(|d| error(radius, d))?;
    let with_hand = |[q1, q2]: [f64; 2]| [q1, q2, wrap_angle(phi - q2)];
    let kinds = [Joint::Prismatic, Joint::Revolute, Joint::Revolute];
    let branches = finite([with_hand(a), with_hand(b)])?;
    fit_branches(&kinds, &ranges, slack, branches)
        .map(|b| b.map(Vector3::from))
        .map_err(|excess| error(radius, excess))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::test_support::{fk_joints as fk, Rng};
    use crate::kinematics::REACH_TOLERANCE;
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
                    Err(ArmError::Unreachable {
                        target,
                        orientation,
                        radius,
                        distance,
                        ..
                    }) => {
                        refused += 1;
                        assert!(!expected[0] && !expected[1], "({x}, {y}) refused");
                        assert_eq!((target, orientation), ([x, y], None));
                        assert!((radius - r).abs() < 1e-15 && distance > 0.0);
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
            Err(ArmError::Unreachable { inner, outer, distance, .. })
                if (inner - 0.8).abs() < 1e-15 && (outer - 1.3).abs() < 1e-15
                    && (distance - 0.8).abs() < 1e-15
        ));
        // q1 free but ranged: a representative of 0, else the lower bound.
        let [a, _] = ik_rp(0.2, 0.5, Some((6.0, 7.0)), None, &Point2::origin()).unwrap();
        assert_eq!(a[0], TAU);
        let [a, _] = ik_rp(0.2, 0.5, Some((1.0, 2.0)), None, &Point2::origin()).unwrap();
        assert_eq!(a[0], 1.0);
        // Too far, by 0.2 m of slide.
        assert!(matches!(
            ik_rp(0.2, 0.5, None, Some((0.1, 0.6)), &Point2::new(0.0, 1.5)),
            Err(ArmError::Unreachable { distance, .. }) if (distance - 0.2).abs() < 1e-12
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
            matches!(e, Err(ArmError::Unreachable { distance, .. }) if (distance - 0.5).abs() < 1e-12)
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
                    Err(ArmError::Unreachable { distance, .. }) => {
                        refused += 1;
                        assert!(!expected[0] && !expected[1], "({x}, {y}) refused");
                        assert!(distance > 0.0);
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
                            assert!(
                                carriage(&qs[0]) <= w.0 + 1e-12 && carriage(&qs[1]) >= w.0 - 1e-12
                            );
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
                        if w.1.abs() <= l2.abs() {
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
}
