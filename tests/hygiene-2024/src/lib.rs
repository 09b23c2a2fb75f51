//! A derived arm in an edition 2024 crate, under the lints that guard the edition.
#![deny(
    warnings,
    rust_2024_compatibility,
    unsafe_op_in_unsafe_fn,
    clippy::all,
    clippy::pedantic
)]

use planar_arm::prelude::*;

/// Two links, the paper's arm.
#[derive(PlanarArm, Debug, Default, Clone, Copy)]
#[arm(gravity = 9.81)]
pub struct Two {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 0.5, mass = 2, com = 0.2)]
    fore: Revolute,
}

/// Three links.
#[derive(PlanarArm, Debug, Default, Clone, Copy)]
pub struct Three {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 0.5, mass = 2)]
    fore: Revolute,
    #[arm(length = 0.2, mass = 0.5, inertia = 0)]
    hand: Revolute,
}

/// The elbow-up solution, if the target is reachable: written with a let chain, which only
/// edition 2024 accepts, so this crate cannot silently be built as 2021.
#[must_use]
pub fn elbow_up(arm: &Two, target: &Point2<f64>) -> Option<SVector<f64, 2>> {
    if let Ok([up, _]) = arm.inverse_kinematics(target)
        && up.iter().all(|a| a.is_finite())
    {
        Some(up)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derived_arms_work_in_edition_2024() {
        let two = Two::default();
        let q = SVector::<f64, 2>::new(0.3, 1.2);
        let tip = two.tip_pose(&q).translation.vector;
        let up = elbow_up(&two, &Point2::new(tip.x, tip.y)).expect("reachable");
        assert!((up - q).amax() < 1e-12);
        let tau = two.inverse_dynamics(&q, &q, &q);
        assert!((two.forward_dynamics(&q, &q, &tau) - q).amax() < 1e-12);
        assert!(elbow_up(&two, &Point2::new(3.0, 0.0)).is_none());

        let three = Three::default();
        let q = SVector::<f64, 3>::new(0.3, 1.2, -0.5);
        let pose = three.tip_pose(&q);
        assert!(three.inverse_kinematics(&pose).is_ok());
        assert!(three.mass_matrix(&q).cholesky().is_some());
    }
}
