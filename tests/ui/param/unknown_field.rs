use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 0.5, mass = self.mas)]
    upper: Revolute,
    mass: f64,
}

fn main() {}
