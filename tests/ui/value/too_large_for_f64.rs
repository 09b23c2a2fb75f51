use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1e400, mass = 1)]
    upper: Revolute,
}

fn main() {}
