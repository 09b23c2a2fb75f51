use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(gravity = 9.81, tip = "hand")]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
