use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(tool(xyz = (0, 0, 0.1), yaw = pi/2))]
struct Arm {
    #[arm(dh(a = 0.4))]
    shoulder: Revolute,
}

fn main() {}
