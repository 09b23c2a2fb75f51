//! The exact result of a derivation, as `const` data on the arm type.
//!
//! Every derived arm carries [`PlanarArm::EXACT`](crate::PlanarArm::EXACT): the rational
//! coefficients and trigonometric atoms of its energies, mass matrix, velocity-product and
//! gravity torques. It is `const`, so a claim about the derivation can be checked by the
//! compiler:
//!
//! ```
//! use planar_arm::prelude::*;
//! use planar_arm::exact::{constant_term, cos_coefficient, Rational};
//!
//! #[derive(PlanarArm, Default)]
//! #[arm(gravity = 0)]
//! struct Paper2 {
//!     #[arm(length = 1, mass = 1)]
//!     upper: Revolute,
//!     #[arm(length = 1, mass = 1)]
//!     fore: Revolute,
//! }
//!
//! // M11 = 5/3 + cos q2 for the paper's two equal rods (m = l = 1).
//! const M11: &[planar_arm::exact::Term] = <Paper2 as PlanarArm<2>>::EXACT.mass_matrix[0][0];
//! const _: () = assert!(constant_term(M11).eq(Rational::new(5, 3)));
//! const _: () = assert!(cos_coefficient(M11, &[0, 1]).eq(Rational::new(1, 1)));
//! ```

/// An exact fraction with `i128` parts, reduced, denominator positive.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rational {
    numer: i128,
    denom: i128,
}

const fn gcd(mut a: i128, mut b: i128) -> i128 {
    if a < 0 {
        a = -a;
    }
    if b < 0 {
        b = -b;
    }
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
}

impl Rational {
    /// Zero.
    pub const ZERO: Self = Self { numer: 0, denom: 1 };

    /// `numer / denom`, reduced.
    ///
    /// # Panics
    /// If `denom == 0` (at compile time when used in a `const`).
    #[must_use]
    pub const fn new(numer: i128, denom: i128) -> Self {
        assert!(denom != 0, "denominator is zero");
        let g = gcd(numer, denom);
        let (mut n, mut d) = (numer / g, denom / g);
        if d < 0 {
            n = -n;
            d = -d;
        }
        Self { numer: n, denom: d }
    }

    /// The numerator.
    #[must_use]
    pub const fn numer(self) -> i128 {
        self.numer
    }

    /// The denominator (positive).
    #[must_use]
    pub const fn denom(self) -> i128 {
        self.denom
    }

    /// Equality, usable in `const` contexts.
    #[must_use]
    pub const fn eq(self, other: Self) -> bool {
        self.numer == other.numer && self.denom == other.denom
    }

    /// The nearest `f64` (up to one rounding of each part).
    #[must_use]
    #[allow(clippy::cast_precision_loss)] // documented: a float view of an exact value
    pub fn to_f64(self) -> f64 {
        self.numer as f64 / self.denom as f64
    }
}

impl core::fmt::Display for Rational {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        if self.denom == 1 {
            write!(f, "{}", self.numer)
        } else {
            write!(f, "{}/{}", self.numer, self.denom)
        }
    }
}

/// A trigonometric atom: `1`, `cos(k . q)` or `sin(k . q)`; `k[0]` multiplies q1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Trig {
    /// The constant 1.
    One,
    /// `cos(k . q)`.
    Cos(&'static [i32]),
    /// `sin(k . q)`.
    Sin(&'static [i32]),
}

/// A joint rate or acceleration (0-based joint).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Var {
    /// `qd[j]`.
    Qd(usize),
    /// `qdd[j]`.
    Qdd(usize),
}

/// One term `coeff x params x trig x product of powers`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Term {
    /// The exact coefficient.
    pub coeff: Rational,
    /// The trigonometric atom.
    pub trig: Trig,
    /// Rates and accelerations with their exponents (empty for a function of `q` alone).
    pub powers: &'static [(Var, u32)],
    /// Run-time parameters (the arm's `f64` fields named by `self.NAME`) with their
    /// exponents; empty for a term whose coefficient is a number.
    pub params: &'static [(&'static str, u32)],
}

impl Term {
    /// The term's value, for a term without run-time parameters (NaN if it has some: use
    /// [`eval_with`](Self::eval_with)).
    #[must_use]
    pub fn eval(&self, q: &[f64], qd: &[f64]) -> f64 {
        self.eval_with(q, qd, &|_| f64::NAN)
    }

    /// The term's value, each run-time parameter's value given by `param(name)`.
    #[must_use]
    pub fn eval_with(&self, q: &[f64], qd: &[f64], param: &dyn Fn(&str) -> f64) -> f64 {
        let angle = |k: &[i32]| -> f64 { k.iter().zip(q).map(|(&k, &x)| f64::from(k) * x).sum() };
        let t = match self.trig {
            Trig::One => 1.0,
            Trig::Cos(k) => angle(k).cos(),
            Trig::Sin(k) => angle(k).sin(),
        };
        let m: f64 = self
            .powers
            .iter()
            .map(|&(v, e)| match v {
                Var::Qd(j) => qd[j].powi(i32::try_from(e).unwrap_or(i32::MAX)),
                Var::Qdd(_) => f64::NAN,
            })
            .product();
        let k: f64 = self
            .params
            .iter()
            .map(|&(name, e)| param(name).powi(i32::try_from(e).unwrap_or(i32::MAX)))
            .product();
        self.coeff.to_f64() * k * t * m
    }
}

/// The exact derivation of an `N`-link arm.
#[derive(Clone, Copy, Debug)]
pub struct Derivation<const N: usize> {
    /// Kinetic energy T(q, qd).
    pub kinetic_energy: &'static [Term],
    /// Potential energy V(q).
    pub potential_energy: &'static [Term],
    /// The mass matrix, row-major (both triangles).
    pub mass_matrix: [[&'static [Term]; N]; N],
    /// The velocity-product torques c(q, qd).
    pub coriolis: [&'static [Term]; N],
    /// The gravity torques g(q).
    pub gravity: [&'static [Term]; N],
}

const fn same_angle(a: &[i32], b: &[i32]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// The constant term (atom `1`, no rates, no run-time parameter) of a sum; zero if absent.
#[must_use]
pub const fn constant_term(terms: &[Term]) -> Rational {
    let mut i = 0;
    while i < terms.len() {
        if matches!(terms[i].trig, Trig::One)
            && terms[i].powers.is_empty()
            && terms[i].params.is_empty()
        {
            return terms[i].coeff;
        }
        i += 1;
    }
    Rational::ZERO
}

/// The coefficient of the atom `trig` (no rates, no run-time parameter) in a sum; zero if
/// absent.
const fn coefficient(terms: &[Term], cos: bool, angle: &[i32]) -> Rational {
    let mut i = 0;
    while i < terms.len() {
        let k = match (terms[i].trig, cos) {
            (Trig::Cos(k), true) | (Trig::Sin(k), false) => k,
            _ => &[],
        };
        if !k.is_empty()
            && same_angle(k, angle)
            && terms[i].powers.is_empty()
            && terms[i].params.is_empty()
        {
            return terms[i].coeff;
        }
        i += 1;
    }
    Rational::ZERO
}

/// The coefficient of `cos(angle . q)` (no rates) in a sum; zero if absent. `angle` has its
/// trailing zeros trimmed and its first non-zero entry positive, as the engine stores it.
#[must_use]
pub const fn cos_coefficient(terms: &[Term], angle: &[i32]) -> Rational {
    coefficient(terms, true, angle)
}

/// The coefficient of `sin(angle . q)` (no rates) in a sum; zero if absent.
#[must_use]
pub const fn sin_coefficient(terms: &[Term], angle: &[i32]) -> Rational {
    coefficient(terms, false, angle)
}

/// The value of a sum of terms at `(q, qd)` (NaN if a term has run-time parameters: use
/// [`eval_with`]).
#[must_use]
pub fn eval(terms: &[Term], q: &[f64], qd: &[f64]) -> f64 {
    terms.iter().map(|t| t.eval(q, qd)).sum()
}

/// The value of a sum of terms at `(q, qd)`, each run-time parameter's value given by
/// `param(name)`.
#[must_use]
pub fn eval_with(terms: &[Term], q: &[f64], qd: &[f64], param: &dyn Fn(&str) -> f64) -> f64 {
    terms.iter().map(|t| t.eval_with(q, qd, param)).sum()
}
