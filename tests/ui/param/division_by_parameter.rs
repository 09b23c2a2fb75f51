use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 0.5, mass = 1, inertia = 1 / self.k)]
    upper: Revolute,
    k: f64,
}

fn main() {}
