//! The Levenberg-Marquardt loop of the damped-least-squares solvers, apart from what they
//! solve: planar arms' [`solve_dls`](super::solve_dls) (a 3-row task) and spatial arms' (a
//! 6-row pose error) share it.

use nalgebra::{SMatrix, SVector};

use super::{checked_limits, DlsOptions, DLS_MAX_DAMPING, DLS_MAX_STEP};
use crate::ArmError;

/// From `seed`, steps `step(J, e, lambda)` on the task error `error(q)` and Jacobian
/// `jacobian(q)` (`R` task rows), the step's norm limited to [`DLS_MAX_STEP`], keeping a step
/// only when it lowers `|e|`, the damping halved after a kept step and quadrupled after a
/// refused one; joints at a limit of `options` that a step pushes outward are held there.
///
/// # Errors
/// [`ArmError::NonFinite`] for non-finite `options`, a non-finite Jacobian or an `error` that
/// fails; [`ArmError::NoConvergence`] when the tolerance is not met.
pub(crate) fn levenberg_marquardt<const N: usize, const R: usize>(
    error: impl Fn(&SVector<f64, N>) -> Result<SVector<f64, R>, ArmError>,
    jacobian: impl Fn(&SVector<f64, N>) -> SMatrix<f64, R, N>,
    step: impl Fn(&SMatrix<f64, R, N>, &SVector<f64, R>, f64) -> Option<SVector<f64, N>>,
    seed: &SVector<f64, N>,
    options: &DlsOptions<N>,
) -> Result<SVector<f64, N>, ArmError> {
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
    // The floor is low enough for the slow, singular approach to a target on the outer
    // boundary (stretched arm, error quadratic in the angles), where a floor of 1e-3 of the
    // damping stalled a six-link arm at 1.3e-10.
    let floor = options.damping.abs() * 1e-6;
    let mut lambda = options.damping.abs();
    let mut q = clamp(*seed);
    let mut e = error(&q)?;
    let mut residual = e.norm();
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
        let mut dq = step(&j, &e, lambda);
        if let Some(limits) = &limits {
            // Hold the joints that sit at a limit and would step beyond it; the others take
            // the step recomputed without them (at most N rounds: each holds one more joint).
            for _ in 0..N {
                let Some(current) = dq else { break };
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
                dq = step(&j, &e, lambda);
            }
        }
        if let Some(mut dq) = dq {
            let norm = dq.norm();
            if norm > DLS_MAX_STEP {
                dq *= DLS_MAX_STEP / norm;
            }
            let candidate = clamp(q + dq);
            let candidate_error = error(&candidate)?;
            let candidate_residual = candidate_error.norm();
            if candidate_residual < residual {
                q = candidate;
                e = candidate_error;
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
