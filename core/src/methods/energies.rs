//! The programs of the energies: T as its expanded formula or as `qd^T M qd / 2` on the mass
//! matrix's program, and V.

use num_traits::Zero;

use super::{cost, Derived, Method};
use crate::ring::Rational;
use crate::slp::{Emit, Id, Input};

impl<C: Emit> Derived<C> {
    /// `T(q, qd)`: the cheaper of the expanded energy and `qd^T M qd / 2` on
    /// [`mass_matrix_method`](Self::mass_matrix_method)'s program (the same number in exact
    /// arithmetic: T is that quadratic form in the rates). From four links on the expanded
    /// energy is built only when its term count could compete.
    #[must_use]
    pub fn kinetic_energy_method(&self) -> Method {
        self.kinetic_energy_choice().0
    }

    /// [`kinetic_energy_method`](Self::kinetic_energy_method), and whether it is the quadratic
    /// form on the mass matrix's program (then the derive emits `kinetic_energy` as a call of
    /// `mass_matrix` and the run-time crate's quadratic form: the same operations, none of them
    /// type-checked again in the user's crate). On a tie the expanded energy is kept.
    pub(crate) fn kinetic_energy_choice(&self) -> (Method, bool) {
        let quadratic = self.kinetic_energy_quadratic_method();
        let terms = Self::terms(&[&self.dynamics.kinetic_energy]);
        if self.worth_expanding(terms, &quadratic) {
            let expanded = self.vector_method(
                "kinetic",
                std::slice::from_ref(&self.dynamics.kinetic_energy),
            );
            if cost(&expanded) <= cost(&quadratic) {
                return (expanded, false);
            }
        }
        (quadratic, true)
    }

    /// `T = sum_i qd_i (M_ii qd_i / 2 + sum_{j > i} M_ij qd_j)`.
    fn kinetic_energy_quadratic_method(&self) -> Method {
        let n = self.n();
        let mass = self.mass_matrix_method();
        let mut p = mass.program;
        let m = |i: usize, j: usize| mass.outputs[i * n + j].1;
        let half = p.constant(Rational::new(1.into(), 2.into()));
        let qd: Vec<Id> = (0..n).map(|j| p.input(Input::Qd(j))).collect();
        let mut rows = Vec::with_capacity(n);
        for i in 0..n {
            let diagonal = p.mul(m(i, i), qd[i]);
            let mut terms = vec![p.mul(half, diagonal)];
            for (j, &rate) in qd.iter().enumerate().skip(i + 1) {
                terms.push(p.mul(m(i, j), rate));
            }
            // `terms` holds the diagonal term at least.
            let row = p
                .balanced_sum(&terms)
                .unwrap_or_else(|| p.constant(Rational::zero()));
            rows.push(p.mul(qd[i], row));
        }
        let t = p
            .balanced_sum(&rows)
            .unwrap_or_else(|| p.constant(Rational::zero()));
        Method::new(p, vec![("kinetic".into(), t)]).described(
            "Evaluated as `qd^T M qd / 2` on the mass matrix's program (`M` as `mass_matrix` \
             computes it).",
        )
    }

    /// `V(q)`.
    #[must_use]
    pub fn potential_energy_method(&self) -> Method {
        self.vector_method(
            "potential",
            std::slice::from_ref(&self.dynamics.potential_energy),
        )
    }
}
