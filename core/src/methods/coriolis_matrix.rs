//! The program of the Coriolis matrix C: in the links' absolute angles for arms whose joints
//! all turn ([`crate::christoffel`]), the expanded entries otherwise.

use super::{cheapest, Derived, Method};
use crate::christoffel::{absolute_derivatives, absolute_program};
use crate::expr::Expr;
use crate::programs::method::two;
use crate::slp::{Emit, Program};

impl<C: Emit> Derived<C> {
    /// `C(q, qd)`, Christoffel's: for arms whose joints all turn, by the absolute angles'
    /// route of [`crate::christoffel`] (the expanded entries are built and compared only for
    /// fewer than four links, where they can be cheaper); the expanded entries otherwise.
    #[must_use]
    pub fn coriolis_matrix_method(&self) -> Method {
        let Some(d) = absolute_derivatives(&self.arm, &self.dynamics.mass_matrix) else {
            return self.coriolis_matrix_expanded_method();
        };
        let absolute = self.coriolis_matrix_absolute_method(&d);
        if self.n() < 4 {
            cheapest(vec![self.coriolis_matrix_expanded_method(), absolute])
        } else {
            absolute
        }
    }

    /// `C(q, qd)` entry by entry from the expanded formulas.
    #[must_use]
    pub fn coriolis_matrix_expanded_method(&self) -> Method {
        let cm = self.dynamics.coriolis_matrix();
        let mut p = Program::new();
        let mut outputs = Vec::new();
        for (i, row) in cm.iter().enumerate() {
            for (j, e) in row.iter().enumerate() {
                let id = p.expr(e);
                outputs.push((format!("cm{}", two(i, j)), id));
            }
        }
        Method::new(p, outputs)
    }

    /// `C(q, qd) = J^T Ct J` in the links' absolute angles, from `D` of
    /// [`crate::christoffel::absolute_derivatives`].
    fn coriolis_matrix_absolute_method(&self, d: &[Vec<Expr<C>>]) -> Method {
        let n = self.n();
        let mut p = Program::new();
        let senses: Vec<i32> = (0..n).map(|i| self.arm.sense(i)).collect();
        let c = absolute_program(&mut p, d, &senses);
        let outputs = (0..n * n)
            .map(|k| (format!("cm{}", two(k / n, k % n)), c[k]))
            .collect();
        Method::new(p, outputs).described(
            "Evaluated in the links' absolute angles, where each entry of C is a sum of \
             products `dM~_ab/dphi_b w_b` of one small derivative and one absolute rate \
             (see `planar_arm::symbolic::christoffel`).",
        )
    }
}
