use planar_arm::prelude::*;

// A centre and a tensor without the payload's mass.
#[derive(SpatialArm)]
#[arm(payload_com = (0, 0, 0.1), payload_inertia(xx = 0.01))]
struct NoMass {
    #[arm(dh(a = 0.4), mass = 1)]
    shoulder: Revolute,
}

#[derive(SpatialArm)]
#[arm(payload = -2, payload_inertia(xx = -0.01))]
struct Negative {
    #[arm(dh(a = 0.4), mass = 1)]
    shoulder: Revolute,
}

// A planar payload's single moment of inertia.
#[derive(SpatialArm)]
#[arm(payload = 2, payload_inertia = 0.01)]
struct Scalar {
    #[arm(dh(a = 0.4), mass = 1)]
    shoulder: Revolute,
}

fn main() {}
