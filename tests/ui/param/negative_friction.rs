use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(payload = -1)]
struct Arm {
    #[arm(length = 0.5, mass = 1, damping = -0.1, frictionloss = -2, armature = -0.5)]
    upper: Revolute,
}

fn main() {}
