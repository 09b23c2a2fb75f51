//! Independent forward kinematics and Jacobian, a seeded generator and the sample arms that
//! the tests of several files share.

use core::f64::consts::PI;

use nalgebra::{Isometry2, SMatrix, SVector, Vector2};
use proptest::prelude::*;

use super::wrap_angle;
use crate::ArmError;

/// Independent forward kinematics: tip x, tip y and the absolute angle of the last link.
pub(super) fn fk(lengths: &[f64], q: &[f64]) -> (f64, f64, f64) {
    let (mut x, mut y, mut phi) = (0.0, 0.0, 0.0);
    for (l, qk) in lengths.iter().zip(q) {
        phi += qk;
        x += l * phi.cos();
        y += l * phi.sin();
    }
    (x, y, phi)
}

/// Independent forward kinematics of any mix of joints, by the rules of
/// [`Joint`](crate::Joint): a revolute joint adds its angle and starts at the previous link's
/// end; a prismatic joint keeps the angle and starts `q` further along the previous link
/// (along +x before the first). Tip x, tip y and the absolute angle of the last link.
pub(super) fn fk_joints(kinds: &[crate::Joint], lengths: &[f64], q: &[f64]) -> (f64, f64, f64) {
    use crate::Joint;
    let (mut x, mut y, mut phi) = (0.0_f64, 0.0_f64, 0.0_f64);
    // The length of the previous link: none before the first.
    let mut previous = 0.0;
    for ((kind, l), qk) in kinds.iter().zip(lengths).zip(q) {
        let advance = match kind {
            Joint::Revolute => previous,
            Joint::Prismatic => previous + qk,
        };
        x += advance * phi.cos();
        y += advance * phi.sin();
        if *kind == Joint::Revolute {
            phi += qk;
        }
        previous = *l;
    }
    (x + previous * phi.cos(), y + previous * phi.sin(), phi)
}

/// Independent Jacobian: column i is the sum over k >= i of l_k (-sin phi_k, cos phi_k), 1.
pub(super) fn jacobian<const N: usize>(
    lengths: &[f64; N],
    q: &SVector<f64, N>,
) -> SMatrix<f64, 3, N> {
    let mut j = SMatrix::<f64, 3, N>::zeros();
    let mut phi = 0.0;
    for k in 0..N {
        phi += q[k];
        for i in 0..=k {
            j[(0, i)] -= lengths[k] * phi.sin();
            j[(1, i)] += lengths[k] * phi.cos();
        }
        j[(2, k)] = 1.0;
    }
    j
}

pub(super) fn pose_of<const N: usize>(lengths: &[f64; N], q: &SVector<f64, N>) -> Isometry2<f64> {
    let (x, y, phi) = fk(lengths, q.as_slice());
    Isometry2::new(Vector2::new(x, y), phi)
}

pub(super) fn angle_gap(a: f64, b: f64) -> f64 {
    wrap_angle(a - b).abs()
}

pub(super) fn in_range(a: f64) -> bool {
    a > -PI && a <= PI
}

/// Deterministic splitmix64 generator.
pub(super) struct Rng(pub(super) u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    pub(super) fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    pub(super) fn angle(&mut self) -> f64 {
        self.range(-PI, PI)
    }
}

pub(super) const PAIRS: [(f64, f64); 8] = [
    (1.0, 0.5),
    (0.5, 1.0),
    (0.7, 1.3),
    (1.0, 1.0),
    (2.5, 2.5),
    (0.3, 3.0),
    (1e-3, 2e-3),
    (4e3, 1e3),
];

pub(super) const TRIPLES: [(f64, f64, f64); 6] = [
    (1.0, 0.5, 0.3),
    (1.0, 1.0, 0.4),
    (0.6, 1.2, 1.5),
    (1.0, 1.0, 1.5),
    (2.0, 0.5, 0.2),
    (0.8, 0.8, 0.0),
];

pub(super) fn clean(result: &Result<impl Sized, ArmError>) -> bool {
    match result {
        Err(ArmError::Unreachable {
            radius,
            inner,
            outer,
            distance,
            ..
        }) => ![radius, inner, outer, distance].iter().any(|v| v.is_nan()) && *distance > 0.0,
        Err(ArmError::Unbalanced {
            residual,
            tolerance,
        }) => !residual.is_nan() && !tolerance.is_nan(),
        Err(ArmError::Singular { measure, threshold }) => !measure.is_nan() && !threshold.is_nan(),
        Err(ArmError::NoConvergence { residual, .. }) => !residual.is_nan(),
        _ => true,
    }
}

pub(super) fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>(),
        -10.0..10.0,
        Just(0.0),
        Just(-0.0),
        Just(1.0),
        Just(f64::MAX),
        Just(f64::MIN_POSITIVE),
        Just(5e-324),
    ]
}

mod tests {
    use super::*;
    use nalgebra::Vector3;

    #[test]
    fn test_jacobian_matches_finite_differences() {
        let mut rng = Rng(14);
        let lengths = [1.0, 0.7, 0.3, 0.9];
        for _ in 0..50 {
            let q = SVector::<f64, 4>::from_fn(|_, _| rng.angle());
            let j = jacobian(&lengths, &q);
            for i in 0..4 {
                let h = 1e-6;
                let mut qp = q;
                let mut qm = q;
                qp[i] += h;
                qm[i] -= h;
                let (xp, yp, pp) = fk(&lengths, qp.as_slice());
                let (xm, ym, pm) = fk(&lengths, qm.as_slice());
                let d = Vector3::new(xp - xm, yp - ym, pp - pm) / (2.0 * h);
                assert!((d - j.column(i)).norm() < 1e-8);
            }
        }
    }
}
