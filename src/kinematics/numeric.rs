//! Damped-least-squares (numeric) inverse kinematics for any number of links.

use nalgebra::{Isometry2, Matrix2, Matrix3, Point2, SMatrix, SVector, Vector2, Vector3};

use super::{
    annulus_check_with_slack, check_lengths, check_vector, wrap_angle, Workspace, REACH_TOLERANCE,
};
use crate::ArmError;

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
    /// Joint limits `(lower, upper)` in radians for each joint, MuJoCo's `range`; `None` (the
    /// default) leaves every joint free. The limits apply to the raw angles (not wrapped, so
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

/// [`PlanarArm::inverse_kinematics_near`](crate::PlanarArm::inverse_kinematics_near): the
/// reach check of [`reachable_target`] on the arm's link lengths, then [`solve_dls`] on its
/// generated tip pose and Jacobian.
///
/// # Errors
/// As [`reachable_target`] and [`solve_dls`].
pub fn inverse_kinematics_near<A: crate::PlanarArm<N> + ?Sized, const N: usize>(
    arm: &A,
    target: &IkTarget,
    seed: &SVector<f64, N>,
    options: &DlsOptions<N>,
) -> Result<SVector<f64, N>, ArmError> {
    check_vector(seed, "seed")?;
    let target = reachable_target(&arm.links().map(|l| l.length), target)?;
    solve_dls(
        |q| arm.tip_pose(q),
        |q| arm.jacobian(q),
        &target,
        seed,
        options,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::ik3;
    use crate::kinematics::test_support::{angle_gap, any_f64, clean, jacobian, pose_of, Rng};
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
