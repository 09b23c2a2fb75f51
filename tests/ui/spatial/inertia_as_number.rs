use planar_arm::prelude::*;

// A planar link's inertia is one number; a spatial link's is a tensor.
#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), mass = 1, inertia = 0.1)]
    shoulder: Revolute,
}

fn main() {}
