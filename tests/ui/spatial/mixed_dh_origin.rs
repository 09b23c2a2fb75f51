use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0, alpha = pi/2, d = 0.3))]
    shoulder: Revolute,
    #[arm(origin(xyz = (0.4, 0, 0)), axis = (0, 1, 0))]
    elbow: Revolute,
}

fn main() {}
