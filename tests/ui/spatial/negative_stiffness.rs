use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0.4), mass = 1, stiffness = -2, springref = 0.1)]
    shoulder: Revolute,
}

fn main() {}
