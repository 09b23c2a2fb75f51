use planar_arm::prelude::*;

// A flag with a value.
#[derive(SpatialArm)]
#[arm(exact_dynamics = true)]
struct WithValue {
    #[arm(dh(a = 0.4))]
    shoulder: Revolute,
}

// On a joint field.
#[derive(SpatialArm)]
struct OnField {
    #[arm(dh(a = 0.4), exact_dynamics)]
    shoulder: Revolute,
}

// Twice.
#[derive(SpatialArm)]
#[arm(exact_dynamics, exact_dynamics)]
struct Twice {
    #[arm(dh(a = 0.4))]
    shoulder: Revolute,
}

// Generic twists at every joint: the tool pose does not multiply out, so M would not either.
#[derive(SpatialArm)]
#[arm(exact_dynamics)]
struct Generic {
    #[arm(dh(a = 0.1, alpha = 0.3, d = 0.1), mass = 1)]
    j1: Revolute,
    #[arm(dh(a = 0.2, alpha = 0.4, d = 0.1), mass = 1)]
    j2: Revolute,
    #[arm(dh(a = 0.3, alpha = 0.5, d = 0.1), mass = 1)]
    j3: Revolute,
    #[arm(dh(a = 0.1, alpha = 0.6, d = 0.1), mass = 1)]
    j4: Revolute,
    #[arm(dh(a = 0.2, alpha = 0.7, d = 0.1), mass = 1)]
    j5: Revolute,
    #[arm(dh(a = 0.3, alpha = 0.8, d = 0.1), mass = 1)]
    j6: Revolute,
}

fn main() {}
