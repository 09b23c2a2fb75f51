//! Manipulability and singularity of the task Jacobian, for any number of links.

use nalgebra::{SMatrix, SVector};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

/// The manipulability `sqrt(det(J J^T))` (Yoshikawa) of the task rows of a 3 x N Jacobian
/// whose rows are tip x, tip y and the last link's angle: the product of the singular values.
///
/// - `N >= 3`: the full 3 x N Jacobian (position and orientation);
/// - `N == 2`: the two position rows, so `|det J_xy|` (`|l1 l2 sin q2|` for two links);
/// - `N == 1`: one joint cannot span the plane, so `det(J J^T)` would always be 0; the
///   measure is instead `sqrt(det(J^T J))`, the tip speed per unit joint rate `|J_xy|`;
/// - `N == 0`: 0.
///
/// Allocation-free. A Jacobian holding NaN or infinities gives 0 (it is treated as singular).
#[must_use]
pub fn manipulability<const N: usize>(jacobian: &SMatrix<f64, 3, N>) -> f64 {
    if N == 0 || !jacobian.iter().all(|x| x.is_finite()) {
        return 0.0;
    }
    // Scale the entries to at most 1 so that no product overflows.
    let scale = jacobian.amax();
    if scale == 0.0 {
        return 0.0;
    }
    let j = jacobian / scale;
    match N {
        1 => j[(0, 0)].hypot(j[(1, 0)]) * scale,
        2 => (j[(0, 0)] * j[(1, 1)] - j[(0, 1)] * j[(1, 0)]).abs() * scale * scale,
        _ => row_volume(&j) * scale * scale * scale,
    }
}

/// `sqrt(det(J J^T))` for three rows, as the volume of the parallelepiped they span: the
/// product of the norms that Gram-Schmidt (with one re-orthogonalisation) leaves. Accurate to
/// rounding even near a singularity, where `sqrt` of a computed determinant is not.
fn row_volume<const N: usize>(j: &SMatrix<f64, 3, N>) -> f64 {
    let mut basis = [SVector::<f64, N>::zeros(); 2];
    let mut volume = 1.0;
    for k in 0..3 {
        let mut v = j.row(k).transpose();
        for _ in 0..2 {
            for e in &basis[..k.min(2)] {
                v -= e * e.dot(&v);
            }
        }
        let norm = v.norm();
        if norm == 0.0 {
            return 0.0;
        }
        volume *= norm;
        if k < 2 {
            basis[k] = v / norm;
        }
    }
    volume
}

/// Whether the Jacobian is singular: [`manipulability`] is not above `threshold` (a NaN
/// threshold counts every Jacobian as singular).
#[must_use]
pub fn is_singular<const N: usize>(jacobian: &SMatrix<f64, 3, N>, threshold: f64) -> bool {
    threshold.is_nan() || manipulability(jacobian) <= threshold
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::test_support::{jacobian, Rng};
    use core::f64::consts::FRAC_PI_2;
    use nalgebra::{Matrix3, Vector3};

    #[test]
    fn manipulability_matches_closed_forms() {
        let mut rng = Rng(11);
        for _ in 0..500 {
            let l = [
                rng.range(0.2, 2.0),
                rng.range(0.2, 2.0),
                rng.range(0.2, 2.0),
                rng.range(0.2, 2.0),
            ];
            let q = SVector::<f64, 4>::from_fn(|_, _| rng.angle());
            let expected = (l[0] * l[1] * q[1].sin()).abs();
            // Two links: |l1 l2 sin q2|.
            let j2 = jacobian(&[l[0], l[1]], &q.fixed_rows::<2>(0).into_owned());
            assert!((manipulability(&j2) - expected).abs() < 1e-12);
            // Three links, square: |det J| = |l1 l2 sin q2|, the paper's determinant.
            let j3 = jacobian(&[l[0], l[1], l[2]], &q.fixed_rows::<3>(0).into_owned());
            assert!((manipulability(&j3) - expected).abs() < 1e-9);
            // Four links: Cauchy-Binet, det(J J^T) = sum of squared 3 x 3 minors.
            let j4 = jacobian(&l, &q);
            let mut sum = 0.0;
            for skip in 0..4 {
                let cols: Vec<usize> = (0..4).filter(|&c| c != skip).collect();
                let minor = Matrix3::from_fn(|r, c| j4[(r, cols[c])]);
                sum += minor.determinant().powi(2);
            }
            assert!((manipulability(&j4) - sum.sqrt()).abs() < 1e-9);
            // One link: the tip speed |l1|.
            let j1 = jacobian(&[l[0]], &q.fixed_rows::<1>(0).into_owned());
            assert!((manipulability(&j1) - l[0]).abs() < 1e-12);
        }
        let stretched = jacobian(&[1.0, 1.0, 1.0], &Vector3::new(0.4, 0.0, 0.3));
        assert!(is_singular(&stretched, 1e-9));
        let bent = jacobian(&[1.0, 1.0, 1.0], &Vector3::new(0.4, FRAC_PI_2, 0.3));
        assert!(!is_singular(&bent, 1e-9));
        assert!(is_singular(&bent, f64::NAN));
        assert_eq!(manipulability(&SMatrix::<f64, 3, 0>::zeros()), 0.0);
        let huge = bent * 1e200;
        assert_eq!(manipulability(&huge), f64::INFINITY);
        assert!((manipulability(&(bent * 1e-100)) - 1e-300).abs() < 1e-310);
    }
}
