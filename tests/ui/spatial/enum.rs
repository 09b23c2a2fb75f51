use planar_arm::prelude::*;

#[derive(SpatialArm)]
enum Arm {
    Shoulder,
}

fn main() {}
