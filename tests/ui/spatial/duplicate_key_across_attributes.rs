use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(gravity = (0, 0, -9.81))]
#[arm(gravity = (0, 0, -1.62))]
struct Arm {
    #[arm(dh(a = 0.4), range = (-1, 1))]
    #[arm(range = (-2, 2))]
    shoulder: Revolute,
}

fn main() {}
