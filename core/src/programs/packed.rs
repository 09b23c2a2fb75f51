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
    /// `a * s + c` for the lanes `a` and `c` and the scalar value `s`, rounded once: a fused
    /// multiply-add, which [`pack`] makes of a sum that reads a product read nowhere else.
    MulAdd(usize, usize, usize),
    /// `c - a * s`, rounded once.
    NegMulAdd(usize, usize, usize),
    /// `a * s - c`, rounded once.
    MulSub(usize, usize, usize),
    /// The seed of a reverse-mode program ([`adjoint`](crate::adjoint)) for its
    /// output `k` and lane group `g`: lane `l` is `-W(width g + l, k)`, `W` a matrix read at
    /// run time (emitted as zero past its last row; a lane past the rows is read by no
    /// derivative).
    Seed(usize, usize),
}

impl Lane {
    /// The lane operations this one reads.
    fn operands(self) -> [Option<usize>; 2] {
        match self {
            Lane::Const(_) | Lane::Seed(..) => [None, None],
            Lane::Neg(a) | Lane::Scale(a, _) => [Some(a), None],
            Lane::Add(a, b)
            | Lane::Sub(a, b)
            | Lane::MulAdd(a, _, b)
            | Lane::NegMulAdd(a, _, b)
            | Lane::MulSub(a, _, b) => [Some(a), Some(b)],
        }
    }
}

/// The derivatives of some outputs along some directions, four directions per lane group.
#[derive(Clone, Debug)]
pub struct Packed {
    /// The program's values: the original program, with the scalars the lanes read as its
    /// outputs (named `v0`, `v1`, ...).
    pub values: Method,
    /// The lane operations, operands before their readers.
    pub ops: Vec<Lane>,
    /// Lanes per operation: four (`Lanes` in the run-time crate), or for a reverse-mode program
    /// the width it was built with (the emitted ones eight, `Lanes::Wide`), which has no
    /// [`Lane::Const`].
    pub width: usize,
    /// Per derivative (output-major, then direction): the operation and lane holding it, or
    /// `None` where it is structurally zero.
    pub derivatives: Vec<Option<(usize, usize)>>,
}

impl Packed {
    /// Whether each operation is read by some derivative, directly or through others.
    #[must_use]
    pub fn live(&self) -> Vec<bool> {
        live(
            &self.ops,
            self.derivatives.iter().flatten().map(|&(op, _)| op),
        )
    }

    /// The derivatives evaluated by an interpreter of the lanes (zero where structurally zero),
    /// given the inputs as [`Program::eval`] takes them.
    #[must_use]
    pub fn eval(&self, input: &dyn Fn(Input) -> f64) -> Vec<f64> {
        self.eval_seeded(input, &|_, _| 0.0)
    }

    /// [`eval`](Self::eval) with the seeds of a reverse-mode program: `w(row, k)` is `W(row,
    /// k)` of [`Lane::Seed`].
    #[must_use]
    pub fn eval_seeded(
        &self,
        input: &dyn Fn(Input) -> f64,
        w: &dyn Fn(usize, usize) -> f64,
    ) -> Vec<f64> {
        let scalars = self.values.eval(input);
        let width = self.width;
        let mut lanes: Vec<Vec<f64>> = Vec::with_capacity(self.ops.len());
        for op in &self.ops {
            let lane = |f: &dyn Fn(usize) -> f64| -> Vec<f64> { (0..width).map(f).collect() };
            let v = match *op {
                Lane::Const(c) => lane(&|l| f64::from(c[l])),
                Lane::Seed(k, g) => lane(&|l| -w(width * g + l, k)),
                Lane::Add(a, b) => lane(&|l| lanes[a][l] + lanes[b][l]),
                Lane::Sub(a, b) => lane(&|l| lanes[a][l] - lanes[b][l]),
                Lane::Neg(a) => lane(&|l| -lanes[a][l]),
                Lane::Scale(a, s) => lane(&|l| lanes[a][l] * scalars[s]),
                Lane::MulAdd(a, s, c) => lane(&|l| lanes[a][l].mul_add(scalars[s], lanes[c][l])),
                Lane::NegMulAdd(a, s, c) => {
                    lane(&|l| (-lanes[a][l]).mul_add(scalars[s], lanes[c][l]))
                }
                Lane::MulSub(a, s, c) => lane(&|l| lanes[a][l].mul_add(scalars[s], -lanes[c][l])),
            };
            lanes.push(v);
        }
        self.derivatives
            .iter()
            .map(|d| d.map_or(0.0, |(op, l)| lanes[op][l]))
            .collect()
    }

    /// The four-lane additions, subtractions, negations, products and fused multiply-adds the
    /// derivatives cost.
    #[must_use]
    pub fn lane_op_count(&self) -> usize {
        self.ops
            .iter()
            .zip(self.live())
            .filter(|(op, live)| *live && !matches!(op, Lane::Const(_) | Lane::Seed(..)))
            .count()
    }

    /// How many of [`lane_op_count`](Self::lane_op_count)'s operations are fused
    /// multiply-adds.
    #[must_use]
    pub fn fused_count(&self) -> usize {
        self.ops
            .iter()
            .zip(self.live())
            .filter(|(op, live)| {
                *live
                    && matches!(
                        op,
                        Lane::MulAdd(..) | Lane::NegMulAdd(..) | Lane::MulSub(..)
                    )
            })
            .count()
    }
}

/// Whether each of `ops` is among `read` or read by a live operation.
fn live(ops: &[Lane], read: impl Iterator<Item = usize>) -> Vec<bool> {
    let mut live = vec![false; ops.len()];
    for op in read {
        live[op] = true;
    }
    for k in (0..ops.len()).rev() {
        if live[k] {
            for x in ops[k].operands().into_iter().flatten() {
                live[x] = true;
            }
        }
    }
    live
}

/// Fuses each sum or difference that reads a product of lanes and a scalar, read nowhere else,
/// into one multiply-add, in place: `x + a s`, `x - a s` and `a s - x`. The product rule makes
/// most of a derivative program such sums (`da b + a db`), and the processors that have AVX2
/// have FMA, whose one instruction replaces two and rounds once; the product is left dead. A
/// product with other readers stays: fused there too, its operands lived longer, and the
/// Panda's inverse derivatives spilled more and measured slower than with this rule
/// (docs/performance.md, "Seventh session").
fn fuse(ops: &mut [Lane], outputs: &[usize]) {
    let live = live(ops, outputs.iter().copied());
    let mut readers = vec![0usize; ops.len()];
    for &o in outputs {
        readers[o] += 1;
    }
    for op in ops.iter().zip(&live).filter(|(_, &l)| l).map(|(op, _)| op) {
        for x in op.operands().into_iter().flatten() {
            readers[x] += 1;
        }
    }
    for k in 0..ops.len() {
        let product = |x: usize| match ops[x] {
            Lane::Scale(a, s) if readers[x] == 1 => Some((a, s)),
            _ => None,
        };
        let fused = match ops[k] {
            Lane::Add(x, y) => match (product(x), product(y)) {
                (_, Some((a, s))) => Some(Lane::MulAdd(a, s, x)),
                (Some((a, s)), None) => Some(Lane::MulAdd(a, s, y)),
                (None, None) => None,
            },
            Lane::Sub(x, y) => match (product(x), product(y)) {
                (_, Some((a, s))) => Some(Lane::NegMulAdd(a, s, x)),
                (Some((a, s)), None) => Some(Lane::MulSub(a, s, y)),
                (None, None) => None,
            },
            _ => None,
        };
        if let Some(f) = fused {
            ops[k] = f;
        }
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
pub(crate) struct Builder {
    pub(crate) ops: Vec<Lane>,
    memo: BTreeMap<Lane, usize>,
    /// Scalar nodes read by the lanes, in first-read order, and their index.
    pub(crate) scalars: Vec<Id>,
    scalar_index: BTreeMap<Id, usize>,
}

impl Builder {
    pub(crate) fn new() -> Self {
        Self {
            ops: Vec::new(),
            memo: BTreeMap::new(),
            scalars: Vec::new(),
            scalar_index: BTreeMap::new(),
        }
    }

    pub(crate) fn op(&mut self, lane: Lane) -> usize {
        if let Some(&k) = self.memo.get(&lane) {
            return k;
        }
        self.ops.push(lane);
        self.memo.insert(lane, self.ops.len() - 1);
        self.ops.len() - 1
    }

    /// The index of the scalar node `s` among those the lanes read.
    pub(crate) fn scalar(&mut self, s: Id) -> usize {
        let next = self.scalars.len();
        let k = *self.scalar_index.entry(s).or_insert(next);
        if k == next {
            self.scalars.push(s);
        }
        k
    }

    fn scale(&mut self, v: usize, s: Id) -> usize {
        let k = self.scalar(s);
        self.op(Lane::Scale(v, k))
    }

    /// The scalars as the values' outputs `v0`, `v1`, ... of `p`.
    pub(crate) fn values(&self, p: Program) -> Method {
        Method::new(
            p,
            self.scalars
                .iter()
                .enumerate()
                .map(|(k, id)| (format!("v{k}"), *id))
                .collect(),
        )
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
    let mut b = Builder::new();
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
    let values = b.values(p.clone());
    let mut ops = b.ops;
    let read: Vec<usize> = derivatives.iter().flatten().map(|&(op, _)| op).collect();
    fuse(&mut ops, &read);
    Some(Packed {
        values,
        ops,
        width: 4,
        derivatives,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::derivative::differentiate;
    use crate::derivative::tests::state;

    /// Sums and differences of products in every arrangement `fuse` rewrites (`x + a s`,
    /// `a s + x`, `x - a s`, `a s - x`, and a product read twice, which stays), with the
    /// tangents of trigonometric atoms: the packed derivatives, fused, equal `differentiate`'s
    /// one direction at a time.
    #[test]
    fn fused_lanes_agree_with_one_direction_at_a_time() {
        let mut p = Program::new();
        let q: Vec<Id> = (0..3).map(|j| p.input(Input::Q(j))).collect();
        let qd: Vec<Id> = (0..3).map(|j| p.input(Input::Qd(j))).collect();
        let (c1, s1) = p.trig_pair(&Angle::new(vec![1]));
        // Each joint's own pair is an atom, as in the arms' programs.
        p.trig_pair(&Angle::new(vec![0, 1]));
        let (c12, s12) = p.trig_pair(&Angle::new(vec![1, 1]));
        let a = p.mul(c1, qd[0]);
        let b = p.mul(s12, qd[1]);
        let ab = p.add(a, b);
        let c = p.mul(ab, q[2]);
        let d = p.sub(c, s1);
        let e = p.mul(c12, qd[2]);
        let f = p.sub(e, d);
        let g = p.mul(f, ab);
        let shared = p.mul(q[1], qd[2]);
        let h = p.add(g, shared);
        let k = p.sub(shared, c);
        // A product whose tangent is read once, beside a value whose tangent is no product,
        // in each order.
        let once: Vec<Id> = (0..4)
            .map(|j| {
                let held = p.input(Input::Tau(j));
                p.mul(s12, held)
            })
            .collect();
        let later = p.sub(q[2], qd[0]);
        let m = p.add(once[0], later);
        let n = p.add(q[1], once[1]);
        let r = p.sub(once[2], q[1]);
        let t = p.sub(q[0], once[3]);
        let outputs = [ab, d, f, g, h, k, m, n, r, t];
        let directions: Vec<Input> = (0..3).map(Input::Q).chain((0..3).map(Input::Qd)).collect();
        let pk = pack(&p, &outputs, &directions).expect("no quotient");
        assert!(pk.fused_count() > 0, "nothing fused");
        assert!(pk.fused_count() < pk.lane_op_count());
        #[allow(clippy::cast_precision_loss)]
        let at = |i: Input| match i {
            Input::Tau(j) => 0.8 + 0.3 * j as f64,
            _ => state(i),
        };
        let packed = pk.eval(&at);
        let mut reference = p.clone();
        let tangents = differentiate(&mut reference, &outputs, &directions).unwrap();
        let values = reference.eval(&at);
        for (o, row) in tangents.iter().enumerate() {
            for (dir, id) in row.iter().enumerate() {
                let (x, y) = (packed[o * directions.len() + dir], values[id.0 as usize]);
                assert!(
                    (x - y).abs() <= 1e-14 * (1.0 + y.abs()),
                    "{o} {dir}: {x} {y}"
                );
            }
        }
    }
}
