//! The links' absolute rates and their products, which the energies and the velocity
//! products share.

use super::spec::ArmSpec;
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
    /// `1` or `-1` per joint ([`ArmSpec::sense`]); joints past the end turn the standard way.
    senses: Vec<i32>,
}

impl<C: Coefficient> RateProducts<C> {
    /// An empty cache.
    #[must_use]
    pub fn new() -> Self {
        Self {
            products: std::collections::BTreeMap::new(),
            senses: Vec::new(),
        }
    }

    /// Takes the senses of `arm`'s joints, forgetting the products if they differ.
    pub(crate) fn sync(&mut self, arm: &ArmSpec<C>) {
        let senses: Vec<i32> = (0..arm.links.len()).map(|i| arm.sense(i)).collect();
        if senses != self.senses {
            self.products.clear();
            self.senses = senses;
        }
    }

    /// `omega_a omega_b` (`a >= b`), `omega_a = qd_1 + ... + qd_(a+1)` (a reversed joint's
    /// rate subtracted).
    pub(crate) fn product(&mut self, a: usize, b: usize) -> &Expr<C> {
        let senses = &self.senses;
        self.products.entry((a, b)).or_insert_with(|| {
            let omega = |k: usize| {
                let mut w = Expr::zero();
                for j in 0..=k {
                    if senses.get(j) == Some(&-1) {
                        w.sub_assign(&Expr::var(rate(j)));
                    } else {
                        w.add_assign(&Expr::var(rate(j)));
                    }
                }
                w
            };
            omega(a).mul(&omega(b))
        })
    }
}
