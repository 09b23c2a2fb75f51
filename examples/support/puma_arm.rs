//! The PUMA 560 the `puma` examples share.

use planar_arm::prelude::*;

/// PUMA 560, standard Denavit-Hartenberg parameters and mass properties (Corke's model).
#[derive(SpatialArm, Default)]
#[arm(gravity = (0, 0, -9.81))]
pub struct Puma560 {
    #[arm(dh(a = 0, alpha = pi/2, d = 0), inertia(yy = 0.35))]
    waist: Revolute,
    #[arm(dh(a = 0.4318, alpha = 0, d = 0), mass = 17.4, com = (-0.3638, 0.006, 0.2275),
          inertia(xx = 0.13, yy = 0.524, zz = 0.539))]
    shoulder: Revolute,
    #[arm(dh(a = 0.0203, alpha = -pi/2, d = 0.15005), mass = 4.8, com = (-0.0203, -0.0141, 0.07),
          inertia(xx = 0.066, yy = 0.086, zz = 0.0125))]
    elbow: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0.4318), mass = 0.82, com = (0, 0.019, 0),
          inertia(xx = 1.8e-3, yy = 1.3e-3, zz = 1.8e-3))]
    wrist1: Revolute,
    #[arm(dh(a = 0, alpha = -pi/2, d = 0), mass = 0.34, inertia(xx = 0.3e-3, yy = 0.4e-3, zz = 0.3e-3))]
    wrist2: Revolute,
    #[arm(dh(a = 0, alpha = 0, d = 0), mass = 0.09, com = (0, 0, 0.032),
          inertia(xx = 0.15e-3, yy = 0.15e-3, zz = 0.04e-3))]
    wrist3: Revolute,
}
