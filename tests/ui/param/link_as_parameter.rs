use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 0.5, mass = self.upper)]
    upper: Revolute,
}

fn main() {}
