use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4, alpha = 0, a = 0.5))]
    shoulder: Revolute,
}

fn main() {}
