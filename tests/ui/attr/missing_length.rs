use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(mass = 1)]
    upper: Revolute,
}

fn main() {}
