//! The articulated body algorithm: forward dynamics in O(N) without the mass matrix.

use nalgebra::{Matrix3, SVector, Vector2, Vector3};

use super::newton_euler::{friction, springs};
use super::{in_world, last_direction, link_directions, slides};
use crate::Model;

/// Planar spatial motion cross product `v x m` for vectors `[angular; x; y]`.
#[inline(always)]
fn cross_motion(v: &Vector3<f64>, m: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(0.0, v.z * m.x - v.x * m.z, v.x * m.y - v.y * m.x)
}

/// Planar spatial force cross product `v x* f` for vectors `[angular; x; y]`.
#[inline(always)]
fn cross_force(v: &Vector3<f64>, f: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(v.y * f.z - v.z * f.y, -v.x * f.z, v.x * f.y)
}

/// The planar spatial inertia about the world origin of a body of mass `m`, rotational inertia
/// `inertia` about its centre of mass, with the centre of mass at `c`.
#[inline(always)]
fn spatial_inertia(m: f64, inertia: f64, c: Vector2<f64>) -> Matrix3<f64> {
    let mx = m * c.x;
    let my = m * c.y;
    Matrix3::new(
        inertia + mx * c.x + my * c.y,
        -my,
        mx,
        -my,
        m,
        0.0,
        mx,
        0.0,
        m,
    )
}

/// Joint accelerations `qdd` that solve `M qdd = tau - c - g - f` by the articulated body
/// algorithm.
///
/// O(N), and never forms the mass matrix. This is Featherstone's ABA specialised to the plane:
/// spatial vectors are `[angular; x; y]` with 3x3 spatial inertias, all expressed in the world
/// frame about the origin, so that the joint axes are `S_i = [1, y_i, -x_i]` for a revolute
/// joint (with `(x_i, y_i)` the link's frame origin) and `S_i = [0, u_i]`, a translation along
/// the axis, for a prismatic one, and no coordinate transforms are needed between links. Each
/// axis is fixed in the previous link (a revolute joint's point, a prismatic joint's
/// direction), so its rate is `v_{i-1} x S_i` and the velocity-product acceleration
/// `v_i x S_i qd_i`, as in three dimensions. Three passes:
/// velocities and velocity-product terms outwards, articulated inertias and bias forces
/// inwards, accelerations outwards (gravity as an upward base acceleration). The payload's
/// spatial inertia is added to the last link's; the armature enters the joint-space
/// articulated inertia `D_i = S_i^T I^A_i S_i + armature_i`, the friction the joint's torque
/// or force.
///
/// The result is meaningless (non-finite) if the arm has a degenerate articulated inertia, e.g.
/// a massless, inertialess last link without armature or payload.
#[must_use]
pub fn forward_dynamics<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> SVector<f64, N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return s.component_mul(&forward_dynamics(
            &m,
            &s.component_mul(q),
            &s.component_mul(qd),
            &s.component_mul(tau),
        ));
    }
    let links = &model.links;
    let dirs = link_directions(links, q);

    // Pass 1 (outwards): joint axes, velocities, velocity-product accelerations, rigid-body
    // inertias and bias forces. `joint` is link i's frame origin, then its end.
    let mut axis = [Vector3::zeros(); N];
    let mut c = [Vector3::zeros(); N];
    let mut inertia = [Matrix3::zeros(); N];
    let mut bias = [Vector3::zeros(); N];
    let mut joint = Vector2::zeros();
    let mut v = Vector3::zeros();
    for i in 0..N {
        let link = &links[i];
        let u = dirs[i];
        let s = if slides(link) {
            joint += u * q[i];
            Vector3::new(0.0, u.x, u.y)
        } else {
            Vector3::new(1.0, joint.y, -joint.x)
        };
        let vj = s * qd[i];
        v += vj;
        c[i] = cross_motion(&v, &vj);
        let ii = spatial_inertia(link.mass, link.inertia, joint + in_world(dirs[i], link.com));
        bias[i] = cross_force(&v, &(ii * v));
        inertia[i] = ii;
        axis[i] = s;
        joint += dirs[i] * link.length;
    }
    // The payload moves with the last link (`joint` is the tip, `v` the last link's velocity).
    if let (Some(last_inertia), Some(last_bias)) = (inertia.last_mut(), bias.last_mut()) {
        let payload = &model.payload;
        let centre = joint + in_world(last_direction(&dirs), payload.com);
        let ip = spatial_inertia(payload.mass, payload.inertia, centre);
        *last_inertia += ip;
        *last_bias += cross_force(&v, &(ip * v));
    }

    // Pass 2 (inwards): articulated-body inertias and bias forces.
    // Friction and the springs are known torques at the joints.
    let f = friction(model, qd) + springs(model, q);
    let mut u_vec = [Vector3::zeros(); N];
    let mut d_inv = [0.0; N];
    let mut u_sc = [0.0; N];
    for i in (0..N).rev() {
        let s = axis[i];
        let u = inertia[i] * s;
        let di = 1.0 / (s.dot(&u) + links[i].armature);
        let ui = tau[i] - f[i] - s.dot(&bias[i]);
        if i > 0 {
            let ia = inertia[i] - (u * u.transpose()) * di;
            let pa = bias[i] + ia * c[i] + u * (ui * di);
            inertia[i - 1] += ia;
            bias[i - 1] += pa;
        }
        u_vec[i] = u;
        d_inv[i] = di;
        u_sc[i] = ui;
    }

    // Pass 3 (outwards): accelerations.
    let mut qdd = SVector::zeros();
    let mut a = Vector3::new(0.0, -model.gravity.x, -model.gravity.y);
    for i in 0..N {
        a += c[i];
        let qddi = (u_sc[i] - u_vec[i].dot(&a)) * d_inv[i];
        a += axis[i] * qddi;
        qdd[i] = qddi;
    }
    qdd
}
