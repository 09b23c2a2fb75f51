use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), mass = 1, inertia(xx = 0.1, yy = -0.1, xy = -0.05))]
    shoulder: Revolute,
}

fn main() {}
