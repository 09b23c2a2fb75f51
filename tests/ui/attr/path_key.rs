use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1, link::mass = 3)]
    upper: Revolute,
}

fn main() {}
