use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(gravty = 9.81, height = 0)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
