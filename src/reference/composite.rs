//! Composite bodies: the mass matrix by the composite rigid body algorithm, the gravity
//! torques by the statics of the composites, and forward dynamics through the mass matrix.

use nalgebra::{SMatrix, SVector, Vector2};

use super::newton_euler::{friction, rnea_dirs};
use super::{in_world, last_direction, link_directions};
use crate::Model;

/// Composite rigid body algorithm on precomputed link directions.
#[inline(always)]
fn crba_dirs<const N: usize>(model: &Model<N>, dirs: &[Vector2<f64>; N]) -> SMatrix<f64, N, N> {
    let links = &model.links;
    let mut m = SMatrix::<f64, N, N>::zeros();
    // Composite body of links j..N and the payload about joint j: mass, first moment (world
    // frame, relative to joint j) and rotational inertia. It starts as the payload about the
    // tip.
    let payload = &model.payload;
    let mut mass = payload.mass;
    let mut first = in_world(last_direction(dirs), payload.com) * payload.mass;
    let mut rot = payload.inertia + payload.mass * payload.com.norm_squared();
    for j in (0..N).rev() {
        let link = &links[j];
        let u = dirs[j];
        // Shift the composite beyond joint j+1 from joint j+1 to joint j (offset d = l_j u_j),
        // then add link j itself.
        let d = u * link.length;
        rot += link.inertia_about_joint() + 2.0 * d.dot(&first) + mass * link.length * link.length;
        first += in_world(u, link.com) * link.mass + d * mass;
        mass += link.mass;

        // Unit rate at joint j gives the composite angular momentum `rot` about joint j and
        // linear momentum `perp(first)`; its moment about joint i < j adds
        // `(p_j - p_i) x perp(first) = (p_j - p_i) . first`, accumulated link by link. The
        // rotor turns with joint j alone: its armature is on the diagonal only.
        let mut mij = rot;
        m[(j, j)] = rot + link.armature;
        for i in (0..j).rev() {
            mij += links[i].length * dirs[i].dot(&first);
            m[(i, j)] = mij;
            m[(j, i)] = mij;
        }
    }
    m
}

/// The joint-space mass matrix `M(q)` by the composite rigid body algorithm, each joint's
/// armature on its diagonal.
///
/// O(N^2): one inward pass builds the composite mass, first moment and rotational inertia about
/// each joint; the off-diagonal entries follow by shifting each composite's momentum inwards.
#[inline]
#[must_use]
pub fn mass_matrix<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SMatrix<f64, N, N> {
    crba_dirs(model, &link_directions(q))
}

/// The gravity torques `g(q) = dV/dq`: the joint torques that hold the arm still.
///
/// O(N): joint i must support the weight of links i..N and the payload, whose moment about
/// joint i is `gravity` times the horizontal first moment of that composite body.
#[inline]
#[must_use]
pub fn gravity_torques<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SVector<f64, N> {
    let dirs = link_directions(q);
    let payload = &model.payload;
    let mut tau = SVector::zeros();
    let mut mass = payload.mass;
    let mut first_x = payload.mass * in_world(last_direction(&dirs), payload.com).x;
    for i in (0..N).rev() {
        let link = &model.links[i];
        let u = dirs[i];
        first_x += link.mass * in_world(u, link.com).x + mass * link.length * u.x;
        mass += link.mass;
        tau[i] = model.gravity * first_x;
    }
    tau
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
    let dirs = link_directions(q);
    let m = crba_dirs(model, &dirs);
    let rhs =
        tau - rnea_dirs(model, model.gravity, &dirs, qd, &SVector::zeros()) - friction(model, qd);
    match m.cholesky() {
        Some(cholesky) => cholesky.solve(&rhs),
        None => SVector::repeat(f64::NAN),
    }
}
