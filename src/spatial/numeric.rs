//! Damped-least-squares inverse kinematics of spatial arms: the planar solvers' loop on a 6-D
//! pose error.

use nalgebra::{Isometry3, Matrix6, SMatrix, SVector};

use super::SpatialArm;
use crate::kinematics::numeric::{arm::with_ranges, lm::levenberg_marquardt};
use crate::kinematics::DlsOptions;
use crate::ArmError;

/// The pose error `(p* - p, log(R* R^T))` in base coordinates, as the Jacobian's rows are.
pub(crate) fn pose_error(
    target: &Isometry3<f64>,
    now: &Isometry3<f64>,
) -> Result<SVector<f64, 6>, ArmError> {
    let mut e = SVector::<f64, 6>::zeros();
    e.fixed_rows_mut::<3>(0)
        .copy_from(&(target.translation.vector - now.translation.vector));
    e.fixed_rows_mut::<3>(3)
        .copy_from(&(target.rotation * now.rotation.inverse()).scaled_axis());
    if e.iter().all(|x| x.is_finite()) {
        Ok(e)
    } else {
        Err(ArmError::NonFinite { argument: "fk" })
    }
}

/// One step `J^T (J J^T + lambda^2 I)^-1 e`.
fn step<const N: usize>(
    j: &SMatrix<f64, 6, N>,
    e: &SVector<f64, 6>,
    lambda: f64,
) -> Option<SVector<f64, N>> {
    let a = j * j.transpose() + Matrix6::identity() * (lambda * lambda);
    let dq = j.transpose() * a.cholesky()?.solve(e);
    dq.iter().all(|x| x.is_finite()).then_some(dq)
}

/// [`SpatialArm::inverse_kinematics_near`].
pub(crate) fn inverse_kinematics_near<A: SpatialArm<N> + ?Sized, const N: usize>(
    arm: &A,
    target: &Isometry3<f64>,
    seed: &SVector<f64, N>,
    options: &DlsOptions<N>,
) -> Result<SVector<f64, N>, ArmError> {
    if !seed.iter().all(|x| x.is_finite()) {
        return Err(ArmError::NonFinite { argument: "seed" });
    }
    let finite = target.translation.vector.iter().all(|x| x.is_finite())
        && target.rotation.coords.iter().all(|x| x.is_finite());
    if !finite {
        return Err(ArmError::NonFinite { argument: "target" });
    }
    let ranges = arm.model().joints.map(|j| j.range);
    levenberg_marquardt(
        |q| pose_error(target, &arm.tip_pose(q)),
        |q| arm.jacobian(q),
        step,
        seed,
        &with_ranges(&ranges, options),
    )
}
