use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {}

fn main() {}
