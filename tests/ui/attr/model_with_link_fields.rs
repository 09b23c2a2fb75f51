use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(mjcf = "models/reacher.xml")]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
