use planar_arm::prelude::*;

// `90deg` lexes as the number 90 with a suffix; it must not silently mean 90 radians.
#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4, alpha = 90deg))]
    shoulder: Revolute,
}

fn main() {}
