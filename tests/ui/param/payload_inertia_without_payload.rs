use planar_arm::prelude::*;

#[derive(PlanarArm)]
#[arm(payload_inertia = 0.01)]
struct Arm {
    #[arm(length = 0.5, mass = 1)]
    upper: Revolute,
}

fn main() {}
