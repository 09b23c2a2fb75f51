use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(dh(a = 0.4, alpha = pi/2), mass = 1)]
    upper: Revolute,
}

fn main() {}
