use planar_arm::prelude::*;

// A planar link's com may be a pair; a spatial one is a point in space.
#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), mass = 1, com = (0.2, 0))]
    shoulder: Revolute,
}

fn main() {}
