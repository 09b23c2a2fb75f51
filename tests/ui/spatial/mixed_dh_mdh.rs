use planar_arm::prelude::*;

// One convention per arm: `elbow` switches from standard to modified DH.
#[derive(SpatialArm)]
struct Arm {
    #[arm(dh(a = 0, alpha = pi/2, d = 0.3))]
    shoulder: Revolute,
    #[arm(mdh(a = 0.4, alpha = 0, d = 0))]
    elbow: Revolute,
}

fn main() {}
