use planar_arm::prelude::*;

// Sixteen factors of 1e100000 took minutes of exact arithmetic before literals were bounded.
#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1e100000 * 1e100000 * 1e100000 * 1e100000 * 1e100000 * 1e100000 * 1e100000 * 1e100000 * 1e-100000 * 1e-100000 * 1e-100000 * 1e-100000 * 1e-100000 * 1e-100000 * 1e-100000 * 1e-100000, mass = 1)]
    upper: Revolute,
}

fn main() {}
