//! Statics of spatial arms: the tool wrench that joint torques hold.

use nalgebra::{SMatrix, SVector, Vector3};

use crate::kinematics::SINGULAR_THRESHOLD;
use crate::ArmError;

/// The wrench `(force, torque)` at the tool origin with `J^T w = tau`, for six joints.
pub(crate) fn tip_wrench<const N: usize>(
    jacobian: &SMatrix<f64, 6, N>,
    q: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> Result<(Vector3<f64>, Vector3<f64>), ArmError> {
    if N != 6 {
        return Err(ArmError::NoClosedForm {
            what: "tip_wrench needs six joints: J^T w = tau is not square",
        });
    }
    if !q.iter().all(|x| x.is_finite()) {
        return Err(ArmError::NonFinite { argument: "q" });
    }
    if !tau.iter().all(|x| x.is_finite()) {
        return Err(ArmError::NonFinite { argument: "tau" });
    }
    let j = SMatrix::<f64, 6, 6>::from_fn(|r, c| jacobian[(r, c)]);
    let t = SVector::<f64, 6>::from_fn(|r, _| tau[r]);
    let det = j.determinant();
    let bound: f64 = j.column_iter().map(|c| c.norm()).product();
    let singular = ArmError::Singular {
        measure: det,
        threshold: SINGULAR_THRESHOLD * bound,
    };
    if det.is_nan() || det.abs() < SINGULAR_THRESHOLD * bound || bound == 0.0 {
        return Err(singular);
    }
    let w = j.transpose().lu().solve(&t).ok_or(singular)?;
    if !w.iter().all(|x| x.is_finite()) {
        return Err(ArmError::NonFinite { argument: "result" });
    }
    Ok((
        w.fixed_rows::<3>(0).into_owned(),
        w.fixed_rows::<3>(3).into_owned(),
    ))
}
