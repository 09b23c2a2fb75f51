use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(urdf = "models/ur5.urdf", tool(xyz = (0, 0, 0.1)))]
struct Arm;

fn main() {}
