//! Arms shared by several test crates, each of which includes this file as `mod arms`
//! (not through `common`, so that the others do not derive them).
#![allow(dead_code)] // each test crate uses a different subset

use planar_arm::prelude::*;

use super::Rng;

/// A SCARA-like pair with run-time mass, inertia, centre of mass, Coulomb friction and payload,
/// armature and damping on the shoulder, a 2-D centre of mass on the elbow.
#[derive(PlanarArm, Clone)]
#[arm(gravity = 9.81, payload = self.load, payload_com = (0.03, -0.01))]
pub struct Scara {
    #[arm(length = 0.35, mass = self.m1, inertia = self.i1, com = self.c1, armature = 0.02, damping = 0.1)]
    pub shoulder: Revolute,
    #[arm(length = 0.25, mass = 1.2, com = (0.11, 0.005), frictionloss = self.f2)]
    pub elbow: Revolute,
    pub m1: f64,
    pub i1: f64,
    pub c1: f64,
    pub f2: f64,
    pub load: f64,
}

impl Scara {
    /// Fixed values.
    pub fn sample() -> Self {
        Self {
            shoulder: Revolute,
            elbow: Revolute,
            m1: 2.5,
            i1: 0.04,
            c1: 0.17,
            f2: 0.3,
            load: 0.8,
        }
    }

    /// Random values in plausible ranges.
    pub fn random(rng: &mut Rng) -> Self {
        Self {
            shoulder: Revolute,
            elbow: Revolute,
            m1: rng.range(0.5, 4.0),
            i1: rng.range(0.01, 0.1),
            c1: rng.range(0.05, 0.3),
            f2: rng.range(0.0, 0.5),
            load: rng.range(0.0, 2.0),
        }
    }
}

/// Eight links with random rational parameters, a 2-D centre of mass, damping, armature and
/// Coulomb friction.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.80665)]
pub struct Eight {
    #[arm(length = 9/4, mass = 11/8, inertia = 16/25, com = -9/20)]
    a: Revolute,
    #[arm(length = 3/5, mass = 4/5, inertia = 3/5, com = 3/10, damping = 1/5)]
    b: Revolute,
    #[arm(length = 9/5, mass = 11/4, inertia = 3/2, com = 54/25)]
    c: Revolute,
    #[arm(length = 14/5, mass = 2, inertia = 21/50, com = (0, 1/7))]
    d: Revolute,
    #[arm(length = 9/10, mass = 5, inertia = 1/25, com = 27/50, armature = 1/20)]
    e: Revolute,
    #[arm(length = 4/5, mass = 6/5, inertia = 2/5, com = 24/25)]
    f: Revolute,
    #[arm(length = 3/2, mass = 16/5, inertia = 29/25, com = 0)]
    g: Revolute,
    #[arm(length = 16/5, mass = 33/8, inertia = 3/10, com = 96/25, frictionloss = 1/3)]
    h: Revolute,
}

/// Six tapering links (kinematics and statics).
#[derive(PlanarArm, Default, Debug, Clone, Copy)]
#[arm(gravity = 9.81)]
pub struct Six {
    #[arm(length = 1, mass = 3)]
    pub l1: Revolute,
    #[arm(length = 4/5, mass = 2)]
    pub l2: Revolute,
    #[arm(length = 3/5, mass = 3/2)]
    pub l3: Revolute,
    #[arm(length = 1/2, mass = 1)]
    pub l4: Revolute,
    #[arm(length = 2/5, mass = 1/2)]
    pub l5: Revolute,
    #[arm(length = 3/10, mass = 1/4)]
    pub l6: Revolute,
}
