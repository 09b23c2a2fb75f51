//! Run-time parameters: polynomials in named parameters with exact rational coefficients.
//!
//! A link value written `self.m1` in `#[arm(...)]` is not known at compile time. The engine
//! still derives exactly: the coefficient ring becomes [`Poly`], polynomials in the named
//! [`Param`]s with [`Rational`] coefficients, so `M11 = i1 + c1^2 m1 + ...` is derived with the
//! same canonical form and the same differentiation as an all-literal arm, and the generated
//! code reads each parameter from its field when a method is called. Values stay polynomial:
//! sums, differences, products and division by a non-zero rational.

use std::collections::BTreeMap;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::sync::Arc;

use num_traits::{One, Signed, Zero};

use crate::ring::{show, Rational};

/// A run-time parameter, named after the `f64` field of the arm's struct it is read from.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
///
/// Or a named constant: a value the derive knows, but not as a rational (the cosine of a twist of
/// 0.3 rad), kept exact in its symbol (`cos(0.3)`) in the formulas and entering the generated
/// code as the `f64` it rounds to.
pub struct Param(Arc<str>, Option<u64>);

impl Param {
    /// The parameter read from field `name`.
    #[must_use]
    pub fn new(name: &str) -> Self {
        Self(Arc::from(name), None)
    }

    /// The named constant `name` of value `value`.
    #[must_use]
    pub fn constant(name: &str, value: f64) -> Self {
        Self(Arc::from(name), Some(value.to_bits()))
    }

    /// The field name, or the constant's name.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.0
    }

    /// The value of a named constant; `None` for a run-time parameter.
    #[must_use]
    pub fn value(&self) -> Option<f64> {
        self.1.map(f64::from_bits)
    }
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// A product of parameters with positive exponents, sorted by name (empty: the constant 1).
/// Ordered by degree first, so that sums read `1 + i1 + c1^2 m1`.
#[derive(Clone, PartialEq, Eq, Hash, Debug, Default)]
pub struct ParamMonomial(Vec<(Param, u32)>);

impl PartialOrd for ParamMonomial {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for ParamMonomial {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.degree()
            .cmp(&other.degree())
            .then_with(|| self.0.cmp(&other.0))
    }
}

impl ParamMonomial {
    /// The parameters and their exponents, sorted by name.
    #[must_use]
    pub fn powers(&self) -> &[(Param, u32)] {
        &self.0
    }

    /// Total degree.
    #[must_use]
    pub fn degree(&self) -> u32 {
        self.0.iter().map(|(_, e)| e).sum()
    }

    /// The product of `powers` (positive exponents, distinct parameters, any order).
    #[must_use]
    pub fn from_powers(mut powers: Vec<(Param, u32)>) -> Self {
        powers.retain(|(_, e)| *e > 0);
        powers.sort();
        Self(powers)
    }

    fn mul(&self, other: &Self) -> Self {
        // Most products in a derivation have a constant side.
        if other.0.is_empty() {
            return self.clone();
        }
        if self.0.is_empty() {
            return other.clone();
        }
        let mut out: BTreeMap<Param, u32> = self.0.iter().cloned().collect();
        for (p, e) in &other.0 {
            *out.entry(p.clone()).or_insert(0) += e;
        }
        Self(out.into_iter().collect())
    }
}

impl fmt::Display for ParamMonomial {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, (p, e)) in self.0.iter().enumerate() {
            if i > 0 {
                f.write_str(" ")?;
            }
            write!(f, "{p}")?;
            if *e > 1 {
                write!(f, "^{e}")?;
            }
        }
        Ok(())
    }
}

/// A polynomial in run-time parameters with exact rational coefficients, in canonical form
/// (no zero coefficients), so equal polynomials are structurally equal.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Debug, Default)]
pub struct Poly(BTreeMap<ParamMonomial, Rational>);

impl Poly {
    /// The parameter itself.
    #[must_use]
    pub fn param(p: Param) -> Self {
        Self(BTreeMap::from([(
            ParamMonomial(vec![(p, 1)]),
            Rational::one(),
        )]))
    }

    /// `r m`.
    #[must_use]
    pub fn monomial(m: ParamMonomial, r: Rational) -> Self {
        let mut out = Self::default();
        out.add_term(m, r);
        out
    }

    /// A rational constant.
    #[must_use]
    pub fn constant(r: Rational) -> Self {
        let mut out = Self::default();
        out.add_term(ParamMonomial::default(), r);
        out
    }

    /// The terms, constant first.
    pub fn terms(&self) -> impl Iterator<Item = (&ParamMonomial, &Rational)> + '_ {
        self.0.iter()
    }

    /// The value, if no parameter occurs.
    #[must_use]
    pub fn as_rational(&self) -> Option<Rational> {
        match self.0.len() {
            0 => Some(Rational::zero()),
            1 => self.0.get(&ParamMonomial::default()).cloned(),
            _ => None,
        }
    }

    /// The parameters that occur, sorted by name.
    #[must_use]
    pub fn params(&self) -> Vec<Param> {
        let mut out: Vec<Param> = self
            .0
            .keys()
            .flat_map(|m| m.0.iter().map(|(p, _)| p.clone()))
            .collect();
        out.sort();
        out.dedup();
        out
    }

    /// The value with each parameter replaced by `value(param)`.
    #[must_use]
    pub fn eval(&self, value: &dyn Fn(&Param) -> f64) -> f64 {
        self.0
            .iter()
            .map(|(m, c)| {
                let c = crate::ring::to_f64(c).unwrap_or(f64::NAN);
                m.0.iter().fold(c, |acc, (p, e)| {
                    acc * value(p).powi(i32::try_from(*e).unwrap_or(i32::MAX))
                })
            })
            .sum()
    }

    fn add_term(&mut self, m: ParamMonomial, c: Rational) {
        if c.is_zero() {
            return;
        }
        match self.0.remove(&m) {
            Some(old) => {
                let sum = old + c;
                if !sum.is_zero() {
                    self.0.insert(m, sum);
                }
            }
            None => {
                self.0.insert(m, c);
            }
        }
    }
}

impl Add for Poly {
    type Output = Self;
    fn add(mut self, other: Self) -> Self {
        for (m, c) in other.0 {
            self.add_term(m, c);
        }
        self
    }
}

impl Neg for Poly {
    type Output = Self;
    fn neg(self) -> Self {
        Self(self.0.into_iter().map(|(m, c)| (m, -c)).collect())
    }
}

impl Sub for Poly {
    type Output = Self;
    fn sub(self, other: Self) -> Self {
        self + (-other)
    }
}

impl Mul for Poly {
    type Output = Self;
    fn mul(self, other: Self) -> Self {
        // A constant factor (the rates' 1 and 2, the lengths of literal links) only scales:
        // no monomial products, no map rebuilt.
        if let Some(r) = other.as_rational() {
            return crate::ring::Coefficient::scale(&self, &r);
        }
        if let Some(r) = self.as_rational() {
            return crate::ring::Coefficient::scale(&other, &r);
        }
        let mut out = Self::default();
        for (m1, c1) in &self.0 {
            for (m2, c2) in &other.0 {
                out.add_term(m1.mul(m2), c1 * c2);
            }
        }
        out
    }
}

impl crate::ring::Coefficient for Poly {
    fn from_rational(r: Rational) -> Self {
        Self::constant(r)
    }
    fn is_zero(&self) -> bool {
        self.0.is_empty()
    }
    fn scale(&self, r: &Rational) -> Self {
        if Zero::is_zero(r) {
            return Self::default();
        }
        // The rationals' own scaling: no gcd for the common factors 1, -1 and 1/2.
        Self(
            self.0
                .iter()
                .map(|(m, c)| (m.clone(), crate::ring::Coefficient::scale(c, r)))
                .collect(),
        )
    }
}

impl fmt::Display for Poly {
    /// `5/3`, `-m2`, `1/2 l1 m2`, or a sum in parentheses `(i1 + c1^2 m1)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let term = |m: &ParamMonomial, c: &Rational| -> String {
            let mag = c.abs();
            match (m.0.is_empty(), mag.is_one()) {
                (true, _) => show(&mag),
                (false, true) => m.to_string(),
                (false, false) => format!("{} {m}", show(&mag)),
            }
        };
        match self.0.len() {
            0 => f.write_str("0"),
            1 => {
                let (m, c) = self.0.iter().next().ok_or(fmt::Error)?;
                let sign = if c.is_negative() { "-" } else { "" };
                write!(f, "{sign}{}", term(m, c))
            }
            _ => {
                f.write_str("(")?;
                for (i, (m, c)) in self.0.iter().enumerate() {
                    match (i, c.is_negative()) {
                        (0, true) => write!(f, "-{}", term(m, c))?,
                        (0, false) => f.write_str(&term(m, c))?,
                        (_, true) => write!(f, " - {}", term(m, c))?,
                        (_, false) => write!(f, " + {}", term(m, c))?,
                    }
                }
                f.write_str(")")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ring::{int, ratio, Coefficient as _};

    fn p(name: &str) -> Poly {
        Poly::param(Param::new(name))
    }

    #[test]
    fn arithmetic_is_exact_and_canonical() {
        // (m + 1/2)(m - 1/2) = m^2 - 1/4
        let m = p("m");
        let half = Poly::constant(ratio(1, 2));
        let prod = (m.clone() + half.clone()) * (m.clone() - half);
        assert_eq!(prod, m.clone() * m.clone() - Poly::constant(ratio(1, 4)));
        assert!((m.clone() - m).0.is_empty());
        assert_eq!(Poly::constant(int(3)).as_rational(), Some(int(3)));
        assert_eq!(p("a").as_rational(), None);
    }

    #[test]
    fn display_names_parameters() {
        let e = p("i1") + p("m1") * p("c1") * p("c1");
        assert_eq!(e.to_string(), "(i1 + c1^2 m1)");
        assert_eq!((-p("m2")).scale(&ratio(1, 2)).to_string(), "-1/2 m2");
        assert_eq!(Poly::constant(ratio(5, 3)).to_string(), "5/3");
        assert_eq!(
            (p("l") * p("m")).eval(&|q| if q.name() == "l" { 2.0 } else { 3.0 }),
            6.0
        );
    }
}
