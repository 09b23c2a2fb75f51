//! The polynomial part of a term: products of joint rates, accelerations and prismatic
//! displacements, ordered as the paper writes them.

use std::fmt;

/// A variable of the polynomial part: a joint rate, a joint acceleration or a prismatic
/// joint's displacement (0-based joint).
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
pub enum Var {
    /// `qd_j`, the rate of joint `j`.
    Qd(usize),
    /// `qdd_j`, the acceleration of joint `j`.
    Qdd(usize),
    /// `q_j` of a prismatic joint `j` (a revolute joint's angle appears only inside trig atoms).
    Q(usize),
}

impl fmt::Display for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Var::Qd(j) => write!(f, "qd{}", j + 1),
            Var::Qdd(j) => write!(f, "qdd{}", j + 1),
            Var::Q(j) => write!(f, "q{}", j + 1),
        }
    }
}

/// A product of variables with positive exponents.
///
/// Ordered by degree, then with higher powers of earlier variables first, as the paper writes
/// `qd1^2, qd1 qd2, qd2^2`.
///
/// Stored as `(variable, exponent)` pairs sorted by variable, with the degree alongside: the
/// expressions' term maps compare monomials on every insertion, and the engine runs
/// unoptimised inside the user's compiler, so comparison must not allocate.
#[derive(Clone, PartialEq, Eq, Hash, Debug, Default)]
pub struct Monomial {
    degree: u32,
    powers: Vec<(Var, u32)>,
}

impl PartialOrd for Monomial {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Monomial {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        use std::cmp::Ordering;
        if self.degree != other.degree {
            return self.degree.cmp(&other.degree);
        }
        // Walk both sorted lists: at the first variable whose exponents differ, the higher
        // exponent comes first.
        let (a, b) = (&self.powers, &other.powers);
        let (mut i, mut j) = (0, 0);
        loop {
            let (ea, eb) = match (a.get(i), b.get(j)) {
                (None, None) => return Ordering::Equal,
                (Some(&(_, ea)), None) => (ea, 0),
                (None, Some(&(_, eb))) => (0, eb),
                (Some(&(va, ea)), Some(&(vb, eb))) => match va.cmp(&vb) {
                    Ordering::Less => (ea, 0),
                    Ordering::Greater => (0, eb),
                    Ordering::Equal => (ea, eb),
                },
            };
            if ea != eb {
                return eb.cmp(&ea);
            }
            // Equal exponents mean the same variable in both (exponents are positive).
            i += 1;
            j += 1;
        }
    }
}

impl Monomial {
    /// The empty product, 1.
    #[must_use]
    pub fn one() -> Self {
        Self::default()
    }

    /// A single variable.
    #[must_use]
    pub fn var(v: Var) -> Self {
        Self {
            degree: 1,
            powers: vec![(v, 1)],
        }
    }

    /// Total degree.
    #[must_use]
    pub fn degree(&self) -> u32 {
        self.degree
    }

    /// The variables and their exponents, in order.
    pub fn powers(&self) -> impl Iterator<Item = (Var, u32)> + '_ {
        self.powers.iter().copied()
    }

    /// The exponent of `v`.
    #[must_use]
    pub fn exponent(&self, v: Var) -> u32 {
        self.powers
            .binary_search_by(|p| p.0.cmp(&v))
            .map_or(0, |k| self.powers[k].1)
    }

    /// The product of two monomials.
    #[must_use]
    pub fn mul(&self, other: &Self) -> Self {
        let (a, b) = (&self.powers, &other.powers);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() || j < b.len() {
            match (a.get(i), b.get(j)) {
                (Some(&(va, ea)), Some(&(vb, eb))) if va == vb => {
                    out.push((va, ea + eb));
                    i += 1;
                    j += 1;
                }
                (Some(&x), Some(&(vb, _))) if x.0 < vb => {
                    out.push(x);
                    i += 1;
                }
                (Some(&x), None) => {
                    out.push(x);
                    i += 1;
                }
                (_, Some(&y)) => {
                    out.push(y);
                    j += 1;
                }
                (None, None) => break,
            }
        }
        Self {
            degree: self.degree + other.degree,
            powers: out,
        }
    }

    /// `(positions, rest)`: the prismatic displacements' factors and the rates' and
    /// accelerations'.
    #[must_use]
    pub fn split_positions(&self) -> (Self, Self) {
        let (p, r): (Vec<_>, Vec<_>) = self
            .powers
            .iter()
            .partition(|(v, _)| matches!(v, Var::Q(_)));
        let degree = |v: &[(Var, u32)]| v.iter().map(|(_, e)| e).sum();
        (
            Self {
                degree: degree(&p),
                powers: p,
            },
            Self {
                degree: degree(&r),
                powers: r,
            },
        )
    }

    /// `d/dv`: `(exponent, monomial / v)`, or `None` when `v` does not occur.
    pub(super) fn diff(&self, v: Var) -> Option<(u32, Self)> {
        let k = self.powers.binary_search_by(|p| p.0.cmp(&v)).ok()?;
        let e = self.powers[k].1;
        let mut out = self.powers.clone();
        if e == 1 {
            out.remove(k);
        } else {
            out[k].1 = e - 1;
        }
        Some((
            e,
            Self {
                degree: self.degree - 1,
                powers: out,
            },
        ))
    }

    /// Numeric value given the joint positions, rates and accelerations.
    #[must_use]
    pub fn eval(&self, q: &[f64], qd: &[f64], qdd: &[f64]) -> f64 {
        self.powers()
            .map(|(v, e)| {
                let x = match v {
                    Var::Qd(j) => qd[j],
                    Var::Qdd(j) => qdd[j],
                    Var::Q(j) => q[j],
                };
                x.powi(i32::try_from(e).unwrap_or(i32::MAX))
            })
            .product()
    }
}

impl fmt::Display for Monomial {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (v, e) in self.powers() {
            if !first {
                write!(f, " ")?;
            }
            first = false;
            write!(f, "{v}")?;
            if e > 1 {
                write!(f, "^{e}")?;
            }
        }
        Ok(())
    }
}
