use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(gravity = 9.81)]
#[arm(gravity = 1.62)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
