use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), mas = 1)]
    shoulder: Revolute,
}

fn main() {}
