use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1e30, mass = 1)]
    upper: Revolute,
    #[arm(length = 1e30, mass = 1)]
    fore: Revolute,
}

fn main() {}
