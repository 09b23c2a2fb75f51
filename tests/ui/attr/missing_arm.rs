use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    fore: Revolute,
}

fn main() {}
