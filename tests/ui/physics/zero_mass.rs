use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 0.0)]
    upper: Revolute,
}

fn main() {}
