use planar_arm::prelude::*;

#[derive(SpatialArm)]
struct Arm<__T> {
    #[arm(dh(a = 0.4))]
    shoulder: Revolute,
    label: __T,
}

fn main() {}
