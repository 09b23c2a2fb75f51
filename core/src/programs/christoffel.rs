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
//!   ([`crate::mechanics`] builds it pair by pair). For such a metric the Christoffel sum
//!   collapses to `Ct_ab = dMt_ab/dphi_b w_b`, and since `J` is constant the symbols transform as a tensor:
//!   `C = J^T Ct J`, sums of suffixes. `D_ab = dMt_ab/dphi_b` is antisymmetric, so the
//!   program needs `n (n - 1) / 2` small derivatives, twice as many products with the rates
//!   and about `2 n^2` additions, instead of `n^2` expanded entries.

use crate::expr::Expr;
use crate::slp::{Emit, Id, Input, Program};

pub use crate::mechanics::planar::christoffel::{absolute_derivatives, expanded};

/// The program of `C = J^T Ct J` from [`absolute_derivatives`]: `n^2` output nodes,
/// row-major. `C_ij = s_i s_j sum_(a >= i) R_aj` with the row suffixes
/// `R_aj = sum_(b >= j) Ct_ab` and `Ct_ab = D_ab w_b` (`-D_ba w_b` above the diagonal, zero on
/// it), `s` the joints' senses (`-1` reversed; `J_ak = s_k` for `k <= a`): `n (n - 1)`
/// products and `2 n^2` additions at most.
pub fn absolute_program<C: Emit>(p: &mut Program, d: &[Vec<Expr<C>>], senses: &[i32]) -> Vec<Id> {
    let n = d.len();
    let zero = p.constant(crate::ring::int(0));
    let mut w: Vec<Id> = Vec::with_capacity(n);
    for k in 0..n {
        let qd = p.input(Input::Qd(k));
        let reversed = senses.get(k) == Some(&-1);
        let wk = match (k, reversed) {
            (0, false) => qd,
            (0, true) => p.neg(qd),
            (_, false) => p.add(w[k - 1], qd),
            (_, true) => p.sub(w[k - 1], qd),
        };
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
            let sign = senses.get(i).unwrap_or(&1) * senses.get(j).unwrap_or(&1);
            c[i * n + j] = if sign < 0 { p.neg(acc) } else { acc };
        }
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanics::planar::tests::{turned_arm, uneven_arm};
    use crate::mechanics::Dynamics;

    /// The program evaluates what the expanded entries evaluate: plain arms of 1 to 6 links,
    /// and arms of 1 to 4 with offsets and every pattern of reversed joints.
    #[test]
    fn the_program_is_the_expanded_matrix() {
        let plain = (1..=6).map(uneven_arm);
        let turned = (1..=4).flat_map(|n| (0..1u32 << n).map(move |r| turned_arm(n, r)));
        for arm in plain.chain(turned) {
            let n = arm.links.len();
            let dy = Dynamics::derive(&arm);
            let d = absolute_derivatives(&arm, &dy.mass_matrix).expect("all revolute");
            let mut p = Program::new();
            let senses: Vec<i32> = (0..n).map(|i| arm.sense(i)).collect();
            let out = absolute_program(&mut p, &d, &senses);
            #[allow(clippy::cast_precision_loss)]
            let q: Vec<f64> = (0..n).map(|k| 0.3 + 0.7 * k as f64).collect();
            #[allow(clippy::cast_precision_loss)]
            let qd: Vec<f64> = (0..n).map(|k| 1.1 - 0.45 * k as f64).collect();
            let values = p.eval(&|i| match i {
                Input::Q(k) => q[k],
                Input::Qd(k) => qd[k],
                _ => f64::NAN,
            });
            let cm = expanded(&dy.mass_matrix);
            for i in 0..n {
                for j in 0..n {
                    let want = cm[i][j].eval(&q, &qd, &[]);
                    let got = values[out[i * n + j].0 as usize];
                    assert!(
                        (got - want).abs() <= 1e-12 * want.abs().max(1.0),
                        "C{i}{j}: {got} vs {want}"
                    );
                }
            }
        }
    }
}
