//! The coefficient ring of the symbolic engine.
//!
//! Every expression the engine builds is a sum of `coefficient x trig x monomial` terms. The
//! coefficient is generic: today it is an exact [`Rational`] (a big-integer fraction, so it
//! cannot overflow); a later coefficient type (polynomials in named run-time parameters such as
//! a payload mass) only has to implement [`Coefficient`] to reuse the whole derivation.

use core::fmt::{Debug, Display};
use core::ops::{Add, Mul, Neg, Sub};

use num_bigint::BigInt;
use num_integer::Integer as _;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// An exact fraction of big integers, always reduced, denominator positive.
pub type Rational = num_rational::BigRational;

/// What a coefficient of the engine's expressions must support.
///
/// The ring must contain the rationals (trigonometric product formulas halve coefficients, and
/// link parameters are rational), and must be totally ordered so that expressions have one
/// canonical, deterministic form.
pub trait Coefficient:
    Clone
    + Ord
    + Debug
    + Display
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
{
    /// The embedding of the rationals.
    fn from_rational(r: Rational) -> Self;
    /// Whether this is the additive identity.
    fn is_zero(&self) -> bool;
    /// Multiplication by a rational.
    fn scale(&self, r: &Rational) -> Self;
}

impl Coefficient for Rational {
    fn from_rational(r: Rational) -> Self {
        r
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn scale(&self, r: &Rational) -> Self {
        // The engine scales by 1 and -1 often (derivatives of trig atoms); skip the gcd.
        if r.is_one() {
            self.clone()
        } else if (-r).is_one() {
            -self.clone()
        } else if r.numer().is_one() && r.denom() == &BigInt::from(2) {
            // Halving a reduced fraction needs no gcd: an even numerator halves, an odd one
            // doubles the denominator, and either stays reduced.
            let (n, d) = (self.numer(), self.denom());
            if n.is_even() {
                Rational::new_raw(n / 2, d.clone())
            } else {
                Rational::new_raw(n.clone(), d * 2)
            }
        } else {
            self * r
        }
    }
}

/// The rational `n / d`.
///
/// # Panics
/// If `d == 0`.
#[must_use]
pub fn ratio(n: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(n), BigInt::from(d))
}

/// The integer `n` as a rational.
#[must_use]
pub fn int(n: i64) -> Rational {
    Rational::from_integer(BigInt::from(n))
}

/// Parses an exact decimal such as `0.35`, `12`, `1e-3`, `2.5E+2` (no sign, no underscores).
///
/// `0.35` is `7/20`: the value never passes through a float.
#[must_use]
pub fn parse_decimal(text: &str) -> Option<Rational> {
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(i) => (&text[..i], text[i + 1..].parse::<i64>().ok()?),
        None => (text, 0),
    };
    let (int_part, frac_part) = match mantissa.find('.') {
        Some(i) => (&mantissa[..i], &mantissa[i + 1..]),
        None => (mantissa, ""),
    };
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    if !int_part
        .bytes()
        .chain(frac_part.bytes())
        .all(|b| b.is_ascii_digit())
    {
        return None;
    }
    let digits: BigInt = format!("{int_part}{frac_part}0").parse().ok()?;
    let digits = digits / BigInt::from(10);
    let scale = exponent.checked_sub(i64::try_from(frac_part.len()).ok()?)?;
    // Bound the exponent so a hostile literal cannot make us build a gigantic power of ten.
    if scale.unsigned_abs() > 100_000 {
        return None;
    }
    let pow = num_traits::pow(
        BigInt::from(10),
        usize::try_from(scale.unsigned_abs()).ok()?,
    );
    Some(if scale >= 0 {
        Rational::from_integer(digits * pow)
    } else {
        Rational::new(digits, pow)
    })
}

/// The nearest `f64`, or `None` when the value is outside the finite `f64` range.
#[must_use]
pub fn to_f64(r: &Rational) -> Option<f64> {
    let v = r.to_f64()?;
    v.is_finite().then_some(v)
}

/// The value as an exact `(numerator, denominator)` pair of `i128`, if it fits.
#[must_use]
pub fn to_i128_pair(r: &Rational) -> Option<(i128, i128)> {
    Some((r.numer().to_i128()?, r.denom().to_i128()?))
}

/// Renders a rational the way the paper writes it: `5/3`, `-1/2`, `2`.
#[must_use]
pub fn show(r: &Rational) -> String {
    if r.is_integer() {
        r.numer().to_string()
    } else {
        format!("{}/{}", r.numer(), r.denom())
    }
}

/// Whether the rational is negative.
#[must_use]
pub fn is_negative(r: &Rational) -> bool {
    r.is_negative()
}

/// The rational one.
#[must_use]
pub fn one() -> Rational {
    Rational::one()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_are_exact() {
        assert_eq!(parse_decimal("0.35"), Some(ratio(7, 20)));
        assert_eq!(parse_decimal("12"), Some(int(12)));
        assert_eq!(parse_decimal("9.80665"), Some(ratio(980_665, 100_000)));
        assert_eq!(parse_decimal("1e-3"), Some(ratio(1, 1000)));
        assert_eq!(parse_decimal("2.5E+2"), Some(int(250)));
        assert_eq!(parse_decimal(".5"), Some(ratio(1, 2)));
        assert_eq!(parse_decimal("abc"), None);
        assert_eq!(parse_decimal("1e999999999"), None);
    }

    #[test]
    fn float_range_is_checked() {
        assert_eq!(to_f64(&ratio(1, 4)), Some(0.25));
        let huge = parse_decimal("1e400").unwrap();
        assert_eq!(to_f64(&huge), None);
        assert_eq!(to_i128_pair(&huge), None);
    }
}
