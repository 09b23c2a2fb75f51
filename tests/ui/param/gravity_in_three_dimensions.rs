use planar_arm::prelude::*;

// A spatial arm's gravity on a planar arm: the plane takes a pair.
#[derive(PlanarArm)]
#[arm(gravity = (0, 0, -9.81))]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
