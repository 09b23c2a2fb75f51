use planar_arm::prelude::*;

#[derive(SpatialArm)]
#[arm(urdf = "models/ur5.urdf")]
struct Arm {
    #[arm(dh(a = 0.4))]
    shoulder: Revolute,
}

fn main() {}
