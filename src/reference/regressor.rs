//! The numeric joint-torque regressor: the columns of `tau = Y(q, qd, qdd) theta` by the
//! Newton-Euler recursion, with each body's wrench per unit parameter moved to the joints
//! before it: in the world frame at once ([`regressor`]), or joint by joint in local frames as
//! Pinocchio's `computeJointTorqueRegressor` does ([`regressor_local`]). A revolute joint reads
//! the wrench's moment about its link's frame origin, a prismatic joint its force along the
//! joint's axis.

use nalgebra::{SMatrix, SVector, Vector2, Vector4};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use super::{cross, link_directions, perp, sign, slides};
use crate::{Link, Model, Payload};

/// The regressor of the standard parameters at one state, in blocks.
///
/// Body `j` (a link, or the payload) enters the torques through four parameters, in its own
/// frame and about its own frame origin, the joint (the payload's are in the last link's frame,
/// about its origin):
/// `[zz, mx, my, m] = [Izz + m |c|^2, m cx, m cy, m]`. Its block is the `N x 4` matrix of the
/// generalised forces (torques at revolute joints, axial forces at prismatic ones) those four
/// parameters produce per unit value. A joint's armature, damping and
/// Coulomb friction act on that joint alone, so their columns are `qdd_i`, `qd_i` and
/// `sign(qd_i)` (with `sign(0) = 0`) in row `i` and zero elsewhere; they are kept as vectors.
///
/// [`column`](Self::column) reads a column by the names of the generated
/// [`Identification::PARAMETERS`](crate::Identification::PARAMETERS), so the generated
/// regressor can be checked column by column against this one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Regressor<const N: usize> {
    /// Per link, the torques of `[zz, mx, my, m]`.
    pub links: [SMatrix<f64, N, 4>; N],
    /// The payload's `[zz, mx, my, m]`, in the last link's frame about its origin (the last
    /// joint).
    pub payload: SMatrix<f64, N, 4>,
    /// `qdd`: the armature column of joint `i` is `armature[i]` in row `i`.
    pub armature: SVector<f64, N>,
    /// `qd`: the damping (viscous friction) columns, one per joint, on the diagonal.
    pub damping: SVector<f64, N>,
    /// `sign(qd)`: the Coulomb friction columns, one per joint, on the diagonal.
    pub coulomb: SVector<f64, N>,
}

impl<const N: usize> Regressor<N> {
    /// The regressor of a plain model at `s q` as that of the model with joints reversed where
    /// `s` is `-1`: each row times `s`, the joints' own columns at the model's `qd`, `qdd`.
    fn sensed(self, s: &SVector<f64, N>, qd: &SVector<f64, N>, qdd: &SVector<f64, N>) -> Self {
        let rows = SMatrix::<f64, N, N>::from_diagonal(s);
        Self {
            links: self.links.map(|b| rows * b),
            payload: rows * self.payload,
            ..Self::with_joint_columns(qd, qdd)
        }
    }

    /// The joints' own columns at these rates and accelerations, the bodies' still zero.
    fn with_joint_columns(qd: &SVector<f64, N>, qdd: &SVector<f64, N>) -> Self {
        Self {
            links: [SMatrix::zeros(); N],
            payload: SMatrix::zeros(),
            armature: *qdd,
            damping: *qd,
            coulomb: qd.map(sign),
        }
    }

    /// The column of the standard parameter called `name` (`zz2`, `mx1`, `myp`, `m3`, `ia1`,
    /// `fv2`, `fc1`; links count from 1, `p` is the payload), or `None` for a name that is not
    /// one of them.
    #[must_use]
    pub fn column(&self, name: &str) -> Option<SVector<f64, N>> {
        let split = name.find(|c: char| c.is_ascii_digit() || c == 'p')?;
        let (kind, index) = name.split_at(split);
        let block = if index == "p" {
            &self.payload
        } else {
            let j: usize = index.parse().ok()?;
            if !(1..=N).contains(&j) || index.starts_with('0') {
                return None;
            }
            match kind {
                "ia" | "fv" | "fc" => {
                    let diag = match kind {
                        "ia" => self.armature,
                        "fv" => self.damping,
                        _ => self.coulomb,
                    };
                    let mut col = SVector::zeros();
                    col[j - 1] = diag[j - 1];
                    return Some(col);
                }
                _ => &self.links[j - 1],
            }
        };
        let k = ["zz", "mx", "my", "m"].iter().position(|&k| k == kind)?;
        Some(block.column(k).into_owned())
    }

    /// `Y theta` for the model's own parameter values: the torques
    /// [`inverse_dynamics`](super::inverse_dynamics) computes.
    #[must_use]
    pub fn torques(&self, model: &Model<N>) -> SVector<f64, N> {
        let mut tau = self.payload * payload_parameters(model);
        for (block, link) in self.links.iter().zip(model.links.iter()) {
            tau += block * link_parameters(link);
        }
        for (i, link) in model.links.iter().enumerate() {
            tau[i] += link.armature * self.armature[i]
                + link.damping * self.damping[i]
                + link.frictionloss * self.coulomb[i];
        }
        tau
    }
}

/// A link's `[zz, mx, my, m]`: inertia about its joint, first moments, mass.
#[must_use]
pub fn link_parameters(link: &Link) -> Vector4<f64> {
    let m = link.mass;
    Vector4::new(
        link.inertia_about_joint(),
        m * link.com.x,
        m * link.com.y,
        m,
    )
}

/// The payload's `[zz, mx, my, m]` as a body of the last link: in that link's frame, about its
/// joint (the payload's centre of mass is `length + com.x` along the link).
#[must_use]
pub fn payload_parameters<const N: usize>(model: &Model<N>) -> Vector4<f64> {
    let Payload {
        mass: m,
        inertia,
        com,
    } = model.payload;
    let c = com + Vector2::new(model.links.last().map_or(0.0, |l| l.length), 0.0);
    Vector4::new(inertia + m * c.norm_squared(), m * c.x, m * c.y, m)
}

/// The regressor at `(q, qd, qdd)`: it depends on the model's lengths, joint kinds and gravity
/// only.
///
/// An outward pass gives each body's frame origin `p_j` (slid by a prismatic joint), direction
/// `u_j`, angular rate and acceleration, and origin acceleration `a_j` (gravity as an upward
/// base acceleration). A body with first moment `h` (world frame, from its origin) and inertia
/// `zz` about its origin feels the force `f = m a_j + alpha perp(h) - omega^2 h` and the moment
/// `n = zz alpha + h x a_j` about its origin, linear in `[zz, mx, my, m]` since
/// `h = mx u_j + my perp(u_j)`. Its torque at a revolute joint `i <= j` is
/// `n + (p_j - p_i) x f`, the moment about the world origin less `p_i x f`; its force at a
/// prismatic joint `i <= j` is `u_i . f`. O(N^2), no allocation.
#[must_use]
pub fn regressor<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> Regressor<N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return regressor(
            &m,
            &s.component_mul(q),
            &s.component_mul(qd),
            &s.component_mul(qdd),
        )
        .sensed(&s, qd, qdd);
    }
    let dirs = link_directions(&model.links, q);
    let mut joints = [Axis::About(Vector2::zeros()); N];
    let mut out = Regressor::with_joint_columns(qd, qdd);
    let mut p = Vector2::zeros();
    let mut a = -model.gravity;
    let (mut omega, mut alpha) = (0.0, 0.0);
    // The payload is a body of the last link's frame about the last joint (the base's for an
    // arm of no links): the last block starts where its link's did.
    let mut last = (p, Vector2::x(), a);
    for j in 0..N {
        let u = dirs[j];
        if slides(&model.links[j]) {
            p += u * q[j];
            a += u * (qdd[j] - q[j] * (omega * omega))
                + perp(u) * (2.0 * qd[j] * omega + q[j] * alpha);
            joints[j] = Axis::Along(u);
        } else {
            omega += qd[j];
            alpha += qdd[j];
            joints[j] = Axis::About(p);
        }
        last = (p, u, a);
        out.links[j] = body_block(&joints[..=j], p, u, omega, alpha, a);
        let l = model.links[j].length;
        a += (perp(u) * alpha - u * (omega * omega)) * l;
        p += u * l;
    }
    let (p, u, a) = last;
    out.payload = body_block(&joints, p, u, omega, alpha, a);
    out
}

/// [`regressor`] by the algorithm of Pinocchio's `computeJointTorqueRegressor`, specialised to
/// the plane: each body's regressor in its own frame, moved inwards one joint at a time.
///
/// An outward pass gives, in each link's own frame (x along the link), its rate, acceleration
/// and origin acceleration, with one `sin_cos` of each revolute joint's *relative* angle (a
/// prismatic joint does not turn its frame); each body's `[n; fx; fy]` per unit parameter is
/// formed there, then rotated into the previous link's frame and its moment shifted to that
/// link's origin, joint by joint down to the base, each revolute joint reading the moment about
/// its origin and each prismatic joint the force along x, its axis in its own link's frame.
/// O(N^2), like [`regressor`], with more arithmetic
/// per step (a rotation of four forces); it is the baseline the issue that asked for the
/// regressor named, [`regressor`] a tighter one.
#[must_use]
pub fn regressor_local<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> Regressor<N> {
    // A reversed joint is a plain one at -q_i (see `unreversed`).
    if let Some((m, s)) = super::unreversed(model) {
        return regressor_local(
            &m,
            &s.component_mul(q),
            &s.component_mul(qd),
            &s.component_mul(qdd),
        )
        .sensed(&s, qd, qdd);
    }
    let links = &model.links;
    // The rotation of each joint's frame from the previous one's: a revolute joint's angle and
    // offset; a prismatic joint's offset, if any (without, its frame keeps the previous one's).
    let rot: [Option<(f64, f64)>; N] = core::array::from_fn(|i| {
        let l = &links[i];
        match (slides(l), l.offset != 0.0) {
            (false, _) => Some((q[i] + l.offset).sin_cos()),
            (true, true) => Some(l.offset.sin_cos()),
            (true, false) => None,
        }
    });
    // Link i+1's origin in link i's frame: its length along x, then the next joint's slide
    // along that joint's axis.
    let step: [Vector2<f64>; N] = core::array::from_fn(|i| {
        let along = Vector2::new(links[i].length, 0.0);
        match (links.get(i + 1), q.get(i + 1)) {
            (Some(next), Some(&slide)) if slides(next) => {
                let (s, c) = next.offset.sin_cos();
                along + Vector2::new(c, s) * slide
            }
            _ => along,
        }
    });
    let mut out = Regressor::with_joint_columns(qd, qdd);
    // The acceleration of the end of link j-1 (the base's origin for j = 0) in its frame, then
    // of link j's origin in link j's frame.
    let mut a = -model.gravity;
    let (mut omega, mut alpha) = (0.0, 0.0);
    for j in 0..N {
        if let Some((s, c)) = rot[j] {
            a = Vector2::new(c * a.x + s * a.y, c * a.y - s * a.x);
        }
        if !slides(&links[j]) {
            omega += qd[j];
            alpha += qdd[j];
        } else {
            // The origin slides along x by q_j (see `regressor`), in a frame turning at omega.
            a += Vector2::new(
                qdd[j] - q[j] * (omega * omega),
                2.0 * qd[j] * omega + q[j] * alpha,
            );
        }
        let w2 = omega * omega;
        // Rows: the moment about link j's origin and the force, per unit zz, mx, my, m.
        let mut body = nalgebra::Matrix3x4::new(
            alpha, a.y, -a.x, 0.0, //
            0.0, -w2, -alpha, a.x, //
            0.0, alpha, -w2, a.y,
        );
        // A revolute joint reads the moment (row 0), a prismatic one the force along x (row 1).
        let read = |i: usize| usize::from(slides(&links[i]));
        out.links[j].set_row(j, &body.row(read(j)));
        for i in (0..j).rev() {
            // Into the frame of link i: rotate by joint i+1's turn (if it turns), shift the
            // moment from link i+1's origin to link i's (by `step_i`).
            let d = step[i];
            for k in 0..4 {
                let (fx, fy) = (body[(1, k)], body[(2, k)]);
                let (gx, gy) = match rot[i + 1] {
                    Some((s, c)) => (c * fx - s * fy, s * fx + c * fy),
                    None => (fx, fy),
                };
                body[(0, k)] += d.x * gy - d.y * gx;
                body[(1, k)] = gx;
                body[(2, k)] = gy;
            }
            out.links[j].set_row(i, &body.row(read(i)));
        }
        let l = model.links[j].length;
        a += Vector2::new(-w2 * l, alpha * l);
    }
    if let Some(last) = out.links.last() {
        out.payload = *last;
    }
    out
}

/// How a joint reads a wrench: a revolute joint its moment about the point (its link's frame
/// origin, world frame), a prismatic joint its force along the direction (its axis).
#[derive(Clone, Copy)]
enum Axis {
    About(Vector2<f64>),
    Along(Vector2<f64>),
}

/// The `N x 4` block of a body at frame origin `p` with direction `u`, rate `omega`,
/// acceleration `alpha` and origin acceleration `a`, seen from the joints `joints` (those at or
/// before it; later rows stay zero).
#[inline(always)]
fn body_block<const N: usize>(
    joints: &[Axis],
    p: Vector2<f64>,
    u: Vector2<f64>,
    omega: f64,
    alpha: f64,
    a: Vector2<f64>,
) -> SMatrix<f64, N, 4> {
    let w2 = omega * omega;
    let v = perp(u);
    // Per parameter: the force and the moment about the body's origin per unit value.
    let forces = [Vector2::zeros(), v * alpha - u * w2, -u * alpha - v * w2, a];
    let moments = [alpha, cross(u, a), cross(v, a), 0.0];
    let mut block = SMatrix::<f64, N, 4>::zeros();
    for (k, (f, n)) in forces.iter().zip(moments).enumerate() {
        let about_origin = n + cross(p, *f);
        for (i, joint) in joints.iter().enumerate() {
            block[(i, k)] = match joint {
                Axis::About(point) => about_origin - cross(*point, *f),
                Axis::Along(axis) => axis.dot(f),
            };
        }
    }
    block
}
