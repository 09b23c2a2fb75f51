//! Inverse statics: the tip force (two links) or wrench (three or more links) that the joint
//! torques hold in balance.
//!
//! Every function here takes the sine and cosine of each raw joint angle and composes the
//! absolute angles by the angle-sum formulas, never wrapping or summing angles first, so the
//! results are as accurate at `q = 1e15` as at `q = 1`.
//!
//! This file holds the paper's closed forms for two and three revolute links, which need no
//! more than the sines and cosines above. The least-squares wrench for any number of links and
//! any mix of joints, with the traits a derived arm gets, lives in `least_squares`: it reuses
//! [`tip_force2`] for two links and is otherwise a different computation (a QR of `J^T`).

use nalgebra::{SVector, Vector2};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use super::{check_lengths, check_vector};
use crate::ArmError;

mod least_squares;
#[cfg(test)]
mod tests;

pub use least_squares::{
    inverse_statics, inverse_statics_of, InverseStatics, RedundantTipWrench, StaticWrench,
    UNBALANCED_TOLERANCE,
};

/// Singularity threshold of the inverse statics: the configuration counts as singular when
/// `|l1 l2 sin q2| < SINGULAR_THRESHOLD * |l1 l2|`, that is when `|sin q2| < SINGULAR_THRESHOLD`
/// (or a length is zero). The error then reports `measure = l1 l2 sin q2` and
/// `threshold = SINGULAR_THRESHOLD * |l1 l2|`.
pub const SINGULAR_THRESHOLD: f64 = 1e-9;

/// Inverse statics of a two-link arm: the force the tip exerts, from the joint torques.
pub trait TipForce {
    /// The force `F` with `J^T F = tau` (see [`tip_force2`]).
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite arguments, [`ArmError::Singular`] when
    /// `|sin q2| < SINGULAR_THRESHOLD`.
    fn tip_force(
        &self,
        q: &SVector<f64, 2>,
        tau: &SVector<f64, 2>,
    ) -> Result<Vector2<f64>, ArmError>;
}

/// Inverse statics of a three-link arm: the force and torque the tip exerts, from the joint
/// torques.
pub trait TipWrench {
    /// The force `F` and torque `T` with `J^T (F, T) = tau` (see [`tip_wrench3`]), as the
    /// [`StaticWrench`] that [`inverse_statics`](super::inverse_statics) returns (its residual
    /// zero: three joints, three unknowns).
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite arguments, [`ArmError::Singular`] when
    /// `|sin q2| < SINGULAR_THRESHOLD`.
    fn tip_wrench(
        &self,
        q: &SVector<f64, 3>,
        tau: &SVector<f64, 3>,
    ) -> Result<StaticWrench<3>, ArmError>;
}

/// The singularity error of the inverse statics.
#[inline]
fn statics_singular(l1: f64, l2: f64, s2: f64) -> ArmError {
    ArmError::Singular {
        // l1 * s2 is finite, so the product is finite or infinite, never NaN.
        measure: l1 * s2 * l2,
        threshold: SINGULAR_THRESHOLD * (l1 * l2).abs(),
    }
}

/// Inverse statics of a two-link arm: the force `F = (u, v)` the tip exerts when the joints
/// apply the torques `tau`, i.e. the solution of `J^T F = tau`:
///
/// ```text
/// tau1 = (r1 + r2) x F,   tau2 = r2 x F,   (a, b) x (c, d) = a d - b c
/// u = (l2 c12 tau1 - (l1 c1 + l2 c12) tau2) / (l1 l2 s2)
/// v = (l2 s12 tau1 - (l1 s1 + l2 s12) tau2) / (l1 l2 s2)
/// ```
///
/// (the paper's formula, which is correct), evaluated as
/// `u = (c12 (tau1 - tau2) / l1 - c1 tau2 / l2) / s2` and likewise for `v`, with `c12`, `s12`
/// composed from the sines and cosines of `q1` and `q2` (accurate for any finite angle).
///
/// # Errors
/// [`ArmError::NonFinite`] (`"lengths"`, `"q"`, `"tau"`) for NaN or infinite arguments, and
/// `"result"` when finite arguments give a force beyond `f64::MAX`;
/// [`ArmError::Singular`] when `|sin q2| < SINGULAR_THRESHOLD` (see [`SINGULAR_THRESHOLD`]) or a
/// length is zero: the links are parallel and the torques cannot balance a force along them.
///
/// # Example
/// ```
/// use planar_arm::kinematics::tip_force2;
/// use planar_arm::nalgebra::Vector2;
///
/// // q = (0, pi/2): r1 = (1, 0), r2 = (0, 0.5), so tau1 = (r1 + r2) x F = v - 0.5 u and
/// // tau2 = r2 x F = -0.5 u.
/// let q = Vector2::new(0.0, std::f64::consts::FRAC_PI_2);
/// let f = tip_force2(1.0, 0.5, &q, &Vector2::new(1.0, 0.5)).unwrap();
/// assert!((f.y - 0.5 * f.x - 1.0).abs() < 1e-12 && (-0.5 * f.x - 0.5).abs() < 1e-12);
/// ```
#[inline]
pub fn tip_force2(
    l1: f64,
    l2: f64,
    q: &SVector<f64, 2>,
    tau: &SVector<f64, 2>,
) -> Result<Vector2<f64>, ArmError> {
    check_lengths(&[l1, l2])?;
    check_vector(q, "q")?;
    check_vector(tau, "tau")?;
    let (s1, c1) = q[0].sin_cos();
    let (s2, c2) = q[1].sin_cos();
    let (s12, c12) = angle_sum((s1, c1), (s2, c2));
    if s2.abs() < SINGULAR_THRESHOLD || l1 == 0.0 || l2 == 0.0 {
        return Err(statics_singular(l1, l2, s2));
    }
    // Scale the torques to at most 1 so that no intermediate overflows.
    let scale = tau.amax();
    if scale == 0.0 {
        return Ok(Vector2::zeros());
    }
    let (t1, t2) = (tau[0] / scale, tau[1] / scale);
    let (a, b) = ((t1 - t2) / l1, t2 / l2);
    let force = Vector2::new((c12 * a - c1 * b) / s2, (s12 * a - s1 * b) / s2) * scale;
    if force.iter().any(|f| f.is_nan()) {
        return Err(statics_singular(l1, l2, s2));
    }
    finite_result(force.iter().copied())?;
    Ok(force)
}

/// `(sin, cos)` of `a + b` from those of `a` and `b`. Summing the angles first would round
/// the sum (by up to 0.06 rad at `|q| = 1e15`); the sine and cosine of each raw angle are
/// accurate for any finite angle (the standard library and `libm` reduce arguments exactly).
#[inline]
pub(super) fn angle_sum((sa, ca): (f64, f64), (sb, cb): (f64, f64)) -> (f64, f64) {
    (sa * cb + ca * sb, ca * cb - sa * sb)
}

/// `Err(NonFinite { argument: "result" })` when finite input overflowed to an infinity.
#[inline]
fn finite_result(values: impl IntoIterator<Item = f64>) -> Result<(), ArmError> {
    if values.into_iter().all(f64::is_finite) {
        Ok(())
    } else {
        Err(ArmError::NonFinite { argument: "result" })
    }
}

/// Inverse statics of a three-link arm: the force `F = (u, v)` and torque `T` the tip exerts
/// when the joints apply the torques `tau`, i.e. the solution of
///
/// ```text
/// tau_i = T + (r_i + ... + r_3) x F,   r_k = l_k (cos phi_k, sin phi_k)
/// ```
///
/// with `phi_k` the absolute angle of link k. The 3 x 3 matrix has determinant `l1 l2 sin q2`;
/// its inverse (the paper prints it correctly) is
///
/// ```text
/// | u |      1       |  l2 c12     -(l1 c1 + l2 c12)        l1 c1             | | tau1 |
/// | v | = --------- |  l2 s12     -(l1 s1 + l2 s12)        l1 s1             | | tau2 |
/// | T |   l1 l2 s2   |  l2 l3 s3   -(l1 l3 s23 + l2 l3 s3)  l1 l2 s2 + l1 l3 s23 | | tau3 |
/// ```
///
/// evaluated without products of lengths: with `a = (tau1 - tau2) / l1`, `b = (tau2 - tau3) / l2`,
/// `u = (c12 a - c1 b) / s2`, `v = (s12 a - s1 b) / s2`, `T = tau3 + l3 (s3 a - s23 b) / s2`.
///
/// # Errors
/// As [`tip_force2`]: [`ArmError::NonFinite`] (also `"result"` for an overflowing wrench) or
/// [`ArmError::Singular`] when `|sin q2| < SINGULAR_THRESHOLD`.
///
/// # Example
/// ```
/// use planar_arm::kinematics::tip_wrench3;
/// use planar_arm::nalgebra::Vector3;
///
/// // Equal joint torques produce a pure tip torque.
/// let w = tip_wrench3(1.0, 1.0, 0.3, &Vector3::new(0.2, 1.0, -0.4), &Vector3::repeat(2.0)).unwrap();
/// assert!(w.force.norm() < 1e-12 && (w.torque - 2.0).abs() < 1e-12);
/// ```
#[inline]
pub fn tip_wrench3(
    l1: f64,
    l2: f64,
    l3: f64,
    q: &SVector<f64, 3>,
    tau: &SVector<f64, 3>,
) -> Result<StaticWrench<3>, ArmError> {
    let wrench = |force, torque| StaticWrench {
        force,
        torque,
        residual: SVector::<f64, 3>::zeros(),
    };
    check_lengths(&[l1, l2, l3])?;
    check_vector(q, "q")?;
    check_vector(tau, "tau")?;
    let (s1, c1) = q[0].sin_cos();
    let (s2, c2) = q[1].sin_cos();
    let (s3, c3) = q[2].sin_cos();
    let (s12, c12) = angle_sum((s1, c1), (s2, c2));
    let (s23, _) = angle_sum((s2, c2), (s3, c3));
    if s2.abs() < SINGULAR_THRESHOLD || l1 == 0.0 || l2 == 0.0 {
        return Err(statics_singular(l1, l2, s2));
    }
    let scale = tau.amax();
    if scale == 0.0 {
        return Ok(wrench(Vector2::zeros(), 0.0));
    }
    let (t1, t2, t3) = (tau[0] / scale, tau[1] / scale, tau[2] / scale);
    let (a, b) = ((t1 - t2) / l1, (t2 - t3) / l2);
    let force = Vector2::new((c12 * a - c1 * b) / s2, (s12 * a - s1 * b) / s2) * scale;
    let torque = (t3 + l3 * ((s3 * a - s23 * b) / s2)) * scale;
    if force.iter().any(|f| f.is_nan()) || torque.is_nan() {
        return Err(statics_singular(l1, l2, s2));
    }
    finite_result(force.iter().copied().chain([torque]))?;
    Ok(wrench(force, torque))
}
