use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(crate = planar_arm)]
struct Arm {
    #[arm(dh(a = 0.4))]
    shoulder: Revolute,
}

fn main() {}
