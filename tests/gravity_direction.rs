//! Gravity in any direction of the plane, `gravity = (gx, gy)`: what a model file whose links
//! stand up at `q = 0` needs (the control suite's acrobot has its gravity along -x of its
//! plane).
//!
//! Two checks independent of the derive. Turning gravity by `beta` is turning the base by
//! `-beta`, so for an arm whose first joint turns, every joint-space quantity under gravity
//! `R(beta) (0, -g)` at `q` equals the same quantity under `(0, -g)` at `q - beta e_1`: the
//! tilted arm against its upright twin, which the derive builds from other formulas. An arm
//! whose first joint slides has no such twin; it is checked against the spatial reference's
//! Newton-Euler recursion on `to_spatial` (which shares no code with the planar path) and the
//! planar reference.

mod common;

use common::assert_matrix_close as close;
use planar_arm::nalgebra::{SVector, Vector2};
use planar_arm::prelude::*;
use planar_arm::reference;

/// Gravity of magnitude 5 turned by `beta = atan2(3, 4)` from -y.
#[derive(PlanarArm, Default)]
#[arm(gravity = (3, -4))]
struct Tilted {
    #[arm(length = 0.5, mass = 2, com = (0.2, 0.03), armature = 0.01, damping = 0.1)]
    upper: Revolute,
    #[arm(length = 0.4, mass = 1.5, inertia = 0.02, com = (0.15, -0.02))]
    fore: Revolute,
    #[arm(length = 0.3, mass = 0.5, frictionloss = 0.2)]
    hand: Revolute,
}

/// [`Tilted`] with its gravity along -y.
#[derive(PlanarArm, Default)]
#[arm(gravity = 5)]
struct Upright {
    #[arm(length = 0.5, mass = 2, com = (0.2, 0.03), armature = 0.01, damping = 0.1)]
    upper: Revolute,
    #[arm(length = 0.4, mass = 1.5, inertia = 0.02, com = (0.15, -0.02))]
    fore: Revolute,
    #[arm(length = 0.3, mass = 0.5, frictionloss = 0.2)]
    hand: Revolute,
}

/// [`Tilted`] with its gravity read at run time.
#[derive(PlanarArm)]
#[arm(gravity = (self.gx, self.gy))]
struct Steered {
    #[arm(length = 0.5, mass = 2, com = (0.2, 0.03), armature = 0.01, damping = 0.1)]
    upper: Revolute,
    #[arm(length = 0.4, mass = 1.5, inertia = 0.02, com = (0.15, -0.02))]
    fore: Revolute,
    #[arm(length = 0.3, mass = 0.5, frictionloss = 0.2)]
    hand: Revolute,
    gx: f64,
    gy: f64,
}

/// A cart on a slide along +x carrying a two-link arm, under gravity that has a part along
/// the slide (a cart on a slope).
#[derive(PlanarArm, Default)]
#[arm(gravity = (-2.5, -9), payload = 0.3, payload_com = (0.05, 0.01))]
struct Slope {
    #[arm(length = 0.2, mass = 3, inertia = 0.05, com = (0.1, 0.02), damping = 0.5)]
    cart: Prismatic,
    #[arm(length = 0.6, mass = 1, com = (0.3, 0.01), armature = 0.02)]
    pole: Revolute,
    #[arm(length = 0.4, mass = 0.7, inertia = 0.01)]
    tip: Revolute,
}

fn states<const N: usize>() -> Vec<[SVector<f64, N>; 3]> {
    common::states(&mut common::Rng(37), 8, 2.0)
}

#[test]
fn tilted_gravity_is_an_upright_arm_with_its_base_turned() {
    let (tilted, upright) = (Tilted::default(), Upright::default());
    let beta = 3.0_f64.atan2(4.0);
    for [q, qd, qdd] in states::<3>() {
        let mut shifted = q;
        shifted[0] -= beta;
        close(&tilted.gravity(&q), &upright.gravity(&shifted), "g");
        close(&tilted.mass_matrix(&q), &upright.mass_matrix(&shifted), "M");
        close(&tilted.bias(&q, &qd), &upright.bias(&shifted, &qd), "bias");
        close(
            &tilted.inverse_dynamics(&q, &qd, &qdd),
            &upright.inverse_dynamics(&shifted, &qd, &qdd),
            "ID",
        );
        close(
            &tilted.forward_dynamics(&q, &qd, &qdd),
            &upright.forward_dynamics(&shifted, &qd, &qdd),
            "FD",
        );
        let (a, b) = (
            tilted.potential_energy(&q),
            upright.potential_energy(&shifted),
        );
        assert!((a - b).abs() <= 1e-12 * a.abs().max(1.0), "V: {a} vs {b}");
        let (da, db) = (
            tilted.inverse_dynamics_derivatives(&q, &qd, &qdd),
            upright.inverse_dynamics_derivatives(&shifted, &qd, &qdd),
        );
        close(&da.0, &db.0, "dID/dq");
        close(&da.1, &db.1, "dID/dqd");
    }
}

#[test]
fn the_regressors_hold_under_tilted_gravity() {
    fn check<const N: usize, const P: usize, const B: usize>(arm: &impl Identification<N, P, B>) {
        for [q, qd, qdd] in states::<N>() {
            let tau = arm.inverse_dynamics(&q, &qd, &qdd);
            close(
                &(arm.regressor(&q, &qd, &qdd) * arm.standard_parameters()),
                &tau,
                "Y theta",
            );
            close(
                &(arm.base_regressor(&q, &qd, &qdd) * arm.base_parameters()),
                &tau,
                "Y_b theta_b",
            );
        }
    }
    check(&Tilted::default());
    check(&Slope::default());
    // Turning gravity groups the parameters as turning the base does: the same base
    // parameters as the upright twin.
    assert_eq!(
        Tilted::base_parameter_names(),
        Upright::base_parameter_names()
    );
}

#[test]
fn gravity_read_at_run_time_is_the_literal_one() {
    let (literal, steered) = (
        Tilted::default(),
        Steered {
            upper: Revolute,
            fore: Revolute,
            hand: Revolute,
            gx: 3.0,
            gy: -4.0,
        },
    );
    assert_eq!(steered.model().gravity, Vector2::new(3.0, -4.0));
    for [q, qd, qdd] in states::<3>() {
        close(&literal.gravity(&q), &steered.gravity(&q), "g");
        close(
            &literal.inverse_dynamics(&q, &qd, &qdd),
            &steered.inverse_dynamics(&q, &qd, &qdd),
            "ID",
        );
    }
}

#[test]
fn a_cart_on_a_slope_has_the_spatial_references_dynamics() {
    let arm = Slope::default();
    let model = arm.model();
    assert_eq!(model.gravity, Vector2::new(-2.5, -9.0));
    let spatial = model.to_spatial();
    for [q, qd, qdd] in states::<3>() {
        let tau = reference::spatial::inverse_dynamics(&spatial, &q, &qd, &qdd);
        close(&arm.inverse_dynamics(&q, &qd, &qdd), &tau, "ID vs spatial");
        close(
            &arm.gravity(&q),
            &reference::spatial::gravity(&spatial, &q),
            "g vs spatial",
        );
        let v = reference::spatial::potential_energy(&spatial, &q);
        let ours = arm.potential_energy(&q);
        assert!((v - ours).abs() <= 1e-12 * v.abs().max(1.0), "{v} {ours}");
        close(
            &arm.inverse_dynamics(&q, &qd, &qdd),
            &reference::inverse_dynamics(&model, &q, &qd, &qdd),
            "ID vs planar reference",
        );
        close(
            &arm.forward_dynamics(&q, &qd, &qdd),
            &reference::forward_dynamics(&model, &q, &qd, &qdd),
            "FD vs articulated bodies",
        );
        close(
            &arm.gravity(&q),
            &reference::gravity_torques(&model, &q),
            "g vs composite statics",
        );
    }
}
