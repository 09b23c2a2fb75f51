use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 3 / (2 - 2))]
    upper: Revolute,
}

fn main() {}
