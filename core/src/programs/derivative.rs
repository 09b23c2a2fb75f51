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

use num_traits::One;

use crate::ring::Rational;
use crate::slp::{Id, Input, Node, Program};
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
pub(crate) mod tests {
    use super::*;

    /// Central differences of the program interpreter along one input.
    pub(crate) fn central(p: &Program, out: Id, at: &dyn Fn(Input) -> f64, dir: Input) -> f64 {
        let h = 1e-6;
        let shifted = |delta: f64| {
            let f = |i: Input| at(i) + if i == dir { delta } else { 0.0 };
            p.eval(&f)[out.0 as usize]
        };
        (shifted(h) - shifted(-h)) / (2.0 * h)
    }

    pub(crate) fn state(i: Input) -> f64 {
        match i {
            Input::Q(j) => 0.3 + 0.7 * j as f64,
            Input::Qd(j) => -0.4 + 0.5 * j as f64,
            Input::Qdd(j) => 1.1 - 0.9 * j as f64,
            _ => 0.0,
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
}
