use planar_arm::prelude::*;

// A point mass on the joint axis: M11 would be zero.
#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1, inertia = 0, com = 0)]
    upper: Revolute,
}

fn main() {}
