use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm]
struct Arm {
    #[arm(dh(a = 0.4))]
    shoulder: Revolute,
}

fn main() {}
