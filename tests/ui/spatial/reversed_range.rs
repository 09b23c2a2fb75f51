use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), range = (1.5, -1.5))]
    shoulder: Revolute,
}

fn main() {}
