//! Forward kinematics: the tip, the joints and the tip Jacobian.

use nalgebra::{Point2, SMatrix, SVector, Vector2};

use super::{link_directions, slides};
use crate::Model;

/// The position of the tip (the far end of the last link), m.
#[inline]
#[must_use]
pub fn tip_position<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> Point2<f64> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return tip_position(&m, &s.component_mul(q));
    }
    let dirs = link_directions(&model.links, q);
    let mut tip = Point2::origin();
    for ((link, dir), &qi) in model.links.iter().zip(dirs.iter()).zip(q.iter()) {
        if slides(link) {
            tip += dir * qi;
        }
        tip += dir * link.length;
    }
    tip
}

/// The absolute angle of the last link from +x, `q[0] + ... + q[N-1]` (not wrapped), rad, for
/// an arm whose joints are all revolute.
///
/// It sees only `q`, not the joint kinds, so it also adds a prismatic joint's displacement;
/// [`tip_orientation`] is the same angle for any arm.
#[inline]
#[must_use]
pub fn tip_angle<const N: usize>(q: &SVector<f64, N>) -> f64 {
    q.sum()
}

/// The absolute angle of the last link from +x, the sum of the revolute joints' `q` (not
/// wrapped), rad: a prismatic joint does not turn its link. With all joints revolute it is
/// [`tip_angle`].
#[inline]
#[must_use]
pub fn tip_orientation<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> f64 {
    let mut phi = 0.0;
    for (link, &qi) in model.links.iter().zip(q.iter()) {
        phi += link.offset;
        if !slides(link) {
            phi += if link.reversed { -qi } else { qi };
        }
    }
    phi
}

/// The positions of the links' frame origins, joints 1..=N, m: a revolute joint's axis, and
/// for a prismatic joint the carriage it slid, `q_i` beyond the end of the link before it.
/// Joint 1 is at the origin unless it is prismatic.
#[inline]
#[must_use]
pub fn joint_positions<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> [Point2<f64>; N] {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return joint_positions(&m, &s.component_mul(q));
    }
    let dirs = link_directions(&model.links, q);
    let mut joints = [Point2::origin(); N];
    let mut p = Point2::origin();
    for (((joint, link), dir), &qi) in joints
        .iter_mut()
        .zip(model.links.iter())
        .zip(dirs.iter())
        .zip(q.iter())
    {
        if slides(link) {
            p += dir * qi;
        }
        *joint = p;
        p += dir * link.length;
    }
    joints
}

/// The 3 x N tip Jacobian: rows are the rates of the tip's x, the tip's y and the last link's
/// absolute angle with respect to `qd`.
///
/// Column j is `[perp(tip - o_j); 1]` for a revolute joint, which turns everything beyond it
/// about its frame origin `o_j`, and `[u_j; 0]` for a prismatic one, which slides everything
/// beyond it along its axis without turning it.
#[inline]
#[must_use]
pub fn jacobian<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SMatrix<f64, 3, N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return jacobian(&m, &s.component_mul(q)) * SMatrix::from_diagonal(&s);
    }
    let dirs = link_directions(&model.links, q);
    let mut jac = SMatrix::<f64, 3, N>::zeros();
    // Walk inwards accumulating the vector from link j's frame origin to the tip.
    let mut r = Vector2::zeros();
    for j in (0..N).rev() {
        let (link, u) = (&model.links[j], dirs[j]);
        r += u * link.length;
        if slides(link) {
            jac[(0, j)] = u.x;
            jac[(1, j)] = u.y;
            // From the carriage back to the end of the link before it.
            r += u * q[j];
        } else {
            jac[(0, j)] = -r.y;
            jac[(1, j)] = r.x;
            jac[(2, j)] = 1.0;
        }
    }
    jac
}
