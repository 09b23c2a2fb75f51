use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(dh(a = 0.4, alpha = pi/2))]
struct Arm {
    #[arm(dh(a = 0, alpha = 0, d = 0.3))]
    shoulder: Revolute,
}

fn main() {}
