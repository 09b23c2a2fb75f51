//! Inverse statics: the tip force (two links) or wrench (three links) that the joint torques
//! hold in balance.

use nalgebra::{SVector, Vector2};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use super::{check_lengths, check_vector, wrap_angle};
use crate::ArmError;

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
    /// The force `F` and torque `T` with `J^T (F, T) = tau` (see [`tip_wrench3`]).
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for NaN or infinite arguments, [`ArmError::Singular`] when
    /// `|sin q2| < SINGULAR_THRESHOLD`.
    fn tip_wrench(
        &self,
        q: &SVector<f64, 3>,
        tau: &SVector<f64, 3>,
    ) -> Result<(Vector2<f64>, f64), ArmError>;
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
/// `u = (c12 (tau1 - tau2) / l1 - c1 tau2 / l2) / s2` and likewise for `v`.
///
/// # Errors
/// [`ArmError::NonFinite`] (`"lengths"`, `"q"`, `"tau"`) for NaN or infinite arguments;
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
    let (q1, q2) = (wrap_angle(q[0]), wrap_angle(q[1]));
    let (s1, c1) = q1.sin_cos();
    let (s12, c12) = (q1 + q2).sin_cos();
    let s2 = q2.sin();
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
    Ok(force)
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
/// As [`tip_force2`]: [`ArmError::NonFinite`] or [`ArmError::Singular`] when
/// `|sin q2| < SINGULAR_THRESHOLD`.
///
/// # Example
/// ```
/// use planar_arm::kinematics::tip_wrench3;
/// use planar_arm::nalgebra::Vector3;
///
/// // Equal joint torques produce a pure tip torque.
/// let (force, torque) =
///     tip_wrench3(1.0, 1.0, 0.3, &Vector3::new(0.2, 1.0, -0.4), &Vector3::repeat(2.0)).unwrap();
/// assert!(force.norm() < 1e-12 && (torque - 2.0).abs() < 1e-12);
/// ```
#[inline]
pub fn tip_wrench3(
    l1: f64,
    l2: f64,
    l3: f64,
    q: &SVector<f64, 3>,
    tau: &SVector<f64, 3>,
) -> Result<(Vector2<f64>, f64), ArmError> {
    check_lengths(&[l1, l2, l3])?;
    check_vector(q, "q")?;
    check_vector(tau, "tau")?;
    let (q1, q2, q3) = (wrap_angle(q[0]), wrap_angle(q[1]), wrap_angle(q[2]));
    let (s1, c1) = q1.sin_cos();
    let (s12, c12) = (q1 + q2).sin_cos();
    let s2 = q2.sin();
    let s3 = q3.sin();
    let s23 = (q2 + q3).sin();
    if s2.abs() < SINGULAR_THRESHOLD || l1 == 0.0 || l2 == 0.0 {
        return Err(statics_singular(l1, l2, s2));
    }
    let scale = tau.amax();
    if scale == 0.0 {
        return Ok((Vector2::zeros(), 0.0));
    }
    let (t1, t2, t3) = (tau[0] / scale, tau[1] / scale, tau[2] / scale);
    let (a, b) = ((t1 - t2) / l1, (t2 - t3) / l2);
    let force = Vector2::new((c12 * a - c1 * b) / s2, (s12 * a - s1 * b) / s2) * scale;
    let torque = (t3 + l3 * ((s3 * a - s23 * b) / s2)) * scale;
    if force.iter().any(|f| f.is_nan()) || torque.is_nan() {
        return Err(statics_singular(l1, l2, s2));
    }
    Ok((force, torque))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::test_support::{jacobian, Rng, PAIRS, TRIPLES};
    use core::f64::consts::{PI, TAU};
    use nalgebra::{Matrix2, Matrix3, Vector3};

    /// `a x b = a.x b.y - a.y b.x`, the paper's planar cross product.
    fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
        a.x * b.y - a.y * b.x
    }

    /// Joint torques for tip force `f` and torque `t` from the paper's statics:
    /// tau_i = t + (r_i + ... + r_n) x f.
    fn joint_torques(lengths: &[f64], q: &[f64], f: Vector2<f64>, t: f64) -> Vec<f64> {
        let mut phi = 0.0;
        let links: Vec<Vector2<f64>> = lengths
            .iter()
            .zip(q)
            .map(|(l, qk)| {
                phi += qk;
                Vector2::new(l * phi.cos(), l * phi.sin())
            })
            .collect();
        (0..links.len())
            .map(|i| t + cross(links[i..].iter().sum(), f))
            .collect()
    }

    fn random_force(rng: &mut Rng) -> Vector2<f64> {
        Vector2::new(rng.range(-10.0, 10.0), rng.range(-10.0, 10.0))
    }

    #[test]
    fn tip_force2_inverts_the_transposed_jacobian() {
        let mut rng = Rng(5);
        for (l1, l2) in PAIRS {
            for _ in 0..2000 {
                let q = Vector2::new(rng.angle(), rng.angle());
                if q[1].sin().abs() < 0.05 {
                    continue;
                }
                // Force -> torques (the paper's statics) -> force.
                let f = random_force(&mut rng);
                let tau = joint_torques(&[l1, l2], q.as_slice(), f, 0.0);
                let back = tip_force2(l1, l2, &q, &Vector2::new(tau[0], tau[1])).unwrap();
                assert!(
                    (back - f).norm() < 1e-9 * f.norm().max(1.0),
                    "{f} came back as {back}"
                );
                // Torques -> force -> torques, via the independent Jacobian.
                let tau = Vector2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
                let f = tip_force2(l1, l2, &q, &tau).unwrap();
                let j = jacobian(&[l1, l2], &q);
                let again = j.fixed_rows::<2>(0).transpose() * f;
                assert!((again - tau).norm() < 1e-9 * tau.norm().max(1.0));
            }
        }
    }

    #[test]
    fn tip_wrench3_inverts_the_transposed_jacobian() {
        let mut rng = Rng(6);
        for (l1, l2, l3) in TRIPLES {
            for _ in 0..2000 {
                let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
                if q[1].sin().abs() < 0.05 {
                    continue;
                }
                let f = random_force(&mut rng);
                let t = rng.range(-3.0, 3.0);
                let tau = joint_torques(&[l1, l2, l3], q.as_slice(), f, t);
                let (f_back, t_back) =
                    tip_wrench3(l1, l2, l3, &q, &Vector3::new(tau[0], tau[1], tau[2])).unwrap();
                assert!((f_back - f).norm() < 1e-9 * f.norm().max(1.0));
                assert!((t_back - t).abs() < 1e-9 * t.abs().max(1.0));
                let tau = Vector3::new(
                    rng.range(-5.0, 5.0),
                    rng.range(-5.0, 5.0),
                    rng.range(-5.0, 5.0),
                );
                let (f, t) = tip_wrench3(l1, l2, l3, &q, &tau).unwrap();
                let again = jacobian(&[l1, l2, l3], &q).transpose() * Vector3::new(f.x, f.y, t);
                assert!((again - tau).norm() < 1e-9 * tau.norm().max(1.0));
            }
        }
    }

    /// The paper's printed inverse statics, entry by entry, against the forward matrices.
    #[test]
    fn paper_statics_inverses_are_correct_as_printed() {
        let mut rng = Rng(7);
        let (l1, l2, l3) = (1.0, 0.7, 0.4);
        for _ in 0..500 {
            let q = Vector3::new(rng.angle(), rng.angle(), rng.angle());
            let det = l1 * l2 * q[1].sin();
            if det.abs() < 0.05 {
                continue;
            }
            let (s1, c1) = q[0].sin_cos();
            let (s12, c12) = (q[0] + q[1]).sin_cos();
            let (s123, c123) = (q[0] + q[1] + q[2]).sin_cos();
            let (s2, s3, s23) = (q[1].sin(), q[2].sin(), (q[1] + q[2]).sin());
            let forward = Matrix3::new(
                -(l1 * s1 + l2 * s12 + l3 * s123),
                l1 * c1 + l2 * c12 + l3 * c123,
                1.0,
                -(l2 * s12 + l3 * s123),
                l2 * c12 + l3 * c123,
                1.0,
                -(l3 * s123),
                l3 * c123,
                1.0,
            );
            assert!((forward.determinant() - det).abs() < 1e-12);
            let printed = Matrix3::new(
                l2 * c12,
                -(l1 * c1 + l2 * c12),
                l1 * c1,
                l2 * s12,
                -(l1 * s1 + l2 * s12),
                l1 * s1,
                l2 * l3 * s3,
                -(l1 * l3 * s23 + l2 * l3 * s3),
                l1 * l2 * s2 + l1 * l3 * s23,
            ) / det;
            assert!((printed * forward - Matrix3::identity()).norm() < 1e-9);
            // Two links: u = {l2 c12 T1 - (l1 c1 + l2 c12) T2} / (l1 l2 s2), v likewise.
            let forward2 = Matrix2::new(
                -(l1 * s1 + l2 * s12),
                l1 * c1 + l2 * c12,
                -(l2 * s12),
                l2 * c12,
            );
            let printed2 = Matrix2::new(
                l2 * c12,
                -(l1 * c1 + l2 * c12),
                l2 * s12,
                -(l1 * s1 + l2 * s12),
            ) / det;
            assert!((printed2 * forward2 - Matrix2::identity()).norm() < 1e-9);
        }
    }

    #[test]
    fn singular_configurations_are_rejected() {
        let (l1, l2, l3) = (1.0, 0.5, 0.25);
        for q2 in [0.0, PI, -PI, 1e-12, PI - 1e-12, TAU, 0.5e-9] {
            let expected = Err(ArmError::Singular {
                measure: l1 * l2 * wrap_angle(q2).sin(),
                threshold: SINGULAR_THRESHOLD * l1 * l2,
            });
            let tau2 = Vector2::new(1.0, -1.0);
            assert_eq!(tip_force2(l1, l2, &Vector2::new(0.3, q2), &tau2), expected);
            let tau3 = Vector3::new(1.0, -1.0, 0.5);
            let got = tip_wrench3(l1, l2, l3, &Vector3::new(0.3, q2, 1.0), &tau3);
            assert_eq!(got.map(|_| Vector2::zeros()), expected);
        }
        for q2 in [2e-9, 1e-6, PI - 1e-6] {
            assert!(tip_force2(l1, l2, &Vector2::new(0.3, q2), &Vector2::new(1.0, 0.0)).is_ok());
        }
        assert!(matches!(
            tip_force2(0.0, l2, &Vector2::new(0.3, 1.0), &Vector2::new(1.0, 0.0)),
            Err(ArmError::Singular { .. })
        ));
        // Zero torques give zero force even near (but not at) a singularity.
        assert_eq!(
            tip_force2(l1, l2, &Vector2::new(0.3, 1e-6), &Vector2::zeros()),
            Ok(Vector2::zeros())
        );
    }
}
