//! The links' absolute rates and their products, which the energies and the velocity
//! products share.

use crate::expr::{Expr, Var};
use crate::ring::{Coefficient, Rational};

/// The rate `qd_j` of joint `j` (0-based).
pub(super) fn rate(j: usize) -> Var {
    Var::Qd(j)
}

/// The products `omega_a omega_b` of the links' absolute rates, each built once and shared by
/// every energy derived with the same cache.
#[derive(Clone, Debug, Default)]
pub struct RateProducts<C = Rational> {
    products: std::collections::BTreeMap<(usize, usize), Expr<C>>,
}

impl<C: Coefficient> RateProducts<C> {
    /// An empty cache.
    #[must_use]
    pub fn new() -> Self {
        Self {
            products: std::collections::BTreeMap::new(),
        }
    }

    /// `omega_a omega_b` (`a >= b`), `omega_a = qd_1 + ... + qd_(a+1)`.
    pub(crate) fn product(&mut self, a: usize, b: usize) -> &Expr<C> {
        self.products.entry((a, b)).or_insert_with(|| {
            let omega = |k: usize| {
                let mut w = Expr::zero();
                for j in 0..=k {
                    w.add_assign(&Expr::var(rate(j)));
                }
                w
            };
            omega(a).mul(&omega(b))
        })
    }
}
