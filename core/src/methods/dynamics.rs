//! The programs of M, c, g, the friction, the bias, M and h together, and the inverse
//! dynamics: the expanded formulas or the Newton-Euler and composite-rigid-body recursions
//! unrolled for the arm, whichever is cheaper.

use super::{cheapest, cost, matrix_outputs, vector_outputs, Derived, Method};
use crate::mechanics::Dynamics;
use crate::programs::unrolled::{composite_mass_matrix, newton_euler, Terms};
use crate::slp::{Emit, Id, Input, Program};

impl<C: Emit> Derived<C> {
    /// `M(q)`: the cheaper (by [`OpCount`](crate::slp::OpCount)) of the expanded entries and an
    /// unrolled composite-rigid-body recursion. Upper triangle; the lower one is the same nodes.
    #[must_use]
    pub fn mass_matrix_method(&self) -> Method {
        self.chosen[0]
            .get_or_init(|| {
                let composite = self.mass_matrix_composite_method();
                if self.worth_expanding(self.mass_matrix_terms(), &composite) {
                    cheapest(vec![self.mass_matrix_expanded_method(), composite])
                } else {
                    composite
                }
            })
            .clone()
    }

    /// `M(q)` evaluated entry by entry from the expanded formulas.
    #[must_use]
    pub fn mass_matrix_expanded_method(&self) -> Method {
        self.expanded_mass_matrix
            .get_or_init(|| {
                let mut p = Program::new();
                let m = expanded_mass_matrix(&mut p, &self.dynamics);
                Method::new(p, matrix_outputs(&m))
            })
            .clone()
    }

    /// `M(q)` by the composite-rigid-body recursion, unrolled for this arm.
    #[must_use]
    pub fn mass_matrix_composite_method(&self) -> Method {
        let mut p = Program::new();
        let m = composite_mass_matrix(&mut p, &self.arm);
        Method::new(p, matrix_outputs(&m)).described(CRBA)
    }

    /// `c(q, qd)`: the cheaper of the expanded formulas and an unrolled Newton-Euler recursion
    /// (no gravity, no accelerations).
    #[must_use]
    pub fn coriolis_method(&self) -> Method {
        self.chosen[1]
            .get_or_init(|| {
                let recursive = self.newton_euler_method("cor", Terms::CORIOLIS);
                let terms = Self::terms(&self.dynamics.coriolis.iter().collect::<Vec<_>>());
                if self.worth_expanding(terms, &recursive) {
                    cheapest(vec![
                        self.vector_method("cor", &self.dynamics.coriolis),
                        recursive,
                    ])
                } else {
                    recursive
                }
            })
            .clone()
    }

    /// `g(q)`: the cheaper of the expanded formulas and an unrolled static recursion.
    #[must_use]
    pub fn gravity_method(&self) -> Method {
        self.chosen[2]
            .get_or_init(|| {
                cheapest(vec![
                    self.vector_method("g", &self.dynamics.gravity),
                    self.newton_euler_method("g", Terms::GRAVITY),
                ])
            })
            .clone()
    }

    /// The bias `h(q, qd) = c + g + f`, everything but the inertial term: the cheaper of the
    /// expanded formulas and an unrolled Newton-Euler recursion (no accelerations), plus
    /// friction.
    #[must_use]
    pub fn bias_method(&self) -> Method {
        let recursive = self.with_friction(self.bias_recursive_method());
        if self.worth_expanding(self.bias_terms(), &recursive) {
            cheapest(vec![
                self.with_friction(self.expanded_bias_method()),
                recursive,
            ])
        } else {
            recursive
        }
    }

    fn expanded_bias_method(&self) -> Method {
        self.expanded_bias
            .get_or_init(|| {
                let mut p = Program::new();
                let h = self.expanded_bias(&mut p);
                let outputs = vector_outputs("h", h);
                Method::new(p, outputs)
            })
            .clone()
    }

    /// `c + g` from the expanded formulas.
    pub(super) fn expanded_bias(&self, p: &mut Program) -> Vec<Id> {
        (0..self.n())
            .map(|i| {
                let e = self.dynamics.coriolis[i].add(&self.dynamics.gravity[i]);
                p.expr(&e)
            })
            .collect()
    }

    /// The bias without friction by the unrolled Newton-Euler recursion.
    fn bias_recursive_method(&self) -> Method {
        self.recursive_bias
            .get_or_init(|| self.newton_euler_method("h", Terms::BIAS))
            .clone()
    }

    /// `M(q)` and `h(q, qd) = c + g + f` in one program: one `sin_cos` per joint, and every
    /// subexpression the two share (rotations, products of parameters) computed once. The
    /// cheapest of the expanded and recursive forms of each, chosen together.
    ///
    /// A program holding the expanded M costs at least what the expanded M alone costs (its
    /// operations are among the program's, its chain of dependent operations too), so when
    /// that alone costs more than the all-recursive program, no program with it can win and
    /// none is built; likewise for the expanded bias.
    #[must_use]
    pub fn mass_matrix_and_bias_method(&self) -> Method {
        let joint = |composite: bool, recursive: bool| {
            let mut p = Program::new();
            let m = if composite {
                composite_mass_matrix(&mut p, &self.arm)
            } else {
                expanded_mass_matrix(&mut p, &self.dynamics)
            };
            let h = if recursive {
                newton_euler(&mut p, &self.arm, Terms::BIAS)
            } else {
                self.expanded_bias(&mut p)
            };
            let f = self.friction_nodes(&mut p);
            let mut outputs = matrix_outputs(&m);
            for (i, (h, f)) in h.into_iter().zip(f).enumerate() {
                outputs.push((format!("h{}", i + 1), p.add(h, f)));
            }
            let how = match (composite, recursive) {
                (false, false) => String::new(),
                (c, r) => format!(
                    "M {}, h {}.",
                    if c {
                        "by the composite-rigid-body algorithm unrolled for this arm"
                    } else {
                        "from the formulas"
                    },
                    if r {
                        "by the recursive Newton-Euler algorithm unrolled for this arm"
                    } else {
                        "from the formulas"
                    }
                ),
            };
            Method::new(p, outputs).described(&how)
        };
        let recursive = joint(true, true);
        let bound = cost(&recursive);
        let expand_m = self.worth_expanding(
            self.mass_matrix_terms(),
            &self.mass_matrix_composite_method(),
        ) && cost(&self.mass_matrix_expanded_method()) <= bound;
        let expand_h = self.worth_expanding(self.bias_terms(), &self.bias_recursive_method())
            && cost(&self.expanded_bias_method()) <= bound;
        // The term-by-term forms first, so that they are kept on a tie.
        let mut candidates = Vec::new();
        for (composite, recursive) in [(false, false), (false, true), (true, false)] {
            if (composite || expand_m) && (recursive || expand_h) {
                candidates.push(joint(composite, recursive));
            }
        }
        candidates.push(recursive);
        cheapest(candidates)
    }

    /// `tau = M qdd + c + g`: the cheaper of the expanded Lagrangian torques and an unrolled
    /// Newton-Euler recursion.
    #[must_use]
    pub fn inverse_dynamics_method(&self) -> Method {
        let recursive = self.inverse_dynamics_newton_euler_method();
        let terms = self.dynamics.torque_terms(|c| c.part_count().max(1));
        if self.worth_expanding(terms, &recursive) {
            cheapest(vec![self.inverse_dynamics_lagrange_method(), recursive])
        } else {
            recursive
        }
    }

    /// `tau` from the expanded Lagrangian torques, term by term, plus friction.
    #[must_use]
    pub fn inverse_dynamics_lagrange_method(&self) -> Method {
        self.with_friction(self.vector_method("tau", &self.dynamics.torques()))
    }

    /// `tau` by the planar recursive Newton-Euler algorithm unrolled for this arm, plus
    /// friction.
    #[must_use]
    pub fn inverse_dynamics_newton_euler_method(&self) -> Method {
        self.with_friction(self.newton_euler_method("tau", Terms::ALL))
    }

    pub(super) fn newton_euler_method(&self, name: &str, terms: Terms) -> Method {
        let mut p = Program::new();
        let tau = newton_euler(&mut p, &self.arm, terms);
        let outputs = vector_outputs(name, tau);
        Method::new(p, outputs).described(RNEA)
    }

    /// `f(qd)`: the joint friction torques, `damping qd_i + frictionloss sign(qd_i)`.
    #[must_use]
    pub fn friction_method(&self) -> Method {
        let mut p = Program::new();
        let f = self.friction_nodes(&mut p);
        let outputs = vector_outputs("f", f);
        Method::new(p, outputs)
    }

    /// The joint friction torques `damping qd_i + frictionloss sign(qd_i)` (zero nodes for an
    /// arm without friction).
    pub(super) fn friction_nodes(&self, p: &mut Program) -> Vec<Id> {
        self.arm
            .links
            .iter()
            .enumerate()
            .map(|(i, link)| {
                let qd = p.input(Input::Qd(i));
                let b = p.coefficient(&link.damping);
                let f = p.coefficient(&link.frictionloss);
                let viscous = p.mul(b, qd);
                let sign = p.sign(qd);
                let coulomb = p.mul(f, sign);
                p.add(viscous, coulomb)
            })
            .collect()
    }

    /// Adds the friction torques to a torque program's outputs.
    pub(super) fn with_friction(&self, mut m: Method) -> Method {
        let f = self.friction_nodes(&mut m.program);
        for ((_, id), fi) in m.outputs.iter_mut().zip(f) {
            *id = m.program.add(*id, fi);
        }
        m
    }
}

/// The doc-comment note of a method evaluated by the unrolled Newton-Euler recursion.
const RNEA: &str = "Evaluated not term by term but by the planar recursive Newton-Euler \
                    algorithm unrolled for this arm (the same function, fewer operations): \
                    link-frame velocities and accelerations outwards, forces and moments \
                    inwards, one rotation by each joint's (cos, sin) per pass, the link \
                    constants folded in.";

/// The doc-comment note of a mass matrix evaluated by the unrolled composite-rigid-body
/// algorithm.
const CRBA: &str = "Evaluated not term by term but by the composite-rigid-body algorithm \
                    unrolled for this arm (the same function, fewer operations): the mass, \
                    first moment and rotational inertia of each tail of the chain, in link \
                    frames, the link constants folded in.";

/// The mass matrix from the expanded entries (upper triangle; the lower is the same nodes).
pub(super) fn expanded_mass_matrix<C: Emit>(p: &mut Program, d: &Dynamics<C>) -> Vec<Vec<Id>> {
    let n = d.n;
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| p.expr(&d.mass_matrix[i.min(j)][i.max(j)]))
                .collect()
        })
        .collect()
}
