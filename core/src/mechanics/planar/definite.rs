//! Whether an arm's mass matrix is positive definite: its exact `L D L^T` pivots at one generic
//! configuration.
//!
//! `M(q)` is singular at every configuration exactly when some combination of joint rates moves
//! no mass and turns no inertia: a hinge whose link has its mass on the joint axis and no
//! inertia, with nothing after it, say. Then `det M` vanishes identically, and in particular at
//! any configuration chosen without regard to the arm. Conversely a mass matrix singular only at
//! special configurations is definite at a generic one. So the test evaluates `M` exactly at
//! one configuration whose sines and cosines are rational (Pythagorean triples) and factors it
//! exactly. Pivots that are positive but tiny beside the joint's diagonal entry (below
//! [`RELATIVE_PIVOT`]) count as singular too: forward dynamics in `f64` cannot resolve them;
//! and so do diagonal entries too small for a normal `f64` (below `f64::MIN_POSITIVE`, as a
//! link 1e-300 m long gives), which the generated code would compute as zero.
//!
//! The computation is independent of the symbolic derivation: Jacobians of each body's centre
//! of mass and angle, from the joint frames, in exact rationals.

use num_traits::{Signed, Zero};

use crate::mechanics::{ArmSpec, JointKind};
use crate::ring::{int, ratio, Rational};

/// Pivots at or below this fraction of their joint's diagonal entry count as singular: four
/// rounding errors of that entry, below which an `f64` evaluation of the pivot cannot tell it
/// from zero. Ill-conditioned but regular arms (relative pivots of 1e-14) pass.
pub const RELATIVE_PIVOT: f64 = 4.0 * f64::EPSILON;

/// `(cos, sin)` of the generic hinge angles: Pythagorean triples, no two alike.
const TRIPLES: [(i64, i64, i64); 8] = [
    (3, 4, 5),
    (5, 12, 13),
    (8, 15, 17),
    (7, 24, 25),
    (20, 21, 29),
    (12, 35, 37),
    (9, 40, 41),
    (28, 45, 53),
];

/// The generic configuration: joint `k`'s `(cos, sin)` if it is a hinge, its displacement if it
/// slides. The run-time check (`Model::check`) uses the same angles.
#[must_use]
pub fn generic_configuration(kinds: &[JointKind]) -> Vec<(Rational, Rational, Rational)> {
    kinds
        .iter()
        .enumerate()
        .map(|(k, kind)| {
            let (a, b, c) = TRIPLES[k % TRIPLES.len()];
            // Alternate signs so that the angles do not all turn one way.
            let sign = if k % 2 == 0 { 1 } else { -1 };
            match kind {
                JointKind::Revolute => (ratio(a, c), ratio(sign * b, c), int(0)),
                JointKind::Prismatic => (int(1), int(0), ratio(1 + k as i64 % 5, 7)),
            }
        })
        .collect()
}

/// A point or direction in the plane, exact.
#[derive(Clone)]
struct V(Rational, Rational);

impl V {
    fn rotate(&self, (c, s): (&Rational, &Rational)) -> V {
        V(c * &self.0 - s * &self.1, s * &self.0 + c * &self.1)
    }
    fn add(&self, o: &V) -> V {
        V(&self.0 + &o.0, &self.1 + &o.1)
    }
    fn sub(&self, o: &V) -> V {
        V(&self.0 - &o.0, &self.1 - &o.1)
    }
    fn scale(&self, k: &Rational) -> V {
        V(&self.0 * k, &self.1 * k)
    }
}

/// A rigid body of the chain: mass, inertia about its centre, centre, and the last joint that
/// moves it (0-based).
struct BodyAt {
    mass: Rational,
    inertia: Rational,
    centre: V,
    joint: usize,
}

/// The exact mass matrix at the generic configuration.
#[must_use]
pub fn generic_mass_matrix(arm: &ArmSpec<Rational>) -> Vec<Vec<Rational>> {
    let n = arm.links.len();
    let kinds: Vec<JointKind> = arm.links.iter().map(|l| l.joint).collect();
    let config = generic_configuration(&kinds);
    // Walk the chain: each joint's axis point (hinge) or direction (slide), each body's centre.
    let mut direction = (int(1), int(0));
    let mut origin = V(int(0), int(0));
    let mut previous = int(0);
    let mut axes = Vec::with_capacity(n);
    let mut bodies = Vec::with_capacity(n + 1);
    for (k, link) in arm.links.iter().enumerate() {
        let (c, s, d) = &config[k];
        // The previous link's end, then this joint's offset turns the frame.
        origin = origin.add(&V(direction.0.clone(), direction.1.clone()).scale(&previous));
        if let Some(o) = &link.offset {
            direction = (
                &o.cos * &direction.0 - &o.sin * &direction.1,
                &o.sin * &direction.0 + &o.cos * &direction.1,
            );
        }
        // A reversed joint's unit rate turns (slides) the other way: its Jacobian column
        // changes sign, which leaves M's pivots unchanged; the generic values stay as they are.
        let along = V(direction.0.clone(), direction.1.clone());
        if link.joint == JointKind::Prismatic {
            origin = origin.add(&along.scale(d));
        }
        axes.push((link.joint, origin.clone(), along));
        if link.joint == JointKind::Revolute {
            direction = (
                c * &direction.0 - s * &direction.1,
                s * &direction.0 + c * &direction.1,
            );
        }
        let turn = (&direction.0, &direction.1);
        let com = V(link.com.0.clone(), link.com.1.clone()).rotate(turn);
        bodies.push(BodyAt {
            mass: link.mass.clone(),
            inertia: link.inertia.clone(),
            centre: origin.add(&com),
            joint: k,
        });
        previous = link.length.clone();
    }
    if let (Some(p), Some(last)) = (&arm.payload, arm.links.last()) {
        let turn = (&direction.0, &direction.1);
        let offset = V(&last.length + &p.com.0, p.com.1.clone()).rotate(turn);
        bodies.push(BodyAt {
            mass: p.mass.clone(),
            inertia: p.inertia.clone(),
            centre: origin.add(&offset),
            joint: n - 1,
        });
    }
    let mut m = vec![vec![int(0); n]; n];
    for body in &bodies {
        // Column k of the centre's Jacobian, and whether joint k turns the body.
        let columns: Vec<(V, bool)> = (0..=body.joint)
            .map(|k| {
                let (kind, point, along) = &axes[k];
                match kind {
                    JointKind::Revolute => {
                        let r = body.centre.sub(point);
                        (V(-r.1, r.0), true)
                    }
                    JointKind::Prismatic => (along.clone(), false),
                }
            })
            .collect();
        for (i, (vi, ti)) in columns.iter().enumerate() {
            for (j, (vj, tj)) in columns.iter().enumerate() {
                let mut e = &body.mass * (&vi.0 * &vj.0 + &vi.1 * &vj.1);
                if *ti && *tj {
                    e += &body.inertia;
                }
                m[i][j] += e;
            }
        }
    }
    for (k, link) in arm.links.iter().enumerate() {
        m[k][k] += &link.armature;
    }
    m
}

/// The first joint (0-based) whose `L D L^T` pivot of the mass matrix at the generic
/// configuration is at most [`RELATIVE_PIVOT`] times its diagonal entry (or not positive), or
/// whose diagonal entry is below `f64::MIN_POSITIVE`, with the pivot relative to that entry (0
/// when the entry is 0 too, or underflows); `None` when `M` is definite there.
#[must_use]
pub fn weak_joint(arm: &ArmSpec<Rational>) -> Option<(usize, f64)> {
    let m = generic_mass_matrix(arm);
    let n = m.len();
    // 4 eps = 2^-50, exactly.
    let threshold = Rational::new(1.into(), num_bigint::BigInt::from(1u64 << 50));
    // Crout's L D L^T on the exact entries.
    let mut l = vec![vec![int(0); n]; n];
    let mut d = vec![int(0); n];
    for j in 0..n {
        let mut pivot = m[j][j].clone();
        for k in 0..j {
            pivot -= &l[j][k] * &l[j][k] * &d[k];
        }
        let diagonal = &m[j][j];
        let normal = crate::ring::to_f64(diagonal).is_some_and(|x| x >= f64::MIN_POSITIVE);
        if !normal || !pivot.is_positive() || pivot <= diagonal * &threshold {
            let relative = if diagonal.is_zero() || !normal {
                0.0
            } else {
                crate::ring::to_f64(&(&pivot / diagonal)).unwrap_or(0.0)
            };
            return Some((j, relative));
        }
        for i in j + 1..n {
            let mut e = m[i][j].clone();
            for k in 0..j {
                e -= &l[i][k] * &l[j][k] * &d[k];
            }
            l[i][j] = e / &pivot;
        }
        d[j] = pivot;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanics::{LinkSpec, PayloadSpec};

    fn arm(links: Vec<LinkSpec>) -> ArmSpec {
        ArmSpec {
            links,
            gravity: crate::down(int(0)),
            payload: None,
        }
    }

    #[test]
    fn the_paper_arms_are_definite() {
        for n in 1..=6 {
            assert_eq!(weak_joint(&ArmSpec::paper(n)), None);
        }
    }

    #[test]
    fn the_generic_matrix_is_the_derived_one_there() {
        // Against the symbolic derivation at the same angles.
        let mut a = ArmSpec::paper(3);
        a.links[1].com = (ratio(1, 3), ratio(1, 7));
        a.links[2].armature = ratio(1, 10);
        let d = crate::Dynamics::derive(&a);
        let config = generic_configuration(&[JointKind::Revolute; 3]);
        let q: Vec<f64> = config
            .iter()
            .map(|(c, s, _)| {
                crate::ring::to_f64(s)
                    .unwrap()
                    .atan2(crate::ring::to_f64(c).unwrap())
            })
            .collect();
        let m = generic_mass_matrix(&a);
        for (i, row) in m.iter().enumerate() {
            for (j, entry) in row.iter().enumerate() {
                let exact = crate::ring::to_f64(entry).unwrap();
                let derived = d.mass_matrix[i][j].eval(&q, &[0.0; 3], &[0.0; 3]);
                assert!(
                    (exact - derived).abs() < 1e-13,
                    "{i} {j}: {exact} {derived}"
                );
            }
        }
    }

    #[test]
    fn a_joint_that_moves_nothing_is_found() {
        let mut links = vec![LinkSpec::rod(int(1), int(1)); 2];
        // The last link's mass on its own axis, no inertia: its joint moves nothing.
        links[1].inertia = int(0);
        links[1].com = (int(0), int(0));
        let a = arm(links.clone());
        assert_eq!(weak_joint(&a).map(|(j, _)| j), Some(1));
        // Armature, or a payload beyond it, makes it definite again.
        let mut geared = links.clone();
        geared[1].armature = ratio(1, 100);
        assert_eq!(weak_joint(&arm(geared)), None);
        let mut holding = arm(links.clone());
        holding.payload = Some(PayloadSpec {
            mass: int(1),
            inertia: int(0),
            com: (int(0), int(0)),
        });
        assert_eq!(weak_joint(&holding), None);
        // The same on the first link, with a second link after it: definite.
        let mut first = vec![LinkSpec::rod(int(1), int(1)); 2];
        first[0].inertia = int(0);
        first[0].com = (int(0), int(0));
        assert_eq!(weak_joint(&arm(first)), None);
        // A point cart (no length) under a pole: definite.
        let mut cart = vec![
            LinkSpec::rod(int(0), int(1)),
            LinkSpec::rod(int(1), ratio(1, 10)),
        ];
        cart[0].joint = JointKind::Prismatic;
        assert_eq!(weak_joint(&arm(cart.clone())), None);
        // A pole of 1e-300 m: definite in exact arithmetic, but M22 ~ 1e-601 is zero in f64.
        cart[1] = LinkSpec::rod(crate::ring::parse_decimal("1e-300").unwrap(), int(1));
        let (j, relative) = weak_joint(&arm(cart)).unwrap();
        assert_eq!((j, relative), (1, 0.0));
    }
}
