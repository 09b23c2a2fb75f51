//! The numeric reference for the dynamics of spatial arms, for the tests of
//! `#[derive(SpatialArm)]`'s dynamics and for anyone who wants `M`, `c`, `g` of a
//! [`SpatialModel`] without a derive.
//!
//! Everything is written in base coordinates from the link poses of
//! [`link_poses`](super::link_poses), so no convention's frame bookkeeping enters:
//!
//! - [`inverse_dynamics`]: recursive Newton-Euler. Outwards, each link's angular velocity and
//!   acceleration and the acceleration of its frame origin `p_i`, composed from the link before
//!   it and the joint's motion relative to it (a hinge turns `p_i` about the joint's axis, a
//!   slide moves it along the axis; the Coriolis term `2 w_{i-1} x v_rel`); gravity enters as
//!   the base accelerating by `-g`. Inwards, each link's inertial force and moment (the tensor
//!   turned into base axes, `R I R^T`) summed from the tip, and read on each joint's axis: the
//!   moment about a point on it (hinge) or the force along it (slide).
//! - [`mass_matrix`]: from the links' Jacobians, `M = sum m J_c^T J_c + J_w^T (R I R^T) J_w`,
//!   which shares nothing with the recursion above; the tests check one against the other.
//! - [`kinetic_energy`]: each link's velocity by an outward recursion of its own.
//!
//! The equations of motion are those of planar arms: `tau = M qdd + c + g + f`, `M` holding
//! each joint's armature on its diagonal, `g = dV/dq` ([`gravity`](super::gravity): gravity's
//! and the joint springs' torques) and
//! `f_i = damping_i qd_i + frictionloss_i sign(qd_i)` ([`friction`]).

use nalgebra::{Matrix3, Point3, SMatrix, SVector, Vector3};

use super::{joint_axes, link_poses};
use crate::spatial::SpatialModel;
use crate::Joint;

/// Each link's motion in base coordinates, from the outward recursion.
pub(super) struct Motion {
    /// Angular velocity and acceleration.
    pub(super) w: Vector3<f64>,
    pub(super) dw: Vector3<f64>,
    /// The acceleration of the link frame's origin.
    pub(super) a: Vector3<f64>,
}

/// Each link's motion at `(q, qd, qdd)` with the base accelerating by `-gravity`, by the
/// outward recursion in base coordinates.
pub(super) fn motions<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
    gravity: &Vector3<f64>,
) -> [Motion; N] {
    let poses = link_poses(model, q);
    let axes = joint_axes(model, q);
    let mut before = Motion {
        w: Vector3::zeros(),
        dw: Vector3::zeros(),
        a: -gravity,
    };
    let mut origin_before = Vector3::zeros();
    core::array::from_fn(|i| {
        let (o, z) = axes[i];
        let p = poses[i].translation.vector;
        let r = p - origin_before;
        // The joint's motion of p relative to the link before it, in that link's terms.
        let (v_rel, a_rel, w, dw) = match model.joints[i].kind {
            Joint::Revolute => {
                let spin = z * qd[i];
                let lever = p - o;
                let v_rel = spin.cross(&lever);
                let a_rel = (z * qdd[i]).cross(&lever) + spin.cross(&v_rel);
                (
                    v_rel,
                    a_rel,
                    before.w + spin,
                    before.dw + z * qdd[i] + before.w.cross(&spin),
                )
            }
            Joint::Prismatic => (z * qd[i], z * qdd[i], before.w, before.dw),
        };
        let a = before.a
            + before.dw.cross(&r)
            + before.w.cross(&before.w.cross(&r))
            + a_rel
            + 2.0 * before.w.cross(&v_rel);
        before = Motion { w, dw, a };
        origin_before = p;
        Motion { w, dw, a }
    })
}

/// The joint forces of the rigid bodies alone, `M_rigid qdd + c + g` with gravity `gravity`:
/// no armature, no friction.
fn rnea<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
    gravity: &Vector3<f64>,
) -> SVector<f64, N> {
    let poses = link_poses(model, q);
    let axes = joint_axes(model, q);
    let motions = motions(model, q, qd, qdd, gravity);
    let links = super::rigid_links(model);
    let mut tau = SVector::zeros();
    // Force on link i from link i - 1 and the moment about p_i, summed from the tip.
    let mut force = Vector3::zeros();
    let mut moment = Vector3::zeros();
    let mut origin_after = Vector3::zeros();
    for i in (0..N).rev() {
        let link = &links[i];
        let m = &motions[i];
        let p = poses[i].translation.vector;
        let rotation = poses[i].rotation.to_rotation_matrix().into_inner();
        let inertia: Matrix3<f64> = rotation * link.inertia * rotation.transpose();
        let to_com = rotation * link.com;
        let a_com = m.a + m.dw.cross(&to_com) + m.w.cross(&m.w.cross(&to_com));
        let f_com = a_com * link.mass;
        let n_com = inertia * m.dw + m.w.cross(&(inertia * m.w));
        // Moving the previous (outer) sum's moment from p_{i+1} to p_i.
        moment += (origin_after - p).cross(&force);
        force += f_com;
        moment += n_com + to_com.cross(&f_com);
        origin_after = p;
        let (o, z) = axes[i];
        tau[i] = match model.joints[i].kind {
            Joint::Revolute => z.dot(&(moment + (p - o).cross(&force))),
            Joint::Prismatic => z.dot(&force),
        };
    }
    tau
}

/// The joint forces `tau = M qdd + c + g + f` that give the arm the accelerations `qdd` at
/// `(q, qd)`, by recursive Newton-Euler in base coordinates (see the module's docs).
#[must_use]
pub fn inverse_dynamics<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    let armature = SVector::<f64, N>::from_fn(|i, _| model.joints[i].armature * qdd[i]);
    rnea(model, q, qd, qdd, &model.gravity)
        + armature
        + friction(model, qd)
        + super::springs(model, q)
}

/// `c + g + f`: [`inverse_dynamics`] at zero acceleration.
#[must_use]
pub fn bias_forces<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> SVector<f64, N> {
    inverse_dynamics(model, q, qd, &SVector::zeros())
}

/// The velocity-product (Coriolis and centrifugal) forces `c(q, qd)` alone.
#[must_use]
pub fn coriolis<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea(model, q, qd, &SVector::zeros(), &Vector3::zeros())
}

/// Joint friction `f_i = damping_i qd_i + frictionloss_i sign(qd_i)`, `sign(0) = 0`.
#[must_use]
pub fn friction<const N: usize>(model: &SpatialModel<N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
    SVector::from_fn(|i, _| {
        let j = &model.joints[i];
        j.damping * qd[i] + j.frictionloss * crate::reference::sign(qd[i])
    })
}

/// The mass matrix `M(q)`, armature on the diagonal, from each link's Jacobians: column `i` of
/// link `j`'s (for `i <= j`) is `z_i x (c_j - o_i)` and `z_i` for a hinge, `z_i` and `0` for a
/// slide.
#[must_use]
pub fn mass_matrix<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
) -> SMatrix<f64, N, N> {
    let poses = link_poses(model, q);
    let axes = joint_axes(model, q);
    let mut m = SMatrix::<f64, N, N>::zeros();
    for (j, link) in super::rigid_links(model).iter().enumerate() {
        let centre = poses[j].transform_point(&Point3::from(link.com)).coords;
        let rotation = poses[j].rotation.to_rotation_matrix().into_inner();
        let inertia: Matrix3<f64> = rotation * link.inertia * rotation.transpose();
        let columns: [(Vector3<f64>, Vector3<f64>); N] = core::array::from_fn(|i| {
            let (o, z) = axes[i];
            match (i <= j, model.joints[i].kind) {
                (false, _) => (Vector3::zeros(), Vector3::zeros()),
                (true, Joint::Revolute) => (z.cross(&(centre - o)), z),
                (true, Joint::Prismatic) => (z, Vector3::zeros()),
            }
        });
        for r in 0..=j {
            for c in 0..=j {
                let (vr, wr) = &columns[r];
                let (vc, wc) = &columns[c];
                m[(r, c)] += link.mass * vr.dot(vc) + wr.dot(&(inertia * wc));
            }
        }
    }
    for (i, joint) in model.joints.iter().enumerate() {
        m[(i, i)] += joint.armature;
    }
    m
}

/// The kinetic energy `sum (m |v_c|^2 + w . (R I R^T) w) / 2 + sum armature qd^2 / 2`, each
/// link's velocity from an outward recursion (not from [`mass_matrix`]).
#[must_use]
pub fn kinetic_energy<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> f64 {
    let poses = link_poses(model, q);
    let axes = joint_axes(model, q);
    let links = super::rigid_links(model);
    let (mut w, mut v, mut origin) = (Vector3::zeros(), Vector3::zeros(), Vector3::zeros());
    let mut energy = 0.0;
    for i in 0..N {
        let (o, z) = axes[i];
        let p = poses[i].translation.vector;
        // The velocity of p as a point of the link before, then the joint's own motion.
        v += w.cross(&(p - origin));
        match model.joints[i].kind {
            Joint::Revolute => {
                v += (z * qd[i]).cross(&(p - o));
                w += z * qd[i];
            }
            Joint::Prismatic => v += z * qd[i],
        }
        origin = p;
        let link = &links[i];
        let rotation = poses[i].rotation.to_rotation_matrix().into_inner();
        let inertia: Matrix3<f64> = rotation * link.inertia * rotation.transpose();
        let v_com = v + w.cross(&(rotation * link.com));
        energy += 0.5 * (link.mass * v_com.norm_squared() + w.dot(&(inertia * w)));
        energy += 0.5 * model.joints[i].armature * qd[i] * qd[i];
    }
    energy
}

/// The accelerations `qdd = M^-1 (tau - c - g - f)`, by a Cholesky factorisation of
/// [`mass_matrix`]; every entry NaN where `M` is not positive definite (a chain whose last
/// links carry no mass, inertia or armature).
#[must_use]
pub fn forward_dynamics<const N: usize>(
    model: &SpatialModel<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> SVector<f64, N> {
    let rhs = tau - bias_forces(model, q, qd);
    match mass_matrix(model, q).cholesky() {
        Some(cholesky) => cholesky.solve(&rhs),
        None => SVector::repeat(f64::NAN),
    }
}
