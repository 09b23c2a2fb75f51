use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(urdf = models::ur5)]
struct Arm;

fn main() {}
