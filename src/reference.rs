//! Independent numeric reference implementations of planar-arm dynamics and kinematics.
//!
//! Everything here is plain `f64` arithmetic written from first principles (Newton-Euler
//! mechanics and Featherstone's spatial-vector algorithms specialised to the plane). It shares
//! no code with the symbolic Lagrangian path of `#[derive(PlanarArm)]`, so the tests, the
//! benchmarks and the `paper` example use it as the ground truth the generated code is checked
//! and timed against. Every function takes the arm as a [`Model`]: links,
//! gravity, payload.
//!
//! # Conventions
//!
//! Those of the crate, for any mix of revolute and prismatic joints (`model.links[i].joint`).
//! Link i (0-based) has an absolute angle `phi_i`, a direction `u_i = (cos phi_i, sin phi_i)`
//! and a frame origin `o_i`, the point its own frame (`x` along `u_i`) is fixed at:
//!
//! - a revolute joint i turns link i about the end of the previous link by `q[i]` radians:
//!   `phi_i = phi_{i-1} + q[i]` and `o_i = o_{i-1} + l_{i-1} u_{i-1}`;
//! - a prismatic joint i slides link i along the previous link's direction by `q[i]` metres
//!   without turning it: `phi_i = phi_{i-1}` (so `u_i = u_{i-1}` is its axis) and
//!   `o_i = o_{i-1} + (l_{i-1} + q[i]) u_{i-1}`,
//!
//! where `o_{-1} + l_{-1} u_{-1}` is the base origin and `phi_{-1} = 0`: the first joint turns
//! about the origin or slides along +x. A joint's [`offset`](crate::Link::offset) adds to
//! `phi_i` (a prismatic joint's too, so that it slides along `u_i`, turned from `u_{i-1}`, and
//! `o_i = o_{i-1} + l_{i-1} u_{i-1} + q[i] u_i`); a [`reversed`](crate::Link::reversed) joint
//! is the plain one at `-q[i]`, its generalised force negated, which is how every function
//! here treats it. So `phi_i` sums the revolute `q`s up to `i`, and a link
//! starts at the origin unless the first joint is prismatic. [`joint_positions`] are the
//! `o_i` (for a prismatic joint the slid carriage, not the end of the link before it), the
//! tip is `o_{N-1} + l_{N-1} u_{N-1}`, its orientation `phi_{N-1}` ([`tip_orientation`]).
//! Gravity is the acceleration `model.gravity` (`(0, -g)` for the usual -y). A link's centre of mass
//! `com = (cx, cy)` is in its own frame, at `o_i + cx u_i + cy perp(u_i)` in the world
//! (`perp` turns by +90 degrees); the payload's is at `tip + R(phi_{N-1}) payload.com`.
//!
//! The equations of motion are
//!
//! ```text
//! tau = M(q) qdd + c(q, qd) + g(q) + f(qd)
//! ```
//!
//! with `M` the mass matrix including each joint's armature on its diagonal, `c` the
//! velocity-product terms, `g = dV/dq` the gravity terms and
//! `f_i = damping_i qd_i + frictionloss_i sign(qd_i)` the joint friction ([`friction`];
//! `sign(0) = 0`). These are MuJoCo's joint `armature`, `damping` and `frictionloss`.
//! [`bias_forces`] is `c + g + f`; Pinocchio's `nonLinearEffects` is `c + g`. The generalised
//! force `tau_i` of a revolute joint is a torque (N m); that of a prismatic joint is the force
//! along its axis `u_i` (N), its armature a reflected mass (kg, kinetic energy
//! `armature qd_i^2 / 2`), its damping N s/m and its frictionloss N.
//!
//! # Algorithms and cost
//!
//! All functions are generic over the number of links `N`, work on fixed-size arrays and
//! nalgebra `SVector`/`SMatrix` values, never allocate, never panic, and evaluate exactly one
//! `sin_cos` per revolute joint (of the cumulative absolute angle); a prismatic joint reuses
//! the direction of the link before it. The payload enters each algorithm as one more body
//! rigidly fixed beyond the tip (the Newton-Euler recursion starts from its inertial wrench at
//! the tip, the composite and articulated inertias start from its inertia), not through
//! [`Model::rigid_links`](crate::Model::rigid_links), which the tests check against.
//!
//! A prismatic joint enters each algorithm in two places. Outwards, its frame origin slides:
//! `o_i` gains `q_i u_i`, its velocity `qd_i u_i + q_i omega perp(u_i)` and its acceleration
//! `(qdd_i - q_i omega^2) u_i + (2 qd_i omega + q_i alpha) perp(u_i)` (`omega`, `alpha` the
//! rate and acceleration of the previous link, which the joint does not change). Inwards, its
//! generalised force is the axial component `u_i . F` of the force it transmits, where a
//! revolute joint's is the moment about `o_i`; moments are shifted between frame origins by
//! `o_{i+1} - o_i = reach_i u_i`, with `reach_i` the link's length plus the next joint's slide.
//!
//! | function | algorithm | cost |
//! |---|---|---|
//! | [`inverse_dynamics`], [`bias_forces`], [`coriolis`] | recursive Newton-Euler (RNEA): outward pass for angular velocity/acceleration and frame-origin/COM linear accelerations (gravity as the base accelerating at `-g`), inward pass for the forces and moments at each frame origin, read as the moment (revolute) or the axial force (prismatic); armature and friction added per joint | O(N) |
//! | [`gravity_torques`] | inward accumulation of composite mass and first moment `F` (statics): `-g . perp(F)` about `o_i` (revolute), or `-g . u_i` times the composite's mass (prismatic) | O(N) |
//! | [`friction`] | per joint | O(N) |
//! | [`mass_matrix`] | composite rigid body algorithm (CRBA) with planar composite inertias (mass, first moment, rotational inertia about each frame origin): a unit rate of joint j gives the composite beyond it the momentum `(rot, perp(first))` (revolute) or `(first x u_j, mass u_j)` (prismatic), read at each joint before it as a moment or an axial component; armature on the diagonal | O(N^2) |
//! | [`forward_dynamics`] | articulated body algorithm (ABA) with 3x3 planar spatial inertias `[angular; x; y]`, all expressed about the world origin so that no inter-link transforms are needed: the motion subspace is `S_i = [1, y_i, -x_i]` for a revolute joint at `o_i = (x_i, y_i)` and `S_i = [0, u_i]`, a translation along the axis, for a prismatic one; armature in the joint-space articulated inertia; never forms `M` | O(N) |
//! | [`forward_dynamics_crba`] | CRBA + RNEA bias + Cholesky solve | O(N^3) |
//! | [`kinetic_energy`], [`potential_energy`] | direct sums over COM velocities / heights, payload as its own body | O(N) |
//! | [`tip_position`], [`tip_orientation`], [`joint_positions`], [`jacobian`] | forward kinematics; the Jacobian column of joint j is `[perp(tip - o_j); 1]` (revolute) or `[u_j; 0]` (prismatic) | O(N) each |
//! | [`regressor`] | the generalised forces of each body's four inertial parameters per unit value, by one outward Newton-Euler pass and each body's wrench moved to every joint before it | O(N^2) |
//! | [`regressor_local`] | the same by Pinocchio's `computeJointTorqueRegressor` algorithm: each body's regressor in its own frame, moved inwards joint by joint | O(N^2) |

use nalgebra::{SVector, Vector2};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use crate::{Joint, Link, Model};

mod articulated;
mod composite;
mod energy;
mod kinematics;
mod newton_euler;
mod regressor;
pub mod spatial;

pub use articulated::forward_dynamics;
pub use composite::{forward_dynamics_crba, gravity_torques, mass_matrix};
pub use energy::{kinetic_energy, potential_energy};
pub use kinematics::{jacobian, joint_positions, tip_angle, tip_orientation, tip_position};
pub use newton_euler::{
    bias_forces, coriolis, friction, inverse_dynamics, inverse_dynamics_batched_trig, springs,
};
pub use regressor::{link_parameters, payload_parameters, regressor, regressor_local, Regressor};

/// Whether a link's joint slides it along the previous link's direction (prismatic) rather
/// than turning it (revolute).
#[inline(always)]
fn slides(link: &Link) -> bool {
    link.joint == Joint::Prismatic
}

/// Unit vectors `u_i = (cos phi_i, sin phi_i)` along each link: one `sin_cos` of the cumulative
/// absolute angle per revolute joint; a prismatic joint keeps the previous link's direction
/// (+x for the first link).
#[inline(always)]
fn link_directions<const N: usize>(links: &[Link; N], q: &SVector<f64, N>) -> [Vector2<f64>; N] {
    // A plain loop: mapping over `absolute_angles` instead measured 2-6 % slower, and the
    // reference is not to be pessimised.
    let mut dirs = [Vector2::zeros(); N];
    let mut phi = 0.0;
    let mut u = Vector2::x();
    for ((dir, &qi), link) in dirs.iter_mut().zip(q.iter()).zip(links.iter()) {
        if !slides(link) || link.offset != 0.0 {
            phi += link.offset;
            if !slides(link) {
                phi += qi;
            }
            let (s, c) = phi.sin_cos();
            u = Vector2::new(c, s);
        }
        *dir = u;
    }
    dirs
}

/// `model` with its reversed joints turned the standard way, and the senses `s` (`-1` at a
/// reversed joint, else `1`), if any joint is reversed: a reversed joint's `q_i` is the plain
/// one's `-q_i`, so the model's quantities at `q` are the plain model's at `s q`, generalised
/// forces (and rows) times `s`.
fn unreversed<const N: usize>(model: &Model<N>) -> Option<(Model<N>, SVector<f64, N>)> {
    if model.links.iter().all(|l| !l.reversed) {
        return None;
    }
    let mut plain = *model;
    let s = SVector::from_fn(|i, _| if model.links[i].reversed { -1.0 } else { 1.0 });
    for l in &mut plain.links {
        if l.reversed {
            // Its spring is slack where the plain joint is at -springref.
            l.springref = -l.springref;
        }
        l.reversed = false;
    }
    Some((plain, s))
}

/// Each link's absolute angle `phi_i`, the offsets and the revolute joints' `q` up to `i`,
/// for one batched `sin_cos`.
#[inline(always)]
fn absolute_angles<const N: usize>(links: &[Link; N], q: &SVector<f64, N>) -> [f64; N] {
    let mut phi = 0.0;
    core::array::from_fn(|i| {
        phi += links[i].offset;
        if !slides(&links[i]) {
            phi += q[i];
        }
        phi
    })
}

/// [`link_directions`] from the sines and cosines of [`absolute_angles`]: the entry of a
/// prismatic joint without an offset is not read, its link keeps the previous direction, as
/// there.
#[inline(always)]
fn directions_from<const N: usize>(
    links: &[Link; N],
    sin_cos: &[(f64, f64); N],
) -> [Vector2<f64>; N] {
    let mut u = Vector2::x();
    core::array::from_fn(|i| {
        if !slides(&links[i]) || links[i].offset != 0.0 {
            let (s, c) = sin_cos[i];
            u = Vector2::new(c, s);
        }
        u
    })
}

/// `o_{i+1} - o_i`, from link i's frame origin to the next link's (to the tip for the last
/// link): its length along `u_i`, plus the next joint's slide `q_{i+1} u_{i+1}` if that joint
/// is prismatic.
#[inline(always)]
fn steps<const N: usize>(
    links: &[Link; N],
    dirs: &[Vector2<f64>; N],
    q: &SVector<f64, N>,
) -> [Vector2<f64>; N] {
    core::array::from_fn(|i| match (links.get(i + 1), q.get(i + 1)) {
        (Some(next), Some(&slide)) if slides(next) => {
            dirs[i] * links[i].length + dirs[i + 1] * slide
        }
        _ => dirs[i] * links[i].length,
    })
}

/// The direction of the last link, the frame the payload is fixed in (+x with no links).
#[inline(always)]
fn last_direction<const N: usize>(dirs: &[Vector2<f64>; N]) -> Vector2<f64> {
    dirs.last().copied().unwrap_or_else(Vector2::x)
}

/// `a` rotated by +90 degrees.
#[inline(always)]
fn perp(a: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-a.y, a.x)
}

/// The vector `c`, given in the frame of a link with direction `u`, in the world frame:
/// `c.x u + c.y perp(u)`.
#[inline(always)]
fn in_world(u: Vector2<f64>, c: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(c.x * u.x - c.y * u.y, c.x * u.y + c.y * u.x)
}

/// The scalar (z) component of the planar cross product `a x b`.
#[inline(always)]
fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The sign of `x` with `sign(0) = sign(-0) = 0` (unlike `f64::signum`); NaN stays NaN.
#[inline(always)]
fn sign(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x.signum()
    }
}

#[cfg(test)]
mod tests;
