use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, MASS = 1)]
    upper: Revolute,
}

fn main() {}
