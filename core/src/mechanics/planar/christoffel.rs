//! The Coriolis matrix `C(q, qd)` of Christoffel symbols, `C qd = c` with `Mdot - 2 C` skew,
//! by two routes that give the same exact function.
//!
//! - [`expanded`]: every entry as an expanded formula,
//!   `2 C_ij = Mdot_ij + dp_i/dq_j - dp_j/dq_i` from the momenta `p = M qd`. Its entries have
//!   as many terms as M's times the rates, and deriving and emitting them cost long arms most
//!   of the derive's time.
//! - [`absolute_derivatives`] and [`absolute_program`]: for arms whose joints all turn. In
//!   the links' absolute angles `phi_a = q_1 + ... + q_a` (rates `w = J qd`, `J` the lower
//!   triangle of ones) the kinetic energy is `1/2 w^T Mt(phi) w` with
//!   `M = J^T Mt J + diag(armature)` and each `Mt_ab` a function of `phi_a - phi_b` alone
//!   ([`crate::mechanics`] builds it pair by pair). For such a metric the Christoffel sum collapses to
//!   `Ct_ab = dMt_ab/dphi_b w_b`, and since `J` is constant the symbols transform as a tensor:
//!   `C = J^T Ct J`, sums of suffixes. `D_ab = dMt_ab/dphi_b` is antisymmetric, so the
//!   program needs `n (n - 1) / 2` small derivatives, twice as many products with the rates
//!   and about `2 n^2` additions, instead of `n^2` expanded entries.

use crate::expr::{Expr, Var};
use crate::mechanics::ArmSpec;
use crate::ring::{ratio, Coefficient};
use crate::slp::{Emit, Id, Input, Program};

/// `C` row-major from M and the momenta `p = M qd`, expanded:
/// `C_ij = sum_k 1/2 (dM_ij/dq_k + dM_ik/dq_j - dM_jk/dq_i) qd_k`, summed in closed form:
/// `sum_k dM_ij/dq_k qd_k` is `Mdot_ij` and `sum_k dM_ik/dq_j qd_k = dp_i/dq_j`, so
/// `2 C_ij = Mdot_ij + dp_i/dq_j - dp_j/dq_i`: `n^2` derivatives instead of the `n^3` symbols
/// (the symbol-by-symbol sum is the test's check).
#[must_use]
pub fn expanded<C: Coefficient>(m: &[Vec<Expr<C>>]) -> Vec<Vec<Expr<C>>> {
    let n = m.len();
    let momenta: Vec<Expr<C>> = (0..n)
        .map(|i| {
            let mut p = Expr::zero();
            for (k, mik) in m[i].iter().enumerate() {
                p.add_assign(&mik.mul_var(Var::Qd(k)));
            }
            p
        })
        .collect();
    let half = ratio(1, 2);
    let dp: Vec<Vec<Expr<C>>> = momenta
        .iter()
        .map(|p| (0..n).map(|j| p.diff_q(j)).collect())
        .collect();
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| m[i][j].dt_q(n).add(&dp[i][j]).sub(&dp[j][i]).scale(&half))
                .collect()
        })
        .collect()
}

/// `D_ab = dMt_ab/dphi_b` for `a > b` (`D[a][b]`, the strict lower triangle; `D_ba = -D_ab`),
/// or `None` unless every joint is revolute.
///
/// `Mt_ab = M_ab - M_(a+1)b - M_a(b+1) + M_(a+1)(b+1)` (entries past the last joint are
/// zero) inverts `M_ij = sum_(a >= i, b >= j) Mt_ab`. For `a > b`, `Mt_ab` depends on the
/// joint angles only through `phi_a - phi_b = q_(b+1) + ... + q_a`, in which `q_a` appears
/// once, so `dMt_ab/dphi_b = -dMt_ab/dq_a`.
#[must_use]
pub fn absolute_derivatives<C: Coefficient>(
    arm: &ArmSpec<C>,
    m: &[Vec<Expr<C>>],
) -> Option<Vec<Vec<Expr<C>>>> {
    if !arm.all_revolute() {
        return None;
    }
    let n = m.len();
    let entry = |i: usize, j: usize| (i < n && j < n).then(|| &m[i][j]);
    let mut d = Vec::with_capacity(n);
    for (a, m_a) in m.iter().enumerate() {
        let mut row = Vec::with_capacity(a);
        for (b, m_ab) in m_a.iter().enumerate().take(a) {
            let mut mt = m_ab.clone();
            for (sign, e) in [
                (false, entry(a + 1, b)),
                (false, entry(a, b + 1)),
                (true, entry(a + 1, b + 1)),
            ] {
                match (sign, e) {
                    (false, Some(e)) => mt.sub_assign(e),
                    (true, Some(e)) => mt.add_assign(e),
                    (_, None) => {}
                }
            }
            row.push(mt.diff_q(a).scale(&ratio(-1, 1)));
        }
        d.push(row);
    }
    Some(d)
}

/// The program of `C = J^T Ct J` from [`absolute_derivatives`]: `n^2` output nodes,
/// row-major. `C_ij = sum_(a >= i) R_aj` with the row suffixes `R_aj = sum_(b >= j) Ct_ab`
/// and `Ct_ab = D_ab w_b` (`-D_ba w_b` above the diagonal, zero on it): `n (n - 1)`
/// products and `2 n^2` additions at most.
pub fn absolute_program<C: Emit>(p: &mut Program, d: &[Vec<Expr<C>>]) -> Vec<Id> {
    let n = d.len();
    let zero = p.constant(crate::ring::int(0));
    let mut w = Vec::with_capacity(n);
    for k in 0..n {
        let qd = p.input(Input::Qd(k));
        let wk = if k == 0 { qd } else { p.add(w[k - 1], qd) };
        w.push(wk);
    }
    let dn: Vec<Vec<Id>> = d
        .iter()
        .map(|row| row.iter().map(|e| p.expr(e)).collect())
        .collect();
    // r[a][j] = R_aj.
    let mut r = vec![vec![zero; n]; n];
    for a in 0..n {
        let mut acc = zero;
        for b in (0..n).rev() {
            acc = match a.cmp(&b) {
                std::cmp::Ordering::Greater => {
                    let t = p.mul(dn[a][b], w[b]);
                    p.add(t, acc)
                }
                std::cmp::Ordering::Less => {
                    let t = p.mul(dn[b][a], w[b]);
                    p.sub(acc, t)
                }
                std::cmp::Ordering::Equal => acc,
            };
            r[a][b] = acc;
        }
    }
    let mut c = vec![zero; n * n];
    for j in 0..n {
        let mut acc = zero;
        for i in (0..n).rev() {
            acc = p.add(r[i][j], acc);
            c[i * n + j] = acc;
        }
    }
    c
}

#[cfg(test)]
mod tests;
