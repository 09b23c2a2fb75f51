//! The equations of motion: M as the Hessian of T, c from the momenta or the metric, g as
//! dV/dq; and Lagrange's equation expanded, the independent check.

use std::fmt;

use super::bodies::{standard_bodies, Body};
use super::energy::{kinetic_energy, potential_energy, spring_energy};
use super::rates::{rate, RateProducts};
use super::spec::ArmSpec;
use super::{christoffel, metric};
use crate::expr::{Expr, Monomial, Var};
use crate::ring::{Coefficient, Rational};

/// The equations of motion `tau = M(q) qdd + c(q, qd) + g(q)`, exact (joint friction, which no
/// Lagrangian holds, is added by the generated methods from the arm's `damping` and
/// `frictionloss`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dynamics<C = Rational> {
    /// Number of joints.
    pub n: usize,
    /// Kinetic energy T(q, qd).
    pub kinetic_energy: Expr<C>,
    /// Potential energy V(q): gravity's, zero at the base origin, and the joint springs'.
    pub potential_energy: Expr<C>,
    /// The mass matrix, row-major.
    pub mass_matrix: Vec<Vec<Expr<C>>>,
    /// The velocity-product torques c(q, qd).
    pub coriolis: Vec<Expr<C>>,
    /// The gravity torques g(q) = dV/dq.
    pub gravity: Vec<Expr<C>>,
}

impl<C: Coefficient> Dynamics<C> {
    /// Derives the equations of motion by Lagrange's equation.
    #[must_use]
    pub fn derive(arm: &ArmSpec<C>) -> Self {
        Self::of_bodies(arm, &standard_bodies(arm))
    }

    /// The kinetic and potential energies of the arm's geometry (lengths, armature, gravity)
    /// carrying `bodies`: linear in the bodies' standard parameters.
    #[must_use]
    pub fn energies(
        arm: &ArmSpec<C>,
        bodies: &[Body<C>],
        rates: &mut RateProducts<C>,
    ) -> (Expr<C>, Expr<C>) {
        (
            kinetic_energy(arm, bodies, rates),
            potential_energy(arm, bodies),
        )
    }

    /// The equations of motion of the arm's links and joints (lengths, armature) carrying
    /// `bodies` in standard parameters instead of its own links' masses. The energies are
    /// linear in the bodies' parameters, which is what the regressor uses.
    #[must_use]
    pub fn of_bodies(arm: &ArmSpec<C>, bodies: &[Body<C>]) -> Self {
        let n = arm.links.len();
        let mut rates = RateProducts::new();
        let kinetic = kinetic_energy(arm, bodies, &mut rates);
        // Gravity's and the joint springs'.
        let potential = potential_energy(arm, bodies).add(&spring_energy(arm));
        // M as the Hessian of T in the rates, g = dV/dq, and the velocity terms from the
        // momenta p = dT/dqd: the same exact functions Lagrange's equation gives (checked
        // against it by `lagrange_torques`), without expanding d/dt dL/dqd, the costliest step.
        // For arms whose joints all turn, M and c are summed from the metric in absolute
        // angles instead (small expressions per pair of links): the same expressions at a
        // fraction of the cost for long arms.
        let (mass_matrix, coriolis) = if arm.all_revolute() {
            let pairs = metric::pairs(arm, bodies);
            (pairs.mass_matrix(arm), pairs.coriolis(&mut rates))
        } else {
            let p: Vec<Expr<C>> = (0..n).map(|i| kinetic.diff_var(rate(i))).collect();
            let m: Vec<Vec<Expr<C>>> = (0..n)
                .map(|i| (0..n).map(|j| p[i].diff_var(rate(j))).collect())
                .collect();
            // c_i = sum_j Mdot_ij qd_j - dT/dq_i, with sum_j Mdot_ij qd_j the derivative of
            // p_i along the angles; equal to C qd (checked in the tests).
            let c = (0..n)
                .map(|i| p[i].dt_q(n).sub(&kinetic.diff_q(i)))
                .collect();
            (m, c)
        };
        let gravity: Vec<Expr<C>> = (0..n).map(|i| potential.diff_q(i)).collect();
        Self {
            n,
            kinetic_energy: kinetic,
            potential_energy: potential,
            mass_matrix,
            coriolis,
            gravity,
        }
    }

    /// The Lagrangian L = T - V. Built on demand: for long arms it is as large as T, and
    /// only the paper's route and the printed derivation need it.
    #[must_use]
    pub fn lagrangian(&self) -> Expr<C> {
        self.kinetic_energy.sub(&self.potential_energy)
    }

    /// The torques `tau_i = d/dt dL/dqd_i - dL/dq_i` of Lagrange's equation, per joint, expanded
    /// (assembled as `M qdd + c + g`; equal to [`lagrange_torques`](Self::lagrange_torques)).
    /// Built on demand: they hold as many terms as M, c and g together (see
    /// [`torque_terms`](Self::torque_terms)), which a forty-link arm counts in millions.
    #[must_use]
    pub fn torques(&self) -> Vec<Expr<C>> {
        (0..self.n)
            .map(|i| {
                let mut t = self.coriolis[i].add(&self.gravity[i]);
                for (j, mij) in self.mass_matrix[i].iter().enumerate() {
                    t.add_assign(&mij.mul_var(Var::Qdd(j)));
                }
                t
            })
            .collect()
    }

    /// The terms of [`torques`](Self::torques) without building them, and the coefficients'
    /// parts (`part_count` of each) where `parts`: c's monomials are quadratic in the rates,
    /// g's free of them and each `M_ij qdd_j`'s linear in `qdd_j`, so no two terms merge.
    #[must_use]
    pub fn torque_terms(&self, parts: impl Fn(&C) -> usize) -> usize {
        let count = |e: &Expr<C>| e.terms().map(|(_, _, c)| parts(c)).sum::<usize>();
        (0..self.n)
            .map(|i| {
                count(&self.coriolis[i])
                    + count(&self.gravity[i])
                    + self.mass_matrix[i].iter().map(count).sum::<usize>()
            })
            .sum()
    }

    /// Lagrange's equation, `d/dt dL/dqd_i - dL/dq_i`, expanded: the route of the paper,
    /// independent of how [`derive`](Self::derive) assembles [`torques`](Self::torques) (from
    /// the Hessian of T, Christoffel symbols and dV/dq), and equal to it.
    #[must_use]
    pub fn lagrange_torques(&self) -> Vec<Expr<C>> {
        let lagrangian = self.lagrangian();
        (0..self.n)
            .map(|i| {
                lagrangian
                    .diff_var(rate(i))
                    .dt(self.n)
                    .sub(&lagrangian.diff_q(i))
            })
            .collect()
    }

    /// The Coriolis matrix of Christoffel symbols, row-major, expanded: `C qd = c` and
    /// `Mdot - 2 C` is skew (see [`crate::christoffel`]; the generated method evaluates the
    /// same function by a cheaper route for arms whose joints all turn).
    #[must_use]
    pub fn coriolis_matrix(&self) -> Vec<Vec<Expr<C>>> {
        christoffel::expanded(&self.mass_matrix)
    }

    /// The mass matrix read off Lagrange's equation (the coefficients of the accelerations in
    /// [`lagrange_torques`](Self::lagrange_torques)): an independent reading of M that must
    /// agree with the Hessian of the kinetic energy that [`derive`](Self::derive) takes.
    #[must_use]
    pub fn mass_matrix_from_lagrange(&self) -> Vec<Vec<Expr<C>>> {
        self.lagrange_torques()
            .iter()
            .map(|t| {
                (0..self.n)
                    .map(|j| t.coefficient_of(&Monomial::var(Var::Qdd(j))))
                    .collect()
            })
            .collect()
    }
}

impl<C: Coefficient> fmt::Display for Dynamics<C> {
    /// The derivation in readable notation: L, M, c, g.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "T = {}", self.kinetic_energy)?;
        writeln!(f, "V = {}", self.potential_energy)?;
        writeln!(f, "L = T - V = {}", self.lagrangian())?;
        for i in 0..self.n {
            for j in i..self.n {
                writeln!(f, "M{}{} = {}", i + 1, j + 1, self.mass_matrix[i][j])?;
            }
        }
        for i in 0..self.n {
            writeln!(f, "c{} = {}", i + 1, self.coriolis[i])?;
        }
        for i in 0..self.n {
            writeln!(f, "g{} = {}", i + 1, self.gravity[i])?;
        }
        Ok(())
    }
}
