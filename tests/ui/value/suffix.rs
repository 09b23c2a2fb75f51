use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1u8, mass = 1)]
    upper: Revolute,
}

fn main() {}
