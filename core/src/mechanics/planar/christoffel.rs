//! The Christoffel symbols of the mass matrix, by the two routes of [`crate::christoffel`]:
//! the Coriolis matrix expanded entry by entry, and the derivatives `D_ab = dMt_ab/dphi_b` of
//! the metric in the links' absolute angles, from which a program sums it.

use super::spec::ArmSpec;
use crate::expr::{Expr, Var};
use crate::ring::{ratio, Coefficient};

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
/// With `N_ij = s_i s_j M_ij` (`s_i` joint `i`'s sense, [`ArmSpec::sense`]),
/// `Mt_ab = N_ab - N_(a+1)b - N_a(b+1) + N_(a+1)(b+1)` (entries past the last joint are
/// zero) inverts `N_ij = sum_(a >= i, b >= j) Mt_ab`. For `a > b`, `Mt_ab` depends on the
/// joint angles only through `phi_a - phi_b = s_(b+1) q_(b+1) + ... + s_a q_a` (plus the
/// offsets, constant), in which `q_a` appears once, so `dMt_ab/dphi_b = -s_a dMt_ab/dq_a`.
#[must_use]
pub fn absolute_derivatives<C: Coefficient>(
    arm: &ArmSpec<C>,
    m: &[Vec<Expr<C>>],
) -> Option<Vec<Vec<Expr<C>>>> {
    if !arm.all_revolute() {
        return None;
    }
    let n = m.len();
    let sense = |i: usize| arm.sense(i);
    let signed: Vec<Vec<Expr<C>>> = m
        .iter()
        .enumerate()
        .map(|(i, row)| {
            row.iter()
                .enumerate()
                .map(|(j, e)| {
                    if sense(i) * sense(j) < 0 {
                        e.scale(&ratio(-1, 1))
                    } else {
                        e.clone()
                    }
                })
                .collect()
        })
        .collect();
    let m = &signed;
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
            row.push(mt.diff_q(a).scale(&ratio(-i64::from(sense(a)), 1)));
        }
        d.push(row);
    }
    Some(d)
}

#[cfg(test)]
mod tests;
