//! The derivatives of the dynamics as generated methods: which differentiated program
//! computes `(dtau/dq, dtau/dqd)` and `(dqdd/dq, dqdd/dqd, dqdd/dtau)`, and the solve that turns
//! the one into the other.

use num_traits::{One, Zero};

use super::{cheapest, Derived, Method};
use crate::expr::Var;
use crate::programs::derivative::{differentiate, MAX_FORWARD_OPS, MAX_LINKS, MAX_OPS};
use crate::programs::unrolled::{ldlt_solve, pivot_floor};
use crate::ring::Rational;
use crate::slp::{Emit, Id, Input, Program};

impl<C: Emit> Derived<C> {
    /// `(dtau/dq, dtau/dqd)` of the inverse dynamics, the cheapest of: the unrolled
    /// Newton-Euler recursion differentiated by [`differentiate`], and for arms of up to three
    /// links the expanded torques' program differentiated likewise and the torques
    /// differentiated symbolically. Outputs row-major, `dtau/dq`
    /// first. `None` past [`MAX_OPS`] or [`MAX_LINKS`].
    #[must_use]
    pub fn inverse_dynamics_derivatives_method(&self) -> Option<Method> {
        let n = self.arm.links.len();
        if n > MAX_LINKS {
            return None;
        }
        let recursive = self.inverse_dynamics_newton_euler_method();
        let mut candidates = Vec::new();
        let mut differentiated = Vec::new();
        // The expanded forms' derivatives grow faster than the recursion's: from four links on
        // they were never the cheaper (op counts, 1 to 10 links, docs/performance.md), and
        // differentiating them symbolically costs the derive more than the rest of the method.
        if n < 4 {
            differentiated.push(self.symbolic_derivatives_method());
            candidates.push(self.inverse_dynamics_lagrange_method());
        }
        candidates.push(recursive);
        let directions: Vec<Input> = (0..n).map(Input::Q).chain((0..n).map(Input::Qd)).collect();
        differentiated.extend(candidates.into_iter().filter_map(|m| {
            let mut p = m.program;
            let outs: Vec<Id> = m.outputs.iter().map(|o| o.1).collect();
            let jac = differentiate(&mut p, &outs, &directions).ok()?;
            let mut outputs = Vec::with_capacity(2 * n * n);
            for (wrt, offset) in [("q", 0), ("qd", n)] {
                for (i, row) in jac.iter().enumerate() {
                    for j in 0..n {
                        outputs.push((format!("dtau{}_d{wrt}{}", i + 1, j + 1), row[offset + j]));
                    }
                }
            }
            let from = if m.evaluation.is_empty() {
                "the expanded torques, term by term"
            } else {
                "the planar recursive Newton-Euler algorithm unrolled for this arm"
            };
            let how = format!(
                "Differentiated at compile time from {from}: the chain rule applied once per \
                     operation of that straight-line program (forward mode), the sines and \
                     cosines of angle sums differentiated into each other, structural zeros \
                     dropped and common subexpressions shared."
            );
            Some(Method::new(p, outputs).described(&how))
        }));
        if differentiated.is_empty() {
            return None;
        }
        let best = cheapest(differentiated);
        let ops = best.op_count();
        (ops.mul + ops.add + ops.div <= MAX_OPS).then_some(best)
    }

    /// `(dtau/dq, dtau/dqd)` from the expanded torques differentiated symbolically, exact
    /// coefficients, evaluated term by term; the viscous friction adds `damping_i` to
    /// `dtau_i/dqd_i` (Coulomb friction nothing).
    fn symbolic_derivatives_method(&self) -> Method {
        let n = self.arm.links.len();
        let mut p = Program::new();
        let mut outputs = Vec::with_capacity(2 * n * n);
        let torques = self.dynamics.torques();
        for (i, tau) in torques.iter().enumerate() {
            for j in 0..n {
                let id = p.expr(&tau.diff_q(j));
                outputs.push((format!("dtau{}_dq{}", i + 1, j + 1), id));
            }
        }
        for (i, tau) in torques.iter().enumerate() {
            for j in 0..n {
                let mut id = p.expr(&tau.diff_var(Var::Qd(j)));
                if i == j {
                    let damping = p.coefficient(&self.arm.links[i].damping);
                    id = p.add(id, damping);
                }
                outputs.push((format!("dtau{}_dqd{}", i + 1, j + 1), id));
            }
        }
        Method::new(p, outputs).described(
            "Differentiated exactly at compile time: each torque's expanded formula \
             differentiated symbolically (exact rational coefficients), evaluated term by term.",
        )
    }

    /// `(dqdd/dq, dqdd/dqd, dqdd/dtau)` of the forward dynamics, one program: `qdd` as
    /// `forward_dynamics` computes it, the inverse dynamics' derivatives of
    /// [`inverse_dynamics_derivatives_method`](Self::inverse_dynamics_derivatives_method)
    /// evaluated at that `qdd`, and `M x = b` solved for each of their columns (negated) and
    /// each unit vector, with `M` factored once (`L D L^T` as in `forward_dynamics`; Cramer's
    /// rule with `M`'s determinant for two links). Outputs row-major, in that order. `None`
    /// past [`MAX_FORWARD_OPS`].
    #[must_use]
    pub fn forward_dynamics_derivatives_method(&self) -> Option<Method> {
        let n = self.arm.links.len();
        let derivatives = self.inverse_dynamics_derivatives_method()?;
        // The forward program holds the inverse one and 2 N^3 products more: on every arm
        // measured it cost 2.3-2.8x the inverse one (2,450-2,560 against 970-1,010 operations
        // at six links). Past this bound it would not be emitted, so it is not built.
        let inverse = derivatives.op_count();
        if (inverse.mul + inverse.add + inverse.div) * 11 > MAX_FORWARD_OPS * 5 {
            return None;
        }
        let fd = self.forward_dynamics_method();
        let mut p = fd.program;
        let qdd: Vec<Id> = fd.outputs.iter().map(|o| o.1).collect();
        let mass = self.mass_matrix_method();
        let entries: Vec<Id> = mass.outputs.iter().map(|o| o.1).collect();
        let entries = p.graft(&mass.program, &entries, &|_| None);
        let m: Vec<Vec<Id>> = entries.chunks(n).map(<[Id]>::to_vec).collect();
        let roots: Vec<Id> = derivatives.outputs.iter().map(|o| o.1).collect();
        let dtau = p.graft(&derivatives.program, &roots, &|i| match i {
            Input::Qdd(j) => Some(qdd[j]),
            _ => None,
        });
        let solve = solver(self, &mut p, &m);
        let column = |k: usize, j: usize| -> Vec<Id> {
            (0..n).map(|i| dtau[k * n * n + i * n + j]).collect()
        };
        let candidates = [false, true].map(|products| {
            let mut p = p.clone();
            let zero = p.constant(Rational::zero());
            let one = p.constant(Rational::one());
            // Columns of M^-1 (one solve per unit vector; its zeros fold away).
            let inverse: Vec<Vec<Id>> = (0..n)
                .map(|j| {
                    let b: Vec<Id> = (0..n).map(|i| if i == j { one } else { zero }).collect();
                    solve.solve(&mut p, &b)
                })
                .collect();
            // -M^-1 b: solved for b, or as the products of b with -M^-1 (whose entries are
            // negated once), independent multiply-adds instead of triangular chains.
            let negated: Vec<Vec<Id>> = if products {
                (0..n)
                    .map(|i| (0..n).map(|j| p.neg(inverse[i.min(j)][i.max(j)])).collect())
                    .collect()
            } else {
                Vec::new()
            };
            let mut columns: Vec<(&str, Vec<Vec<Id>>)> = Vec::new();
            for (k, wrt) in ["q", "qd"].into_iter().enumerate() {
                let cols = (0..n)
                    .map(|j| {
                        let b = column(k, j);
                        if products {
                            (0..n)
                                .map(|i| {
                                    let terms: Vec<Id> =
                                        (0..n).map(|l| p.mul(negated[l][i], b[l])).collect();
                                    p.balanced_sum(&terms).unwrap_or(zero)
                                })
                                .collect()
                        } else {
                            let x = solve.solve(&mut p, &b);
                            x.into_iter().map(|x| p.neg(x)).collect()
                        }
                    })
                    .collect();
                columns.push((wrt, cols));
            }
            columns.push(("tau", inverse));
            let mut outputs = Vec::with_capacity(3 * n * n);
            for (wrt, cols) in &columns {
                for i in 0..n {
                    for (j, col) in cols.iter().enumerate() {
                        outputs.push((format!("dqdd{}_d{wrt}{}", i + 1, j + 1), col[i]));
                    }
                }
            }
            let how = if products {
                format!("M^-1 by {}; then dqdd/dq = -M^-1 dtau/dq and dqdd/dqd = -M^-1 dtau/dqd as products", solve.describe())
            } else {
                format!("dqdd/dq = -M^-1 dtau/dq, dqdd/dqd = -M^-1 dtau/dqd and dqdd/dtau = M^-1 by {}", solve.describe())
            };
            Method::new(p, outputs).described(&format!(
                "qdd from the forward dynamics program; dtau/dq and dtau/dqd at that qdd as \
                 `inverse_dynamics_derivatives` computes them; {how}."
            ))
        });
        let method = cheapest(candidates.into());
        let ops = method.op_count();
        (ops.mul + ops.add + ops.div <= MAX_FORWARD_OPS).then_some(method)
    }
}

/// How `M x = b` is solved for many right-hand sides with one factorisation.
enum Solver {
    /// One link: `x = b / M11`.
    One(Id),
    /// Two links: Cramer's rule, `1 / det M` computed once.
    Two { m: [[Id; 2]; 2], inv_det: Id },
    /// `L D L^T`, with the pivot floors of `forward_dynamics`; hash-consing shares the
    /// factorisation between the right-hand sides.
    Ldlt { m: Vec<Vec<Id>>, floors: Vec<Id> },
}

fn solver<C: Emit>(d: &Derived<C>, p: &mut Program, m: &[Vec<Id>]) -> Solver {
    let one = p.constant(Rational::one());
    match m.len() {
        1 => Solver::One(p.div(one, m[0][0])),
        2 => {
            let det = d.two_link_det(p).unwrap_or_else(|| {
                let a = p.mul(m[0][0], m[1][1]);
                let b = p.mul(m[0][1], m[0][1]);
                p.sub(a, b)
            });
            p.set_name(det, "det".into());
            let inv_det = p.div(one, det);
            p.set_name(inv_det, "inv_det".into());
            Solver::Two {
                m: [[m[0][0], m[0][1]], [m[1][0], m[1][1]]],
                inv_det,
            }
        }
        n => Solver::Ldlt {
            m: m.to_vec(),
            floors: (0..n)
                .map(|i| pivot_floor(p, &d.dynamics.mass_matrix[i][i], m[i][i]))
                .collect(),
        },
    }
}

impl Solver {
    fn solve(&self, p: &mut Program, b: &[Id]) -> Vec<Id> {
        match self {
            Self::One(inv) => vec![p.mul(b[0], *inv)],
            Self::Two { m, inv_det } => {
                let x0 = {
                    let u = p.mul(m[1][1], b[0]);
                    let v = p.mul(m[0][1], b[1]);
                    p.sub(u, v)
                };
                let x1 = {
                    let u = p.mul(m[0][0], b[1]);
                    let v = p.mul(m[0][1], b[0]);
                    p.sub(u, v)
                };
                vec![p.mul(x0, *inv_det), p.mul(x1, *inv_det)]
            }
            Self::Ldlt { m, floors } => ldlt_solve(p, m, b, floors),
        }
    }

    fn describe(&self) -> &'static str {
        match self {
            Self::One(_) => "1 / M11",
            Self::Two { .. } => "Cramer's rule with 1 / det M computed once",
            Self::Ldlt { .. } => "an unrolled L D L^T factorisation of M, computed once",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanics::ArmSpec;
    use crate::programs::derivative::tests::{central, state};
    use crate::ring::ratio;

    #[test]
    fn matches_central_differences_of_both_programs() {
        for n in 1..=4 {
            let mut arm = ArmSpec::paper(n);
            arm.gravity = crate::down(ratio(981, 100));
            arm.links[0].damping = ratio(1, 10);
            arm.links[n - 1].frictionloss = ratio(1, 5);
            let d = Derived::new(&arm);
            for m in [
                d.inverse_dynamics_lagrange_method(),
                d.inverse_dynamics_newton_euler_method(),
            ] {
                let mut p = m.program.clone();
                let outs: Vec<Id> = m.outputs.iter().map(|o| o.1).collect();
                let dirs: Vec<Input> = (0..n).map(Input::Q).chain((0..n).map(Input::Qd)).collect();
                let jac = differentiate(&mut p, &outs, &dirs).unwrap();
                let values = p.eval(&state);
                for (i, row) in jac.iter().enumerate() {
                    for (k, &id) in row.iter().enumerate() {
                        let want = central(&p, outs[i], &state, dirs[k]);
                        let got = values[id.0 as usize];
                        assert!(
                            (got - want).abs() < 1e-6 * (1.0 + want.abs()),
                            "n = {n} d tau{i} / d {:?}: {got} vs {want}",
                            dirs[k]
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn forward_dynamics_derivatives_match_central_differences() {
        for n in 1..=4 {
            let mut arm = ArmSpec::paper(n);
            arm.gravity = crate::down(ratio(981, 100));
            arm.links[0].damping = ratio(1, 10);
            let d = Derived::new(&arm);
            let fd = d.forward_dynamics_method();
            let m = d.forward_dynamics_derivatives_method().unwrap();
            let at = |i: Input| match i {
                Input::Tau(j) => 2.0 - 1.3 * j as f64,
                other => state(other),
            };
            let got = m.eval(&at);
            let mut k = 0;
            for dir in [Input::Q as fn(usize) -> Input, Input::Qd, Input::Tau] {
                for i in 0..n {
                    for j in 0..n {
                        let want = central(&fd.program, fd.outputs[i].1, &at, dir(j));
                        assert!(
                            (got[k] - want).abs() < 1e-6 * (1.0 + want.abs()),
                            "n = {n} {}: {} vs {want}",
                            m.outputs[k].0,
                            got[k]
                        );
                        k += 1;
                    }
                }
            }
        }
    }

    #[test]
    #[ignore = "prints a table"]
    fn print_parameterised_op_counts() {
        for n in [4, 6, 8, 9, 10] {
            let mut arm = ArmSpec::paper(n);
            arm.gravity = crate::down(ratio(981, 100));
            let (spec, _) = arm.parameterised();
            let d = Derived::new(&spec);
            let show = |m: Option<Method>| m.map_or("none".into(), |m| m.op_count().to_string());
            println!(
                "N = {n}: id derivatives {} | fd derivatives {}",
                show(d.inverse_dynamics_derivatives_method()),
                show(d.forward_dynamics_derivatives_method())
            );
        }
    }

    #[test]
    #[ignore = "prints a table"]
    fn print_op_counts() {
        for n in 1..=10 {
            let mut arm = ArmSpec::paper(n);
            arm.gravity = crate::down(ratio(981, 100));
            let d = Derived::new(&arm);
            let start = std::time::Instant::now();
            let id = d.inverse_dynamics_derivatives_method();
            let fd = d.forward_dynamics_derivatives_method();
            let took = start.elapsed();
            let show = |m: &Option<Method>| {
                m.as_ref().map_or("none".into(), |m| {
                    format!("{} ({})", m.op_count(), &m.evaluation[..60])
                })
            };
            println!("N = {n} ({took:?})");
            println!("  tau {}", d.inverse_dynamics_method().op_count());
            println!("  dtau {}", show(&id));
            println!("  qdd {}", d.forward_dynamics_method().op_count());
            println!("  dqdd {}", show(&fd));
        }
    }
}
