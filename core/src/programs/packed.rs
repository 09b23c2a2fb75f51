//! Forward-mode derivatives four directions at a time: the tangents of a program along four
//! inputs held in one four-lane value, so that one vector operation does the work of four
//! scalar ones.
//!
//! [`differentiate`](crate::derivative::differentiate) appends one scalar node per direction
//! and operation. Its programs are long (the PUMA 560's `d tau / d(q, qd)` 3,583 operations,
//! the Panda's 8,303), and compiled they outgrow the processor's instruction cache, where the
//! time goes in fetching and reloading rather than arithmetic (docs/performance.md). Here the
//! same chain rule runs on lanes: the value of each node is computed once as a scalar, and its
//! tangent along a group of four directions is one four-lane value, `d(a b) = da * b + a * db`
//! with the scalars broadcast. A lane whose tangent is structurally zero costs nothing extra
//! but is not skipped: the grouping puts together directions whose tangents start at the same
//! link, so that few lanes are idle.

use std::collections::BTreeMap;

use crate::programs::method::Method;
use crate::slp::{Id, Input, Node, Program};
use crate::trig::Angle;

/// A four-lane operation; operands are earlier operations (by index) or scalar values (by
/// index into the values' outputs).
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
pub enum Lane {
    /// The constant `[k0, k1, k2, k3]`.
    Const([i32; 4]),
    /// Lane-wise sum.
    Add(usize, usize),
    /// Lane-wise difference.
    Sub(usize, usize),
    /// Lane-wise negation.
    Neg(usize),
    /// Every lane times one scalar value.
    Scale(usize, usize),
}

/// The derivatives of some outputs along some directions, four directions per lane group.
#[derive(Clone, Debug)]
pub struct Packed {
    /// The program's values: the original program, with the scalars the lanes read as its
    /// outputs (named `v0`, `v1`, ...).
    pub values: Method,
    /// The lane operations, operands before their readers.
    pub ops: Vec<Lane>,
    /// Per derivative (output-major, then direction): the operation and lane holding it, or
    /// `None` where it is structurally zero.
    pub derivatives: Vec<Option<(usize, usize)>>,
}

impl Packed {
    /// Whether each operation is read by some derivative, directly or through others.
    #[must_use]
    pub fn live(&self) -> Vec<bool> {
        let mut live = vec![false; self.ops.len()];
        for &(op, _) in self.derivatives.iter().flatten() {
            live[op] = true;
        }
        for k in (0..self.ops.len()).rev() {
            if !live[k] {
                continue;
            }
            match self.ops[k] {
                Lane::Const(_) => {}
                Lane::Add(a, b) | Lane::Sub(a, b) => {
                    live[a] = true;
                    live[b] = true;
                }
                Lane::Neg(a) | Lane::Scale(a, _) => live[a] = true,
            }
        }
        live
    }

    /// The derivatives evaluated by an interpreter of the lanes (zero where structurally zero),
    /// given the inputs as [`Program::eval`] takes them.
    #[must_use]
    pub fn eval(&self, input: &dyn Fn(Input) -> f64) -> Vec<f64> {
        let scalars = self.values.eval(input);
        let mut lanes: Vec<[f64; 4]> = Vec::with_capacity(self.ops.len());
        for op in &self.ops {
            let lane = |f: &dyn Fn(usize) -> f64| -> [f64; 4] { core::array::from_fn(f) };
            let v = match *op {
                Lane::Const(c) => c.map(f64::from),
                Lane::Add(a, b) => lane(&|l| lanes[a][l] + lanes[b][l]),
                Lane::Sub(a, b) => lane(&|l| lanes[a][l] - lanes[b][l]),
                Lane::Neg(a) => lane(&|l| -lanes[a][l]),
                Lane::Scale(a, s) => lane(&|l| lanes[a][l] * scalars[s]),
            };
            lanes.push(v);
        }
        self.derivatives
            .iter()
            .map(|d| d.map_or(0.0, |(op, l)| lanes[op][l]))
            .collect()
    }

    /// The four-lane additions, subtractions, negations and products the derivatives cost.
    #[must_use]
    pub fn lane_op_count(&self) -> usize {
        self.ops
            .iter()
            .zip(self.live())
            .filter(|(op, live)| *live && !matches!(op, Lane::Const(_)))
            .count()
    }
}

/// The directions grouped four by four: the angles and rates of the first four joints, then
/// of the rest, so that the tangents in a group start at the same link.
fn groups(directions: &[Input]) -> Vec<[Option<Input>; 4]> {
    let q: Vec<Input> = directions
        .iter()
        .copied()
        .filter(|d| matches!(d, Input::Q(_)))
        .collect();
    let others: Vec<Input> = directions
        .iter()
        .copied()
        .filter(|d| !matches!(d, Input::Q(_)))
        .collect();
    let split = |v: &[Input]| -> (Vec<Input>, Vec<Input>) {
        let k = v.len().min(4);
        (v[..k].to_vec(), v[k..].to_vec())
    };
    let (q_head, q_tail) = split(&q);
    let (o_head, o_tail) = split(&others);
    let mut order = Vec::new();
    for part in [q_head, o_head, q_tail, o_tail] {
        order.extend(part);
    }
    order
        .chunks(4)
        .map(|c| core::array::from_fn(|l| c.get(l).copied()))
        .collect()
}

/// Builds the lane operations, hash-consed.
struct Builder {
    ops: Vec<Lane>,
    memo: BTreeMap<Lane, usize>,
    /// Scalar nodes read by the lanes, in first-read order, and their index.
    scalars: Vec<Id>,
    scalar_index: BTreeMap<Id, usize>,
}

impl Builder {
    fn op(&mut self, lane: Lane) -> usize {
        if let Some(&k) = self.memo.get(&lane) {
            return k;
        }
        self.ops.push(lane);
        self.memo.insert(lane, self.ops.len() - 1);
        self.ops.len() - 1
    }

    fn scale(&mut self, v: usize, s: Id) -> usize {
        let next = self.scalars.len();
        let k = *self.scalar_index.entry(s).or_insert(next);
        if k == next {
            self.scalars.push(s);
        }
        self.op(Lane::Scale(v, k))
    }
}

/// The derivatives of `outputs` along `directions`, packed, or `None` if the program has an
/// operation this does not differentiate (a quotient, a `max`).
#[must_use]
pub fn pack(p: &Program, outputs: &[Id], directions: &[Input]) -> Option<Packed> {
    let uses = p.use_counts(outputs);
    let mut atoms: BTreeMap<Id, (Angle, bool)> = BTreeMap::new();
    for (angle, (c, s)) in p.trig_atoms() {
        atoms.entry(c).or_insert((angle.clone(), true));
        atoms.entry(s).or_insert((angle.clone(), false));
    }
    let pairs: BTreeMap<Angle, (Id, Id)> =
        p.trig_atoms().map(|(a, ids)| (a.clone(), ids)).collect();
    let groups = groups(directions);
    let mut b = Builder {
        ops: Vec::new(),
        memo: BTreeMap::new(),
        scalars: Vec::new(),
        scalar_index: BTreeMap::new(),
    };
    // tangent[g][node]: the operation holding the node's tangents along group g.
    let mut tangent: Vec<Vec<Option<usize>>> = vec![vec![None; p.nodes().len()]; groups.len()];
    for (g, lanes) in groups.iter().enumerate() {
        for (i, node) in p.nodes().iter().enumerate() {
            if uses[i] == 0 {
                continue;
            }
            let id = Id(u32::try_from(i).ok()?);
            let t = |x: &Id, tangent: &Vec<Vec<Option<usize>>>| tangent[g][x.0 as usize];
            let out = if let Some((angle, is_cos)) = atoms.get(&id) {
                // d cos(a) = -k sin(a), d sin(a) = k cos(a), with k per lane.
                let k: [i32; 4] = core::array::from_fn(|l| match lanes[l] {
                    Some(Input::Q(j)) => {
                        let c = angle.coefficient(j);
                        if *is_cos {
                            -c
                        } else {
                            c
                        }
                    }
                    _ => 0,
                });
                if k == [0; 4] {
                    None
                } else {
                    let (c, s) = pairs[angle];
                    let k = b.op(Lane::Const(k));
                    Some(b.scale(k, if *is_cos { s } else { c }))
                }
            } else {
                match node {
                    Node::Input(input) => {
                        let k: [i32; 4] =
                            core::array::from_fn(|l| i32::from(lanes[l] == Some(*input)));
                        (k != [0; 4]).then(|| b.op(Lane::Const(k)))
                    }
                    Node::Const(_) | Node::Sign(_) => None,
                    // Sines and cosines of one joint's angle are trig atoms.
                    Node::Sin(_) | Node::Cos(_) | Node::Div(..) | Node::Max(..) => return None,
                    Node::Add(x, y) => match (t(x, &tangent), t(y, &tangent)) {
                        (Some(u), Some(v)) => Some(b.op(Lane::Add(u, v))),
                        (u, v) => u.or(v),
                    },
                    Node::Sub(x, y) => match (t(x, &tangent), t(y, &tangent)) {
                        (Some(u), Some(v)) => Some(b.op(Lane::Sub(u, v))),
                        (Some(u), None) => Some(u),
                        (None, Some(v)) => Some(b.op(Lane::Neg(v))),
                        (None, None) => None,
                    },
                    Node::Neg(x) => t(x, &tangent).map(|u| b.op(Lane::Neg(u))),
                    Node::Mul(x, y) => match (t(x, &tangent), t(y, &tangent)) {
                        (Some(u), Some(v)) => {
                            let uy = b.scale(u, *y);
                            let xv = b.scale(v, *x);
                            Some(b.op(Lane::Add(uy, xv)))
                        }
                        (Some(u), None) => Some(b.scale(u, *y)),
                        (None, Some(v)) => Some(b.scale(v, *x)),
                        (None, None) => None,
                    },
                }
            };
            tangent[g][i] = out;
        }
    }
    let mut derivatives = Vec::with_capacity(outputs.len() * directions.len());
    for o in outputs {
        for d in directions {
            let (g, l) = groups
                .iter()
                .enumerate()
                .find_map(|(g, lanes)| lanes.iter().position(|x| *x == Some(*d)).map(|l| (g, l)))?;
            derivatives.push(tangent[g][o.0 as usize].map(|op| (op, l)));
        }
    }
    let values = Method::new(
        p.clone(),
        b.scalars
            .iter()
            .enumerate()
            .map(|(k, id)| (format!("v{k}"), *id))
            .collect(),
    );
    Some(Packed {
        values,
        ops: b.ops,
        derivatives,
    })
}
