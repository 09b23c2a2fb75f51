use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = true)]
    upper: Revolute,
}

fn main() {}
