use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(origin(xyz = (0, 0, 0.3), rpy = pi/2))]
    shoulder: Revolute,
}

fn main() {}
