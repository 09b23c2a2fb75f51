//! Links that look degenerate but leave the mass matrix definite compile and have finite
//! forward dynamics: a point cart, a link whose mass sits on its joint axis with armature, or
//! with a later link to move.
use planar_arm::prelude::*;

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct CartPole {
    #[arm(length = 0, mass = 1)]
    cart: Prismatic,
    #[arm(length = 0.5, mass = 0.1)]
    pole: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct GearedTip {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 0.5, mass = 1, inertia = 0, com = 0, armature = 0.01)]
    fore: Revolute,
}

#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct HubFirst {
    #[arm(length = 0.3, mass = 2, inertia = 0, com = 0)]
    hub: Revolute,
    #[arm(length = 0.5, mass = 1)]
    arm: Revolute,
}

fn main() {
    let q = Vector2::new(0.3, -0.7);
    let tau = Vector2::new(0.5, 0.1);
    let all: [Vector2<f64>; 3] = [
        CartPole::default().forward_dynamics(&q, &q, &tau),
        GearedTip::default().forward_dynamics(&q, &q, &tau),
        HubFirst::default().forward_dynamics(&q, &q, &tau),
    ];
    for qdd in all {
        assert!(qdd.iter().all(|x| x.is_finite()), "{qdd}");
    }
    assert!(CartPole::default().model().check().is_ok());
}
