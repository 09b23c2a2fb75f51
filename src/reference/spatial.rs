//! The numeric reference for spatial arms: each joint's transformation built from its
//! convention's parameters at run time, multiplied out base to tip. It shares nothing with the
//! symbolic path of `#[derive(SpatialArm)]`, which the tests check against it.
//!
//! Conventions as [`JointGeometry`](crate::spatial::JointGeometry) lists them; the geometric
//! Jacobian's rows are the tool origin's linear velocity, then the angular velocity, both in
//! base coordinates (Pinocchio's `LOCAL_WORLD_ALIGNED`); gravity torques are `dV/dq`, what the
//! joints apply to hold the arm still, with `V = -sum m_i g . c_i` (zero at the base origin).
//!
//! The dynamics, `tau = M qdd + c + g + f` as for planar arms ([`inverse_dynamics`] by
//! recursive Newton-Euler, [`mass_matrix`] from the links' Jacobians, [`kinetic_energy`],
//! [`forward_dynamics`]), are in base coordinates too; they agree with Pinocchio's `rnea` and
//! `crba` to 2e-15 on the PUMA 560 and a seven-joint arm (`tests/spatial_dynamics_reference.rs`).
//! [`regressor`] is the inverse dynamics' linear map from each link's ten
//! [`standard_parameters`] (Pinocchio's order).

use nalgebra::{Isometry3, Matrix3, Point3, SMatrix, SVector, Vector3};

use crate::spatial::{SpatialLink, SpatialModel};
use crate::Joint;

mod dynamics;
mod regressor;

pub use dynamics::{
    bias_forces, coriolis, forward_dynamics, friction, inverse_dynamics, kinetic_energy,
    mass_matrix,
};
pub use regressor::{regressor, standard_parameters};

/// Each link's frame in the base frame, base first.
#[must_use]
pub fn link_poses<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
) -> [Isometry3<f64>; N] {
    let mut pose = Isometry3::identity();
    core::array::from_fn(|i| {
        let j = &model.joints[i];
        pose *= j.geometry.transform(j.kind, q[i]);
        pose
    })
}

/// The tool frame in the base frame.
#[must_use]
pub fn tip_pose<const N: usize>(model: &SpatialModel<N>, q: &SVector<f64, N>) -> Isometry3<f64> {
    link_poses(model, q)
        .last()
        .copied()
        .unwrap_or_else(Isometry3::identity)
        * model.tool
}

/// Each joint's axis in the base frame at `q`: a point on it and its unit direction.
#[must_use]
pub fn joint_axes<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
) -> [(Vector3<f64>, Vector3<f64>); N] {
    let poses = link_poses(model, q);
    core::array::from_fn(|i| {
        let parent = if i == 0 {
            Isometry3::identity()
        } else {
            poses[i - 1]
        };
        let (point, direction) = model.joints[i].geometry.axis_in_parent();
        (
            parent.transform_point(&Point3::from(point)).coords,
            parent.rotation * direction,
        )
    })
}

/// The geometric Jacobian of the tool origin: column `i` is `(z_i x (p - o_i), z_i)` for a
/// hinge and `(z_i, 0)` for a slide, `z_i` its axis, `o_i` a point on it, `p` the tool origin.
#[must_use]
pub fn jacobian<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
) -> SMatrix<f64, 6, N> {
    let tip = tip_pose(model, q).translation.vector;
    let axes = joint_axes(model, q);
    SMatrix::from_fn(|r, c| {
        let (o, z) = axes[c];
        let column = match model.joints[c].kind {
            Joint::Revolute => [z.cross(&(tip - o)), z],
            Joint::Prismatic => [z, Vector3::zeros()],
        };
        column[r / 3][r % 3]
    })
}

/// The links' mass properties with the payload, if any, merged into the last link: one rigid
/// body of the summed mass, at the mass-weighted centre, with both tensors turned into the
/// link's axes and moved there by the parallel-axis theorem. The functions of this module use
/// these.
#[must_use]
pub fn rigid_links<const N: usize>(model: &SpatialModel<N>) -> [SpatialLink; N] {
    let mut links = model.links;
    let (Some(payload), Some(last)) = (model.payload, links.last_mut()) else {
        return links;
    };
    let r = model.tool.rotation.to_rotation_matrix().into_inner();
    let parts = [
        (last.mass, last.com, last.inertia),
        (
            payload.mass,
            model
                .tool
                .transform_point(&Point3::from(payload.com))
                .coords,
            r * payload.inertia * r.transpose(),
        ),
    ];
    let mass = parts[0].0 + parts[1].0;
    let com = if mass > 0.0 {
        (parts[0].1 * parts[0].0 + parts[1].1 * parts[1].0) / mass
    } else {
        Vector3::zeros()
    };
    let inertia = parts.iter().fold(Matrix3::zeros(), |acc, (m, c, i)| {
        let d = c - com;
        acc + i + (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * *m
    });
    *last = SpatialLink { mass, com, inertia };
    links
}

/// Each link's centre of mass in the base frame (the last link's with the payload).
#[must_use]
pub fn centres_of_mass<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
) -> [Vector3<f64>; N] {
    let poses = link_poses(model, q);
    let links = rigid_links(model);
    core::array::from_fn(|i| poses[i].transform_point(&Point3::from(links[i].com)).coords)
}

/// The potential energy `-sum m_i g . c_i` of gravity and `sum k_i (q_i - r_i)^2 / 2` of the
/// joint springs, J.
#[must_use]
pub fn potential_energy<const N: usize>(model: &SpatialModel<N>, q: &SVector<f64, N>) -> f64 {
    let springs: f64 = model
        .joints
        .iter()
        .zip(q.iter())
        .map(|(j, q)| j.stiffness * (q - j.springref) * (q - j.springref) / 2.0)
        .sum();
    centres_of_mass(model, q)
        .iter()
        .zip(&rigid_links(model))
        .map(|(c, l)| -l.mass * model.gravity.dot(c))
        .sum::<f64>()
        + springs
}

/// The joint springs' torques `k_i (q_i - r_i)`.
#[must_use]
pub fn springs<const N: usize>(model: &SpatialModel<N>, q: &SVector<f64, N>) -> SVector<f64, N> {
    SVector::from_fn(|i, _| {
        let j = &model.joints[i];
        j.stiffness * (q[i] - j.springref)
    })
}

/// The static torques `g = dV/dq` (forces for slides): gravity's,
/// `-sum_{j >= i} m_j g . dc_j/dq_i` with `dc_j/dq_i = z_i x (c_j - o_i)` for a hinge and `z_i`
/// for a slide, and the joint's spring's ([`springs`]).
#[must_use]
pub fn gravity<const N: usize>(model: &SpatialModel<N>, q: &SVector<f64, N>) -> SVector<f64, N> {
    let axes = joint_axes(model, q);
    let centres = centres_of_mass(model, q);
    let links = rigid_links(model);
    SVector::from_fn(|i, _| {
        let (o, z) = axes[i];
        (i..N)
            .map(|j| {
                let dc = match model.joints[i].kind {
                    Joint::Revolute => z.cross(&(centres[j] - o)),
                    Joint::Prismatic => z,
                };
                -links[j].mass * model.gravity.dot(&dc)
            })
            .sum::<f64>()
    }) + springs(model, q)
}
