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
use super::workspace::swept_radii;
#[cfg(doc)]
use super::REACH_TOLERANCE;
use super::{check_lengths, wrap_angle};
use crate::{ArmError, Joint};

#[cfg(test)]
mod tests;

/// The error for a point (the tip, or for a pose the wrist) farther than `|l2|` from the
/// slider's line: `distance` beyond the band it can reach.
fn beyond_band(
    target: [f64; 2],
    orientation: Option<f64>,
    radius: f64,
    (inner, outer): (f64, f64),
    distance: f64,
) -> ArmError {
    ArmError::Unreachable {
        target,
        orientation,
        radius,
        inner,
        outer,
        distance,
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
/// for a range with `lower > upper`; [`ArmError::BeyondJointRange`] when neither branch lies
/// within the ranges, naming the joint that lies farthest outside its range in the nearer
/// branch, and by how much (radians or metres).
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
        .map_err(|miss| miss.error())
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
/// [`ArmError::Unreachable`] beyond the band, with `radius = |target|`, `inner ..= outer` the
/// radii about the base between which the reachable region lies (see
/// [`Workspace::of_links`](super::Workspace::of_links); `0 ..= inf` without `range1`) and
/// `distance = |y| - |l2|`; [`ArmError::BeyondJointRange`] inside the band when neither branch
/// lies within the ranges, as [`ik_rp`].
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
    let error = |distance| beyond_band([x, y], None, x.hypot(y), radii(), distance);
    let branches = finite(slider_branches(l1, l2, x, y, range2, slack).map_err(error)?)?;
    let kinds = [Joint::Prismatic, Joint::Revolute];
    fit_branches(&kinds, &ranges, slack, branches)
        .map(|b| b.map(SVector::from))
        .map_err(|miss| miss.error())
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
/// [`ArmError::Unreachable`] when the wrist lies beyond the band it can reach, with `target`
/// and `orientation` the pose asked for, `radius` the wrist's distance from the base,
/// `inner ..= outer` the radii about the base between which the wrist positions of the first
/// two links lie, and `distance = |w_y| - |l2|`; [`ArmError::BeyondJointRange`] inside the band
/// when neither branch lies within the ranges, as [`ik_rp`].
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
    let error = |radius, distance| beyond_band([t.x, t.y], Some(phi), radius, radii(), distance);
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
        .map_err(|miss| miss.error())
}
