use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh = (0.4, pi/2, 0, 0), mass = 1)]
    shoulder: Revolute,
}

fn main() {}
