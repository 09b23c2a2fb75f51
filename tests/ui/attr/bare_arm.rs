use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm]
    upper: Revolute,
}

fn main() {}
