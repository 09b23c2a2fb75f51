//! A crate that knows `planar_arm` as `arm` (renamed in its Cargo.toml), so generated code
//! that named `::planar_arm` would not compile: `#[arm(crate = "arm")]` tells the derive, and
//! without it the derive reads the name from this crate's Cargo.toml.

use arm::{PlanarArm, Revolute};

/// Two links; the path to the library is the renamed one.
#[derive(PlanarArm, Default)]
#[arm(crate = "arm", gravity = 9.81)]
pub struct Renamed {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

/// The same without `crate = "..."`: found in Cargo.toml.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
pub struct Found {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

#[cfg(test)]
mod tests {
    use super::*;
    use arm::nalgebra::Vector2;
    use arm::Dynamics;

    #[test]
    fn the_renamed_crate_derives_and_runs() {
        let arm = Renamed::default();
        let q = Vector2::new(0.3, -0.2);
        let tau = arm.inverse_dynamics(&q, &Vector2::zeros(), &Vector2::zeros());
        // Held still, the torques are the gravity torques.
        assert!((tau - arm.gravity(&q)).norm() < 1e-12);
        assert!(tau[0] > 0.0);
        assert_eq!(Found::default().gravity(&q), arm.gravity(&q));
    }
}
