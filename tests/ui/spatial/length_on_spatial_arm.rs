use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    shoulder: Revolute,
}

fn main() {}
