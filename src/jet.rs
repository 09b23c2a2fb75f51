//! [`Jet`]: a value with its derivatives along `K` directions, for forward-mode
//! differentiation of the generated code.

use core::ops::{Add, Div, Mul, Neg, Sub};

use nalgebra::{SMatrix, SVector};

use crate::Real;

/// A number `re + eps . e` carrying its derivatives `eps` along `K` directions at once
/// (forward-mode automatic differentiation, `e_i e_j = 0`).
///
/// It implements [`Real`], so every generic generated method evaluates in it: seed the inputs
/// with unit derivatives and the outputs carry their exact partial derivatives (to rounding),
/// computed through the same straight-line code, in one pass.
/// [`Dynamics::inverse_dynamics_derivatives`](crate::Dynamics::inverse_dynamics_derivatives)
/// is built this way.
///
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::Jet;
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Two {
///     #[arm(length = 1, mass = 1)]
///     a: Revolute,
///     #[arm(length = 1, mass = 1)]
///     b: Revolute,
/// }
///
/// // dM/dq2 at q2 = 0.5: M11 = 5/3 + cos q2, so dM11/dq2 = -sin q2.
/// let q = Vector2::new(Jet::<1>::constant(0.1), Jet::variable(0.5, 0));
/// let m = Two::default().mass_matrix(&q);
/// assert!((m[(0, 0)].eps[0] + 0.5_f64.sin()).abs() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jet<const K: usize> {
    /// The value.
    pub re: f64,
    /// Its derivatives along the `K` directions.
    pub eps: [f64; K],
}

impl<const K: usize> Jet<K> {
    /// A constant: no derivative.
    #[must_use]
    pub const fn constant(re: f64) -> Self {
        Self { re, eps: [0.0; K] }
    }

    /// The variable of direction `k`: derivative 1 along it, 0 along the others.
    #[must_use]
    pub fn variable(re: f64, k: usize) -> Self {
        let mut eps = [0.0; K];
        if let Some(e) = eps.get_mut(k) {
            *e = 1.0;
        }
        Self { re, eps }
    }

    /// `(dtau/dq, dtau/dqd)` of `arm`'s generated inverse dynamics evaluated twice in jets,
    /// seeded once along the angles and once along the rates: what
    /// [`Dynamics::inverse_dynamics_derivatives`](crate::Dynamics::inverse_dynamics_derivatives)
    /// returns for arms too large for its derivatives to be emitted as code, and the check of
    /// the emitted ones.
    #[must_use]
    pub fn inverse_dynamics_derivatives<A: crate::Dynamics<K> + ?Sized>(
        arm: &A,
        q: &SVector<f64, K>,
        qd: &SVector<f64, K>,
        qdd: &SVector<f64, K>,
    ) -> (SMatrix<f64, K, K>, SMatrix<f64, K, K>) {
        let seeded =
            |x: &SVector<f64, K>| SVector::<Self, K>::from_fn(|j, _| Self::variable(x[j], j));
        let fixed = |x: &SVector<f64, K>| x.map(Self::constant);
        let along_q = arm.inverse_dynamics(&seeded(q), &fixed(qd), &fixed(qdd));
        let along_qd = arm.inverse_dynamics(&fixed(q), &seeded(qd), &fixed(qdd));
        (
            SMatrix::from_fn(|i, j| along_q[i].eps[j]),
            SMatrix::from_fn(|i, j| along_qd[i].eps[j]),
        )
    }

    #[inline(always)]
    fn map2(self, o: Self, f: impl Fn(f64, f64) -> f64) -> [f64; K] {
        core::array::from_fn(|k| f(self.eps[k], o.eps[k]))
    }
}

impl<const K: usize> Add for Jet<K> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self {
            re: self.re + o.re,
            eps: self.map2(o, |a, b| a + b),
        }
    }
}

impl<const K: usize> Sub for Jet<K> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self {
            re: self.re - o.re,
            eps: self.map2(o, |a, b| a - b),
        }
    }
}

#[allow(clippy::suspicious_arithmetic_impl)] // the product rule
impl<const K: usize> Mul for Jet<K> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        let (a, b) = (self.re, o.re);
        Self {
            re: a * b,
            eps: self.map2(o, |da, db| da * b + a * db),
        }
    }
}

#[allow(clippy::suspicious_arithmetic_impl)] // the quotient rule
impl<const K: usize> Div for Jet<K> {
    type Output = Self;
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        // d(a/b) = (da - (a/b) db) / b
        let q = self.re / o.re;
        Self {
            re: q,
            eps: self.map2(o, |da, db| (da - q * db) / o.re),
        }
    }
}

impl<const K: usize> Neg for Jet<K> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self {
            re: -self.re,
            eps: self.eps.map(|e| -e),
        }
    }
}

impl<const K: usize> Real for Jet<K> {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        Self::constant(x)
    }

    #[inline(always)]
    fn sin_cos<const N: usize>(q: [Self; N]) -> [(Self, Self); N] {
        let sc = <f64 as Real>::sin_cos(q.map(|x| x.re));
        core::array::from_fn(|j| {
            let ((s, c), e) = (sc[j], q[j].eps);
            (
                Self {
                    re: s,
                    eps: e.map(|d| c * d),
                },
                Self {
                    re: c,
                    eps: e.map(|d| -s * d),
                },
            )
        })
    }

    /// The sign, with derivative 0: Coulomb friction's jump at zero rate is not
    /// differentiated.
    #[inline(always)]
    fn sign(self) -> Self {
        Self::constant(self.re.sign())
    }

    /// The larger by value, with its derivatives.
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        if self.re >= other.re || other.re.is_nan() {
            self
        } else {
            other
        }
    }
}
