use planar_arm::prelude::*;

// Every problem of one struct is reported in one compilation.
#[derive(PlanarArm)]
#[arm(gravity = -1, length = 2)]
struct Arm {
    #[arm(lenght = 1, mass = 0)]
    upper: Revolute,
    #[arm(length = "1", mass = 1, inertia = -0.1)]
    fore: Revolute,
    hand: Revolute,
    #[arm(length = 1/0, mass = 1, mass = 2)]
    finger: f32,
}

fn main() {}
