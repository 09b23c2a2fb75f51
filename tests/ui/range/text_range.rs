use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Polar {
    #[arm(length = 0.2, mass = 3)]
    turret: Revolute,
    #[arm(length = 0.5, mass = 1.5, range = (0, "far"))]
    boom: Prismatic,
    reach: f64,
}

fn main() {}
