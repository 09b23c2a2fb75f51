//! Forward-mode differentiation of straight-line programs at compile time.
//!
//! [`differentiate`] appends to a [`Program`] the nodes that compute the partial derivatives of
//! some of its nodes along given inputs (a joint angle or rate), node by node in program order:
//! the chain rule applied once per operation, as a dual-number evaluation would at run time,
//! but done here on the program so that the result is itself a straight-line program.
//! Derivatives that are structurally zero never become nodes, constants fold, and hash-consing
//! shares every derivative subexpression with the values and with the other directions, so
//! `d tau / d q` of an unrolled recursion or of the expanded formulas costs a small multiple
//! of `tau` instead of the `2 N` evaluations of a run-time jet.
//!
//! The trigonometric atoms built by [`Program::trig_pair`] are differentiated as what they
//! are, `d/dq_j cos(a) = -k_j sin(a)` for an angle `a = sum k_i q_i`, not through the
//! angle-addition products they are made of, so the derivative of `c23` reuses `s23`.

use std::collections::BTreeMap;

use num_traits::{One, Zero};

use crate::expr::Var;
use crate::methods::{cheapest, Derived, Method};
use crate::programs::unrolled::{ldlt_solve, pivot_floor};
use crate::ring::Rational;
use crate::slp::{Emit, Id, Input, Node, Program};
use crate::trig::Angle;

/// The largest derivative program, in operations, that is emitted as code. Above it the
/// derive emits nothing and the trait's default (the generated inverse dynamics evaluated in
/// run-time jets) applies: a user's build would spend more compiling the method than the
/// method saves at run time. Measured in docs/performance.md.
pub const MAX_OPS: usize = 4000;

/// The largest forward dynamics' derivative program, in operations, that is emitted as code
/// (every arm of up to five links). Larger ones take the trait's default, the emitted inverse
/// dynamics' derivatives at `qdd` and a fixed-size Cholesky inverse of M, which costs 1.4x the
/// emitted program at four and six links (2.1x at two). At six links the emitted program was a
/// fifth of the type checking of a crate that derives the arm (53 KB of its 300 KB), for a
/// method few callers need in every build. Measured in docs/performance.md.
pub const MAX_FORWARD_OPS: usize = 2000;

/// Arms of more links are not differentiated at all: their programs would exceed [`MAX_OPS`]
/// (about 2,500 operations for the inverse dynamics' derivatives at 10 links, growing as
/// `N^2`), and trying would cost the derive time for nothing.
pub const MAX_LINKS: usize = 10;

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

/// Why a program could not be differentiated.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum NotDifferentiable {
    /// The program takes a `max` (a pivot floor), which has no derivative where the two sides
    /// are equal and whose branch the program cannot express.
    Max,
}

/// The derivative of one node along one direction: `None` where it is structurally zero.
type Tangent = Option<Id>;

/// `d output / d direction` for each output (rows) and direction (columns), each a node
/// appended to `p` (a zero constant where the derivative is structurally zero).
///
/// Directions are [`Input::Q`] and [`Input::Qd`] (and [`Input::Qdd`], [`Input::Tau`]): an input
/// node has derivative one along itself and zero along the others; `sin q_j` and `cos q_j`
/// depend on `Q(j)` only. The sign of a value (Coulomb friction) has derivative zero: the
/// derivative away from its jump at zero, also taken at the jump.
///
/// # Errors
///
/// [`NotDifferentiable::Max`] if an output depends on a `max` node.
pub fn differentiate(
    p: &mut Program,
    outputs: &[Id],
    directions: &[Input],
) -> Result<Vec<Vec<Id>>, NotDifferentiable> {
    let original = p.nodes().len();
    let uses = p.use_counts(outputs);
    // The trig atoms by node, to differentiate `cos a` as `-k sin a`.
    let mut atoms: BTreeMap<Id, (Angle, bool)> = BTreeMap::new();
    for (angle, (c, s)) in p.trig_atoms() {
        atoms.entry(c).or_insert((angle.clone(), true));
        atoms.entry(s).or_insert((angle.clone(), false));
    }
    let d = directions.len();
    let mut tangents: Vec<Tangent> = vec![None; original * d];
    for i in 0..original {
        if uses[i] == 0 {
            continue;
        }
        let id = Id(u32::try_from(i).expect("program exceeds u32 nodes"));
        if let Some((angle, is_cos)) = atoms.get(&id).cloned() {
            let (c, s) = p.trig_pair(&angle);
            for (k, dir) in directions.iter().enumerate() {
                let Input::Q(j) = *dir else { continue };
                let coefficient = angle.coefficient(j);
                if coefficient == 0 {
                    continue;
                }
                // d cos(a) = -k sin(a), d sin(a) = k cos(a)
                let (value, factor) = if is_cos {
                    (s, -coefficient)
                } else {
                    (c, coefficient)
                };
                let factor = p.constant(Rational::from_integer(factor.into()));
                tangents[i * d + k] = Some(p.mul(factor, value));
            }
            continue;
        }
        let node = p.node(id).clone();
        for (k, dir) in directions.iter().enumerate() {
            let t = |x: Id| tangents[x.0 as usize * d + k];
            let tangent = match node {
                Node::Input(input) => (input == *dir).then(|| p.constant(Rational::one())),
                Node::Const(_) | Node::Sign(_) => None,
                Node::Sin(j) => (*dir == Input::Q(j)).then(|| p.intern(Node::Cos(j))),
                Node::Cos(j) => (*dir == Input::Q(j)).then(|| {
                    let s = p.intern(Node::Sin(j));
                    p.neg(s)
                }),
                Node::Add(a, b) => match (t(a), t(b)) {
                    (Some(x), Some(y)) => Some(p.add(x, y)),
                    (x, y) => x.or(y),
                },
                Node::Sub(a, b) => match (t(a), t(b)) {
                    (Some(x), Some(y)) => Some(p.sub(x, y)),
                    (Some(x), None) => Some(x),
                    (None, Some(y)) => Some(p.neg(y)),
                    (None, None) => None,
                },
                Node::Neg(a) => t(a).map(|x| p.neg(x)),
                Node::Mul(a, b) => match (t(a), t(b)) {
                    (Some(x), Some(y)) => {
                        let xb = p.mul(x, b);
                        let ay = p.mul(a, y);
                        Some(p.add(xb, ay))
                    }
                    (Some(x), None) => Some(p.mul(x, b)),
                    (None, Some(y)) => Some(p.mul(a, y)),
                    (None, None) => None,
                },
                // d(a / b) = (da - (a / b) db) / b, reusing the quotient itself.
                Node::Div(a, b) => match (t(a), t(b)) {
                    (x, Some(y)) => {
                        let qy = p.mul(id, y);
                        let num = match x {
                            Some(x) => p.sub(x, qy),
                            None => p.neg(qy),
                        };
                        Some(p.div(num, b))
                    }
                    (Some(x), None) => Some(p.div(x, b)),
                    (None, None) => None,
                },
                Node::Max(a, b) => {
                    if t(a).is_some() || t(b).is_some() {
                        return Err(NotDifferentiable::Max);
                    }
                    None
                }
            };
            tangents[i * d + k] = tangent;
        }
    }
    let zero = p.constant(Rational::from_integer(0.into()));
    Ok(outputs
        .iter()
        .map(|o| {
            (0..d)
                .map(|k| tangents[o.0 as usize * d + k].unwrap_or(zero))
                .collect()
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanics::ArmSpec;
    use crate::methods::Derived;
    use crate::ring::ratio;

    /// Central differences of the program interpreter along one input.
    fn central(p: &Program, out: Id, at: &dyn Fn(Input) -> f64, dir: Input) -> f64 {
        let h = 1e-6;
        let shifted = |delta: f64| {
            let f = |i: Input| at(i) + if i == dir { delta } else { 0.0 };
            p.eval(&f)[out.0 as usize]
        };
        (shifted(h) - shifted(-h)) / (2.0 * h)
    }

    fn state(i: Input) -> f64 {
        match i {
            Input::Q(j) => 0.3 + 0.7 * j as f64,
            Input::Qd(j) => -0.4 + 0.5 * j as f64,
            Input::Qdd(j) => 1.1 - 0.9 * j as f64,
            _ => 0.0,
        }
    }

    #[test]
    fn matches_central_differences_of_both_programs() {
        for n in 1..=4 {
            let mut arm = ArmSpec::paper(n);
            arm.gravity = ratio(981, 100);
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
            arm.gravity = ratio(981, 100);
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
    fn quotient_rule_and_refusal_of_max() {
        let mut p = Program::new();
        let (x, y) = (p.input(Input::Q(0)), p.input(Input::Qd(0)));
        let s = p.intern(Node::Sin(0));
        let xs = p.mul(x, s);
        let quotient = p.div(xs, y);
        let d = differentiate(&mut p, &[quotient], &[Input::Q(0), Input::Qd(0)]).unwrap();
        let v = p.eval(&state);
        let (q, qd) = (state(Input::Q(0)), state(Input::Qd(0)));
        let dq = (q.sin() + q * q.cos()) / qd;
        let dqd = -q * q.sin() / (qd * qd);
        assert!((v[d[0][0].0 as usize] - dq).abs() < 1e-14);
        assert!((v[d[0][1].0 as usize] - dqd).abs() < 1e-14);
        let m = p.max(x, y);
        assert_eq!(
            differentiate(&mut p, &[m], &[Input::Q(0)]),
            Err(NotDifferentiable::Max)
        );
    }

    #[test]
    #[ignore = "prints a table"]
    fn print_parameterised_op_counts() {
        for n in [4, 6, 8, 9, 10] {
            let mut arm = ArmSpec::paper(n);
            arm.gravity = ratio(981, 100);
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
            arm.gravity = ratio(981, 100);
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
