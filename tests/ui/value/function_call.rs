use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 2.0_f64.sqrt(), mass = 1)]
    upper: Revolute,
}

fn main() {}
