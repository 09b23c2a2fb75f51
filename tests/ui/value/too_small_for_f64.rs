use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1e-400)]
    upper: Revolute,
}

fn main() {}
