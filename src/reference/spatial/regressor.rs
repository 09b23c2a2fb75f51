//! The joint-torque regressor of a spatial arm: the inverse dynamics is linear in each link's
//! ten standard inertial parameters, in Pinocchio's order `[m, m cx, m cy, m cz, Ixx, Ixy,
//! Iyy, Ixz, Iyz, Izz]`, the inertia about the link frame's origin in its axes
//! ([`standard_parameters`]).
//!
//! A body held about a frame's origin by its mass `m`, first moment `h` and rotational inertia
//! `J` (turned into base axes), moving with the frame's angular velocity `w`, angular
//! acceleration `dw` and origin acceleration `a` (gravity included), needs the force
//! `m a + dw x h + w x (w x h)` and the moment about the origin `J dw + w x J w + h x a`: both
//! linear in `(m, h, J)`. Column `k` of link `j`'s block is the joint forces that carry a body
//! of unit parameter `k` on link `j`, read on every joint from the base to `j`. It shares the
//! outward recursion of [`inverse_dynamics`](super::inverse_dynamics), not its loads, which go
//! through the centre of mass; the tests check `sum_j Y_j theta_j` against it.

use nalgebra::{Matrix3, SMatrix, SVector, Vector3};

use super::dynamics::motions;
use super::{joint_axes, link_poses};
use crate::spatial::SpatialModel;
use crate::Joint;

/// Link `i`'s standard parameters `[m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]`, the
/// inertia about the link frame's origin (the parallel-axis theorem applied to the tensor
/// about the centre of mass), in Pinocchio's order.
#[must_use]
pub fn standard_parameters<const N: usize>(model: &SpatialModel<N>) -> [SVector<f64, 10>; N] {
    let links = super::rigid_links(model);
    core::array::from_fn(|i| {
        let link = &links[i];
        let (m, c) = (link.mass, link.com);
        let j = link.inertia + (Matrix3::identity() * c.norm_squared() - c * c.transpose()) * m;
        SVector::from([
            m,
            m * c.x,
            m * c.y,
            m * c.z,
            j[(0, 0)],
            j[(0, 1)],
            j[(1, 1)],
            j[(0, 2)],
            j[(1, 2)],
            j[(2, 2)],
        ])
    })
}

/// The regressor's blocks, one `N x 10` block a link: `sum_j Y_j theta_j` is the rigid bodies'
/// share of [`inverse_dynamics`](super::inverse_dynamics), `M_rigid qdd + c + g`, without
/// armature and friction (those add `armature_i qdd_i + damping_i qd_i + frictionloss_i
/// sign(qd_i)` to joint `i`).
#[must_use]
pub fn regressor<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> [SMatrix<f64, N, 10>; N] {
    let poses = link_poses(model, q);
    let axes = joint_axes(model, q);
    let motions = motions(model, q, qd, qdd, &model.gravity);
    core::array::from_fn(|j| {
        let motion = &motions[j];
        let origin = poses[j].translation.vector;
        let r = poses[j].rotation.to_rotation_matrix().into_inner();
        let mut block = SMatrix::<f64, N, 10>::zeros();
        for k in 0..10 {
            // The unit body in the link's axes, then in the base's.
            let mut unit = [0.0; 10];
            unit[k] = 1.0;
            let h = r * Vector3::new(unit[1], unit[2], unit[3]);
            let [_, _, _, _, xx, xy, yy, xz, yz, zz] = unit;
            let tensor = r * Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz) * r.transpose();
            let (w, dw, a) = (&motion.w, &motion.dw, &motion.a);
            let force = a * unit[0] + dw.cross(&h) + w.cross(&w.cross(&h));
            let moment = tensor * dw + w.cross(&(tensor * w)) + h.cross(a);
            for (i, (o, z)) in axes.iter().enumerate().take(j + 1) {
                block[(i, k)] = match model.joints[i].kind {
                    Joint::Revolute => z.dot(&(moment + (origin - o).cross(&force))),
                    Joint::Prismatic => z.dot(&force),
                };
            }
        }
        block
    })
}
