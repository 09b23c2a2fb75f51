use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), dh(a = 0.5), mass = 1)]
    shoulder: Revolute,
}

fn main() {}
