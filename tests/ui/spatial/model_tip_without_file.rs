use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(tip = "tool0")]
struct Arm {
    #[arm(dh(a = 0.4))]
    shoulder: Revolute,
}

fn main() {}
