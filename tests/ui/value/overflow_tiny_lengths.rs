use planar_arm::prelude::*;

// Each value fits in f64, but the exact coefficients of the equations of motion do not fit in
// the i128 of the generated `const` data.
#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1/1000000000000000000000000000000, mass = 1)]
    fore: Revolute,
}

fn main() {}
