//! The kinetic energy's metric in the links' absolute angles, for arms whose joints all turn.
//!
//! In the absolute angles `phi_a = q_1 + ... + q_a` (rates `w = J qd`, `J` the lower triangle
//! of ones) `T = 1/2 w^T Mt w + 1/2 sum_i armature_i qd_i^2`, with `Mt_aa` constant and, for
//! `a > b`, `Mt_ab = Mt_ba = A_ab cos(phi_a - phi_b) - B_ab sin(phi_a - phi_b)`: a handful of
//! exact coefficients per pair of links ([`Pairs`]). Then `M = J^T Mt J + diag(armature)`,
//! `M_ij = sum_(a >= i, b >= j) Mt_ab`: sums of small expressions instead of `n^2` second
//! derivatives of the whole kinetic energy. The velocity products follow from the Christoffel
//! symbols of this metric ([`crate::christoffel`]): `c = J^T ct`, `ct_a = sum_b D_ab w_b^2`
//! with `D_ab = dMt_ab/dphi_b = A_ab sin(phi_a - phi_b) + B_ab cos(phi_a - phi_b)` for
//! `a > b` and `D_ba = -D_ab`. The same canonical expressions either way (the tests compare
//! them with the Hessian of T and with Lagrange's equation).

use super::bodies::Body;
use super::rates::RateProducts;
use super::spec::ArmSpec;
use crate::expr::Expr;
use crate::ring::{int, Coefficient};
use crate::trig::Angle;

/// The metric's coefficients: `diag[a] = Mt_aa`; `cross[a][b] = (A_ab, B_ab)` for `a > b`;
/// and the joints' senses (`-1` reversed).
pub(crate) struct Pairs<C> {
    pub(crate) diag: Vec<C>,
    pub(crate) cross: Vec<Vec<(C, C)>>,
    senses: Vec<i32>,
}

/// `theta_hi - theta_lo` (`hi > lo`): the joints `lo + 1 ..= hi`, a reversed one's angle
/// subtracted ([`ArmSpec::sense`]).
pub(crate) fn relative_angle(senses: &[i32], lo: usize, hi: usize) -> Angle {
    Angle::new(
        (0..=hi)
            .map(|k| if k > lo { senses[k] } else { 0 })
            .collect(),
    )
}

/// `(x, y)` of `a conj(b)` for complex numbers `a = (x, y)`.
fn times_conj<C: Coefficient>(a: &(C, C), b: &(C, C)) -> (C, C) {
    (
        a.0.clone() * b.0.clone() + a.1.clone() * b.1.clone(),
        a.1.clone() * b.0.clone() - a.0.clone() * b.1.clone(),
    )
}

/// The coefficients of the bodies on the arm (all joints revolute).
///
/// A body of link `i` has velocity `sum_a omega_a i z_a` (complex plane),
/// `z_a = r_a e^(i theta_a)` with `r_a = l_a` for the links before it and `r_i = cx + i cy`
/// its centre of mass, `theta_a` the absolute angle of link `a` and `omega_a` its rate. So
/// `|v|^2 = sum_(a,b) omega_a omega_b Re(r_a conj(r_b) e^(i (theta_a - theta_b)))`. A joint
/// offset turns `r_a` (and the centre) by the offsets up to its link ([`ArmSpec::turned`]),
/// leaving `theta_a` the part of the angle the joints' `q` give.
pub(crate) fn pairs<C: Coefficient>(arm: &ArmSpec<C>, bodies: &[Body<C>]) -> Pairs<C> {
    let n = arm.links.len();
    let zero = || C::from_rational(int(0));
    let mut diag: Vec<C> = (0..n).map(|_| zero()).collect();
    let mut cross: Vec<Vec<(C, C)>> = (0..n)
        .map(|a| (0..a).map(|_| (zero(), zero())).collect())
        .collect();
    // Each link's end from its joint, turned.
    let ends: Vec<(C, C)> = (0..n)
        .map(|a| arm.turned(a, &(arm.links[a].length.clone(), zero())))
        .collect();
    for body in bodies {
        let (i, m) = (body.link, &body.mass);
        let h = arm.turned(i, &body.first_moment);
        for a in 0..i {
            let ra = &ends[a];
            let (x, y) = ra;
            diag[a] = diag[a].clone() + m.clone() * (x.clone() * x.clone() + y.clone() * y.clone());
            for (pair, rb) in cross[a].iter_mut().zip(&ends) {
                let (p, q) = times_conj(ra, rb);
                pair.0 = pair.0.clone() + m.clone() * p;
                pair.1 = pair.1.clone() + m.clone() * q;
            }
            // The body's own term: m r_i conj(r_a), its first moment times the link's end.
            let (p, q) = times_conj(&h, ra);
            cross[i][a].0 = cross[i][a].0.clone() + p;
            cross[i][a].1 = cross[i][a].1.clone() + q;
        }
        diag[i] = diag[i].clone() + body.joint_inertia.clone();
    }
    let senses = (0..n).map(|i| arm.sense(i)).collect();
    Pairs {
        diag,
        cross,
        senses,
    }
}

impl<C: Coefficient> Pairs<C> {
    /// `Mt_ab`.
    pub(crate) fn entry(&self, a: usize, b: usize) -> Expr<C> {
        if a == b {
            return Expr::constant(self.diag[a].clone());
        }
        let (hi, lo) = (a.max(b), a.min(b));
        let (ca, cb) = &self.cross[hi][lo];
        let angle = relative_angle(&self.senses, lo, hi);
        Expr::cos(ca.clone(), angle.clone()).sub(&Expr::sin(cb.clone(), angle))
    }

    /// `M = J^T Mt J + diag(armature)`, both triangles: `M_ij = R_ij + M_(i+1)j` above the
    /// diagonal with the row suffixes `R_aj = sum_(b >= j) Mt_ab`, so that each entry costs
    /// one sum of its own size. `J_ak` is joint `k`'s sense for `k <= a`, so a reversed joint's
    /// row and column change sign.
    pub(crate) fn mass_matrix(&self, arm: &ArmSpec<C>) -> Vec<Vec<Expr<C>>> {
        let n = self.diag.len();
        // r[a][j] = R_aj.
        let mut r: Vec<Vec<Expr<C>>> = vec![vec![Expr::zero(); n]; n];
        for (a, row) in r.iter_mut().enumerate() {
            let mut acc = Expr::zero();
            for b in (0..n).rev() {
                acc.add_assign(&self.entry(a, b));
                row[b] = acc.clone();
            }
        }
        let mut m: Vec<Vec<Expr<C>>> = vec![vec![Expr::zero(); n]; n];
        for j in 0..n {
            let mut acc = Expr::zero();
            for i in (0..n).rev() {
                acc.add_assign(&r[i][j]);
                if i <= j {
                    m[i][j] = acc.clone();
                }
            }
            m[j][j].add_assign(&Expr::constant(arm.links[j].armature.clone()));
        }
        for (i, row) in m.iter_mut().enumerate() {
            for (j, e) in row.iter_mut().enumerate().skip(i) {
                if self.senses[i] * self.senses[j] < 0 {
                    *e = e.scale(&int(-1));
                }
            }
        }
        for i in 1..n {
            let (upper, lower) = m.split_at_mut(i);
            for (j, row) in upper.iter().enumerate() {
                lower[0][j] = row[i].clone();
            }
        }
        m
    }

    /// `D_ab` for `a > b`.
    fn derivative(&self, a: usize, b: usize) -> Expr<C> {
        let (ca, cb) = &self.cross[a][b];
        let angle = relative_angle(&self.senses, b, a);
        Expr::sin(ca.clone(), angle.clone()).add(&Expr::cos(cb.clone(), angle))
    }

    /// The velocity-product torques `c_i = s_i sum_(a >= i) ct_a` (`s_i` joint `i`'s sense),
    /// `ct_a = sum_(b < a) D_ab w_b^2 - sum_(b > a) D_ba w_b^2`.
    pub(crate) fn coriolis(&self, rates: &mut RateProducts<C>) -> Vec<Expr<C>> {
        let n = self.diag.len();
        let mut ct: Vec<Expr<C>> = vec![Expr::zero(); n];
        for a in 0..n {
            for b in 0..a {
                let d = self.derivative(a, b);
                if d.is_zero() {
                    continue;
                }
                ct[a].add_product(&d, rates.product(b, b));
                ct[b].add_product(&d.scale(&int(-1)), rates.product(a, a));
            }
        }
        let mut c = vec![Expr::zero(); n];
        let mut acc = Expr::zero();
        for i in (0..n).rev() {
            acc.add_assign(&ct[i]);
            c[i] = if self.senses[i] < 0 {
                acc.scale(&int(-1))
            } else {
                acc.clone()
            };
        }
        c
    }
}
