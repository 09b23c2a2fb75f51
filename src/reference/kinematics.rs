//! Forward kinematics: the tip, the joints and the tip Jacobian.

use nalgebra::{Point2, SMatrix, SVector, Vector2};

use super::link_directions;
use crate::Model;

/// The position of the tip (the far end of the last link), m.
#[inline]
#[must_use]
pub fn tip_position<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> Point2<f64> {
    let dirs = link_directions(q);
    let mut tip = Point2::origin();
    for (link, dir) in model.links.iter().zip(dirs.iter()) {
        tip += dir * link.length;
    }
    tip
}

/// The absolute angle of the last link from +x, `q[0] + ... + q[N-1]` (not wrapped), rad.
#[inline]
#[must_use]
pub fn tip_angle<const N: usize>(q: &SVector<f64, N>) -> f64 {
    q.sum()
}

/// The positions of joints 1..=N, m; joint 1 is at the origin.
#[inline]
#[must_use]
pub fn joint_positions<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> [Point2<f64>; N] {
    let dirs = link_directions(q);
    let mut joints = [Point2::origin(); N];
    let mut p = Point2::origin();
    for ((joint, link), dir) in joints.iter_mut().zip(model.links.iter()).zip(dirs.iter()) {
        *joint = p;
        p += dir * link.length;
    }
    joints
}

/// The 3 x N tip Jacobian: rows are the rates of the tip's x, the tip's y and the last link's
/// absolute angle with respect to `qd`.
///
/// Column j is `[perp(tip - joint_j); 1]`, since joint j rotates everything beyond it.
#[inline]
#[must_use]
pub fn jacobian<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SMatrix<f64, 3, N> {
    let dirs = link_directions(q);
    let mut jac = SMatrix::<f64, 3, N>::zeros();
    // Walk inwards accumulating the vector from joint j to the tip.
    let mut r = Vector2::zeros();
    for j in (0..N).rev() {
        r += dirs[j] * model.links[j].length;
        jac[(0, j)] = -r.y;
        jac[(1, j)] = r.x;
        jac[(2, j)] = 1.0;
    }
    jac
}
