//! The kinetic and potential energies, summed body by body.

use nalgebra::{SVector, Vector2};

use super::{in_world, last_direction, link_directions, perp, slides};
use crate::Model;

/// The kinetic energy, J: `sum(m_i |v_com_i|^2 + inertia_i omega_i^2 + armature_i qd_i^2) / 2`
/// over the links, plus the payload's `(m |v_com|^2 + inertia omega_N^2) / 2`, from the
/// centre-of-mass velocities (`omega_i` the absolute rate of link i, the sum of the revolute
/// rates up to i; `qd_i` its joint's own rate, rad/s or m/s). A prismatic joint adds
/// `qd_i u_i + q_i omega_i perp(u_i)` to the velocity of its link's frame origin.
#[inline]
#[must_use]
pub fn kinetic_energy<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> f64 {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return kinetic_energy(&m, &s.component_mul(q), &s.component_mul(qd));
    }
    let dirs = link_directions(&model.links, q);
    let mut v_joint = Vector2::zeros();
    let mut omega = 0.0;
    let mut energy = 0.0;
    for i in 0..N {
        let link = &model.links[i];
        let u = dirs[i];
        if slides(link) {
            v_joint += u * qd[i] + perp(u) * (omega * q[i]);
        } else {
            omega += qd[i];
        }
        let v_com = v_joint + perp(in_world(u, link.com)) * omega;
        energy += link.mass * v_com.norm_squared()
            + link.inertia * omega * omega
            + link.armature * qd[i] * qd[i];
        v_joint += perp(u) * (omega * link.length);
    }
    let payload = &model.payload;
    let v_payload = v_joint + perp(in_world(last_direction(&dirs), payload.com)) * omega;
    energy += payload.mass * v_payload.norm_squared() + payload.inertia * omega * omega;
    0.5 * energy
}

/// The potential energy, J: gravity's `-g . (sum(m_i p_com_i) + m_payload p_payload)`, zero
/// at the base origin (a prismatic joint moves its link's origin by `q_i u_i`), and the joint
/// springs' `sum stiffness_i (q_i - springref_i)^2 / 2`.
#[inline]
#[must_use]
pub fn potential_energy<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> f64 {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return potential_energy(&m, &s.component_mul(q));
    }
    let dirs = link_directions(&model.links, q);
    let mut joint = Vector2::zeros();
    let mut moment = Vector2::zeros();
    for ((link, &dir), &qi) in model.links.iter().zip(dirs.iter()).zip(q.iter()) {
        if slides(link) {
            joint += qi * dir;
        }
        moment += link.mass * (joint + in_world(dir, link.com));
        joint += link.length * dir;
    }
    let payload = &model.payload;
    moment += payload.mass * (joint + in_world(last_direction(&dirs), payload.com));
    let springs: f64 = model
        .links
        .iter()
        .zip(q.iter())
        .filter(|(l, _)| l.stiffness != 0.0)
        .map(|(l, &qi)| l.stiffness * (qi - l.springref) * (qi - l.springref) / 2.0)
        .sum();
    -model.gravity.dot(&moment) + springs
}
