//! A `#![no_std]` crate with no allocator that derives an arm and calls its generated methods
//! in `f64` and `f32`. CI builds it alone (so no other crate's features leak
//! in) for the host and, where rustup can install it, for `thumbv7em-none-eabihf`, a
//! Cortex-M4F microcontroller target that has no `std` at all.
#![no_std]
#![deny(warnings)]

use planar_arm::nalgebra::{SMatrix, SVector, Vector2};
use planar_arm::{ArmError, Dynamics, Linearize, PlanarArm, Revolute};

/// A two-link arm with a run-time payload mass, friction and gravity.
#[derive(PlanarArm)]
#[arm(gravity = 9.81, payload = self.load)]
pub struct Arm {
    #[arm(length = 0.3, mass = 1.2, damping = 0.05)]
    pub upper: Revolute,
    #[arm(length = 0.25, mass = 0.8, frictionloss = 0.1)]
    pub fore: Revolute,
    pub load: f64,
}

/// One control step on an f32 microcontroller: the computed torque for a desired acceleration.
#[must_use]
pub fn computed_torque(
    arm: &Arm,
    q: &Vector2<f32>,
    qd: &Vector2<f32>,
    qdd: &Vector2<f32>,
) -> Vector2<f32> {
    arm.inverse_dynamics(q, qd, qdd)
}

/// The f64 path with its checked variant and the kinematics.
///
/// # Errors
/// `ArmError::NonFinite` for NaN input.
pub fn checked(
    arm: &Arm,
    q: &SVector<f64, 2>,
    qd: &SVector<f64, 2>,
    tau: &SVector<f64, 2>,
) -> Result<(SVector<f64, 2>, f64), ArmError> {
    let qdd = arm.try_forward_dynamics(q, qd, tau)?;
    let tip = arm.tip_pose(q);
    Ok((qdd, tip.translation.x + arm.kinetic_energy(q, qd)))
}

/// The continuous-time LQR gain (unit weights) that holds the arm still at `q`: the regulator
/// needs neither `std` nor an allocator.
///
/// # Errors
/// As `planar_arm::lqr`: `ArmError::NonFinite` for NaN in `q`, for instance.
pub fn holding_gain(arm: &Arm, q: &Vector2<f64>) -> Result<SMatrix<f64, 2, 4>, ArmError> {
    let (a, b) = arm.linearize(q, &Vector2::zeros(), &arm.gravity(q));
    Ok(planar_arm::lqr(&a, &b, &SMatrix::identity(), &SMatrix::identity())?.gain)
}

/// A spatial arm (the UR5's geometry) in `no_std`: its tool pose, Jacobian in `f32`, gravity,
/// and every closed-form inverse-kinematics solution, without an allocator.
#[derive(planar_arm::SpatialArm, Default)]
pub struct Ur5 {
    #[arm(dh(alpha = pi/2, d = 0.089159), mass = 3.7)]
    pub shoulder_pan: Revolute,
    #[arm(dh(a = -0.425), mass = 8.393, com = (0.2125, 0, 0.11336))]
    pub shoulder_lift: Revolute,
    #[arm(dh(a = -0.39225), mass = 2.275, com = (0.15, 0, 0.0265))]
    pub elbow: Revolute,
    #[arm(dh(alpha = pi/2, d = 0.10915))]
    pub wrist1: Revolute,
    #[arm(dh(alpha = -pi/2, d = 0.09465))]
    pub wrist2: Revolute,
    #[arm(dh(d = 0.0823))]
    pub wrist3: Revolute,
}

/// How many closed-form solutions reach the pose at `q`, and the `f32` Jacobian there.
///
/// # Errors
/// As `SpatialArm::inverse_kinematics`.
pub fn spatial(arm: &Ur5, q: &SVector<f64, 6>) -> Result<(usize, SMatrix<f32, 6, 6>), ArmError> {
    use planar_arm::spatial::SpatialArm;
    let target = arm.tip_pose(q);
    let solutions = arm.inverse_kinematics(&target)?;
    let _ = arm.gravity(q);
    Ok((solutions.len(), arm.jacobian(&q.map(|x| x as f32))))
}

/// The spatial arm's dynamics in `no_std`: the torques for a motion and the accelerations they
/// give back (the UR5's wrist is massless here, so its forward dynamics is the `Err` of a
/// singular mass matrix; the inverse dynamics and the derivatives are finite).
///
/// # Errors
/// As `Dynamics::try_inverse_dynamics`.
pub fn spatial_dynamics(
    arm: &Ur5,
    q: &SVector<f64, 6>,
    qd: &SVector<f64, 6>,
) -> Result<(SVector<f64, 6>, SMatrix<f64, 6, 6>), ArmError> {
    let tau = arm.try_inverse_dynamics(q, qd, &SVector::zeros())?;
    let _ = arm.try_forward_dynamics(q, qd, &tau);
    let (dq, _) = arm.inverse_dynamics_derivatives(q, qd, &SVector::zeros());
    Ok((tau, dq))
}
