//! The exact mass matrix and velocity-product forces of a spatial arm, from its kinetic energy.
//!
//! Multiplying every link's frame out into base coordinates and squaring the velocities there
//! makes expressions of hundreds of thousands of terms for a six-joint arm. In each link's own
//! axes the velocities stay small: each joint turns the previous link's by one rotation, so
//! link `k`'s angular velocity `w_k` and its origin's velocity `v_k` are linear in the rates
//! with coefficients in the angles of the joints before it, as the Newton-Euler recursion
//! carries them (`programs::spatial_newton_euler`):
//!
//! ```text
//! w_k = Q_k w_{k-1} + z_k qd_k                       (a slide: Q_k w_{k-1})
//! v_k = Q_k (v_{k-1} + w_{k-1} x pre_p) + w_k x r_k    (a slide: + z_k qd_k, r_k + z_k q_k)
//! T   = sum_k m v_k.v_k / 2 + v_k . (w_k x h_k) + w_k . J_k w_k / 2 + armature_k qd_k^2 / 2
//! ```
//!
//! with each body's mass `m`, first moment `h = m c` and inertia `J` about the link frame's
//! origin. Then `M_ij = d^2 T / dqd_i dqd_j` and, by Lagrange's equation, the velocity-product
//! forces `c_i = d/dt (dT/dqd_i) - dT/dq_i` with only the angles' part of `d/dt`.

use super::frames::{joint_parts, link_bodies, motion, Frame};
use super::spec::{SpatialArmSpec, SpatialBody};
use crate::algebra::expr::{Expr, Var};
use crate::algebra::poly::Poly;
use crate::mechanics::planar::JointKind;

type E = Expr<Poly>;
type V = [E; 3];

/// M and c multiplied out.
#[derive(Clone, Debug)]
pub struct SpatialDynamicsExpansion {
    /// The mass matrix, `mass_matrix[i][j]`.
    pub mass_matrix: Vec<Vec<E>>,
    /// The velocity-product forces.
    pub coriolis: Vec<E>,
}

fn size(e: &E) -> usize {
    e.terms().map(|(_, _, c)| c.terms().count().max(1)).sum()
}

fn cross(a: &V, b: &V) -> V {
    core::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        a[j].mul(&b[k]).sub(&a[k].mul(&b[j]))
    })
}

fn dot(a: &V, b: &V) -> E {
    let mut e = E::zero();
    for (x, y) in a.iter().zip(b) {
        e.add_product(x, y);
    }
    e
}

fn add(a: &V, b: &V) -> V {
    core::array::from_fn(|i| a[i].add(&b[i]))
}

/// `R^T v`.
fn rotate_back(f: &Frame, v: &V) -> V {
    core::array::from_fn(|i| {
        let mut e = E::zero();
        for (k, x) in v.iter().enumerate() {
            e.add_product(&f.r[k][i], x);
        }
        e
    })
}

fn constant(p: &Poly) -> E {
    E::constant(p.clone())
}

/// A body's kinetic energy per link: `m v.v / 2 + v . (w x h) + w . J w / 2`, `(m, h, J)` its
/// standard parameters about the link frame's origin.
fn body_energy(body: &SpatialBody, w: &V, v: &V) -> E {
    let p = body.standard_parameters();
    let half = crate::algebra::ring::ratio(1, 2);
    let h: V = [constant(&p[1]), constant(&p[2]), constant(&p[3])];
    let j = [
        [&p[4], &p[5], &p[7]],
        [&p[5], &p[6], &p[8]],
        [&p[7], &p[8], &p[9]],
    ];
    let jw: V = core::array::from_fn(|a| {
        let mut e = E::zero();
        for (b, wb) in w.iter().enumerate() {
            e.add_assign(&wb.scale_by(j[a][b]));
        }
        e
    });
    let mut t = dot(v, v).scale_by(&p[0]).scale(&half);
    t.add_assign(&dot(v, &cross(w, &h)));
    t.add_assign(&dot(w, &jw).scale(&half));
    t
}

/// How large (terms) a link's velocities may grow before [`expand_dynamics`] stops. The
/// products of trigonometric polynomials with exact coefficients that the energy needs run
/// unoptimised in a user's build: the PUMA 560's velocities reach 244 terms, and multiplying
/// its M and c out took 0.7 s of its derive (1.3 ms per term of the result) and the Panda's 22
/// s, for formulas the docs cannot show. Arms of up to three or four joints stay well within
/// this.
pub const DYNAMICS_BUDGET: usize = 80;

/// M and c, or `None` as soon as a link's velocities exceed `budget` terms (counted as
/// [`EXPANSION_BUDGET`](super::frames::EXPANSION_BUDGET) counts them) or the energy `budget`
/// terms a joint.
#[must_use]
pub fn expand_dynamics(arm: &SpatialArmSpec, budget: usize) -> Option<SpatialDynamicsExpansion> {
    let n = arm.joints.len();
    let zero = || -> V { core::array::from_fn(|_| E::zero()) };
    let (mut w, mut v) = (zero(), zero());
    let mut energy = E::zero();
    let half = crate::algebra::ring::ratio(1, 2);
    for (k, spec) in arm.joints.iter().enumerate() {
        let (pre, u, post) = joint_parts(spec);
        let turn = motion(spec.kind, &u, k);
        let inward = |x: &V| rotate_back(&post, &rotate_back(&turn, &rotate_back(&pre, x)));
        let u_e: V = core::array::from_fn(|i| constant(&u[i]));
        let z = rotate_back(&post, &u_e);
        let mut r = rotate_back(&post, &post.p);
        let qd = E::var(Var::Qd(k));
        let spin: V = core::array::from_fn(|i| z[i].mul(&qd));
        let v_axis = add(&v, &cross(&w, &pre.p));
        w = inward(&w);
        let mut v_next = inward(&v_axis);
        match spec.kind {
            JointKind::Revolute => w = add(&w, &spin),
            JointKind::Prismatic => {
                let q = E::var(Var::Q(k));
                r = core::array::from_fn(|i| r[i].add(&z[i].mul(&q)));
                v_next = add(&v_next, &spin);
            }
        }
        v = add(&v_next, &cross(&w, &r));
        if w.iter().chain(&v).map(size).sum::<usize>() > budget {
            return None;
        }
        for body in link_bodies(arm, k) {
            energy.add_assign(&body_energy(&body, &w, &v));
        }
        energy.add_assign(&qd.mul(&qd).scale_by(&spec.armature).scale(&half));
        if size(&energy) > budget.saturating_mul(n) {
            return None;
        }
    }
    let momenta: Vec<E> = (0..n).map(|i| energy.diff_var(Var::Qd(i))).collect();
    let mass_matrix = momenta
        .iter()
        .map(|p| (0..n).map(|j| p.diff_var(Var::Qd(j))).collect())
        .collect();
    let coriolis = momenta
        .iter()
        .enumerate()
        .map(|(i, p)| p.dt_q(n).sub(&energy.diff_q(i)))
        .collect();
    Some(SpatialDynamicsExpansion {
        mass_matrix,
        coriolis,
    })
}
