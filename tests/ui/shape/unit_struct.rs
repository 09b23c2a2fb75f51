use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm;

fn main() {}
