use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), axis = (0, 1, 0))]
    shoulder: Revolute,
}

fn main() {}
