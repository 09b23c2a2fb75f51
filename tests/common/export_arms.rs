//! Arms written out by `to_mjcf` and `to_urdf` and read back (`tests/export.rs`,
//! `tests/export_round_trip.rs`): every convention, slides, twists off the right angles, full
//! inertia tensors, joint friction and limits, a payload.

#![allow(dead_code)] // each test file uses some of these arms

use planar_arm::prelude::*;

/// Standard DH, a payload at a turned tool.
#[derive(SpatialArm, Default)]
#[arm(tool(xyz = (0, 0, 0.05), rpy = (0, 0, pi/2)), payload = 0.8, payload_com = (0.01, 0, 0.03),
      payload_inertia(xx = 0.002, yy = 0.002, zz = 0.001))]
pub struct DhArm {
    #[arm(dh(d = 0.3, alpha = pi/2), mass = 3.0, com = (0, -0.05, 0.01),
          inertia(xx = 0.05, yy = 0.04, zz = 0.03, xy = 0.001), damping = 0.2)]
    pub base: Revolute,
    #[arm(dh(a = 0.4, theta = -pi/6), mass = 2.0, com = (-0.2, 0, 0.02),
          inertia(xx = 0.01, yy = 0.03, zz = 0.03, xz = -0.002), range = (-2, 2))]
    pub upper: Revolute,
    #[arm(dh(a = 0.3, alpha = -0.4), mass = 1.0, com = (-0.1, 0.01, 0),
          inertia(xx = 0.004, yy = 0.01, zz = 0.011), armature = 0.05, frictionloss = 0.1)]
    pub fore: Revolute,
}

/// Modified DH with a slide.
#[derive(SpatialArm, Default)]
pub struct MdhArm {
    #[arm(mdh(d = 0.2), mass = 2.0, com = (0, 0, -0.1), inertia(xx = 0.02, yy = 0.02, zz = 0.01))]
    pub column: Revolute,
    #[arm(mdh(alpha = -pi/2, d = 0.1), mass = 1.5, com = (0, 0, -0.2),
          inertia(xx = 0.03, yy = 0.03, zz = 0.002), range = (0, 0.5), damping = 1.0)]
    pub slide: Prismatic,
    #[arm(mdh(a = 0.05, alpha = pi/2, theta = pi/2), mass = 0.5, com = (0.05, 0, 0),
          inertia(xx = 0.001, yy = 0.002, zz = 0.002, yz = 0.0001))]
    pub wrist: Revolute,
}

/// URDF joints with tilted axes and a spring.
#[derive(SpatialArm, Default)]
#[arm(gravity = (0.5, 0, -9.8))]
pub struct OriginArm {
    #[arm(origin(xyz = (0, 0, 0.1), rpy = (0.1, 0, 0.3)), axis = (0, 0, 1), mass = 1.0,
          com = (0.02, 0, 0.05), inertia(xx = 0.01, yy = 0.012, zz = 0.008),
          stiffness = 0.8, springref = 0.25)]
    pub first: Revolute,
    #[arm(origin(xyz = (0.2, 0, 0.1), rpy = (0, pi/2, 0)), axis = (0, 1, 1), mass = 0.7,
          com = (0.1, 0, 0), inertia(xx = 0.002, yy = 0.01, zz = 0.01, xy = 0.0005), armature = 0.01)]
    pub second: Revolute,
}

/// A planar arm: hinge, slide, hinge, with friction, a range and a payload.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81, payload = 0.4, payload_com = (0.05, 0.01))]
pub struct PlanarMix {
    #[arm(length = 0.5, mass = 2.0, inertia = 0.05, com = (0.25, 0.02), damping = 0.1)]
    pub shoulder: Revolute,
    #[arm(length = 0.3, mass = 1.0, inertia = 0.01, range = (0, 0.4), armature = 0.2)]
    pub reach: Prismatic,
    #[arm(length = 0.2, mass = 0.5, com = (0.1, -0.01), frictionloss = 0.05)]
    pub wrist: Revolute,
}

/// A planar arm of exact decimals and no payload: its MJCF reads back to the same `EXACT`.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
pub struct PlanarExact {
    #[arm(length = 0.5, mass = 2.0, inertia = 0.05, com = (0.25, 0.02), damping = 0.1)]
    pub shoulder: Revolute,
    #[arm(length = 0.3, mass = 1.0, inertia = 0.01, range = (0, 0.4), armature = 0.2)]
    pub reach: Prismatic,
    #[arm(length = 0.2, mass = 0.5, inertia = 0.002, com = (0.1, -0.01), frictionloss = 0.05)]
    pub wrist: Revolute,
}

/// A planar arm with what model files have and the paper's arms do not: gravity off -y, a
/// slide across the link before it (an offset), a reversed hinge turned back, joint springs.
#[derive(PlanarArm, Default)]
#[arm(gravity = (2, -9), payload = 0.2, payload_com = (0.03, 0))]
pub struct PlanarTurned {
    #[arm(length = 0.4, mass = 1.5, inertia = 0.03, com = (0.2, 0.01), damping = 0.1,
          stiffness = 4, springref = 0.3)]
    pub shoulder: Revolute,
    #[arm(length = 0.2, mass = 0.8, inertia = 0.01, offset = pi/2, range = (-0.2, 0.3),
          stiffness = 30, springref = 0.05)]
    pub lift: Prismatic,
    #[arm(length = 0.3, mass = 0.5, inertia = 0.004, com = (0.15, 0.02), offset = -pi/2,
          reversed, armature = 0.02)]
    pub wrist: Revolute,
}
