//! The recursive Newton-Euler algorithm: inverse dynamics and its parts (bias, Coriolis),
//! and the joint friction.

use nalgebra::{SVector, Vector2};

use super::{
    absolute_angles, cross, directions_from, in_world, last_direction, link_directions, perp, sign,
    slides, steps,
};
use crate::Model;

/// Recursive Newton-Euler on precomputed link directions: `M(q) qdd + c(q, qd) + g(q)` for
/// gravity's acceleration `gravity`, armature included, friction not.
#[inline(always)]
pub(super) fn rnea_dirs<const N: usize>(
    model: &Model<N>,
    gravity: Vector2<f64>,
    dirs: &[Vector2<f64>; N],
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    let links = &model.links;
    // Outward pass. Gravity is modelled by accelerating the base against it.
    // `a_joint` is the acceleration of link i's frame origin, then of its end.
    let mut alpha = [0.0; N];
    let mut r_com = [Vector2::zeros(); N];
    let mut a_com = [Vector2::zeros(); N];
    let mut a_joint = -gravity;
    let mut omega = 0.0;
    let mut omega_dot = 0.0;
    for i in 0..N {
        let u = dirs[i];
        if slides(&links[i]) {
            // The origin slides by `q_i u` along a direction that turns with the previous
            // link: relative, Coriolis and transport accelerations. The rates stay.
            a_joint += u * (qdd[i] - q[i] * (omega * omega))
                + perp(u) * (2.0 * qd[i] * omega + q[i] * omega_dot);
        } else {
            omega += qd[i];
            omega_dot += qdd[i];
        }
        let r = in_world(u, links[i].com);
        // Acceleration of a point at `r` from the link's origin, relative to the origin:
        // tangential `omega_dot * perp(r)` plus centripetal `-omega^2 r`.
        a_com[i] = a_joint + perp(r) * omega_dot - r * (omega * omega);
        a_joint += (perp(u) * omega_dot - u * (omega * omega)) * links[i].length;
        alpha[i] = omega_dot;
        r_com[i] = r;
    }

    // Inward pass: `force` is the force link i exerts on what lies beyond link i+1's origin
    // (the tip for the last link), `moment` the moment it exerts about that point; on exit from
    // iteration i they refer to link i's origin. They start as the payload's inertial wrench
    // about the tip, the payload turning with the last link (`a_joint` is the tip's
    // acceleration by now).
    let payload = &model.payload;
    let r = in_world(last_direction(dirs), payload.com);
    let mut force = (a_joint + perp(r) * omega_dot - r * (omega * omega)) * payload.mass;
    let mut moment = payload.inertia * omega_dot + cross(r, force);
    let step = steps(links, dirs, q);
    let mut tau = SVector::zeros();
    for i in (0..N).rev() {
        let link = &links[i];
        let u = dirs[i];
        let f_com = a_com[i] * link.mass;
        // Euler's equation about the origin (a point with its own acceleration, hence the COM
        // term); the wrench beyond acts at `o_{i+1}`.
        moment += link.inertia * alpha[i] + cross(r_com[i], f_com) + cross(step[i], force);
        force += f_com;
        // A revolute joint carries the moment, a prismatic one the force along its axis; the
        // constraint takes the rest. The rotor's (or the slider's reflected) inertia acts on
        // the joint alone: it is not transmitted inwards.
        let carried = if slides(link) { u.dot(&force) } else { moment };
        tau[i] = carried + link.armature * qdd[i];
    }
    tau
}

/// Joint torques and forces `tau = M(q) qdd + c(q, qd) + g(q) + f(qd)`: the recursive
/// Newton-Euler algorithm for the bodies, plus each joint's armature term `armature_i qdd_i`
/// and its [`friction`].
///
/// O(N): an outward pass computes each link's angular velocity and acceleration and the linear
/// accelerations of its frame origin (slid by a prismatic joint) and centre of mass (gravity
/// enters as an upward base acceleration); an inward pass sums forces and moments about each
/// frame origin, starting from the payload's, and reads off the moment at a revolute joint and
/// the axial force at a prismatic one.
#[inline]
#[must_use]
pub fn inverse_dynamics<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return s.component_mul(&inverse_dynamics(
            &m,
            &s.component_mul(q),
            &s.component_mul(qd),
            &s.component_mul(qdd),
        ));
    }
    let dirs = link_directions(&model.links, q);
    rnea_dirs(model, model.gravity, &dirs, q, qd, qdd) + friction(model, qd) + springs(model, q)
}

/// [`inverse_dynamics`] with the absolute link angles' sines and cosines from
/// [`trig::sin_cos`](crate::trig::sin_cos), all in one call, instead of one `f64::sin_cos` per
/// revolute joint: the same recursion with the generated code's trigonometry, so that the
/// benchmarks can tell what the generated code gains from its trigonometry and what from its
/// arithmetic. The batch has one lane per joint; a prismatic joint's lane repeats the previous
/// angle and is not read.
#[inline]
#[must_use]
pub fn inverse_dynamics_batched_trig<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return s.component_mul(&inverse_dynamics_batched_trig(
            &m,
            &s.component_mul(q),
            &s.component_mul(qd),
            &s.component_mul(qdd),
        ));
    }
    let sin_cos = crate::trig::sin_cos(absolute_angles(&model.links, q));
    let dirs = directions_from(&model.links, &sin_cos);
    rnea_dirs(model, model.gravity, &dirs, q, qd, qdd) + friction(model, qd) + springs(model, q)
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
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return s.component_mul(&bias_forces(&m, &s.component_mul(q), &s.component_mul(qd)));
    }
    let dirs = link_directions(&model.links, q);
    rnea_dirs(model, model.gravity, &dirs, q, qd, &SVector::zeros())
        + friction(model, qd)
        + springs(model, q)
}

/// The velocity-product (Coriolis and centrifugal) terms `c(q, qd)`, torques and forces: the
/// rigid-body part of [`inverse_dynamics`] with zero gravity, `qdd = 0` and no friction.
#[inline]
#[must_use]
pub fn coriolis<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> SVector<f64, N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return s.component_mul(&coriolis(&m, &s.component_mul(q), &s.component_mul(qd)));
    }
    let dirs = link_directions(&model.links, q);
    rnea_dirs(model, Vector2::zeros(), &dirs, q, qd, &SVector::zeros())
}

/// The joint springs' torques (forces at prismatic joints) `stiffness_i (q_i - springref_i)`:
/// part of `g = dV/dq` ([`gravity_torques`](super::gravity_torques)), of the bias and of the
/// inverse dynamics; zero for a joint without a spring.
#[inline]
#[must_use]
pub fn springs<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SVector<f64, N> {
    SVector::from_fn(|i, _| {
        let l = &model.links[i];
        // Zero without a spring even where `q` is infinite.
        if l.stiffness == 0.0 {
            0.0
        } else {
            l.stiffness * (q[i] - l.springref)
        }
    })
}

/// The joint friction torques (forces at prismatic joints)
/// `f_i = damping_i qd_i + frictionloss_i sign(qd_i)`, with `sign(0) = 0`: viscous plus Coulomb
/// friction, opposing the motion when subtracted from the motor's effort (they are part of
/// `tau = M qdd + c + g + f`).
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
