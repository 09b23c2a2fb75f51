use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = std::f64::consts::PI_HALF)]
    upper: Revolute,
}

fn main() {}
