use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 7 % 3, mass = 1)]
    upper: Revolute,
}

fn main() {}
