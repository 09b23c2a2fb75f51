use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1, stiffness = -2, springref = 0.1)]
    upper: Revolute,
}

fn main() {}
