//! Independent numeric reference implementations of planar-arm dynamics and kinematics.
//!
//! Everything here is plain `f64` arithmetic written from first principles (Newton-Euler
//! mechanics and Featherstone's spatial-vector algorithms specialised to the plane). It shares
//! no code with the symbolic Lagrangian path of `#[derive(PlanarArm)]`, so the tests, the
//! benchmarks and the `paper` example use it as the ground truth the generated code is checked
//! and timed against. Every function takes the arm as a [`Model`](crate::Model): links, gravity, payload.
//!
//! Conventions are those of the crate: `q[0]` is link 1's angle from +x and `q[i]` (i > 0) is
//! link i+1's angle relative to link i, so the absolute angle of link i+1 is
//! `phi_i = q[0] + ... + q[i]` and its direction `u_i = (cos phi_i, sin phi_i)`; joint 1 sits
//! at the origin; gravity of magnitude `model.gravity` acts along -y. A link's centre of mass
//! `com = (cx, cy)` is in its own frame, at `joint_i + cx u_i + cy perp(u_i)` in the world
//! (`perp` turns by +90 degrees); the payload's is at `tip + R(phi_N) payload.com`.
//!
//! The equations of motion are
//!
//! ```text
//! tau = M(q) qdd + c(q, qd) + g(q) + f(qd)
//! ```
//!
//! with `M` the mass matrix including each joint's armature on its diagonal, `c` the
//! velocity-product torques, `g = dV/dq` the gravity torques and
//! `f_i = damping_i qd_i + frictionloss_i sign(qd_i)` the joint friction ([`friction`];
//! `sign(0) = 0`). These are MuJoCo's joint `armature`, `damping` and `frictionloss`.
//! [`bias_forces`] is `c + g + f`; Pinocchio's `nonLinearEffects` is `c + g`.
//!
//! # Algorithms and cost
//!
//! All functions are generic over the number of links `N`, work on fixed-size arrays and
//! nalgebra `SVector`/`SMatrix` values, never allocate, never panic, and evaluate exactly one
//! `sin_cos` per joint (of the cumulative absolute angle). The payload enters each algorithm
//! as one more body rigidly fixed beyond the tip (the Newton-Euler recursion starts from its
//! inertial wrench at the tip, the composite and articulated inertias start from its
//! inertia), not through [`Model::rigid_links`](crate::Model::rigid_links), which the tests check against.
//!
//! | function | algorithm | cost |
//! |---|---|---|
//! | [`inverse_dynamics`], [`bias_forces`], [`coriolis`] | recursive Newton-Euler (RNEA): outward pass for angular velocity/acceleration and joint/COM linear accelerations (gravity as a base acceleration `+g` along +y), inward pass for joint forces and moments; armature and friction added per joint | O(N) |
//! | [`gravity_torques`] | inward accumulation of composite mass and first moment (statics) | O(N) |
//! | [`friction`] | per joint | O(N) |
//! | [`mass_matrix`] | composite rigid body algorithm (CRBA) with planar composite inertias (mass, first moment, rotational inertia about each joint), armature on the diagonal | O(N^2) |
//! | [`forward_dynamics`] | articulated body algorithm (ABA) with 3x3 planar spatial inertias `[angular; x; y]`, all expressed about the world origin so that no inter-link transforms are needed; armature in the joint-space articulated inertia; never forms `M` | O(N) |
//! | [`forward_dynamics_crba`] | CRBA + RNEA bias + Cholesky solve | O(N^3) |
//! | [`kinetic_energy`], [`potential_energy`] | direct sums over COM velocities / heights, payload as its own body | O(N) |
//! | [`tip_position`], [`joint_positions`], [`jacobian`] | forward kinematics; the Jacobian column of joint j is `perp(tip - joint_j)` | O(N) / O(N) / O(N) |
//! | [`regressor`] | the torques of each body's four inertial parameters per unit value, by one outward Newton-Euler pass and each body's wrench moved to every joint before it | O(N^2) |
//! | [`regressor_local`] | the same by Pinocchio's `computeJointTorqueRegressor` algorithm: each body's regressor in its own frame, moved inwards joint by joint | O(N^2) |

use nalgebra::{SVector, Vector2};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

mod articulated;
mod composite;
mod energy;
mod kinematics;
mod newton_euler;
mod regressor;

pub use articulated::forward_dynamics;
pub use composite::{forward_dynamics_crba, gravity_torques, mass_matrix};
pub use energy::{kinetic_energy, potential_energy};
pub use kinematics::{jacobian, joint_positions, tip_angle, tip_position};
pub use newton_euler::{
    bias_forces, coriolis, friction, inverse_dynamics, inverse_dynamics_batched_trig,
};
pub use regressor::{link_parameters, payload_parameters, regressor, regressor_local, Regressor};

/// Unit vectors `(cos phi_i, sin phi_i)` along each link, from the cumulative absolute angles.
#[inline(always)]
fn link_directions<const N: usize>(q: &SVector<f64, N>) -> [Vector2<f64>; N] {
    // A plain loop: mapping over `absolute_angles` instead measured 2-6 % slower, and the
    // reference is not to be pessimised.
    let mut dirs = [Vector2::zeros(); N];
    let mut phi = 0.0;
    for (dir, &qi) in dirs.iter_mut().zip(q.iter()) {
        phi += qi;
        let (s, c) = phi.sin_cos();
        *dir = Vector2::new(c, s);
    }
    dirs
}

/// `q1, q1 + q2, ...`: each link's angle from the base x axis, for one batched `sin_cos`.
#[inline(always)]
fn absolute_angles<const N: usize>(q: &SVector<f64, N>) -> [f64; N] {
    let mut phi = 0.0;
    core::array::from_fn(|i| {
        phi += q[i];
        phi
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
