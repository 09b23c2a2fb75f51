use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 0, mass = 1)]
    upper: Revolute,
}

fn main() {}
