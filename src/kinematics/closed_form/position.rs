//! Three revolute links placing the tip at a point (any orientation), within joint ranges.
//!
//! The solutions form a one-parameter family: any `q1` that leaves the tip within reach of the
//! last two links. The work-space's description at the target's distance (`ranged`) gives the
//! `q1` that also leave it within their ranges, exactly; the last two links then follow from
//! [`ik2_in_ranges`].

use core::f64::consts::{PI, TAU};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::{Point2, SVector, Vector3};

#[cfg(doc)]
use super::ik3;
use super::{ik2, ik2_in_ranges, target_coordinates};
use crate::kinematics::range::{check_ranges, fit, Range, RangeMiss};
use crate::kinematics::workspace::ranged::RangedChain;
#[cfg(doc)]
use crate::kinematics::REACH_TOLERANCE;
use crate::kinematics::{annulus_check, check_lengths, wrap_angle};
use crate::{ArmError, Joint};

/// Closed-form inverse kinematics of three revolute links (lengths `l1`, `l2`, `l3`) for a tip
/// position: one configuration that puts the tip at `target` with every angle in its range
/// (`None` a free joint), whenever one exists.
///
/// A point reached by three links is reached by a whole family of configurations, one for each
/// orientation of the last link that works; this returns the one in the middle of the first arc
/// of workable `q1` (counter-clockwise from the target's direction). For a pose, a point and
/// the last link's angle, use [`ik3`] or [`ik3_in_ranges`](super::ik3_in_ranges). Angles are
/// in (-pi, pi] unless a range asks for another turn (as [`ik2_in_ranges`]), and within
/// [`REACH_TOLERANCE`] of the target's region the target counts as reached. It succeeds exactly
/// where [`Workspace::contains`](crate::kinematics::Workspace::contains) holds for the same
/// links.
///
/// # Errors
/// [`ArmError::NonFinite`] for NaN or infinite arguments, [`ArmError::OutOfRange`] for a range
/// with `lower > upper`; [`ArmError::Unreachable`] for a target outside the annulus the links
/// reach with free joints (with its distance); [`ArmError::BeyondJointRange`] for a target inside
/// it that no configuration within the ranges reaches, naming the joint that lies farthest
/// outside its range in the configuration nearest to the ranges (the smallest such excess over
/// the family, minimised numerically to about 1e-9 rad).
///
/// # Example
/// ```
/// use planar_arm::kinematics::ik3_position;
/// use planar_arm::nalgebra::Point2;
///
/// // An elbow and a wrist that bend one way only.
/// let ranges = [None, Some((0.0, 2.5)), Some((0.0, 2.5))];
/// let q = ik3_position(1.0, 0.8, 0.5, ranges, &Point2::new(0.6, 0.9)).unwrap();
/// let (a, b, c) = (q[0], q[0] + q[1], q[0] + q[1] + q[2]);
/// let tip = (a.cos() + 0.8 * b.cos() + 0.5 * c.cos(), a.sin() + 0.8 * b.sin() + 0.5 * c.sin());
/// assert!((tip.0 - 0.6).abs() < 1e-12 && (tip.1 - 0.9).abs() < 1e-12);
/// assert!((0.0..=2.5).contains(&q[1]) && (0.0..=2.5).contains(&q[2]));
/// ```
pub fn ik3_position(
    l1: f64,
    l2: f64,
    l3: f64,
    ranges: [Option<(f64, f64)>; 3],
    target: &Point2<f64>,
) -> Result<SVector<f64, 3>, ArmError> {
    check_lengths(&[l1, l2, l3])?;
    check_ranges(&ranges)?;
    let (x, y) = target_coordinates(target)?;
    let (rho, theta) = (x.hypot(y), y.atan2(x));
    let (inner, outer) = free_radii([l1, l2, l3]);
    annulus_check(rho, inner, outer, [x, y])?;
    let chain = RangedChain {
        lengths: [l1, l2, l3],
        ranges,
        three: true,
    };
    let later = [ranges[1], ranges[2]];
    for (s, e) in chain.later_angles(rho).iter() {
        let Some(q1) = first_angle_within(theta - e, theta - s, ranges[0]) else {
            continue;
        };
        let (sin, cos) = (theta - q1).sin_cos();
        let v = Point2::new(rho * cos - l1, rho * sin);
        if let Ok([q, _]) = ik2_in_ranges(l2, l3, later, &v) {
            return Ok(Vector3::new(q1, q[0], q[1]));
        }
    }
    Err(nearest_miss([l1, l2, l3], &ranges, rho, theta).error())
}

/// The annulus three revolute links reach with free joints.
fn free_radii(lengths: [f64; 3]) -> (f64, f64) {
    let sum: f64 = lengths.iter().map(|l| l.abs()).sum();
    let longest = lengths.iter().fold(0.0_f64, |m, l| m.max(l.abs()));
    ((longest - (sum - longest)).max(0.0), sum)
}

/// A value of the arc `from ..= to` (of angle, `to - from <= 2 pi`) that, up to a multiple of
/// 2 pi, lies in `range`: the middle of the first overlap, as the representative in `range`
/// (or in (-pi, pi] for a free joint).
fn first_angle_within(from: f64, to: f64, range: Range) -> Option<f64> {
    let Some((lo, hi)) = range.filter(|(lo, hi)| hi - lo < TAU) else {
        return Some(wrap_angle(0.5 * (from + to)));
    };
    // The copies of the arc that can meet [lo, hi]: starting at most 2 pi before hi.
    let shift = TAU * ((lo - to) / TAU).ceil();
    for k in 0..2 {
        let (a, b) = (
            from + shift + TAU * f64::from(k),
            to + shift + TAU * f64::from(k),
        );
        let (p, q) = (a.max(lo), b.min(hi));
        if p <= q + crate::kinematics::REACH_TOLERANCE {
            return Some((0.5 * (p + q)).clamp(lo, hi));
        }
    }
    None
}

/// Among the configurations that put the tip at distance `rho` and polar angle `theta` with
/// free joints, the one whose largest range excess is smallest: each elbow branch scanned over
/// `q1`, then every local minimum of the scan refined by golden-section search.
fn nearest_miss(lengths: [f64; 3], ranges: &[Range; 3], rho: f64, theta: f64) -> RangeMiss {
    const SAMPLES: usize = 720;
    let kinds = [Joint::Revolute; 3];
    let miss_at = |q1: f64, branch: usize| -> Option<RangeMiss> {
        let (sin, cos) = (theta - q1).sin_cos();
        let v = Point2::new(rho * cos - lengths[0], rho * sin);
        let q = ik2(lengths[1], lengths[2], &v).ok()?[branch];
        Some(worst([q1, q[0], q[1]], &kinds, ranges))
    };
    let excess = |q1: f64, branch: usize| miss_at(q1, branch).map_or(f64::INFINITY, |m| m.excess);
    let step = TAU / SAMPLES as f64;
    let angle = |k: usize| -PI + step * k as f64;
    let mut found: Option<RangeMiss> = None;
    let mut keep = |m: Option<RangeMiss>| {
        if let Some(m) = m {
            if m.excess > 0.0 && found.is_none_or(|f| m.excess < f.excess) {
                found = Some(m);
            }
        }
    };
    let ratio = 0.5 * (5.0_f64.sqrt() - 1.0);
    for branch in 0..2 {
        let values: [f64; SAMPLES] = core::array::from_fn(|k| excess(angle(k), branch));
        for k in 0..SAMPLES {
            let (before, after) = (
                values[(k + SAMPLES - 1) % SAMPLES],
                values[(k + 1) % SAMPLES],
            );
            if !values[k].is_finite() || values[k] > before || values[k] > after {
                continue;
            }
            keep(miss_at(angle(k), branch));
            let (mut a, mut b) = (angle(k) - step, angle(k) + step);
            for _ in 0..50 {
                let (c, d) = (b - ratio * (b - a), a + ratio * (b - a));
                if excess(c, branch) < excess(d, branch) {
                    b = d;
                } else {
                    a = c;
                }
            }
            // At an end of the elbow's reach the bracket's middle may fall just outside it.
            for q1 in [a, 0.5 * (a + b), b] {
                keep(miss_at(q1, branch));
            }
        }
    }
    // None only when no configuration exists at all, which the annulus check has ruled out;
    // and a miss of 0 would contradict the exact search that found none.
    found.unwrap_or(RangeMiss {
        joint: 0,
        kind: Joint::Revolute,
        excess: f64::MIN_POSITIVE,
    })
}

/// The joint of `q` farthest outside its range, and by how much (0 when all fit).
fn worst(q: [f64; 3], kinds: &[Joint; 3], ranges: &[Range; 3]) -> RangeMiss {
    let mut out = RangeMiss {
        joint: 0,
        kind: Joint::Revolute,
        excess: 0.0,
    };
    for i in 0..3 {
        if let Err(e) = fit(kinds[i], q[i], ranges[i], 0.0) {
            // `fit` never reports less than the smallest positive excess.
            if e > out.excess {
                out = RangeMiss {
                    joint: i,
                    kind: kinds[i],
                    excess: e,
                };
            }
        }
    }
    out
}
