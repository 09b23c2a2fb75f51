//! What a program computes and what it costs: its interpretation, the uses of each node, its
//! longest chain of dependent operations and its operation count.

use super::program::{children, Id, Input, Node, Program};
use crate::algebra::residue::Prime;

/// The latency of a division in units of an addition's or multiplication's (about 13-15
/// cycles against 4 on current x86-64 cores).
pub const DIV_LATENCY: usize = 3;

/// Operation counts of a program (or of the part that reaches given outputs).
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
pub struct OpCount {
    /// Multiplications.
    pub mul: usize,
    /// Additions, subtractions and negations.
    pub add: usize,
    /// Divisions.
    pub div: usize,
    /// Sine-cosine pairs, one per joint angle used (the generated code evaluates them all in
    /// one call of `planar_arm::trig::sin_cos`).
    pub sin_cos: usize,
}

/// The operations of two programs evaluated one after the other at the same joint angles (a
/// method and the values or the solve it delegates to): the arithmetic adds up, the `sin_cos`
/// pairs are shared.
impl std::ops::Add for OpCount {
    type Output = Self;
    fn add(self, other: Self) -> Self {
        Self {
            mul: self.mul + other.mul,
            add: self.add + other.add,
            div: self.div + other.div,
            sin_cos: self.sin_cos.max(other.sin_cos),
        }
    }
}

impl std::fmt::Display for OpCount {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} multiplications, {} additions, {} divisions, {} sin_cos pairs",
            self.mul, self.add, self.div, self.sin_cos
        )
    }
}

impl Program {
    /// Interprets the program: the value of every node, given the inputs and joint angles.
    ///
    /// This is the reference semantics of what [`emit`](crate::emit) renders as Rust, so the
    /// programs can be tested on arms chosen at run time.
    #[must_use]
    pub fn eval(&self, input: &dyn Fn(Input) -> f64) -> Vec<f64> {
        let mut v: Vec<f64> = Vec::with_capacity(self.nodes().len());
        for node in self.nodes() {
            let x = match *node {
                Node::Input(i) => input(i),
                Node::Const(ref r) => crate::ring::to_f64(r).unwrap_or(f64::NAN),
                Node::Sin(j) => input(Input::Q(j)).sin(),
                Node::Cos(j) => input(Input::Q(j)).cos(),
                Node::Add(a, b) => v[a.0 as usize] + v[b.0 as usize],
                Node::Sub(a, b) => v[a.0 as usize] - v[b.0 as usize],
                Node::Mul(a, b) => v[a.0 as usize] * v[b.0 as usize],
                Node::Div(a, b) => v[a.0 as usize] / v[b.0 as usize],
                Node::Neg(a) => -v[a.0 as usize],
                Node::Max(a, b) => v[a.0 as usize].max(v[b.0 as usize]),
                Node::Sign(a) => sign(v[a.0 as usize]),
            };
            v.push(x);
        }
        v
    }

    /// Interprets the program modulo the prime `p`: `input` gives each input's residue,
    /// `trig` each joint's `(cos q_j, sin q_j)` (a point of the circle modulo `p`), and
    /// `opaque` a fresh residue for each node that is not a polynomial of its operands
    /// (`sign`, `max`): a column of `sign(qd_i)` is then a value of its own, independent of
    /// the others as the function is. `None` where an input has no residue or the program
    /// divides by zero.
    #[must_use]
    pub fn eval_mod(
        &self,
        p: Prime,
        input: &dyn Fn(Input) -> Option<u64>,
        trig: &dyn Fn(usize) -> (u64, u64),
        opaque: &mut dyn FnMut() -> u64,
    ) -> Option<Vec<u64>> {
        let mut v: Vec<u64> = Vec::with_capacity(self.nodes().len());
        for node in self.nodes() {
            let at = |id: Id| v[id.0 as usize];
            let x = match *node {
                Node::Input(i) => input(i)?,
                Node::Const(ref r) => p.of(r)?,
                Node::Sin(j) => trig(j).1,
                Node::Cos(j) => trig(j).0,
                Node::Add(a, b) => p.add(at(a), at(b)),
                Node::Sub(a, b) => p.sub(at(a), at(b)),
                Node::Mul(a, b) => p.mul(at(a), at(b)),
                Node::Div(a, b) => p.mul(at(a), p.inv(at(b))?),
                Node::Neg(a) => p.neg(at(a)),
                Node::Max(..) | Node::Sign(_) => opaque(),
            };
            v.push(x);
        }
        Some(v)
    }

    /// How many live nodes use each node, for the given outputs.
    #[must_use]
    pub fn use_counts(&self, outputs: &[Id]) -> Vec<usize> {
        let mut live = vec![false; self.nodes().len()];
        for o in outputs {
            live[o.0 as usize] = true;
        }
        let mut uses = vec![0; self.nodes().len()];
        for o in outputs {
            uses[o.0 as usize] += 1;
        }
        for i in (0..self.nodes().len()).rev() {
            if !live[i] {
                continue;
            }
            for c in children(&self.nodes()[i]) {
                live[c.0 as usize] = true;
                uses[c.0 as usize] += 1;
            }
        }
        uses
    }

    /// The length of the longest chain of dependent operations from the inputs and the
    /// `sin_cos` results to an output (a division counts as [`DIV_LATENCY`] operations): the
    /// latency-bound part of the run time, where [`op_count`](Self::op_count) is the
    /// throughput-bound part.
    #[must_use]
    pub fn depth(&self, outputs: &[Id]) -> usize {
        let mut depth = vec![0usize; self.nodes().len()];
        for (i, node) in self.nodes().iter().enumerate() {
            let below = children(node)
                .iter()
                .map(|c| depth[c.0 as usize])
                .max()
                .unwrap_or(0);
            depth[i] = match node {
                Node::Div(..) => below + DIV_LATENCY,
                Node::Add(..)
                | Node::Sub(..)
                | Node::Mul(..)
                | Node::Neg(..)
                | Node::Max(..)
                | Node::Sign(..) => below + 1,
                Node::Input(_) | Node::Const(_) | Node::Sin(_) | Node::Cos(_) => 0,
            };
        }
        outputs
            .iter()
            .map(|o| depth[o.0 as usize])
            .max()
            .unwrap_or(0)
    }

    /// Operation counts of the part of the program the outputs need.
    #[must_use]
    pub fn op_count(&self, outputs: &[Id]) -> OpCount {
        let uses = self.use_counts(outputs);
        let mut count = OpCount::default();
        let mut joints = std::collections::BTreeSet::new();
        for (node, &u) in self.nodes().iter().zip(&uses) {
            if u == 0 {
                continue;
            }
            match node {
                Node::Mul(..) => count.mul += 1,
                Node::Add(..) | Node::Sub(..) | Node::Neg(..) | Node::Max(..) | Node::Sign(..) => {
                    count.add += 1
                }
                Node::Div(..) => count.div += 1,
                Node::Sin(j) | Node::Cos(j) => {
                    joints.insert(*j);
                }
                Node::Input(_) | Node::Const(_) => {}
            }
        }
        count.sin_cos = joints.len();
        count
    }
}

/// The sign the generated code computes (`planar_arm::__private::sign`): 0 at zero (either
/// sign), NaN for NaN, else -1 or 1.
#[must_use]
pub fn sign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        // 0 for zero, NaN for NaN.
        x * 0.0
    }
}
