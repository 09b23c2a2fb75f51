use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), gravity = (0, 0, -9.81))]
    shoulder: Revolute,
}

fn main() {}
