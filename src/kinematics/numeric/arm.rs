//! Numeric inverse kinematics of an arm: the reach check, then the solver on the arm's tip
//! pose and Jacobian, with the links' ranges as joint limits.
//!
//! The entry points a user calls; they only combine `reach` and the solver, which stay usable
//! on their own (the solver for any closures, the check for any links).

use nalgebra::SVector;

use super::{reachable_target_of, solve_dls, DlsOptions, IkTarget};
use crate::kinematics::{check_vector, jacobian_of, tip_pose_of};
use crate::{ArmError, Link};

/// `options` with the links' ranges added to its joint limits (their intersection; a NaN bound
/// counts as none).
pub(crate) fn with_ranges<const N: usize>(
    ranges: &[Option<(f64, f64)>; N],
    options: &DlsOptions<N>,
) -> DlsOptions<N> {
    if ranges.iter().all(Option::is_none) {
        return *options;
    }
    let free = (f64::NEG_INFINITY, f64::INFINITY);
    let limits = core::array::from_fn(|i| {
        let (lo, hi) = ranges[i].unwrap_or(free);
        let (olo, ohi) = options.limits.map_or(free, |l| l[i]);
        (lo.max(olo), hi.min(ohi))
    });
    DlsOptions {
        limits: Some(limits),
        ..*options
    }
}

/// [`PlanarArm::inverse_kinematics_near`](crate::PlanarArm::inverse_kinematics_near): the
/// reach check of [`reachable_target_of`] on the arm's links, then [`solve_dls`] on its
/// generated tip pose and Jacobian, with the links' ranges
/// ([`Link::range`](crate::Link::range)) as joint limits on top of those in `options` (the
/// intersection of both).
///
/// # Errors
/// As [`reachable_target_of`] and [`solve_dls`]; [`ArmError::OutOfRange`]
/// (`"joint limits"`) when a joint's range and its limit in `options` do not overlap.
pub fn inverse_kinematics_near<A: crate::PlanarArm<N> + ?Sized, const N: usize>(
    arm: &A,
    target: &IkTarget,
    seed: &SVector<f64, N>,
    options: &DlsOptions<N>,
) -> Result<SVector<f64, N>, ArmError> {
    check_vector(seed, "seed")?;
    let links = arm.links();
    let target = reachable_target_of(&links, target)?;
    solve_dls(
        |q| arm.tip_pose(q),
        |q| arm.jacobian(q),
        &target,
        seed,
        &with_ranges(&links.map(|l| l.range), options),
    )
}

/// [`inverse_kinematics_near`] for an arm given by its links alone (any mix of joints): the same
/// reach check and joint limits, with [`tip_pose_of`] and [`jacobian_of`] in place of generated
/// code. Every solution lies within the links' ranges.
///
/// # Errors
/// As [`inverse_kinematics_near`].
///
/// # Example
/// ```
/// use planar_arm::kinematics::{inverse_kinematics_of, tip_pose_of, DlsOptions, IkTarget};
/// use planar_arm::nalgebra::{Point2, Vector2};
/// use planar_arm::{Joint, Link};
///
/// let polar = [
///     Link::rod(0.2, 1.0).with_range(-1.0, 1.0),
///     Link::rod(0.5, 1.0).with_joint(Joint::Prismatic).with_range(0.1, 0.6),
/// ];
/// let target = IkTarget::Position(Point2::new(0.6, 0.8));
/// let q = inverse_kinematics_of(&polar, &target, &Vector2::new(0.0, 0.1), &DlsOptions::default())
///     .unwrap();
/// assert!((tip_pose_of(&polar, &q).translation.vector - Vector2::new(0.6, 0.8)).norm() < 1e-10);
/// assert!((q[1] - 0.3).abs() < 1e-9);
/// ```
pub fn inverse_kinematics_of<const N: usize>(
    links: &[Link; N],
    target: &IkTarget,
    seed: &SVector<f64, N>,
    options: &DlsOptions<N>,
) -> Result<SVector<f64, N>, ArmError> {
    check_vector(seed, "seed")?;
    let target = reachable_target_of(links, target)?;
    solve_dls(
        |q| tip_pose_of(links, q),
        |q| jacobian_of(links, q),
        &target,
        seed,
        &with_ranges(&links.map(|l| l.range), options),
    )
}
