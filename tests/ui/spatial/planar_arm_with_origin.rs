use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1, origin(xyz = (0, 0, 1)), axis = (0, 1, 0))]
    upper: Revolute,
}

fn main() {}
