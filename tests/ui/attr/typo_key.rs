use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(lenght = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
