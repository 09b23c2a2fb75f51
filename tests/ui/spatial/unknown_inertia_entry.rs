use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), mass = 1, inertia(xx = 1, qq = 2))]
    shoulder: Revolute,
}

fn main() {}
