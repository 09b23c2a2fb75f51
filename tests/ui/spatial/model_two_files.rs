use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(urdf = "models/ur5.urdf", mjcf = "models/acrobot.xml")]
struct Arm;

fn main() {}
