use planar_arm::prelude::*;

/// A user's own type that shares the name: the derive reads the joint kind from the name, the
/// compiler refuses the type.
struct Prismatic;

#[derive(PlanarArm)]
struct Polar {
    #[arm(length = 0.2, mass = 3)]
    turret: planar_arm::Revolute,
    #[arm(length = 0.5, mass = 1.5)]
    boom: Prismatic,
}

fn main() {}
