use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length, mass = 1)]
    upper: Revolute,
}

fn main() {}
