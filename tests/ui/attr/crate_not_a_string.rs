use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(crate = planar_arm)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
