use planar_arm::PlanarArm;

/// A user's own type that merely shares the name.
struct Revolute;

#[derive(PlanarArm)]
struct Arm {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
}

fn main() {}
