//! A fixed-size `L D L^T` factorisation of M, and from it `qdd = M^-1 (tau - h)`, `M^-1`,
//! `-M^-1 A` and `-M^-1 B`: the linear algebra that turns the inverse dynamics' derivatives
//! into the forward dynamics' ones (`dqdd/dq = -M^-1 dtau/dq`, `dqdd/dqd = -M^-1 dtau/dqd`,
//! `dqdd/dtau = M^-1`, at the `qdd` that the same factor solves for).
//!
//! Written over arrays of the arm's size so that the compiler unrolls and vectorises every loop:
//! nalgebra's `cholesky().inverse()` followed by two products took 2.4-3.0x the time of the
//! emitted straight-line derivatives at two to six links; this, after one `mass_matrix_and_bias`
//! and with one factor for `qdd` and `M^-1`, 1.0-1.6x at two to four links
//! (`benches/derivatives.rs`). Each column of the factorisation waits for the one before, and
//! `L D L^T` puts one division on that path where Cholesky's `L L^T` puts a square root and a
//! division: the Panda's factor, solve and inverse took 82-99 ns against 148-179, and its
//! forward derivatives 947.6 ns against 983.7 (docs/performance.md, "Eighth session").

use nalgebra::{ArrayStorage, SMatrix, SVector};

/// The factors `M = L D L^T` (`L` unit lower triangular, `D` diagonal) of a symmetric positive
/// definite matrix of the arm's size, kept to solve for the accelerations and then to invert M
/// with the same factor.
#[derive(Clone, Copy, Debug)]
pub struct Factor<const N: usize> {
    /// `l[i][j]` = L(i, j) for `i > j` (the unit diagonal is not read), rows contiguous so that
    /// the dot products of the factorisation read memory in order.
    l: [[f64; N]; N],
    /// `r[j]` = 1 / D(j, j).
    r: [f64; N],
}

impl<const N: usize> Factor<N> {
    /// The factors of `m` (its lower half is read), or `None` when `m` is not numerically
    /// positive definite (a pivot that is not positive, NaN included).
    #[allow(clippy::needless_range_loop)]
    #[inline(always)] // into the AVX2 copy of `forward_dynamics_derivatives` (src/dispatch.rs)
    #[must_use]
    pub fn new(m: &SMatrix<f64, N, N>) -> Option<Self> {
        // nalgebra stores columns: `m[j][i]` is M(i, j).
        let m = &m.data.0;
        let mut l = [[0.0f64; N]; N];
        // e[i][k] = L(i, k) D(k, k): the products the later columns subtract.
        let mut e = [[0.0f64; N]; N];
        let mut r = [0.0f64; N];
        for j in 0..N {
            let mut d = m[j][j];
            for k in 0..j {
                d -= l[j][k] * e[j][k];
            }
            // NaN is not greater either; a subnormal pivot has no finite reciprocal.
            let inv = 1.0 / d;
            if d.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) || !inv.is_finite() {
                return None;
            }
            r[j] = inv;
            for i in j + 1..N {
                let mut s = m[j][i];
                for k in 0..j {
                    s -= l[i][k] * e[j][k];
                }
                e[i][j] = s;
                l[i][j] = s * inv;
            }
        }
        Some(Self { l, r })
    }

    /// `M^-1 b`: `L y = b` forward, `D^-1`, then `L^T x = y` backward.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    #[must_use]
    pub fn solve(&self, b: &SVector<f64, N>) -> SVector<f64, N> {
        let (l, r) = (&self.l, &self.r);
        let mut y = [0.0f64; N];
        for i in 0..N {
            let mut s = b[i];
            for k in 0..i {
                s -= l[i][k] * y[k];
            }
            y[i] = s;
        }
        for i in 0..N {
            y[i] *= r[i];
        }
        for i in (0..N).rev() {
            let mut s = y[i];
            for k in i + 1..N {
                s -= l[k][i] * y[k];
            }
            y[i] = s;
        }
        SVector::from_data(ArrayStorage([y]))
    }

    /// `M^-1 = W^T D^-1 W` with `W = L^-1`, symmetric to the bit.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    #[must_use]
    pub fn inverse(&self) -> SMatrix<f64, N, N> {
        let (l, r) = (&self.l, &self.r);
        // W = L^-1, unit lower triangular, by forward substitution column by column.
        let mut w = [[0.0f64; N]; N];
        for j in 0..N {
            w[j][j] = 1.0;
            for i in j + 1..N {
                let mut s = 0.0;
                for k in j..i {
                    s -= l[i][k] * w[k][j];
                }
                w[i][j] = s;
            }
        }
        // Stored by columns like nalgebra.
        let mut inv = [[0.0f64; N]; N];
        for j in 0..N {
            for i in j..N {
                let mut s = 0.0;
                for k in i..N {
                    s += w[k][i] * r[k] * w[k][j];
                }
                inv[j][i] = s;
                inv[i][j] = s;
            }
        }
        SMatrix::from_data(ArrayStorage(inv))
    }

    /// `(-M^-1 a, -M^-1 b, M^-1)`.
    #[allow(clippy::type_complexity)]
    #[inline(always)]
    #[must_use]
    pub fn inverse_products(
        &self,
        a: &SMatrix<f64, N, N>,
        b: &SMatrix<f64, N, N>,
    ) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        let inv = self.inverse();
        (minus_product(&inv, a), minus_product(&inv, b), inv)
    }
}

/// The forward dynamics' derivatives of `arm` from its `(M, h)` at `(q, qd)`: one factor of M
/// serves the accelerations and `M^-1`, and the inverse dynamics' derivatives are taken at
/// those accelerations (the dispatched method, so that its body's two copies stay the only
/// ones). NaN everywhere if M has no factor (only with NaN or infinite input).
#[allow(clippy::type_complexity)]
#[inline(always)]
#[must_use]
pub fn forward_derivatives<A: crate::Dynamics<N> + ?Sized, const N: usize>(
    arm: &A,
    (m, h): (SMatrix<f64, N, N>, SVector<f64, N>),
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
    let Some(factor) = Factor::new(&m) else {
        let nan = SMatrix::from_element(f64::NAN);
        return (nan, nan, nan);
    };
    let qdd = factor.solve(&(tau - h));
    let (dq, dqd) = arm.inverse_dynamics_derivatives(q, qd, &qdd);
    factor.inverse_products(&dq, &dqd)
}

/// [`forward_derivatives`] in `lanes`, the products by `-M^-1` taken by the arm's
/// `__forward_dynamics_derivatives_adjoint` (for a spatial arm, the inverse dynamics run
/// backward from the torques weighted by the rows of `-M^-1`: `programs::adjoint` in the
/// engine). NaN everywhere if M has no factor.
#[allow(clippy::type_complexity)]
#[inline(always)]
#[must_use]
pub fn forward_derivatives_in<A, L, const N: usize>(
    arm: &A,
    lanes: L,
    (m, h): (SMatrix<f64, N, N>, SVector<f64, N>),
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>, SMatrix<f64, N, N>)
where
    A: crate::Dynamics<N> + ?Sized,
    L: crate::__private::Lanes,
{
    let Some(factor) = Factor::new(&m) else {
        let nan = SMatrix::from_element(f64::NAN);
        return (nan, nan, nan);
    };
    let qdd = factor.solve(&(tau - h));
    let inv = factor.inverse();
    let (dq, dqd) = arm.__forward_dynamics_derivatives_adjoint(lanes, q, qd, &qdd, &inv);
    (dq, dqd, inv)
}

/// Lanes `-m(r + l, k)` for `l` in `0..W`, zero past the last row: the seeds of a reverse-mode
/// lane group (`programs::adjoint`): `m(r + l, k)` is row `r + l` of `M^-1`'s column `k`, the
/// weight of output `k` in row `r + l`, read where nalgebra stores it.
#[inline(always)]
#[must_use]
pub fn negated_rows<const N: usize, const W: usize>(
    m: &SMatrix<f64, N, N>,
    k: usize,
    r: usize,
) -> [f64; W] {
    let column = &m.data.0[k];
    core::array::from_fn(|l| column.get(r + l).map_or(0.0, |x| -x))
}

/// `-inv x`, both stored by columns. A function, not a closure, so that it is inlined into the
/// AVX2 copy of its caller and vectorised there (a closure was compiled on its own, for the
/// baseline).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
#[must_use]
pub fn minus_product<const N: usize>(
    inv: &SMatrix<f64, N, N>,
    x: &SMatrix<f64, N, N>,
) -> SMatrix<f64, N, N> {
    let (inv, x) = (&inv.data.0, &x.data.0);
    let mut out = [[0.0f64; N]; N];
    for c in 0..N {
        for k in 0..N {
            let xk = x[c][k];
            for i in 0..N {
                out[c][i] -= inv[k][i] * xk;
            }
        }
    }
    SMatrix::from_data(ArrayStorage(out))
}

#[cfg(test)]
mod tests {
    use super::Factor;
    use nalgebra::{SMatrix, SVector};

    /// A symmetric positive definite matrix with a spread of eigenvalues, and two others.
    fn inputs<const N: usize>() -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        #[allow(clippy::cast_precision_loss)]
        let g = SMatrix::<f64, N, N>::from_fn(|i, j| ((3 * i + 7 * j + 1) as f64 * 0.37).sin());
        let m = g * g.transpose() + SMatrix::identity() * 0.1;
        #[allow(clippy::cast_precision_loss)]
        let a = SMatrix::from_fn(|i, j| (i as f64 - 2.0 * j as f64) * 0.5);
        #[allow(clippy::cast_precision_loss)]
        let b = SMatrix::from_fn(|i, j| ((i * j) as f64 + 1.0).ln());
        (m, a, b)
    }

    fn against_nalgebra<const N: usize>() {
        let (m, a, b) = inputs::<N>();
        let factor = Factor::new(&m).expect("positive definite");
        let (x, y, inv) = factor.inverse_products(&a, &b);
        let reference = m.cholesky().expect("positive definite").inverse();
        let scale = reference.amax();
        assert!((inv - reference).amax() <= 1e-12 * scale, "N = {N}");
        assert!(
            (x + reference * a).amax() <= 1e-12 * scale * a.amax() * 8.0,
            "N = {N}"
        );
        assert!(
            (y + reference * b).amax() <= 1e-12 * scale * b.amax() * 8.0,
            "N = {N}"
        );
        // The solve, against the product with nalgebra's inverse and by its residual.
        #[allow(clippy::cast_precision_loss)]
        let rhs = SVector::<f64, N>::from_fn(|i, _| (i as f64 * 1.7 + 0.3).cos());
        let x = factor.solve(&rhs);
        assert!(
            (x - reference * rhs).amax() <= 1e-12 * scale * 8.0,
            "N = {N}"
        );
        assert!((m * x - rhs).amax() < 1e-10, "N = {N}");
        // And an independent property: M M^-1 = I.
        assert!(
            (m * inv - SMatrix::<f64, N, N>::identity()).amax() < 1e-10,
            "N = {N}"
        );
    }

    #[test]
    fn agrees_with_nalgebra_from_one_to_nine() {
        against_nalgebra::<1>();
        against_nalgebra::<2>();
        against_nalgebra::<3>();
        against_nalgebra::<4>();
        against_nalgebra::<6>();
        against_nalgebra::<9>();
    }

    #[test]
    fn singular_indefinite_and_nan_give_none() {
        let singular = SMatrix::<f64, 3, 3>::from_element(1.0);
        assert!(Factor::new(&singular).is_none());
        let indefinite = SMatrix::<f64, 2, 2>::new(1.0, 2.0, 2.0, 1.0);
        assert!(Factor::new(&indefinite).is_none());
        let mut nan = SMatrix::<f64, 3, 3>::identity();
        nan[(1, 1)] = f64::NAN;
        assert!(Factor::new(&nan).is_none());
    }
}
