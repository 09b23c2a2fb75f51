//! Composite bodies: the mass matrix by the composite rigid body algorithm, the gravity
//! terms by the statics of the composites, and forward dynamics through the mass matrix.

use nalgebra::{SMatrix, SVector, Vector2};

use super::newton_euler::{friction, rnea_dirs, springs};
use super::{cross, in_world, last_direction, link_directions, perp, slides, steps};
use crate::Model;

/// Composite rigid body algorithm on precomputed link directions.
#[inline(always)]
fn crba_dirs<const N: usize>(
    model: &Model<N>,
    dirs: &[Vector2<f64>; N],
    q: &SVector<f64, N>,
) -> SMatrix<f64, N, N> {
    let links = &model.links;
    let step = steps(links, dirs, q);
    let mut m = SMatrix::<f64, N, N>::zeros();
    // Composite body of links j..N and the payload about link j's frame origin: mass, first
    // moment (world frame, relative to the origin) and rotational inertia. It starts as the
    // payload about the tip.
    let payload = &model.payload;
    let mut mass = payload.mass;
    let mut first = in_world(last_direction(dirs), payload.com) * payload.mass;
    let mut rot = payload.inertia + payload.mass * payload.com.norm_squared();
    for j in (0..N).rev() {
        let link = &links[j];
        let u = dirs[j];
        // Shift the composite beyond link j+1's origin from there to link j's (by
        // d = o_{j+1} - o_j), then add link j itself.
        let d = step[j];
        rot += link.inertia_about_joint() + 2.0 * d.dot(&first) + mass * d.norm_squared();
        first += in_world(u, link.com) * link.mass + d * mass;
        mass += link.mass;

        // A unit rate of joint j gives the composite a momentum; joint i < j reads its moment
        // about link i's origin if revolute, its component along `u_i` if prismatic. The moment
        // moves inwards by `(o_{i+1} - o_i) x p` link by link. The rotor
        // (or the slider's reflected mass) moves with joint j alone: its armature is on the
        // diagonal only.
        if slides(link) {
            // A unit slide: linear momentum `p = mass u`, angular `first x u` about link j's
            // origin.
            let mut moment = cross(first, u);
            m[(j, j)] = mass + link.armature;
            for i in (0..j).rev() {
                moment += mass * cross(step[i], u);
                let mij = if slides(&links[i]) {
                    mass * dirs[i].dot(&u)
                } else {
                    moment
                };
                m[(i, j)] = mij;
                m[(j, i)] = mij;
            }
        } else {
            // A unit turn: angular momentum `rot`, linear `p = perp(first)`, so that
            // `d x p = d . first` and `u_i . p = first x u_i`.
            let mut moment = rot;
            m[(j, j)] = rot + link.armature;
            for i in (0..j).rev() {
                moment += step[i].dot(&first);
                let mij = if slides(&links[i]) {
                    cross(first, dirs[i])
                } else {
                    moment
                };
                m[(i, j)] = mij;
                m[(j, i)] = mij;
            }
        }
    }
    m
}

/// The joint-space mass matrix `M(q)` by the composite rigid body algorithm, each joint's
/// armature on its diagonal.
///
/// O(N^2): one inward pass builds the composite mass, first moment and rotational inertia about
/// each link's frame origin; the off-diagonal entries follow by shifting each composite's
/// momentum inwards, read as a moment at a revolute joint and an axial component at a
/// prismatic one.
#[inline]
#[must_use]
pub fn mass_matrix<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SMatrix<f64, N, N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return mass_matrix(&m, &s.component_mul(q)).component_mul(&(s * s.transpose()));
    }
    crba_dirs(model, &link_directions(&model.links, q), q)
}

/// The gravity torques (forces at prismatic joints) `g(q) = dV/dq`: what holds the arm still,
/// the joint springs' torques ([`springs`](super::springs)) included.
///
/// O(N): joint i must support the weight of links i..N and the payload: a revolute joint its
/// moment about link i's origin, `-g . perp(F)` with `F` the first moment of that composite
/// body about it, a prismatic one its component along the axis, `-g . u_i` times the
/// composite's mass.
#[inline]
#[must_use]
pub fn gravity_torques<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SVector<f64, N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return s.component_mul(&gravity_torques(&m, &s.component_mul(q)));
    }
    let dirs = link_directions(&model.links, q);
    let step = steps(&model.links, &dirs, q);
    let payload = &model.payload;
    let mut tau = SVector::zeros();
    let mut mass = payload.mass;
    let mut first = payload.mass * in_world(last_direction(&dirs), payload.com);
    let g = model.gravity;
    for i in (0..N).rev() {
        let link = &model.links[i];
        let u = dirs[i];
        first += link.mass * in_world(u, link.com) + mass * step[i];
        mass += link.mass;
        tau[i] = if slides(link) {
            -mass * g.dot(&u)
        } else {
            -g.dot(&perp(first))
        };
    }
    tau + springs(model, q)
}

/// Joint accelerations `qdd = M^-1 (tau - c - g - f)` by CRBA, RNEA and a Cholesky solve.
///
/// O(N^3); provided to cross-check and benchmark against
/// [`forward_dynamics`](super::forward_dynamics). If the mass matrix is not positive definite
/// (only possible with degenerate links, e.g. a massless, inertialess last link without
/// armature or payload) every entry is NaN.
#[must_use]
pub fn forward_dynamics_crba<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> SVector<f64, N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return s.component_mul(&forward_dynamics_crba(
            &m,
            &s.component_mul(q),
            &s.component_mul(qd),
            &s.component_mul(tau),
        ));
    }
    let dirs = link_directions(&model.links, q);
    let m = crba_dirs(model, &dirs, q);
    let bias = rnea_dirs(model, model.gravity, &dirs, q, qd, &SVector::zeros());
    let rhs = tau - bias - friction(model, qd) - springs(model, q);
    match m.cholesky() {
        Some(cholesky) => cholesky.solve(&rhs),
        None => SVector::repeat(f64::NAN),
    }
}
