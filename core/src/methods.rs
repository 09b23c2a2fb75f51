//! Which straight-line program computes each generated method.
//!
//! For every method the derive emits there may be several programs that compute the same
//! function: the expanded exact formulas term by term, or a recursion (Newton-Euler,
//! composite-rigid-body) unrolled for the arm with its constants folded in. [`Derived`] builds
//! the candidates and keeps the cheapest by an estimate of run time ([`Method`], `cost`);
//! [`emit`](crate::emit) then writes the chosen program as Rust.
//!
//! This is the engine's fourth stage, after the mechanics and the programs: one `impl Derived`
//! per family of methods (the dynamics, the Coriolis matrix, the energies, the forward
//! dynamics, the kinematics, the derivatives, the identification).

use crate::expr::Expr;
use crate::mechanics::{ArmSpec, Dynamics, Kinematics};
use crate::programs::method::two;
use crate::ring::Rational;
use crate::slp::{Emit, Id, Program};

pub use crate::programs::method::Method;

/// Everything derived for one arm, ready to emit.
///
/// `C` is the coefficient ring: [`Rational`] for an arm whose values are all literals,
/// [`Poly`](crate::poly::Poly) for one with run-time parameters.
#[derive(Clone, Debug)]
pub struct Derived<C = Rational> {
    /// The arm.
    pub arm: ArmSpec<C>,
    /// Its equations of motion.
    pub dynamics: Dynamics<C>,
    /// Its kinematics.
    pub kinematics: Kinematics<C>,
    /// The chosen programs of M, c and g, which forward dynamics reuses.
    chosen: [std::cell::OnceCell<Method>; 3],
    /// M from the expanded formulas, and the bias's unrolled recursion: candidates of more
    /// than one method, built once.
    expanded_mass_matrix: std::cell::OnceCell<Method>,
    expanded_bias: std::cell::OnceCell<Method>,
    recursive_bias: std::cell::OnceCell<Method>,
}

impl<C: Emit> Derived<C> {
    /// Derives dynamics and kinematics of the arm.
    #[must_use]
    pub fn new(arm: &ArmSpec<C>) -> Self {
        Self {
            dynamics: Dynamics::derive(arm),
            kinematics: Kinematics::derive(arm),
            arm: arm.clone(),
            chosen: Default::default(),
            expanded_mass_matrix: std::cell::OnceCell::new(),
            expanded_bias: std::cell::OnceCell::new(),
            recursive_bias: std::cell::OnceCell::new(),
        }
    }

    fn n(&self) -> usize {
        self.arm.links.len()
    }

    /// Whether expanded formulas of `terms` terms can beat `rival`. Their programs share
    /// products between rows, so their cost is below the term count, but not far below: at
    /// least 0.36 of it for arms of up to ten links (M and the torques, op counts in
    /// docs/performance.md). From four links on, formulas of more than 2.75 times the rival's
    /// cost in terms cannot win and are not built: building them dominated the derive's time
    /// for long arms, and still cost a twentieth of a 6-link arm's expansion when the bound was
    /// twice the rival's cost per link (the emitted code of 29 arms of 1 to 10 links, literal,
    /// with parameters, prismatic joints and payloads, is byte-identical under either bound).
    fn worth_expanding(&self, terms: usize, rival: &Method) -> bool {
        let n = self.n();
        n < 4 || terms * 4 <= 11 * cost(rival)
    }

    /// Terms counted by their coefficients' parts: with run-time parameters each part of a
    /// coefficient is its own product in the expanded program.
    fn terms(exprs: &[&Expr<C>]) -> usize {
        exprs
            .iter()
            .flat_map(|e| e.terms())
            .map(|(_, _, c)| c.part_count().max(1))
            .sum()
    }

    fn mass_matrix_terms(&self) -> usize {
        let m = &self.dynamics.mass_matrix;
        (0..self.n())
            .map(|i| Self::terms(&m[i][i..].iter().collect::<Vec<_>>()))
            .sum()
    }

    fn bias_terms(&self) -> usize {
        let d = &self.dynamics;
        Self::terms(&d.coriolis.iter().chain(&d.gravity).collect::<Vec<_>>())
    }
}

/// The estimated run time of a method's program, in units of one multiplication: the
/// operations (a division costs about four multiplications, a `sin_cos` call about twenty) plus
/// the longest chain of dependent operations (latency the out-of-order core cannot hide).
/// The chain is weighted one: weighted two, the expanded three-link torques beat the
/// Newton-Euler recursion on paper but measured slower (docs/performance.md).
pub(crate) fn cost(m: &Method) -> usize {
    let count = m.op_count();
    count.mul + count.add + 4 * count.div + 20 * count.sin_cos + m.depth()
}

/// The cheapest candidate by [`cost`]; the first one on a tie (candidates are listed with the
/// term-by-term form first, so that form is kept when nothing beats it).
pub(crate) fn cheapest(candidates: Vec<Method>) -> Method {
    let mut best: Option<(usize, Method)> = None;
    for m in candidates {
        let c = cost(&m);
        if best.as_ref().is_none_or(|(b, _)| c < *b) {
            best = Some((c, m));
        }
    }
    best.expect("at least one candidate").1
}

impl<C: Emit> Derived<C> {
    /// One output per entry, `name1, name2, ...` (or `name` for an energy), each evaluated
    /// term by term.
    fn vector_method(&self, name: &str, entries: &[Expr<C>]) -> Method {
        let mut p = Program::new();
        let single = matches!(name, "kinetic" | "potential");
        let outputs = entries
            .iter()
            .enumerate()
            .map(|(i, e)| {
                let label = if single {
                    name.to_string()
                } else {
                    format!("{name}{}", i + 1)
                };
                (label, p.expr(e))
            })
            .collect();
        Method::new(p, outputs)
    }
}

/// `name1, name2, ...` for the nodes of a vector.
fn vector_outputs(name: &str, ids: Vec<Id>) -> Vec<(String, Id)> {
    ids.into_iter()
        .enumerate()
        .map(|(i, id)| (format!("{name}{}", i + 1), id))
        .collect()
}

/// Row-major outputs `m11, m12, ...` of a symmetric matrix (repeated nodes below the diagonal).
fn matrix_outputs(m: &[Vec<Id>]) -> Vec<(String, Id)> {
    let mut outputs = Vec::new();
    for (i, row) in m.iter().enumerate() {
        for (j, &id) in row.iter().enumerate() {
            outputs.push((format!("m{}", two(i.min(j), i.max(j))), id));
        }
    }
    outputs
}

mod coriolis_matrix;
mod derivatives;
mod dynamics;
mod energies;
mod forward;
pub(crate) mod identification;
mod kinematics;
pub mod spatial;
#[cfg(test)]
mod tests;
