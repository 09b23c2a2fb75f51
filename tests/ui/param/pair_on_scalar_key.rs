use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = (0.5, 0.1), mass = 1, com = (0.2, 0.1, 0.0))]
    upper: Revolute,
}

fn main() {}
