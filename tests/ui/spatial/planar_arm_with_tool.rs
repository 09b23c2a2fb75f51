use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(tool(xyz = (0.1, 0, 0)))]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
