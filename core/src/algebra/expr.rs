//! The canonical form: sums of `coefficient x trig atom x monomial in joint rates`.
//!
//! Trig atoms come only from revolute angles; a prismatic joint's displacement enters the
//! monomial as the variable [`Var::Q`], so the form is polynomial in it.
//!
//! An [`Expr`] is an ordered map from `(monomial, atom)` to a non-zero coefficient, so two
//! expressions are equal exactly when they are the same function. Differentiation in `q`, in
//! the rates, and `d/dt` by the chain rule act on this form directly.

use std::collections::BTreeMap;
use std::fmt;

use crate::ring::{int, Coefficient, Rational};
use crate::trig::{Angle, Trig};

pub use super::monomial::{Monomial, Var};

/// A sum of `coefficient x atom x monomial` terms in canonical form.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
pub struct Expr<C = Rational> {
    terms: BTreeMap<(Monomial, Trig), C>,
}

impl<C> Default for Expr<C> {
    fn default() -> Self {
        Self {
            terms: BTreeMap::new(),
        }
    }
}

impl<C: Coefficient> Expr<C> {
    /// The zero expression.
    #[must_use]
    pub fn zero() -> Self {
        Self::default()
    }

    /// A constant.
    #[must_use]
    pub fn constant(c: C) -> Self {
        Self::term(c, Trig::One, Monomial::one())
    }

    /// A single term.
    #[must_use]
    pub fn term(c: C, trig: Trig, monomial: Monomial) -> Self {
        let mut e = Self::zero();
        e.add_term(c, trig, monomial);
        e
    }

    /// A single variable (a rate or an acceleration).
    #[must_use]
    pub fn var(v: Var) -> Self {
        Self::term(C::from_rational(int(1)), Trig::One, Monomial::var(v))
    }

    /// `c cos(angle)`.
    #[must_use]
    pub fn cos(c: C, angle: Angle) -> Self {
        let (s, t) = Trig::cos(angle);
        Self::term(c.scale(&int(i64::from(s))), t, Monomial::one())
    }

    /// `c sin(angle)`.
    #[must_use]
    pub fn sin(c: C, angle: Angle) -> Self {
        match Trig::sin(angle) {
            Some((s, t)) => Self::term(c.scale(&int(i64::from(s))), t, Monomial::one()),
            None => Self::zero(),
        }
    }

    fn add_term(&mut self, c: C, trig: Trig, monomial: Monomial) {
        if c.is_zero() {
            return;
        }
        // One search of the map, not a removal and an insertion.
        match self.terms.entry((monomial, trig)) {
            std::collections::btree_map::Entry::Occupied(mut e) => {
                let sum = e.get().clone() + c;
                if sum.is_zero() {
                    e.remove();
                } else {
                    *e.get_mut() = sum;
                }
            }
            std::collections::btree_map::Entry::Vacant(e) => {
                e.insert(c);
            }
        }
    }

    /// The terms in canonical order: `(monomial, atom, coefficient)`.
    pub fn terms(&self) -> impl Iterator<Item = (&Monomial, &Trig, &C)> + '_ {
        self.terms.iter().map(|((m, t), c)| (m, t, c))
    }

    /// Number of terms.
    #[must_use]
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether this is zero (has no terms).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// Whether this is zero.
    #[must_use]
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// `self + other`.
    #[must_use]
    pub fn add(&self, other: &Self) -> Self {
        let mut out = self.clone();
        out.add_assign(other);
        out
    }

    /// `self += other`, in place: an accumulating sum need not copy itself at every step.
    pub fn add_assign(&mut self, other: &Self) {
        for ((m, t), c) in &other.terms {
            self.add_term(c.clone(), t.clone(), m.clone());
        }
    }

    /// `self - other`.
    #[must_use]
    pub fn sub(&self, other: &Self) -> Self {
        self.add(&other.scale(&int(-1)))
    }

    /// `r self` for a rational `r`.
    #[must_use]
    pub fn scale(&self, r: &Rational) -> Self {
        if r.is_zero() {
            return Self::zero();
        }
        // A non-zero factor keeps every term non-zero and the order of the terms.
        Self {
            terms: self
                .terms
                .iter()
                .map(|(k, c)| (k.clone(), c.scale(r)))
                .collect(),
        }
    }

    /// `c self` for a coefficient `c`.
    #[must_use]
    pub fn scale_by(&self, k: &C) -> Self {
        if k.is_zero() {
            return Self::zero();
        }
        // Rationals and polynomials have no zero divisors: the terms stay non-zero.
        Self {
            terms: self
                .terms
                .iter()
                .map(|(key, c)| (key.clone(), c.clone() * k.clone()))
                .collect(),
        }
    }

    /// `self v` for a rate or acceleration `v`: every monomial gains the same factor, which
    /// keeps their order, and no coefficient is multiplied.
    #[must_use]
    pub fn mul_var(&self, v: Var) -> Self {
        let factor = Monomial::var(v);
        Self {
            terms: self
                .terms
                .iter()
                .map(|((m, t), c)| ((m.mul(&factor), t.clone()), c.clone()))
                .collect(),
        }
    }

    /// `self x other`, trig products linearised.
    #[must_use]
    pub fn mul(&self, other: &Self) -> Self {
        let mut out = Self::zero();
        out.add_product(self, other);
        out
    }

    /// `self += a x b`, without building the product on its own first.
    pub fn add_product(&mut self, a: &Self, b: &Self) {
        for ((m1, t1), c1) in &a.terms {
            for ((m2, t2), c2) in &b.terms {
                let m = m1.mul(m2);
                let c = c1.clone() * c2.clone();
                for (r, t) in t1.mul(t2) {
                    self.add_term(c.scale(&r), t, m.clone());
                }
            }
        }
    }

    /// `d/dq_j` (0-based joint): through the trig atoms for a revolute joint, through the
    /// monomials for a prismatic one (whichever `q_j` occurs in).
    #[must_use]
    pub fn diff_q(&self, j: usize) -> Self {
        let mut out = Self::zero();
        for ((m, t), c) in &self.terms {
            if let Some((k, dt)) = t.diff(j) {
                out.add_term(c.scale(&int(i64::from(k))), dt, m.clone());
            }
            if let Some((e, dm)) = m.diff(Var::Q(j)) {
                out.add_term(c.scale(&int(i64::from(e))), t.clone(), dm);
            }
        }
        out
    }

    /// `sum_j (d/dq_j) qd_j` for `n` joints: the time derivative through the angles alone.
    #[must_use]
    pub fn dt_q(&self, n: usize) -> Self {
        // One pass into one map: no intermediate expression per joint.
        let mut out = Self::zero();
        let rates: Vec<Monomial> = (0..n).map(|j| Monomial::var(Var::Qd(j))).collect();
        for ((m, t), c) in &self.terms {
            for (j, rate) in rates.iter().enumerate() {
                if let Some((k, dt)) = t.diff(j) {
                    out.add_term(c.scale(&int(i64::from(k))), dt, m.mul(rate));
                }
                if let Some((e, dm)) = m.diff(Var::Q(j)) {
                    out.add_term(c.scale(&int(i64::from(e))), t.clone(), dm.mul(rate));
                }
            }
        }
        out
    }

    /// `self -= other`.
    pub fn sub_assign(&mut self, other: &Self) {
        for ((m, t), c) in &other.terms {
            self.add_term(-c.clone(), t.clone(), m.clone());
        }
    }

    /// `d/dv` for a rate or acceleration `v`.
    #[must_use]
    pub fn diff_var(&self, v: Var) -> Self {
        let mut out = Self::zero();
        for ((m, t), c) in &self.terms {
            if let Some((e, dm)) = m.diff(v) {
                out.add_term(c.scale(&int(i64::from(e))), t.clone(), dm);
            }
        }
        out
    }

    /// `d/dt` by the chain rule: `sum_j (d/dq_j) qd_j + (d/dqd_j) qdd_j`, for `n` joints.
    ///
    /// The expression must not contain accelerations (their derivative, the jerk, has no
    /// variable here); the engine only differentiates positions and momenta.
    #[must_use]
    pub fn dt(&self, n: usize) -> Self {
        debug_assert!(self
            .terms
            .keys()
            .all(|(m, _)| m.powers().all(|(v, _)| !matches!(v, Var::Qdd(_)))));
        let mut out = Self::zero();
        for j in 0..n {
            out.add_assign(&self.diff_q(j).mul_var(Var::Qd(j)));
            out.add_assign(&self.diff_var(Var::Qd(j)).mul_var(Var::Qdd(j)));
        }
        out
    }

    /// The part multiplying exactly `monomial` in the rates and accelerations, as an
    /// expression in `q` alone (prismatic displacements kept).
    #[must_use]
    pub fn coefficient_of(&self, monomial: &Monomial) -> Self {
        let mut out = Self::zero();
        for ((m, t), c) in &self.terms {
            let (positions, rates) = m.split_positions();
            if rates == *monomial {
                out.add_term(c.clone(), t.clone(), positions);
            }
        }
        out
    }

    /// The terms whose monomial satisfies `keep`.
    #[must_use]
    pub fn filter(&self, keep: impl Fn(&Monomial) -> bool) -> Self {
        let mut out = Self::zero();
        for ((m, t), c) in &self.terms {
            if keep(m) {
                out.add_term(c.clone(), t.clone(), m.clone());
            }
        }
        out
    }

    /// The distinct monomials, in order.
    #[must_use]
    pub fn monomials(&self) -> Vec<Monomial> {
        let mut out: Vec<Monomial> = self.terms.keys().map(|(m, _)| m.clone()).collect();
        out.dedup();
        out
    }

    /// The coefficient of the constant atom with the empty monomial.
    #[must_use]
    pub fn constant_term(&self) -> Option<&C> {
        self.terms.get(&(Monomial::one(), Trig::One))
    }

    /// The coefficient of `atom` with the empty monomial.
    #[must_use]
    pub fn coefficient(&self, atom: &Trig) -> Option<&C> {
        self.terms.get(&(Monomial::one(), atom.clone()))
    }
}

impl Expr<Rational> {
    /// Numeric value at `(q, qd, qdd)`.
    #[must_use]
    pub fn eval(&self, q: &[f64], qd: &[f64], qdd: &[f64]) -> f64 {
        self.terms()
            .map(|(m, t, c)| {
                crate::ring::to_f64(c).unwrap_or(f64::NAN) * t.eval(q) * m.eval(q, qd, qdd)
            })
            .sum()
    }
}

impl<C: Coefficient> fmt::Display for Expr<C> {
    /// Readable notation grouped by monomial: `(5/3 + c2) qd1^2 + (2/3 + c2) qd1 qd2 + ...`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return write!(f, "0");
        }
        let mut first_group = true;
        for m in self.monomials() {
            let group: Vec<(&Trig, &C)> = self
                .terms
                .iter()
                .filter(|((mm, _), _)| *mm == m)
                .map(|((_, t), c)| (t, c))
                .collect();
            let body = render_sum(&group);
            let bare = m == Monomial::one();
            if group.len() == 1 {
                // A single term needs no parentheses; its sign joins the outer sum.
                let (sign, text) = match body.strip_prefix('-') {
                    Some(rest) => ("-", rest.to_string()),
                    None => ("+", body.clone()),
                };
                let text = if !bare && text == "1" {
                    String::new()
                } else {
                    text
                };
                let sep = if bare || text.is_empty() { "" } else { " " };
                match (first_group, sign) {
                    (true, "-") => write!(f, "-{text}{sep}")?,
                    (true, _) => write!(f, "{text}{sep}")?,
                    (false, s) => write!(f, " {s} {text}{sep}")?,
                }
            } else {
                if !first_group {
                    write!(f, " + ")?;
                }
                if bare && first_group && self.monomials().len() == 1 {
                    write!(f, "{body}")?;
                } else {
                    write!(f, "({body}){}", if bare { "" } else { " " })?;
                }
            }
            if !bare {
                write!(f, "{m}")?;
            }
            first_group = false;
        }
        Ok(())
    }
}

/// `5/3 + c2 - 1/2 s23`.
fn render_sum<C: Coefficient>(terms: &[(&Trig, &C)]) -> String {
    let mut out = String::new();
    for (i, (t, c)) in terms.iter().enumerate() {
        let text = c.to_string();
        let (neg, mag) = match text.strip_prefix('-') {
            Some(rest) => (true, rest.to_string()),
            None => (false, text),
        };
        let body = match (t, mag.as_str()) {
            (Trig::One, _) => mag,
            (_, "1") => t.to_string(),
            _ => format!("{mag} {t}"),
        };
        match (i, neg) {
            (0, true) => out.push_str(&format!("-{body}")),
            (0, false) => out.push_str(&body),
            (_, true) => out.push_str(&format!(" - {body}")),
            (_, false) => out.push_str(&format!(" + {body}")),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ring::ratio;

    #[test]
    fn pythagoras_is_structural() {
        let c = Expr::<Rational>::cos(int(1), Angle::new(vec![1]));
        let s = Expr::<Rational>::sin(int(1), Angle::new(vec![1]));
        let one = c.mul(&c).add(&s.mul(&s));
        assert_eq!(one, Expr::constant(int(1)));
    }

    #[test]
    fn time_derivative_uses_the_chain_rule() {
        // d/dt (qd1 cos q2) = qdd1 cos q2 - qd1 qd2 sin q2
        let e = Expr::<Rational>::cos(int(1), Angle::new(vec![0, 1])).mul(&Expr::var(Var::Qd(0)));
        let d = e.dt(2);
        let expected = Expr::cos(int(1), Angle::new(vec![0, 1]))
            .mul(&Expr::var(Var::Qdd(0)))
            .sub(
                &Expr::sin(int(1), Angle::new(vec![0, 1]))
                    .mul(&Expr::var(Var::Qd(0)))
                    .mul(&Expr::var(Var::Qd(1))),
            );
        assert_eq!(d, expected);
    }

    #[test]
    fn display_reads_like_the_paper() {
        let qd1 = Expr::<Rational>::var(Var::Qd(0));
        let e = Expr::constant(ratio(5, 3))
            .add(&Expr::cos(int(1), Angle::new(vec![0, 1])))
            .mul(&qd1)
            .mul(&qd1)
            .add(&Expr::constant(ratio(-1, 3)).mul(&qd1));
        assert_eq!(e.to_string(), "-1/3 qd1 + (5/3 + c2) qd1^2");
    }
}
