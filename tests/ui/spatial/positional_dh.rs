use planar_arm::prelude::*;

// DH tables are often written as rows of numbers; the derive wants names.
#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(0.4, pi/2, 0, 0))]
    shoulder: Revolute,
}

fn main() {}
