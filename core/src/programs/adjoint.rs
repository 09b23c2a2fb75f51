//! Reverse-mode derivatives, several weighted rows at a time: `-W J` for `J = d outputs / d x`
//! and a matrix `W` known only at run time, one lane per row of `W`.
//!
//! The forward dynamics' derivatives are `-M^-1 dtau/dx` at the accelerations `M^-1` gives.
//! Forward mode ([`packed`](crate::programs::packed)) takes `dtau/dx` along all `2n` angles and
//! rates (four lane groups for seven joints) and then multiplies by `M^-1` (`2 n^3` more
//! products, and the derivatives moved out of their lanes into the matrices). Run backward from
//! the torques weighted by the rows of `-M^-1`, the chain rule gives each row of the product
//! directly, the adjoint of a product `a b` being `a' b` and `a b'` as in forward mode. For the
//! Panda's Newton-Euler program that is 1,508 four-lane operations in two groups against the
//! forward program's 2,188 and the product after it, and with eight lanes per group (one
//! AVX-512 register, `Lanes::Wide` in the run-time crate) one group of 754 (docs/performance.md,
//! "Eighth session").

use std::collections::BTreeMap;

use crate::programs::packed::{Builder, Lane, Packed};
use crate::slp::{Id, Input, Node, Program};

/// One term of an adjoint: a lane group, or a lane group times a scalar node, either negated.
#[derive(Clone, Copy)]
enum Term {
    Lane(usize, bool),
    Scaled(usize, Id, bool),
}

/// `acc + term`, fused where the term is a product: each adjoint is summed as its readers
/// are visited, so that one partial sum per value is live rather than every term.
fn accumulate(b: &mut Builder, p: &mut Program, acc: Option<usize>, term: Term) -> usize {
    match (acc, term) {
        (None, Term::Lane(a, false)) => a,
        (None, Term::Lane(a, true)) => b.op(Lane::Neg(a)),
        (None, Term::Scaled(a, s, negated)) => {
            let s = if negated { p.neg(s) } else { s };
            let k = b.scalar(s);
            b.op(Lane::Scale(a, k))
        }
        (Some(c), Term::Lane(a, false)) => b.op(Lane::Add(c, a)),
        (Some(c), Term::Lane(a, true)) => b.op(Lane::Sub(c, a)),
        (Some(c), Term::Scaled(a, s, false)) => {
            let k = b.scalar(s);
            b.op(Lane::MulAdd(a, k, c))
        }
        (Some(c), Term::Scaled(a, s, true)) => {
            let k = b.scalar(s);
            b.op(Lane::NegMulAdd(a, k, c))
        }
    }
}

/// `-W d outputs / d wrt` for a `rows x outputs.len()` matrix `W` read at run time
/// ([`Lane::Seed`]), `width` rows per lane group, row-major (`rows`, then `wrt`); `None` if the
/// program has an operation this does not differentiate (a quotient, a `max`) on the way from
/// `wrt` to `outputs`.
#[must_use]
pub fn adjoint(
    p: &Program,
    outputs: &[Id],
    rows: usize,
    wrt: &[Input],
    width: usize,
) -> Option<Packed> {
    let nodes = p.nodes();
    let uses = p.use_counts(outputs);
    let mut atoms: BTreeMap<Id, (crate::trig::Angle, bool)> = BTreeMap::new();
    for (angle, (c, s)) in p.trig_atoms() {
        atoms.entry(c).or_insert((angle.clone(), true));
        atoms.entry(s).or_insert((angle.clone(), false));
    }
    let pairs: BTreeMap<crate::trig::Angle, (Id, Id)> =
        p.trig_atoms().map(|(a, ids)| (a.clone(), ids)).collect();
    let angle_of = |j: usize| wrt.contains(&Input::Q(j));
    // Whether each node depends on `wrt`: the others have no adjoint to pass on.
    let mut depends = vec![false; nodes.len()];
    for (i, node) in nodes.iter().enumerate() {
        let id = Id(u32::try_from(i).ok()?);
        depends[i] = if let Some((angle, _)) = atoms.get(&id) {
            angle
                .coefficients()
                .iter()
                .enumerate()
                .any(|(j, &c)| c != 0 && angle_of(j))
        } else {
            match node {
                Node::Input(x) => wrt.contains(x),
                Node::Add(x, y)
                | Node::Sub(x, y)
                | Node::Mul(x, y)
                | Node::Div(x, y)
                | Node::Max(x, y) => depends[x.0 as usize] || depends[y.0 as usize],
                Node::Neg(x) => depends[x.0 as usize],
                Node::Sin(j) | Node::Cos(j) => angle_of(*j),
                Node::Const(_) | Node::Sign(_) => false,
            }
        };
    }
    let mut values = p.clone();
    let mut b = Builder::new();
    let groups = rows.div_ceil(width);
    // acc[g][node], by_input[g][x]: the adjoint of a node, of `wrt[x]`, in group g.
    let mut acc: Vec<Vec<Option<usize>>> = vec![vec![None; nodes.len()]; groups];
    let mut by_input = vec![vec![None; wrt.len()]; groups];
    for (g, acc) in acc.iter_mut().enumerate() {
        for (k, o) in outputs.iter().enumerate() {
            if depends[o.0 as usize] {
                let seed = b.op(Lane::Seed(k, g));
                acc[o.0 as usize] = Some(accumulate(
                    &mut b,
                    &mut values,
                    acc[o.0 as usize],
                    Term::Lane(seed, false),
                ));
            }
        }
    }
    // Node by node, each group in turn: the groups read the same scalars one after the other.
    for i in (0..nodes.len()).rev() {
        if uses[i] == 0 || !depends[i] {
            continue;
        }
        let id = Id(u32::try_from(i).ok()?);
        for (acc, by_input) in acc.iter_mut().zip(by_input.iter_mut()) {
            let Some(a) = acc[i] else {
                continue;
            };
            let mut pass = |b: &mut Builder, values: &mut Program, x: &Id, term: Term| {
                if depends[x.0 as usize] {
                    acc[x.0 as usize] = Some(accumulate(b, values, acc[x.0 as usize], term));
                }
            };
            if let Some((angle, is_cos)) = atoms.get(&id) {
                // d cos(a) = -k sin(a) dq_j, d sin(a) = k cos(a) dq_j, k the angle's
                // coefficient of q_j.
                let (c, s) = pairs[angle];
                for (j, &k) in angle.coefficients().iter().enumerate() {
                    let Some(x) = wrt
                        .iter()
                        .position(|w| *w == Input::Q(j))
                        .filter(|_| k != 0)
                    else {
                        continue;
                    };
                    let other = if *is_cos { s } else { c };
                    let scalar = if k.abs() == 1 {
                        other
                    } else {
                        let m = values.constant(crate::algebra::ring::int(i64::from(k.abs())));
                        values.mul(m, other)
                    };
                    let negated = *is_cos == (k > 0);
                    by_input[x] = Some(accumulate(
                        &mut b,
                        &mut values,
                        by_input[x],
                        Term::Scaled(a, scalar, negated),
                    ));
                }
                continue;
            }
            match &nodes[i] {
                Node::Input(input) => {
                    if let Some(x) = wrt.iter().position(|w| w == input) {
                        by_input[x] = Some(accumulate(
                            &mut b,
                            &mut values,
                            by_input[x],
                            Term::Lane(a, false),
                        ));
                    }
                }
                Node::Add(x, y) => {
                    pass(&mut b, &mut values, x, Term::Lane(a, false));
                    pass(&mut b, &mut values, y, Term::Lane(a, false));
                }
                Node::Sub(x, y) => {
                    pass(&mut b, &mut values, x, Term::Lane(a, false));
                    pass(&mut b, &mut values, y, Term::Lane(a, true));
                }
                Node::Neg(x) => pass(&mut b, &mut values, x, Term::Lane(a, true)),
                Node::Mul(x, y) => {
                    pass(&mut b, &mut values, x, Term::Scaled(a, *y, false));
                    pass(&mut b, &mut values, y, Term::Scaled(a, *x, false));
                }
                Node::Const(_) | Node::Sign(_) => {}
                Node::Sin(_) | Node::Cos(_) | Node::Div(..) | Node::Max(..) => return None,
            }
        }
    }
    let mut derivatives = Vec::with_capacity(rows * wrt.len());
    for row in 0..rows {
        derivatives.extend(
            by_input[row / width]
                .iter()
                .map(|d| d.map(|op| (op, row % width))),
        );
    }
    Some(Packed {
        values: b.values(values),
        ops: b.ops,
        width,
        derivatives,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::derivative::differentiate;
    use crate::derivative::tests::state;
    use crate::trig::Angle;

    /// Sums, differences, negations and products of angles, rates and held inputs, with trig
    /// atoms of one joint, of a sum of angles with a coefficient of two and of a difference,
    /// outputs that share values and one listed twice: five weighted rows (in groups of four
    /// and of eight) of the adjoint equal `-W` times `differentiate`'s derivatives, one
    /// direction at a time.
    #[test]
    fn weighted_rows_equal_the_product_with_forward_derivatives() {
        let mut p = Program::new();
        let q: Vec<Id> = (0..3).map(|j| p.input(Input::Q(j))).collect();
        let qd: Vec<Id> = (0..3).map(|j| p.input(Input::Qd(j))).collect();
        let held = p.input(Input::Qdd(0));
        let (c1, s1) = p.trig_pair(&Angle::new(vec![0, 1]));
        let (c02, s02) = p.trig_pair(&Angle::new(vec![1, 0, 2]));
        let a = p.mul(c1, qd[0]);
        let b = p.mul(s02, qd[1]);
        let ab = p.add(a, b);
        let c = p.mul(ab, q[2]);
        let d = p.sub(c, s1);
        let e = p.mul(c02, held);
        let f = p.sub(e, d);
        let g = p.mul(f, ab);
        let sq = p.mul(qd[2], qd[2]);
        let h = p.neg(g);
        let k = p.add(h, sq);
        let m = p.mul(held, q[0]);
        // A negative coefficient (q1 - q2), and an output listed twice.
        let (c1m2, s1m2) = p.trig_pair(&Angle::new(vec![1, -1]));
        let u = p.mul(s1m2, qd[2]);
        let v = p.sub(u, c1m2);
        let outputs = [k, d, m, ab, f, v, d];
        let wrt: Vec<Input> = (0..3).map(Input::Q).chain((0..3).map(Input::Qd)).collect();
        let rows = 5;
        #[allow(clippy::cast_precision_loss)]
        let w = |r: usize, k: usize| ((r * 5 + k) as f64 * 0.61 + 0.2).sin();
        let at = |i: Input| match i {
            Input::Qdd(_) => 0.7,
            _ => state(i),
        };
        for width in [4, 8] {
            let pk = adjoint(&p, &outputs, rows, &wrt, width).expect("no quotient");
            assert!(pk.fused_count() > 0, "nothing fused");
            let got = pk.eval_seeded(&at, &w);
            let mut reference = p.clone();
            let tangents = differentiate(&mut reference, &outputs, &wrt).unwrap();
            let values = reference.eval(&at);
            for r in 0..rows {
                for (x, _) in wrt.iter().enumerate() {
                    let want: f64 = -(0..outputs.len())
                        .map(|o| w(r, o) * values[tangents[o][x].0 as usize])
                        .sum::<f64>();
                    let y = got[r * wrt.len() + x];
                    assert!(
                        (y - want).abs() <= 1e-14 * (1.0 + want.abs()),
                        "width {width}, row {r}, {:?}: {y} against {want}",
                        wrt[x]
                    );
                }
            }
        }
    }

    /// A quotient on the way from an angle to an output is refused.
    #[test]
    fn a_quotient_is_refused() {
        let mut p = Program::new();
        let q = p.input(Input::Q(0));
        let qd = p.input(Input::Qd(0));
        let r = p.div(qd, q);
        assert!(adjoint(&p, &[r], 1, &[Input::Q(0)], 8).is_none());
    }
}
