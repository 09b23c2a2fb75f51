use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1, gravity = 9.81)]
    upper: Revolute,
}

fn main() {}
