use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 0.5, mass = self.mass)]
    upper: Revolute,
    mass: f32,
}

fn main() {}
