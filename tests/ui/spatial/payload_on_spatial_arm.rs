use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(payload = 2)]
struct Arm {
    #[arm(dh(a = 0.4), mass = 1)]
    shoulder: Revolute,
}

fn main() {}
