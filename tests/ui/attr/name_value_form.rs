use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm = 1]
    upper: Revolute,
}

fn main() {}
