//! The recursive Newton-Euler algorithm: inverse dynamics and its parts (bias, Coriolis),
//! and the joint friction.

use nalgebra::{SVector, Vector2};

use super::{absolute_angles, cross, in_world, last_direction, link_directions, perp, sign};
use crate::Model;

/// Recursive Newton-Euler on precomputed link directions: `M(q) qdd + c(q, qd) + g(q)` for
/// gravity of magnitude `gravity`, armature included, friction not.
#[inline(always)]
pub(super) fn rnea_dirs<const N: usize>(
    model: &Model<N>,
    gravity: f64,
    dirs: &[Vector2<f64>; N],
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    let links = &model.links;
    // Outward pass. Gravity is modelled by accelerating the base upwards at `gravity`.
    let mut alpha = [0.0; N];
    let mut r_com = [Vector2::zeros(); N];
    let mut a_com = [Vector2::zeros(); N];
    let mut a_joint = Vector2::new(0.0, gravity);
    let mut omega = 0.0;
    let mut omega_dot = 0.0;
    for i in 0..N {
        omega += qd[i];
        omega_dot += qdd[i];
        let u = dirs[i];
        let r = in_world(u, links[i].com);
        // Acceleration of a point at `r` from the link's joint, relative to the joint:
        // tangential `omega_dot * perp(r)` plus centripetal `-omega^2 r`.
        a_com[i] = a_joint + perp(r) * omega_dot - r * (omega * omega);
        a_joint += (perp(u) * omega_dot - u * (omega * omega)) * links[i].length;
        alpha[i] = omega_dot;
        r_com[i] = r;
    }

    // Inward pass: `force` is the force link i exerts on what lies beyond joint i+1 (the tip
    // for the last link), `moment` the moment it exerts there; on exit from iteration i they
    // refer to joint i. They start as the payload's inertial wrench about the tip, the payload
    // turning with the last link (`a_joint` is the tip's acceleration by now).
    let payload = &model.payload;
    let r = in_world(last_direction(dirs), payload.com);
    let mut force = (a_joint + perp(r) * omega_dot - r * (omega * omega)) * payload.mass;
    let mut moment = payload.inertia * omega_dot + cross(r, force);
    let mut tau = SVector::zeros();
    for i in (0..N).rev() {
        let link = &links[i];
        let u = dirs[i];
        let f_com = a_com[i] * link.mass;
        // Euler's equation about joint i (a point with its own acceleration, hence the COM term).
        moment += link.inertia * alpha[i] + cross(r_com[i], f_com) + link.length * cross(u, force);
        force += f_com;
        // The rotor's torque acts on the joint alone; it is not transmitted inwards.
        tau[i] = moment + link.armature * qdd[i];
    }
    tau
}

/// Joint torques `tau = M(q) qdd + c(q, qd) + g(q) + f(qd)`: the recursive Newton-Euler
/// algorithm for the bodies, plus each joint's armature torque `armature_i qdd_i` and its
/// [`friction`].
///
/// O(N): an outward pass computes each link's angular velocity and acceleration and the linear
/// accelerations of its joint and centre of mass (gravity enters as an upward base acceleration);
/// an inward pass sums forces and moments about each joint, starting from the payload's.
#[inline]
#[must_use]
pub fn inverse_dynamics<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea_dirs(model, model.gravity, &link_directions(q), qd, qdd) + friction(model, qd)
}

/// [`inverse_dynamics`] with the absolute link angles' sines and cosines from
/// [`trig::sin_cos`](crate::trig::sin_cos), all in one call, instead of one `f64::sin_cos` per
/// link: the same recursion with the generated code's trigonometry, so that the benchmarks can
/// tell what the generated code gains from its trigonometry and what from its arithmetic.
#[inline]
#[must_use]
pub fn inverse_dynamics_batched_trig<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    let dirs = crate::trig::sin_cos(absolute_angles(q)).map(|(s, c)| Vector2::new(c, s));
    rnea_dirs(model, model.gravity, &dirs, qd, qdd) + friction(model, qd)
}

/// The bias forces `c(q, qd) + g(q) + f(qd)`: [`inverse_dynamics`] with `qdd = 0`.
///
/// Pinocchio's `nonLinearEffects` and MuJoCo's `qfrc_bias` are `c + g`, without the friction.
#[inline]
#[must_use]
pub fn bias_forces<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea_dirs(
        model,
        model.gravity,
        &link_directions(q),
        qd,
        &SVector::zeros(),
    ) + friction(model, qd)
}

/// The velocity-product (Coriolis and centrifugal) torques `c(q, qd)`: the rigid-body part of
/// [`inverse_dynamics`] with zero gravity, `qdd = 0` and no friction.
#[inline]
#[must_use]
pub fn coriolis<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea_dirs(model, 0.0, &link_directions(q), qd, &SVector::zeros())
}

/// The joint friction torques `f_i = damping_i qd_i + frictionloss_i sign(qd_i)`, with
/// `sign(0) = 0`: viscous plus Coulomb friction, opposing the motion when subtracted from the
/// motor torque (they are part of `tau = M qdd + c + g + f`).
///
/// A joint at rest feels no Coulomb friction here (MuJoCo instead solves for static friction
/// as a constraint). NaN in `qd` gives NaN in the result.
#[inline]
#[must_use]
pub fn friction<const N: usize>(model: &Model<N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
    let mut f = SVector::<f64, N>::zeros();
    for ((fi, link), &w) in f.iter_mut().zip(model.links.iter()).zip(qd.iter()) {
        *fi = link.damping * w + link.frictionloss * sign(w);
    }
    f
}
