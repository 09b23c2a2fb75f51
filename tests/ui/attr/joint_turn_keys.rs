use planar_arm::prelude::*;

// `reversed` is a flag; `offset` an angle in radians or a multiple of pi.
#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1, reversed = true)]
    upper: Revolute,
    #[arm(length = 1, mass = 1, offset = 90deg)]
    fore: Revolute,
    #[arm(length = 1, mass = 1, offset = "pi/2", reversed, reversed)]
    hand: Revolute,
}

fn main() {}
