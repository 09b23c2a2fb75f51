//! Damped-least-squares (numeric) inverse kinematics for any number of links.

use nalgebra::{Isometry2, Matrix2, Matrix3, Point2, SMatrix, SVector, Vector2, Vector3};

use super::{
    annulus_check_with_slack, check_lengths, check_vector, jacobian_of, tip_pose_of, wrap_angle,
    Workspace, REACH_TOLERANCE,
};
use crate::{ArmError, Joint, Link};

/// Largest Euclidean norm, in radians, of one joint step taken by [`solve_dls`].
pub const DLS_MAX_STEP: f64 = 0.5;

/// Largest damping [`solve_dls`] tries before it concludes that no step reduces the error.
const DLS_MAX_DAMPING: f64 = 1e6;

/// What [`solve_dls`] should reach.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum IkTarget {
    /// A tip position; the orientation is free (only the Jacobian's first two rows are used).
    Position(Point2<f64>),
    /// A tip position and the absolute angle of the last link.
    Pose(Isometry2<f64>),
}

/// Settings of [`solve_dls`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DlsOptions<const N: usize> {
    /// The most iterations (each one Jacobian and one forward-kinematics evaluation).
    pub max_iterations: usize,
    /// Converged when the error norm is at most this: metres for a position; for a pose the
    /// norm of (dx, dy, dphi), mixing metres and radians.
    pub tolerance: f64,
    /// The initial damping `lambda`. It adapts as in Levenberg-Marquardt: halved (down to a
    /// millionth of this value) after a step that lowers the error, quadrupled after one that
    /// does not.
    pub damping: f64,
    /// Joint limits `(lower, upper)` for each joint (radians, or metres for a prismatic joint),
    /// MuJoCo's `range`; `None` (the default) leaves every joint free.
    /// [`inverse_kinematics_near`] and [`inverse_kinematics_of`] add the links' own ranges. The limits apply to the raw angles (not wrapped, so
    /// `(-4.0, 4.0)` allows a little more than one turn); an infinite bound is no bound. The
    /// seed is first clamped into them, every iterate stays inside them (a joint at a limit
    /// that the step pushes outward is held there and the step recomputed for the others),
    /// and the result lies inside them. A target reachable only outside the limits gives
    /// [`ArmError::NoConvergence`].
    pub limits: Option<[(f64, f64); N]>,
}

impl<const N: usize> Default for DlsOptions<N> {
    /// 200 iterations, tolerance `1e-10`, initial damping `0.05`, no joint limits.
    fn default() -> Self {
        Self {
            max_iterations: 200,
            tolerance: 1e-10,
            damping: 0.05,
            limits: None,
        }
    }
}

/// The joint limits of `options`, checked: `Err` for NaN bounds (`NonFinite`, `"options"`) or a
/// lower bound above the upper one (`OutOfRange`, `"joint limits"`, the lower bound).
fn checked_limits<const N: usize>(
    options: &DlsOptions<N>,
) -> Result<Option<[(f64, f64); N]>, ArmError> {
    let Some(limits) = options.limits else {
        return Ok(None);
    };
    for (joint, &(lower, upper)) in limits.iter().enumerate() {
        if lower.is_nan() || upper.is_nan() {
            return Err(ArmError::NonFinite {
                argument: "options",
            });
        }
        if lower > upper {
            return Err(ArmError::OutOfRange {
                what: "joint limits",
                link: Some(joint),
                value: lower,
            });
        }
    }
    Ok(Some(limits))
}

/// The task-space error `target - pose` (orientation error wrapped to (-pi, pi], zero for a
/// position target).
#[inline]
fn task_error(target: &IkTarget, pose: &Isometry2<f64>) -> Result<Vector3<f64>, ArmError> {
    let p = pose.translation.vector;
    let rotation = pose.rotation.complex();
    if !(p.x.is_finite() && p.y.is_finite() && rotation.re.is_finite() && rotation.im.is_finite()) {
        return Err(ArmError::NonFinite { argument: "fk" });
    }
    Ok(match target {
        IkTarget::Position(t) => Vector3::new(t.x - p.x, t.y - p.y, 0.0),
        IkTarget::Pose(t) => {
            let v = t.translation.vector;
            let dphi = wrap_angle(t.rotation.angle() - pose.rotation.angle());
            Vector3::new(v.x - p.x, v.y - p.y, dphi)
        }
    })
}

/// One damped-least-squares step `J^T (J J^T + lambda^2 I)^-1 e` over the task rows.
#[inline]
fn dls_step<const N: usize>(
    jacobian: &SMatrix<f64, 3, N>,
    error: &Vector3<f64>,
    lambda: f64,
    pose: bool,
) -> Option<SVector<f64, N>> {
    let damping = lambda * lambda;
    let step = if pose {
        let a = jacobian * jacobian.transpose() + Matrix3::identity() * damping;
        jacobian.transpose() * a.cholesky()?.solve(error)
    } else {
        let rows = jacobian.fixed_rows::<2>(0);
        let a = rows * rows.transpose() + Matrix2::identity() * damping;
        rows.transpose() * a.cholesky()?.solve(&error.xy())
    };
    step.iter().all(|x| x.is_finite()).then_some(step)
}

/// Damped-least-squares (Levenberg-Marquardt) inverse kinematics for any number of links.
///
/// Starting at `seed`, repeats `dq = J^T (J J^T + lambda^2 I)^-1 e` with the task error `e`
/// (position, or position and orientation wrapped to (-pi, pi]), the step norm limited to
/// [`DLS_MAX_STEP`], and keeps a step only when it lowers `|e|`; see [`DlsOptions`] for the
/// damping schedule. `fk` gives the tip pose (position and absolute angle of the last link),
/// `jacobian` the 3 x N Jacobian with rows tip x, tip y and that angle. Returns the
/// configuration reached from the seed, not wrapped, so it stays close to the seed. Uses no
/// heap: fixed-size 2 x 2 or 3 x 3 Cholesky solves.
///
/// # Errors
/// - [`ArmError::NonFinite`] when `seed`, `target` or `options` (`tolerance`, `damping`) hold
///   NaN or infinities, or `fk` (`"fk"`) or `jacobian` (`"jacobian"`) returns them;
/// - [`ArmError::NoConvergence`] when the error is still above the tolerance after
///   `max_iterations`, or earlier when no damping up to `1e6` lowers it any more (a local
///   minimum, e.g. for an unreachable target), with the iterations spent and the final
///   residual.
///
/// # Example
/// ```
/// use planar_arm::kinematics::{solve_dls, DlsOptions, IkTarget};
/// use planar_arm::nalgebra::{Isometry2, Matrix3, Point2, Vector2, Vector3};
///
/// let l = [1.0, 0.8, 0.5];
/// let fk = |q: &Vector3<f64>| {
///     let (mut x, mut y, mut phi) = (0.0, 0.0, 0.0);
///     for k in 0..3 {
///         phi += q[k];
///         x += l[k] * phi.cos();
///         y += l[k] * phi.sin();
///     }
///     Isometry2::new(Vector2::new(x, y), phi)
/// };
/// let jacobian = |q: &Vector3<f64>| {
///     let mut j = Matrix3::zeros();
///     let mut phi = 0.0;
///     for k in 0..3 {
///         phi += q[k];
///         for i in 0..=k {
///             j[(0, i)] -= l[k] * phi.sin();
///             j[(1, i)] += l[k] * phi.cos();
///         }
///         j[(2, k)] = 1.0;
///     }
///     j
/// };
/// let target = IkTarget::Position(Point2::new(1.0, 1.0));
/// let seed = Vector3::new(0.5, 0.5, 0.5);
/// let q = solve_dls(fk, jacobian, &target, &seed, &DlsOptions::default()).unwrap();
/// let tip = fk(&q).translation.vector;
/// assert!((tip - Vector2::new(1.0, 1.0)).norm() < 1e-10);
/// ```
pub fn solve_dls<const N: usize>(
    fk: impl Fn(&SVector<f64, N>) -> Isometry2<f64>,
    jacobian: impl Fn(&SVector<f64, N>) -> SMatrix<f64, 3, N>,
    target: &IkTarget,
    seed: &SVector<f64, N>,
    options: &DlsOptions<N>,
) -> Result<SVector<f64, N>, ArmError> {
    check_vector(seed, "seed")?;
    if !target_is_finite(target) {
        return Err(ArmError::NonFinite { argument: "target" });
    }
    if !(options.tolerance.is_finite() && options.damping.is_finite()) {
        return Err(ArmError::NonFinite {
            argument: "options",
        });
    }
    let limits = checked_limits(options)?;
    let clamp = |q: SVector<f64, N>| match &limits {
        Some(limits) => SVector::from_fn(|i, _| q[i].clamp(limits[i].0, limits[i].1)),
        None => q,
    };
    let pose = matches!(target, IkTarget::Pose(_));
    // The floor is low enough for the slow, singular approach to a target on the outer
    // boundary (stretched arm, error quadratic in the angles), where a floor of 1e-3 of the
    // damping stalled a six-link arm at 1.3e-10.
    let floor = options.damping.abs() * 1e-6;
    let mut lambda = options.damping.abs();
    let mut q = clamp(*seed);
    let mut error = task_error(target, &fk(&q))?;
    let mut residual = error.norm();
    let mut iterations = 0;
    while iterations < options.max_iterations && residual > options.tolerance {
        iterations += 1;
        let mut j = jacobian(&q);
        if !j.iter().all(|x| x.is_finite()) {
            return Err(ArmError::NonFinite {
                argument: "jacobian",
            });
        }
        let mut accepted = false;
        let mut step = dls_step(&j, &error, lambda, pose);
        if let Some(limits) = &limits {
            // Hold the joints that sit at a limit and would step beyond it; the others take
            // the step recomputed without them (at most N rounds: each holds one more joint).
            for _ in 0..N {
                let Some(current) = step else { break };
                let mut held = false;
                for i in 0..N {
                    let outward = (q[i] <= limits[i].0 && current[i] < 0.0)
                        || (q[i] >= limits[i].1 && current[i] > 0.0);
                    if outward && j.column(i).iter().any(|x| *x != 0.0) {
                        j.column_mut(i).fill(0.0);
                        held = true;
                    }
                }
                if !held {
                    break;
                }
                step = dls_step(&j, &error, lambda, pose);
            }
        }
        if let Some(mut step) = step {
            let norm = step.norm();
            if norm > DLS_MAX_STEP {
                step *= DLS_MAX_STEP / norm;
            }
            let candidate = clamp(q + step);
            let candidate_error = task_error(target, &fk(&candidate))?;
            let candidate_residual = candidate_error.norm();
            if candidate_residual < residual {
                q = candidate;
                error = candidate_error;
                residual = candidate_residual;
                accepted = true;
            }
        }
        if accepted {
            lambda = (lambda * 0.5).max(floor);
        } else {
            lambda = (lambda * 4.0).max(1e-6);
            if lambda > DLS_MAX_DAMPING {
                break;
            }
        }
    }
    if residual <= options.tolerance {
        Ok(q)
    } else {
        Err(ArmError::NoConvergence {
            iterations,
            residual,
        })
    }
}

fn target_is_finite(target: &IkTarget) -> bool {
    match target {
        IkTarget::Position(p) => p.x.is_finite() && p.y.is_finite(),
        IkTarget::Pose(pose) => {
            let v = pose.translation.vector;
            let c = pose.rotation.complex();
            v.x.is_finite() && v.y.is_finite() && c.re.is_finite() && c.im.is_finite()
        }
    }
}

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
/// point checked, the work-space's radii and how far outside it the point lies (metres; or,
/// for the polar arm and the slider carrying a link, as [`ik_rp`](super::ik_rp) and
/// [`ik_pr`](super::ik_pr) report it).
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
/// let short = IkTarget::Position(Point2::new(0.5, 0.0));
/// assert!(matches!(reachable_target_of(&polar, &short), Err(ArmError::Unreachable { .. })));
/// ```
pub fn reachable_target_of<const N: usize>(
    links: &[Link; N],
    target: &IkTarget,
) -> Result<IkTarget, ArmError> {
    let lengths = links.map(|l| l.length);
    if links.iter().all(|l| l.joint == Joint::Revolute) {
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
        Some(distance) => Err(ArmError::Unreachable {
            target: asked,
            orientation,
            radius: point.norm(),
            inner: w.inner_radius(),
            outer: w.outer_radius(),
            distance,
        }),
    }
}

/// `options` with the links' ranges added to its joint limits (their intersection; a NaN bound
/// counts as none).
fn with_ranges<const N: usize>(links: &[Link; N], options: &DlsOptions<N>) -> DlsOptions<N> {
    if links.iter().all(|l| l.range.is_none()) {
        return *options;
    }
    let free = (f64::NEG_INFINITY, f64::INFINITY);
    let limits = core::array::from_fn(|i| {
        let (lo, hi) = links[i].range.unwrap_or(free);
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
        &with_ranges(&links, options),
    )
}

/// [`inverse_kinematics_near`] for an arm given by its links alone (any mix of joints): the same
/// reach check and joint limits, with [`tip_pose_of`](super::tip_pose_of) and
/// [`jacobian_of`](super::jacobian_of) in place of generated code. Every solution lies within
/// the links' ranges.
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
        &with_ranges(links, options),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::ik3;
    use crate::kinematics::test_support::{
        angle_gap, any_f64, clean, fk_joints, jacobian, pose_of, Rng,
    };
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
            matches!(reachable_target_of(&polar, &far), Err(ArmError::Unreachable { distance, .. }) if (distance - 0.2).abs() < 1e-12)
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
        assert!(
            reachable_target_of(&unbounded, &IkTarget::Position(Point2::new(3.0, 0.6))).is_err()
        );
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
}
