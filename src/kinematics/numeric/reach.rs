//! The reach check before a numeric solve: whether an arm can reach a target at all, and the
//! target moved onto the work-space's boundary when it lies outside by no more than the
//! tolerance.
//!
//! Apart from the solver because it answers from the work-space alone, without iterating: the
//! solver cannot tell an unreachable target from a slow one, and the check never refuses a
//! target the arm can reach.

use nalgebra::{Isometry2, Point2, Vector2};

use super::{target_is_finite, IkTarget};
use crate::kinematics::workspace::Miss;
use crate::kinematics::{annulus_check_with_slack, check_lengths, Workspace, REACH_TOLERANCE};
use crate::{ArmError, Joint, Link};

/// Checks that an arm of links of lengths `lengths` can reach `target`, and moves a target that
/// lies outside the work-space by no more than the tolerance onto its boundary.
///
/// A position must lie in the [`Workspace`] annulus of all the links. A pose (the tip at `p`,
/// the last link at angle `phi`) is reachable exactly when its wrist point
/// `p - l_N (cos phi, sin phi)`, where the last joint must be, lies in the annulus of the links
/// before the last; that is what is checked. Points outside by at most
/// [`REACH_TOLERANCE`]` * sum |l|` count as on the boundary (the closed forms' rule) and are
/// moved radially onto it, so that a solver can meet a tight tolerance there.
///
/// # Errors
/// [`ArmError::NonFinite`] for NaN or infinite lengths (`"lengths"`) or targets (`"target"`);
/// [`ArmError::Unreachable`] naming the target as given, the radius checked (the target's, or
/// the wrist's for a pose) and the annulus.
///
/// # Example
/// ```
/// use planar_arm::kinematics::{reachable_target, IkTarget};
/// use planar_arm::nalgebra::Point2;
/// use planar_arm::ArmError;
///
/// let lengths = [1.0, 0.5, 0.5];
/// let far = IkTarget::Position(Point2::new(0.0, 2.5));
/// assert!(matches!(
///     reachable_target(&lengths, &far),
///     Err(ArmError::Unreachable { distance, .. }) if (distance - 0.5).abs() < 1e-15
/// ));
/// let edge = IkTarget::Position(Point2::new(0.0, 2.0 + 1e-12));
/// assert_eq!(reachable_target(&lengths, &edge), Ok(IkTarget::Position(Point2::new(0.0, 2.0))));
/// ```
pub fn reachable_target<const N: usize>(
    lengths: &[f64; N],
    target: &IkTarget,
) -> Result<IkTarget, ArmError> {
    check_lengths(lengths)?;
    if !target_is_finite(target) {
        return Err(ArmError::NonFinite { argument: "target" });
    }
    let all = Workspace::of_lengths(lengths);
    let slack = REACH_TOLERANCE * all.outer_radius();
    // The point that must lie in `annulus`, and how to rebuild the target from it.
    let (point, annulus, orientation) = match target {
        IkTarget::Position(p) => (p.coords, all, None),
        IkTarget::Pose(pose) => {
            let last = lengths.last().map_or(0.0, |l| *l);
            let turn = pose.rotation.complex();
            let hand = Vector2::new(turn.re, turn.im) * last;
            let before = Workspace::of_lengths(&lengths[..N.saturating_sub(1)]);
            (pose.translation.vector - hand, before, Some((pose, hand)))
        }
    };
    let radius = point.norm();
    let asked = match target {
        IkTarget::Position(p) => [p.x, p.y],
        IkTarget::Pose(pose) => [pose.translation.vector.x, pose.translation.vector.y],
    };
    let (inner, outer) = (annulus.inner_radius(), annulus.outer_radius());
    annulus_check_with_slack(
        radius,
        inner,
        outer,
        slack,
        asked,
        orientation.map(|(pose, _)| pose.rotation.angle()),
    )?;
    // Not `clamp`, which panics should rounding ever leave inner > outer.
    let onto = radius.max(inner).min(outer);
    if onto == radius {
        return Ok(*target);
    }
    let moved = if radius > 0.0 {
        point * (onto / radius)
    } else {
        Vector2::new(onto, 0.0)
    };
    Ok(match orientation {
        None => IkTarget::Position(Point2::from(moved)),
        Some((pose, hand)) => {
            IkTarget::Pose(Isometry2::from_parts((moved + hand).into(), pose.rotation))
        }
    })
}

/// [`reachable_target`] for an arm of any mix of joints, from its links (lengths, joint kinds
/// and ranges): checks that the arm can reach `target` and never refuses a target it can
/// reach.
///
/// For revolute links it is [`reachable_target`] of their lengths (the annulus, ranges not
/// applied; a target just outside is moved onto the boundary). Otherwise the point that must
/// be reached is the target's position, or for a pose whose last joint is revolute the wrist
/// `p - l_N (cos phi, sin phi)`, which the links before the last must reach; it must lie in the
/// [`Workspace::of_links`] of the links that reach it, which is exact for the arms listed there
/// and otherwise an annulus that holds every reachable point (so the check can only let
/// through targets the solver then cannot reach, never refuse one it can). A pose whose last
/// joint is prismatic is checked by its position alone. Such targets are returned unchanged.
///
/// # Errors
/// [`ArmError::NonFinite`] for NaN or infinite lengths (`"lengths"`) or targets (`"target"`);
/// [`ArmError::Unreachable`] naming the target as given, with the distance from the base of the
/// point checked, the work-space's radii and how far outside it the point lies (metres);
/// [`ArmError::BeyondJointRange`] where the region is exact and the closed form behind it says
/// a joint's range excludes the point (see [`Workspace::of_links`]).
///
/// # Example
/// ```
/// use planar_arm::kinematics::{reachable_target_of, IkTarget};
/// use planar_arm::nalgebra::Point2;
/// use planar_arm::{ArmError, Joint, Link};
///
/// let polar = [
///     Link::rod(0.2, 1.0),
///     Link::rod(0.5, 1.0).with_joint(Joint::Prismatic).with_range(0.1, 0.6),
/// ];
/// let near = IkTarget::Position(Point2::new(0.0, 1.0));
/// assert_eq!(reachable_target_of(&polar, &near), Ok(near));
/// // The slide would have to retract to 0 m, below its range.
/// let short = IkTarget::Position(Point2::new(0.7, 0.0));
/// assert!(matches!(
///     reachable_target_of(&polar, &short),
///     Err(ArmError::BeyondJointRange { joint: 1, kind: Joint::Prismatic, .. })
/// ));
/// // Four links with a range: only the annulus is known, and this point lies beyond it.
/// let four = [Link::rod(1.0, 1.0).with_range(0.0, 1.0), Link::rod(0.5, 1.0), Link::rod(0.5, 1.0), Link::rod(0.5, 1.0)];
/// let far = IkTarget::Position(Point2::new(3.0, 0.0));
/// assert!(matches!(reachable_target_of(&four, &far), Err(ArmError::Unreachable { .. })));
/// ```
pub fn reachable_target_of<const N: usize>(
    links: &[Link; N],
    target: &IkTarget,
) -> Result<IkTarget, ArmError> {
    let lengths = links.map(|l| l.length);
    // Revolute links whose joints turn freely reach an annulus; ranges cut it down.
    let free = |l: &Link| {
        l.range
            .is_none_or(|(lo, hi)| hi - lo >= core::f64::consts::TAU)
    };
    if links.iter().all(|l| l.joint == Joint::Revolute && free(l)) {
        return reachable_target(&lengths, target);
    }
    check_lengths(&lengths)?;
    if !target_is_finite(target) {
        return Err(ArmError::NonFinite { argument: "target" });
    }
    let (point, reaching, asked, orientation) = match target {
        IkTarget::Position(p) => (p.coords, &links[..], [p.x, p.y], None),
        IkTarget::Pose(pose) => {
            let t = pose.translation.vector;
            let phi = pose.rotation.angle();
            match links.split_last() {
                Some((last, before)) if last.joint == Joint::Revolute => {
                    let turn = pose.rotation.complex();
                    let hand = Vector2::new(turn.re, turn.im) * last.length;
                    (t - hand, before, [t.x, t.y], Some(phi))
                }
                _ => (t, &links[..], [t.x, t.y], Some(phi)),
            }
        }
    };
    let w = Workspace::of_links(reaching);
    let p = Point2::from(point);
    match w.miss(&p) {
        None => Ok(*target),
        Some(Miss::Distance(distance)) => Err(ArmError::Unreachable {
            target: asked,
            orientation,
            radius: point.norm(),
            inner: w.inner_radius(),
            outer: w.outer_radius(),
            distance,
        }),
        Some(Miss::Joint(miss)) => Err(miss.error()),
    }
}
