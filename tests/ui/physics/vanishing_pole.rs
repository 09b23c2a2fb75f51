use planar_arm::prelude::*;

// A pole 1e-300 m long: its inertia about the hinge, about 1e-600, is zero in f64.
#[derive(PlanarArm)]
struct CartPole {
    #[arm(length = 0, mass = 1)]
    cart: Prismatic,
    #[arm(length = 1e-300, mass = 1)]
    pole: Revolute,
}

fn main() {}
