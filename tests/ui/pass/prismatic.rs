//! Prismatic joints anywhere in the chain, with ranges on either kind, literal and run-time
//! values, and a zero-inertia slider whose centre of mass is on its axis (a point mass: fine for
//! a slider, which moves all of it).
use planar_arm::prelude::*;

#[derive(PlanarArm)]
struct Polar {
    #[arm(length = 0.2, mass = 3, range = (-3.1, 3.1))]
    turret: Revolute,
    #[arm(length = 0.5, mass = 1.5, range = (0, 0.6))]
    boom: Prismatic,
}

#[derive(PlanarArm)]
#[arm(payload = self.load)]
struct Gantry {
    #[arm(length = 0.1, mass = self.carriage, inertia = 0, com = 0, range = (-1, 1), damping = 2)]
    rail: planar_arm::Prismatic,
    #[arm(length = 0.4, mass = 1, range = (-1.5, 1.5))]
    upper: Revolute,
    #[arm(length = 0.3, mass = 0.5)]
    fore: Revolute,
    carriage: f64,
    load: f64,
}

fn main() {
    let polar = Polar { turret: Revolute, boom: Prismatic };
    let q = Vector2::new(0.3, 0.25);
    assert!((polar.tip_pose(&q).translation.x - 0.95 * 0.3f64.cos()).abs() < 1e-12);
    let gantry = Gantry { rail: Prismatic, upper: Revolute, fore: Revolute, carriage: 4.0, load: 0.2 };
    let m = gantry.mass_matrix(&planar_arm::nalgebra::Vector3::new(0.3, 0.2, -0.1));
    assert!(m.cholesky().is_some());
    assert_eq!(gantry.links()[0].range, Some((-1.0, 1.0)));
    assert_eq!(gantry.links()[0].joint, Joint::Prismatic);
}
