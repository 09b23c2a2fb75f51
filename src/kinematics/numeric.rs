//! Damped-least-squares (numeric) inverse kinematics for any number of links.
//!
//! This file holds the solver, [`solve_dls`], which knows nothing of arms: it takes the tip
//! pose and the Jacobian as closures. `reach` checks a target against the work-space first,
//! so that an unreachable target fails at once with how far off it is rather than after the
//! iterations; `arm` puts the two together for derived arms and for links, with the joints'
//! ranges as limits.

use nalgebra::{Isometry2, Matrix2, Matrix3, Point2, SMatrix, SVector, Vector3};

use super::{check_vector, wrap_angle};
use crate::ArmError;

pub(crate) mod arm;
pub(crate) mod lm;
mod reach;
#[cfg(test)]
mod tests;

pub use arm::{inverse_kinematics_near, inverse_kinematics_of};
pub use reach::{reachable_target, reachable_target_of};

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
    let pose = matches!(target, IkTarget::Pose(_));
    lm::levenberg_marquardt(
        |q| task_error(target, &fk(q)),
        jacobian,
        |j, e, lambda| dls_step(j, e, lambda, pose),
        seed,
        options,
    )
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
