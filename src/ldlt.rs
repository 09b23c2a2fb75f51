//! The forward dynamics' solve, `M qdd = tau - h`, by an `L D L^T` factorisation of fixed
//! size: what the generated `forward_dynamics` of an arm of three or more joints calls after
//! its `mass_matrix_and_bias`.
//!
//! The derive used to write this factorisation out as straight-line code in every arm's
//! `forward_dynamics` (and again in its frozen variant). Written once here over arrays of the
//! arm's size, the compiler unrolls it into the same operations in the same order, and a user's
//! crate no longer type-checks and borrow-checks it twice per arm (docs/performance.md).

use nalgebra::{SMatrix, SVector};

use crate::Real;

/// The floor under pivot `d_i` of `M = L D L^T`. `M` is positive definite, so its exact pivots
/// are positive; a computed pivot at or below the floor only means that `M` is too
/// ill-conditioned for the scalar there, and the floor keeps the accelerations finite instead
/// of infinite or NaN.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Floor {
    /// A fixed floor: for an entry `M_ii` without run-time parameters, 2^-52 times the sum of
    /// the magnitudes of its exact coefficients (a bound on `|M_ii|` over all configurations),
    /// computed by the derive.
    Fixed(f64),
    /// 2^-52 times `M_ii` itself, for an entry with run-time parameters (whose coefficient
    /// bound would cost a polynomial per term at every call); `M_ii` is positive and at least
    /// the exact pivot, so it sets the same level of rounding noise.
    Relative,
}

/// 2^-52: the relative rounding noise of one `f64` operation.
const ULP: f64 = 1.0 / 4_503_599_627_370_496.0;

/// With `$unroll`, every row index below 16 written out (`if I < N` folds away once `N` is
/// known), then a loop for any rows beyond: with each row's index a constant, the compiler
/// unrolls that row's loops fully. As one loop nest over the rows it stopped unrolling at seven
/// joints, where the solve took twice the time of the straight-line code (docs/performance.md).
/// Without, one loop: what an unoptimised build compiles (the sixteen copies are dead weight
/// there, about 2 % of a six-link crate's clean rebuild).
macro_rules! each_row {
    ($unroll:expr, $n:expr, $i:ident => $body:block) => {{
        if $unroll {
            each_row!(@ $n, $i, $body, 0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15);
            for $i in 16..$n $body
        } else {
            for $i in 0..$n $body
        }
    }};
    (@ $n:expr, $i:ident, $body:block, $($k:literal)*) => {
        $( if $k < $n { let $i: usize = $k; $body } )*
    };
}

/// Solves `M x = tau - h` with `M = L D L^T` (Crout's order, one multiplication per
/// inner-product term): `s_ij = M_ij - sum_k L_ik s_jk` is `L_ij d_j`, so
/// `L_ij = s_ij / d_j` and `d_i = M_ii - sum_k L_ik s_ik`, floored; then `L y = tau - h`,
/// `z = y / d`, `L^T x = z`. Reads the lower triangle of `m`. No square roots, one division per
/// joint, no allocation; NaN in gives NaN out, never a panic.
///
/// Optimised builds (no `debug_assertions`) get the rows written out, which the compiler
/// unrolls; unoptimised ones the plain loops. Both are the same arithmetic in the same order.
#[inline(always)]
#[must_use]
pub fn forward_solve<T: Real, const N: usize>(
    m: &SMatrix<T, N, N>,
    tau: &SVector<T, N>,
    h: &SVector<T, N>,
    floors: [Floor; N],
) -> SVector<T, N> {
    solve::<T, N, { !cfg!(debug_assertions) }>(m, tau, h, floors)
}

#[allow(clippy::needless_range_loop)] // the indices are the formula's
#[inline(always)]
fn solve<T: Real, const N: usize, const UNROLL: bool>(
    m: &SMatrix<T, N, N>,
    tau: &SVector<T, N>,
    h: &SVector<T, N>,
    floors: [Floor; N],
) -> SVector<T, N> {
    // nalgebra stores columns: `m[j][i]` is M(i, j).
    let m = &m.data.0;
    let (tau, h) = (&tau.data.0[0], &h.data.0[0]);
    let zero = T::from_f64(0.0);
    let one = T::from_f64(1.0);
    // s[i][j] = L_ij d_j and l[i][j] = L_ij for j < i. The inner loops run over all N
    // indices and skip the ones past the bound: a constant trip count is what lets the compiler
    // unroll them.
    let mut s = [[zero; N]; N];
    let mut l = [[zero; N]; N];
    let mut inv_d = [zero; N];
    each_row!(UNROLL, N, i => {
        for j in 0..N {
            if j < i {
                let mut sij = m[j][i];
                for k in 0..N {
                    if k < j {
                        sij = sij - l[i][k] * s[j][k];
                    }
                }
                s[i][j] = sij;
                l[i][j] = sij * inv_d[j];
            }
        }
        let mut di = m[i][i];
        for k in 0..N {
            if k < i {
                di = di - l[i][k] * s[i][k];
            }
        }
        let floor = match floors[i] {
            Floor::Fixed(f) => T::from_f64(f),
            Floor::Relative => T::from_f64(ULP) * m[i][i],
        };
        inv_d[i] = one / di.max(floor);
    });
    // L y = tau - h
    let mut y = [zero; N];
    each_row!(UNROLL, N, i => {
        let mut yi = tau[i] - h[i];
        for k in 0..N {
            if k < i {
                yi = yi - l[i][k] * y[k];
            }
        }
        y[i] = yi;
    });
    // D z = y, L^T x = z, from the last row up.
    let mut x = [zero; N];
    each_row!(UNROLL, N, r => {
        let i = N - 1 - r;
        let mut xi = y[i] * inv_d[i];
        for k in 0..N {
            if k > i {
                xi = xi - l[k][i] * x[k];
            }
        }
        x[i] = xi;
    });
    SVector::from_array_storage(nalgebra::ArrayStorage([x]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A symmetric positive definite matrix, `G G^T + I / 10` with `G` a smooth deterministic
    /// pattern that `seed` shifts (the eigenvalues spread over a few orders of magnitude).
    fn spd<const N: usize>(seed: usize) -> SMatrix<f64, N, N> {
        #[allow(clippy::cast_precision_loss)]
        let g = SMatrix::<f64, N, N>::from_fn(|i, j| ((3 * i + 7 * j + seed) as f64 * 0.37).sin());
        g * g.transpose() + SMatrix::identity() * 0.1
    }

    fn check<const N: usize>() {
        for seed in 1..20 {
            let m = spd::<N>(seed);
            let tau = SVector::<f64, N>::from_fn(|i, _| (i as f64 + 1.0) * 0.37 - 1.0);
            let h = SVector::<f64, N>::from_fn(|i, _| 0.25 - i as f64 * 0.11);
            let want = m.cholesky().unwrap().solve(&(tau - h));
            for floors in [[Floor::Relative; N], [Floor::Fixed(1e-12); N]] {
                let got = solve::<f64, N, true>(&m, &tau, &h, floors);
                let err = (got - want).norm() / want.norm();
                assert!(err < 1e-13, "N = {N}: relative error {err:e}");
                // The loops of an unoptimised build: the same operations, bit for bit.
                assert_eq!(solve::<f64, N, false>(&m, &tau, &h, floors), got);
            }
        }
    }

    #[test]
    fn solves_like_nalgebras_cholesky() {
        check::<1>();
        check::<2>();
        check::<3>();
        check::<5>();
        check::<8>();
        check::<12>();
        check::<18>();
    }

    #[test]
    fn floors_keep_a_singular_matrix_finite_and_nan_stays_nan() {
        // Rank one: the second pivot is exactly zero.
        let m = SMatrix::<f64, 2, 2>::new(1.0, 1.0, 1.0, 1.0);
        let tau = SVector::<f64, 2>::new(1.0, 2.0);
        let h = SVector::<f64, 2>::zeros();
        for floors in [[Floor::Relative; 2], [Floor::Fixed(1e-9); 2]] {
            for x in [
                solve::<f64, 2, true>(&m, &tau, &h, floors),
                solve::<f64, 2, false>(&m, &tau, &h, floors),
            ] {
                assert!(x.iter().all(|v| v.is_finite()), "{x:?}");
            }
        }
        let nan = SVector::<f64, 2>::new(f64::NAN, 0.0);
        for x in [
            solve::<f64, 2, true>(&m, &nan, &h, [Floor::Relative; 2]),
            solve::<f64, 2, false>(&m, &nan, &h, [Floor::Relative; 2]),
        ] {
            assert!(x.iter().all(|v| v.is_nan()), "{x:?}");
        }
    }
}
