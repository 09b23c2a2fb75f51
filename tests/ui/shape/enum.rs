use planar_arm::prelude::*;

#[derive(PlanarArm)]
enum Arm {
    Upper,
    Fore,
}

fn main() {}
