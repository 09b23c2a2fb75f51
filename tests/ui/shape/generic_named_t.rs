use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm<__T> {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    label: __T,
}

fn main() {}
