use planar_arm::prelude::*;

// The fore-arm's mass on its own joint axis, no inertia, nothing after it: its joint moves
// nothing.
#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1, inertia = 0, com = (0, 0))]
    fore: Revolute,
}

fn main() {}
