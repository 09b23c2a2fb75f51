use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4))]
    shoulder: Revolute,
    #[arm(mass = 1)]
    elbow: Revolute,
}

fn main() {}
