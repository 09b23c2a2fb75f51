use planar_arm::prelude::*;

// A planar arm's EXACT always holds M and c: the key is the spatial derive's.
#[derive(PlanarArm)]
#[arm(gravity = 9.81, exact_dynamics)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
