use planar_arm::prelude::*;

const UPPER_LENGTH: f64 = 0.5;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = UPPER_LENGTH, mass = 1)]
    upper: Revolute,
}

fn main() {}
