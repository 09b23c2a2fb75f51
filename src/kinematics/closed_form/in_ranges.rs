//! The revolute closed forms within joint ranges: the branches of [`ik2`] and [`ik3`] whose
//! angles fit the ranges, each angle taken as the representative `q + 2 pi k` that does.
//!
//! Apart from the closed forms because the fitting is not theirs: it is the joint-range logic
//! shared with the prismatic closed forms, applied to the branches they return.

use nalgebra::{Isometry2, Point2, SVector};

use super::{ik2, ik3};
use crate::kinematics::range::{check_ranges, fit_branches, Range, RangeMiss};
#[cfg(doc)]
use crate::kinematics::REACH_TOLERANCE;
use crate::{ArmError, Joint};

/// [`ik2`] within joint ranges: the elbow solutions whose angles lie in `ranges` (radians,
/// `None` for a free joint, an infinite bound no bound), for an arm whose joints have limits
/// (a derived arm's [`Link::range`](crate::Link::range)).
///
/// An angle satisfies a range when some `q + 2 pi k` lies in it, and that representative is
/// returned: the angle in (-pi, pi] when it lies in the range, else the representative nearest
/// the side of the range it lies beyond. Angles within [`REACH_TOLERANCE`] radians of a range
/// are clamped onto it. The branch order is [`ik2`]'s (index 0 has `sin q2 >= 0`); when only one
/// branch lies within the ranges, both entries hold it.
///
/// # Errors
/// As [`ik2`], and: [`ArmError::NonFinite`] (`"ranges"`) for a NaN bound,
/// [`ArmError::OutOfRange`] (`"range"`, the 0-based joint) for `lower > upper`,
/// [`ArmError::BeyondJointRange`] for a target in the annulus that neither branch reaches
/// within the ranges, naming the joint that lies farthest outside its range in the nearer
/// branch, and by how many radians.
///
/// # Example
/// ```
/// use planar_arm::kinematics::{ik2, ik2_in_ranges};
/// use planar_arm::nalgebra::Point2;
///
/// let target = Point2::new(1.0, 0.5);
/// let [up, down] = ik2(1.0, 0.5, &target).unwrap();
/// // An elbow that bends one way only keeps one branch, in both entries.
/// let bent = [None, Some((0.0, std::f64::consts::PI))];
/// assert_eq!(ik2_in_ranges(1.0, 0.5, bent, &target).unwrap(), [up, up]);
/// let other = [None, Some((-std::f64::consts::PI, 0.0))];
/// assert_eq!(ik2_in_ranges(1.0, 0.5, other, &target).unwrap(), [down, down]);
/// ```
#[inline]
pub fn ik2_in_ranges(
    l1: f64,
    l2: f64,
    ranges: [Option<(f64, f64)>; 2],
    target: &Point2<f64>,
) -> Result<[SVector<f64, 2>; 2], ArmError> {
    check_ranges(&ranges)?;
    let solutions = ik2(l1, l2, target)?;
    fit_revolute(solutions, &ranges).map_err(|miss| miss.error())
}

/// [`ik3`] within joint ranges, as [`ik2_in_ranges`] is [`ik2`] within them: the solutions
/// whose three angles lie in `ranges` (representatives, tolerance and branch order as there).
///
/// # Errors
/// As [`ik3`] and [`ik2_in_ranges`]: [`ArmError::BeyondJointRange`] for a pose whose wrist lies
/// in the two-link annulus but that neither branch reaches within the ranges.
///
/// # Example
/// ```
/// use planar_arm::kinematics::ik3_in_ranges;
/// use planar_arm::nalgebra::{Isometry2, Vector2};
///
/// let target = Isometry2::new(Vector2::new(1.2, 0.4), 0.3);
/// let wrist_up = [None, Some((0.0, 3.2)), Some((-4.0, 4.0))];
/// let [q, same] = ik3_in_ranges(1.0, 0.8, 0.2, wrist_up, &target).unwrap();
/// assert_eq!(q, same);
/// assert!(q[1] >= 0.0 && (q[0] + q[1] + q[2] - 0.3).abs() < 1e-12);
/// ```
#[inline]
pub fn ik3_in_ranges(
    l1: f64,
    l2: f64,
    l3: f64,
    ranges: [Option<(f64, f64)>; 3],
    target: &Isometry2<f64>,
) -> Result<[SVector<f64, 3>; 2], ArmError> {
    check_ranges(&ranges)?;
    let solutions = ik3(l1, l2, l3, target)?;
    fit_revolute(solutions, &ranges).map_err(|miss| miss.error())
}

/// The branches of an all-revolute closed form that fit `ranges`, or the smallest excess.
fn fit_revolute<const N: usize>(
    solutions: [SVector<f64, N>; 2],
    ranges: &[Range; N],
) -> Result<[SVector<f64, N>; 2], RangeMiss> {
    let branches = solutions.map(|q| core::array::from_fn(|i| q[i]));
    fit_branches(&[Joint::Revolute; N], ranges, 0.0, branches).map(|b| b.map(SVector::from))
}
