//! Trigonometric atoms: `1`, `cos(k . q)` and `sin(k . q)` for an integer vector `k`.
//!
//! Products of atoms are linearised (`cos a cos b = (cos(a - b) + cos(a + b)) / 2`), so every
//! expression is a sum of single atoms. Angles are normalised so that their first non-zero
//! coefficient is positive (`cos(-a) = cos a`, `sin(-a) = -sin a`): two equal atoms are
//! structurally equal.

use core::fmt;

use crate::ring::{ratio, Rational};

/// An integer combination `k_1 q_1 + k_2 q_2 + ...` of joint angles, trailing zeros trimmed.
///
/// Ordered as the paper lists its terms: by first joint, then by last joint, so
/// `c2 < c23 < c3`.
///
/// The first joint is kept alongside the coefficients: expressions are maps keyed by atoms,
/// compared on every insertion, and the engine runs unoptimised inside the user's compiler.
#[derive(Clone, PartialEq, Eq, Hash, Debug, Default)]
pub struct Angle {
    first: usize,
    coefficients: Vec<i32>,
}

impl PartialOrd for Angle {
    fn partial_cmp(&self, other: &Self) -> Option<core::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Angle {
    fn cmp(&self, other: &Self) -> core::cmp::Ordering {
        (self.first, self.coefficients.len())
            .cmp(&(other.first, other.coefficients.len()))
            .then_with(|| self.coefficients.cmp(&other.coefficients))
    }
}

impl Angle {
    /// The angle with the given coefficients (index 0 is q1).
    #[must_use]
    pub fn new(mut coefficients: Vec<i32>) -> Self {
        while coefficients.last() == Some(&0) {
            coefficients.pop();
        }
        let first = coefficients.iter().position(|&c| c != 0).unwrap_or(0);
        Self {
            first,
            coefficients,
        }
    }

    /// `q_{from+1} + ... + q_{to}` (0-based joint indices `from..to`).
    #[must_use]
    pub fn range(from: usize, to: usize) -> Self {
        let mut k = vec![0; to];
        for c in &mut k[from..to] {
            *c = 1;
        }
        Self::new(k)
    }

    /// The coefficient of joint `j` (0-based).
    #[must_use]
    pub fn coefficient(&self, j: usize) -> i32 {
        self.coefficients.get(j).copied().unwrap_or(0)
    }

    /// The coefficients, index 0 is q1, trailing zeros trimmed.
    #[must_use]
    pub fn coefficients(&self) -> &[i32] {
        &self.coefficients
    }

    /// Whether this is the zero angle.
    #[must_use]
    pub fn is_zero(&self) -> bool {
        self.coefficients.is_empty()
    }

    fn combine(&self, other: &Self, sign: i32) -> Self {
        let n = self.coefficients.len().max(other.coefficients.len());
        Self::new(
            (0..n)
                .map(|j| self.coefficient(j) + sign * other.coefficient(j))
                .collect(),
        )
    }

    /// `(s, a)` with `self = s a`, `s = +-1` and `a` canonical (first non-zero coefficient positive).
    fn canonical(self) -> (i32, Self) {
        match self.coefficients.iter().find(|&&c| c != 0) {
            Some(&c) if c < 0 => (
                -1,
                Self {
                    first: self.first,
                    coefficients: self.coefficients.iter().map(|c| -c).collect(),
                },
            ),
            _ => (1, self),
        }
    }

    /// The paper's subscript for a contiguous run of unit coefficients (`q2 + q3` is `23`).
    fn paper_subscript(&self) -> Option<String> {
        let first = self.coefficients.iter().position(|&c| c != 0)?;
        self.coefficients[first..].iter().all(|&c| c == 1).then(|| {
            (first + 1..=self.coefficients.len())
                .map(|j| j.to_string())
                .collect()
        })
    }

    /// A short identifier fragment: `23` for `q2 + q3`, `1m2` for `q1 - q2`, `2x2` for `2 q2`.
    #[must_use]
    pub fn ident_fragment(&self) -> String {
        if let Some(s) = self.paper_subscript() {
            return s;
        }
        let mut out = String::new();
        for (j, &c) in self.coefficients.iter().enumerate() {
            if c == 0 {
                continue;
            }
            if !out.is_empty() || c < 0 {
                out.push(if c < 0 { 'm' } else { 'p' });
            }
            if c.abs() != 1 {
                out.push_str(&format!("{}x", c.abs()));
            }
            out.push_str(&(j + 1).to_string());
        }
        out
    }
}

impl fmt::Display for Angle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return write!(f, "0");
        }
        let mut first = true;
        for (j, &c) in self
            .coefficients
            .iter()
            .enumerate()
            .filter(|(_, c)| **c != 0)
        {
            match (first, c < 0) {
                (true, true) => write!(f, "-")?,
                (true, false) => {}
                (false, true) => write!(f, " - ")?,
                (false, false) => write!(f, " + ")?,
            }
            if c.abs() != 1 {
                write!(f, "{}", c.abs())?;
            }
            write!(f, "q{}", j + 1)?;
            first = false;
        }
        Ok(())
    }
}

/// A trigonometric atom.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
pub enum Trig {
    /// The constant 1.
    One,
    /// `cos(angle)`, angle canonical and non-zero.
    Cos(Angle),
    /// `sin(angle)`, angle canonical and non-zero.
    Sin(Angle),
}

impl Trig {
    /// `cos(angle)` as `(sign, atom)`.
    #[must_use]
    pub fn cos(angle: Angle) -> (i32, Trig) {
        if angle.is_zero() {
            return (1, Trig::One);
        }
        let (_, a) = angle.canonical();
        (1, Trig::Cos(a))
    }

    /// `sin(angle)` as `(sign, atom)`, or `None` when the angle is zero.
    #[must_use]
    pub fn sin(angle: Angle) -> Option<(i32, Trig)> {
        if angle.is_zero() {
            return None;
        }
        let (s, a) = angle.canonical();
        Some((s, Trig::Sin(a)))
    }

    /// The angle of the atom (zero for `One`).
    #[must_use]
    pub fn angle(&self) -> Option<&Angle> {
        match self {
            Trig::One => None,
            Trig::Cos(a) | Trig::Sin(a) => Some(a),
        }
    }

    /// The linearised product of two atoms, as `(coefficient, atom)` pairs.
    #[must_use]
    pub fn mul(&self, other: &Trig) -> Vec<(Rational, Trig)> {
        let half = ratio(1, 2);
        let signed = |(s, t): (i32, Trig), c: &Rational| (c * ratio(i64::from(s), 1), t);
        match (self, other) {
            (Trig::One, t) | (t, Trig::One) => vec![(ratio(1, 1), t.clone())],
            (Trig::Cos(a), Trig::Cos(b)) => vec![
                signed(Trig::cos(a.combine(b, -1)), &half),
                signed(Trig::cos(a.combine(b, 1)), &half),
            ],
            (Trig::Sin(a), Trig::Sin(b)) => vec![
                signed(Trig::cos(a.combine(b, -1)), &half),
                signed(Trig::cos(a.combine(b, 1)), &-half.clone()),
            ],
            (Trig::Sin(a), Trig::Cos(b)) | (Trig::Cos(b), Trig::Sin(a)) => {
                // sin a cos b = (sin(a + b) + sin(a - b)) / 2
                [a.combine(b, 1), a.combine(b, -1)]
                    .into_iter()
                    .filter_map(Trig::sin)
                    .map(|st| signed(st, &half))
                    .collect()
            }
        }
    }

    /// `d/dq_j` of the atom, as `(factor, atom)`, or `None` when it is zero.
    #[must_use]
    pub fn diff(&self, j: usize) -> Option<(i32, Trig)> {
        match self {
            Trig::One => None,
            Trig::Cos(a) => match a.coefficient(j) {
                0 => None,
                k => Some((-k, Trig::Sin(a.clone()))),
            },
            Trig::Sin(a) => match a.coefficient(j) {
                0 => None,
                k => Some((k, Trig::Cos(a.clone()))),
            },
        }
    }

    /// Numeric value at joint angles `q`.
    #[must_use]
    pub fn eval(&self, q: &[f64]) -> f64 {
        let angle = |a: &Angle| -> f64 {
            a.coefficients
                .iter()
                .zip(q)
                .map(|(&k, &x)| f64::from(k) * x)
                .sum()
        };
        match self {
            Trig::One => 1.0,
            Trig::Cos(a) => angle(a).cos(),
            Trig::Sin(a) => angle(a).sin(),
        }
    }
}

impl fmt::Display for Trig {
    /// The paper's notation where it applies (`c2`, `s23`), `cos(q1 - q2)` otherwise.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (name, short, a) = match self {
            Trig::One => return write!(f, "1"),
            Trig::Cos(a) => ("cos", "c", a),
            Trig::Sin(a) => ("sin", "s", a),
        };
        match a.paper_subscript() {
            Some(sub) => write!(f, "{short}{sub}"),
            None => write!(f, "{name}({a})"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn a(k: &[i32]) -> Angle {
        Angle::new(k.to_vec())
    }

    #[test]
    fn angles_are_canonical() {
        assert_eq!(Trig::cos(a(&[-1, 1])), (1, Trig::Cos(a(&[1, -1]))));
        assert_eq!(
            Trig::sin(a(&[0, -1, -1])),
            Some((-1, Trig::Sin(a(&[0, 1, 1]))))
        );
        assert_eq!(Trig::sin(a(&[0, 0])), None);
        assert_eq!(Trig::cos(a(&[0])), (1, Trig::One));
    }

    #[test]
    fn products_linearise() {
        // cos q1 cos(q1 + q2) = (cos q2 + cos(2 q1 + q2)) / 2
        let p = Trig::Cos(a(&[1])).mul(&Trig::Cos(a(&[1, 1])));
        assert_eq!(
            p,
            vec![
                (ratio(1, 2), Trig::Cos(a(&[0, 1]))),
                (ratio(1, 2), Trig::Cos(a(&[2, 1])))
            ]
        );
        // sin q1 sin q1 = (1 - cos 2 q1) / 2
        let p = Trig::Sin(a(&[1])).mul(&Trig::Sin(a(&[1])));
        assert_eq!(
            p,
            vec![(ratio(1, 2), Trig::One), (ratio(-1, 2), Trig::Cos(a(&[2])))]
        );
        // sin q1 cos q1 = sin(2 q1) / 2
        let p = Trig::Sin(a(&[1])).mul(&Trig::Cos(a(&[1])));
        assert_eq!(p, vec![(ratio(1, 2), Trig::Sin(a(&[2])))]);
    }

    #[test]
    fn products_match_numbers() {
        let atoms = [
            Trig::One,
            Trig::Cos(a(&[1])),
            Trig::Sin(a(&[1, 1])),
            Trig::Cos(a(&[0, 1, -2])),
            Trig::Sin(a(&[2, -1])),
        ];
        let q = [0.3, -1.1, 2.0];
        for x in &atoms {
            for y in &atoms {
                let exact: f64 = x
                    .mul(y)
                    .iter()
                    .map(|(c, t)| crate::ring::to_f64(c).unwrap() * t.eval(&q))
                    .sum();
                assert!((exact - x.eval(&q) * y.eval(&q)).abs() < 1e-14, "{x} * {y}");
            }
        }
    }

    #[test]
    fn notation_follows_the_paper() {
        assert_eq!(Trig::Cos(a(&[0, 1, 1])).to_string(), "c23");
        assert_eq!(Trig::Sin(a(&[1])).to_string(), "s1");
        assert_eq!(Trig::Cos(a(&[1, -1])).to_string(), "cos(q1 - q2)");
        assert_eq!(Trig::Sin(a(&[2, 1])).to_string(), "sin(2q1 + q2)");
        assert_eq!(a(&[1, -1]).ident_fragment(), "1m2");
    }
}
