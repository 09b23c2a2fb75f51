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
//! const M11: planar_arm::exact::Terms = <Paper2 as PlanarArm<2>>::EXACT.mass_matrix[0][0];
//! const _: () = assert!(constant_term(M11).eq(Rational::new(5, 3)));
//! const _: () = assert!(cos_coefficient(M11, &[0, 1]).eq(Rational::new(1, 1)));
//! assert_eq!(M11.to_string(), "5/3 + cos(q2)");
//! ```
//!
//! # Storage
//!
//! Each sum is one byte-string literal ([`Terms`]), decoded on reading: a ten-link arm's
//! derivation has about 8,000 terms, and as a `const` slice of structs (one constructor call
//! per term) it cost the user's compiler more time and memory than everything else the derive
//! emits together (docs/performance.md). The encoding is private; [`Terms`] reads it, in
//! `const` contexts too ([`constant_term`], [`cos_coefficient`], [`sin_coefficient`]).

#[cfg(not(feature = "std"))]
use num_traits::Float as _;

mod render;
pub use render::Latex;
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

/// A joint rate or acceleration, or a prismatic joint's displacement (0-based joint).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Var {
    /// `qd[j]`.
    Qd(usize),
    /// `qdd[j]`.
    Qdd(usize),
    /// `q[j]` of a prismatic joint (revolute angles appear only inside `cos` and `sin`).
    Q(usize),
}

/// The digits of the encoding: printable, so the literal needs no escapes.
const fn digit(c: u8) -> u128 {
    (match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        _ => 63,
    }) as u128
}

/// A number at `pos`: five bits per digit, low bits first, bit 5 set when more follow.
const fn read(code: &[u8], mut pos: usize) -> (u128, usize) {
    let mut value = 0u128;
    let mut shift = 0;
    loop {
        let d = digit(code[pos]);
        pos += 1;
        if shift < 128 {
            value |= (d & 31) << shift;
        }
        shift += 5;
        if d & 32 == 0 {
            return (value, pos);
        }
    }
}

/// A signed number (zigzag: 0, -1, 1, -2, ... as 0, 1, 2, 3, ...).
#[allow(clippy::cast_possible_wrap)]
const fn read_signed(code: &[u8], pos: usize) -> (i128, usize) {
    let (v, pos) = read(code, pos);
    (((v >> 1) as i128) ^ -((v & 1) as i128), pos)
}

/// A count or a small number.
#[allow(clippy::cast_possible_truncation)]
const fn read_small(code: &[u8], pos: usize) -> (usize, usize) {
    let (v, pos) = read(code, pos);
    (v as usize, pos)
}

/// Skips `count` pairs of numbers.
const fn skip_pairs(code: &[u8], mut pos: usize, count: usize) -> usize {
    let mut k = 0;
    while k < 2 * count {
        pos = read(code, pos).1;
        k += 1;
    }
    pos
}

/// Where each part of the term at `pos` starts.
#[derive(Clone, Copy)]
struct Layout {
    kind: usize,
    coeff: Rational,
    angle: usize,
    angle_len: usize,
    powers: usize,
    powers_len: usize,
    params: usize,
    params_len: usize,
    end: usize,
}

const fn layout(code: &[u8], pos: usize) -> Layout {
    let (kind, pos) = read_small(code, pos);
    let (numer, pos) = read_signed(code, pos);
    let (denom, pos) = read_signed(code, pos);
    let (angle_len, mut angle) = if kind == 0 {
        (0, pos)
    } else {
        read_small(code, pos)
    };
    let mut pos = angle;
    if kind != 0 {
        // The runs: their count, then (zeros before, length, value) each.
        let (runs, next) = read_small(code, pos);
        pos = next;
        let mut k = 0;
        while k < 3 * runs {
            pos = read(code, pos).1;
            k += 1;
        }
    }
    let (powers_len, powers) = read_small(code, pos);
    let pos = skip_pairs(code, powers, powers_len);
    let (params_len, params) = read_small(code, pos);
    let end = skip_pairs(code, params, params_len);
    if angle_len == 0 {
        angle = pos;
    }
    Layout {
        kind,
        coeff: Rational { numer, denom },
        angle,
        angle_len,
        powers,
        powers_len,
        params,
        params_len,
        end,
    }
}

/// A sum of exact terms, as stored in [`Derivation`]: iterate it for its [`Term`]s, or read
/// coefficients in `const` contexts with [`constant_term`] and [`cos_coefficient`].
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Terms {
    code: &'static [u8],
    names: &'static [&'static str],
}

impl Terms {
    /// The sum stored in `code` (the derive's encoding), its run-time parameters named by
    /// index into `names`.
    #[doc(hidden)]
    #[must_use]
    pub const fn from_code(code: &'static [u8], names: &'static [&'static str]) -> Self {
        Self { code, names }
    }

    /// Whether the sum has no term (it is zero).
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        self.code.is_empty()
    }

    /// The number of terms.
    #[must_use]
    pub const fn len(&self) -> usize {
        let (mut pos, mut count) = (0, 0);
        while pos < self.code.len() {
            pos = layout(self.code, pos).end;
            count += 1;
        }
        count
    }

    /// The terms, in the engine's canonical order.
    #[must_use]
    pub fn iter(&self) -> TermIter {
        TermIter {
            terms: *self,
            pos: 0,
        }
    }
}

impl IntoIterator for Terms {
    type Item = Term;
    type IntoIter = TermIter;
    fn into_iter(self) -> TermIter {
        self.iter()
    }
}

/// The terms of a [`Terms`].
#[derive(Clone, Debug)]
pub struct TermIter {
    terms: Terms,
    pos: usize,
}

impl Iterator for TermIter {
    type Item = Term;
    fn next(&mut self) -> Option<Term> {
        let code = self.terms.code;
        if self.pos >= code.len() {
            return None;
        }
        let l = layout(code, self.pos);
        self.pos = l.end;
        let angle = Angle {
            code,
            pos: l.angle,
            len: l.angle_len,
        };
        let trig = match l.kind {
            0 => Trig::One,
            1 => Trig::Cos(angle),
            _ => Trig::Sin(angle),
        };
        Some(Term {
            coeff: l.coeff,
            trig,
            powers: Powers {
                code,
                pos: l.powers,
                len: l.powers_len,
            },
            params: Params {
                code,
                pos: l.params,
                len: l.params_len,
                names: self.terms.names,
            },
        })
    }
}

impl core::fmt::Debug for Terms {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

/// An integer combination of joint angles, `k . q`, with `k[0]` multiplying q1.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Angle {
    code: &'static [u8],
    pos: usize,
    len: usize,
}

impl Angle {
    /// The coefficients `k`, q1's first, trailing zeros trimmed.
    pub fn coefficients(&self) -> impl Iterator<Item = i32> + '_ {
        let (runs, pos) = read_small(self.code, self.pos);
        let mut runs = Runs {
            code: self.code,
            pos,
            runs,
            zeros: 0,
            left: 0,
            value: 0,
        };
        (0..self.len).map(move |_| runs.next_coefficient())
    }

    /// Whether the coefficients are `k`.
    #[must_use]
    pub const fn is(&self, k: &[i32]) -> bool {
        if k.len() != self.len {
            return false;
        }
        let (count, pos) = read_small(self.code, self.pos);
        let mut runs = Runs {
            code: self.code,
            pos,
            runs: count,
            zeros: 0,
            left: 0,
            value: 0,
        };
        let mut j = 0;
        while j < self.len {
            if runs.next_coefficient() != k[j] {
                return false;
            }
            j += 1;
        }
        true
    }

    /// The angle's value at `q`.
    #[must_use]
    pub fn eval(&self, q: &[f64]) -> f64 {
        self.coefficients()
            .zip(q)
            .map(|(k, &x)| f64::from(k) * x)
            .sum()
    }
}

/// An angle's coefficients as stored: runs of one non-zero value, each after some zeros (most
/// angles of an arm are `q_a + ... + q_b`, one run).
struct Runs {
    code: &'static [u8],
    pos: usize,
    runs: usize,
    zeros: usize,
    left: usize,
    value: i32,
}

impl Runs {
    #[allow(clippy::cast_possible_truncation)]
    const fn next_coefficient(&mut self) -> i32 {
        if self.zeros == 0 && self.left == 0 && self.runs > 0 {
            let (zeros, pos) = read_small(self.code, self.pos);
            let (left, pos) = read_small(self.code, pos);
            let (value, pos) = read_signed(self.code, pos);
            self.zeros = zeros;
            self.left = left;
            self.value = value as i32;
            self.pos = pos;
            self.runs -= 1;
        }
        if self.zeros > 0 {
            self.zeros -= 1;
            0
        } else if self.left > 0 {
            self.left -= 1;
            self.value
        } else {
            0
        }
    }
}

impl core::fmt::Debug for Angle {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_list().entries(self.coefficients()).finish()
    }
}

/// A trigonometric atom: `1`, `cos(k . q)` or `sin(k . q)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Trig {
    /// The constant 1.
    One,
    /// `cos(k . q)`.
    Cos(Angle),
    /// `sin(k . q)`.
    Sin(Angle),
}

/// Rates, accelerations and prismatic displacements with their exponents.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Powers {
    code: &'static [u8],
    pos: usize,
    len: usize,
}

impl Powers {
    /// Whether there is none (the term is a function of revolute angles alone).
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl IntoIterator for Powers {
    type Item = (Var, u32);
    type IntoIter = PairIter<(Var, u32)>;
    fn into_iter(self) -> Self::IntoIter {
        PairIter {
            code: self.code,
            pos: self.pos,
            left: self.len,
            make: |v, e, _| {
                let j = usize::try_from(v / 3).unwrap_or(usize::MAX);
                let var = match v % 3 {
                    0 => Var::Qd(j),
                    1 => Var::Qdd(j),
                    _ => Var::Q(j),
                };
                (var, u32::try_from(e).unwrap_or(u32::MAX))
            },
            names: &[],
        }
    }
}

impl core::fmt::Debug for Powers {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_list().entries(*self).finish()
    }
}

/// Run-time parameters (the arm's `f64` fields named by `self.NAME`) with their exponents.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Params {
    code: &'static [u8],
    pos: usize,
    len: usize,
    names: &'static [&'static str],
}

impl Params {
    /// Whether there is none (the coefficient is a number).
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl IntoIterator for Params {
    type Item = (&'static str, u32);
    type IntoIter = PairIter<(&'static str, u32)>;
    fn into_iter(self) -> Self::IntoIter {
        PairIter {
            code: self.code,
            pos: self.pos,
            left: self.len,
            make: |k, e, names| {
                let name = usize::try_from(k)
                    .ok()
                    .and_then(|k| names.get(k))
                    .copied()
                    .unwrap_or("?");
                (name, u32::try_from(e).unwrap_or(u32::MAX))
            },
            names: self.names,
        }
    }
}

impl core::fmt::Debug for Params {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_list().entries(*self).finish()
    }
}

/// The pairs of [`Powers`] or [`Params`].
#[derive(Clone)]
pub struct PairIter<T> {
    code: &'static [u8],
    pos: usize,
    left: usize,
    make: fn(u128, u128, &'static [&'static str]) -> T,
    names: &'static [&'static str],
}

impl<T> core::fmt::Debug for PairIter<T> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("PairIter")
            .field("left", &self.left)
            .finish()
    }
}

impl<T> Iterator for PairIter<T> {
    type Item = T;
    fn next(&mut self) -> Option<T> {
        if self.left == 0 {
            return None;
        }
        self.left -= 1;
        let (a, pos) = read(self.code, self.pos);
        let (b, pos) = read(self.code, pos);
        self.pos = pos;
        Some((self.make)(a, b, self.names))
    }
}

/// One term `coeff x params x trig x product of powers`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Term {
    /// The exact coefficient.
    pub coeff: Rational,
    /// The trigonometric atom.
    pub trig: Trig,
    /// Rates, accelerations and prismatic displacements with their exponents.(empty for a function of `q` alone).
    pub powers: Powers,
    /// Run-time parameters with their exponents; empty for a term whose coefficient is a
    /// number.
    pub params: Params,
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
        let t = match self.trig {
            Trig::One => 1.0,
            Trig::Cos(a) => a.eval(q).cos(),
            Trig::Sin(a) => a.eval(q).sin(),
        };
        let m: f64 = self
            .powers
            .into_iter()
            .map(|(v, e)| match v {
                Var::Qd(j) => qd[j].powi(i32::try_from(e).unwrap_or(i32::MAX)),
                Var::Q(j) => q[j].powi(i32::try_from(e).unwrap_or(i32::MAX)),
                Var::Qdd(_) => f64::NAN,
            })
            .product();
        let k: f64 = self
            .params
            .into_iter()
            .map(|(name, e)| param(name).powi(i32::try_from(e).unwrap_or(i32::MAX)))
            .product();
        self.coeff.to_f64() * k * t * m
    }
}

/// The exact derivation of an `N`-link arm.
#[derive(Clone, Copy, Debug)]
pub struct Derivation<const N: usize> {
    /// Kinetic energy T(q, qd).
    pub kinetic_energy: Terms,
    /// Potential energy V(q).
    pub potential_energy: Terms,
    /// The mass matrix, row-major (both triangles).
    pub mass_matrix: [[Terms; N]; N],
    /// The velocity-product torques c(q, qd).
    pub coriolis: [Terms; N],
    /// The gravity torques g(q).
    pub gravity: [Terms; N],
}

/// The exact kinematics and gravity of an `N`-joint spatial arm (`#[derive(SpatialArm)]`), when
/// they were multiplied out (see [`SpatialExpansion`]).
///
/// Right-angle geometry (twists and offsets at multiples of `pi/2`, as in the PUMA, UR or
/// Panda) multiplies out to a few hundred or thousand terms. Generic twists or rotated URDF
/// origins roughly triple the terms with each joint; past 4 000 terms in a frame the derive
/// stops expanding, `expansion` is `None`, and the generated methods evaluate the product of
/// the joints' transformations, which stays linear in their number.
#[derive(Clone, Copy, Debug)]
pub struct SpatialDerivation<const N: usize> {
    /// The formulas, or `None` where multiplying them out would exceed the budget.
    pub expansion: Option<SpatialExpansion<N>>,
}

/// The multiplied-out kinematics and gravity of a spatial arm: the tool pose's entries,
/// trigonometric polynomials in the joint angles (and polynomials in the slides), its potential
/// energy and gravity torques. Constants the geometry cannot write as rationals (the cosine of a
/// twist of 0.3 rad) appear by name, as run-time parameters do.
#[derive(Clone, Copy, Debug)]
pub struct SpatialExpansion<const N: usize> {
    /// The tool pose's rotation (columns 0-2) and position (column 3), row-major: `tip[r][c]`.
    pub tip: [[Terms; 4]; 3],
    /// Potential energy V(q), zero at the base origin.
    pub potential_energy: Terms,
    /// The gravity torques g(q) = dV/dq.
    pub gravity: [Terms; N],
    /// The mass matrix M(q), row-major (both triangles), from the kinetic energy written in
    /// each link's own axes; `None` where a link's velocities would exceed the budget that
    /// keeps builds quick (80 terms, arms of up to three or four joints; the struct key
    /// `#[arm(exact_dynamics)]` lifts it) or an exact coefficient would not fit the `i128` of
    /// this data.
    pub mass_matrix: Option<[[Terms; N]; N]>,
    /// The velocity-product forces c(q, qd), with `mass_matrix`.
    pub coriolis: Option<[Terms; N]>,
}

/// The coefficient of the first term (no rates, no run-time parameter) whose atom is `1`
/// (`kind` 0), `cos(angle . q)` (1) or `sin(angle . q)` (2); zero if absent.
const fn coefficient(terms: Terms, kind: usize, angle: &[i32]) -> Rational {
    let code = terms.code;
    let mut pos = 0;
    while pos < code.len() {
        let l = layout(code, pos);
        if l.kind == kind && l.powers_len == 0 && l.params_len == 0 {
            let a = Angle {
                code,
                pos: l.angle,
                len: l.angle_len,
            };
            if kind == 0 || a.is(angle) {
                return l.coeff;
            }
        }
        pos = l.end;
    }
    Rational::ZERO
}

/// The constant term (atom `1`, no rates, no run-time parameter) of a sum; zero if absent.
#[must_use]
pub const fn constant_term(terms: Terms) -> Rational {
    coefficient(terms, 0, &[])
}

/// The coefficient of `cos(angle . q)` (no rates) in a sum; zero if absent. `angle` has its
/// trailing zeros trimmed and its first non-zero entry positive, as the engine stores it.
#[must_use]
pub const fn cos_coefficient(terms: Terms, angle: &[i32]) -> Rational {
    coefficient(terms, 1, angle)
}

/// The coefficient of `sin(angle . q)` (no rates) in a sum; zero if absent.
#[must_use]
pub const fn sin_coefficient(terms: Terms, angle: &[i32]) -> Rational {
    coefficient(terms, 2, angle)
}

/// The value of a sum of terms at `(q, qd)` (NaN if a term has run-time parameters: use
/// [`eval_with`]).
#[must_use]
pub fn eval(terms: Terms, q: &[f64], qd: &[f64]) -> f64 {
    terms.iter().map(|t| t.eval(q, qd)).sum()
}

/// The value of a sum of terms at `(q, qd)`, each run-time parameter's value given by
/// `param(name)`.
#[must_use]
pub fn eval_with(terms: Terms, q: &[f64], qd: &[f64], param: &dyn Fn(&str) -> f64) -> f64 {
    terms.iter().map(|t| t.eval_with(q, qd, param)).sum()
}
