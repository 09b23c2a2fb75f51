//! Identifies the PUMA 560's base parameters from simulated noisy joint torques, with the
//! `Identification` trait `#[derive(SpatialArm)]` generates, the way the planar `identify`
//! example calibrates a three-link arm:
//!
//! 1. an exciting trajectory: per joint five harmonics of 0.1 Hz (Swevers et al.), the best of
//!    a few random coefficient sets by the condition number of the stacked base regressor;
//! 2. "measured" torques along it from the independent numeric reference
//!    (`reference::spatial::inverse_dynamics`, not the generated code) plus Gaussian noise of a
//!    different level per joint (the wrist's motors are smaller);
//! 3. weighted least squares on the base regressor stacked over the samples, with each base
//!    parameter's standard deviation;
//! 4. validation: the identified model's torques on a fresh trajectory against fresh
//!    measurements;
//! 5. an unknown payload at the tool, found from the change of the base parameters.
//!
//! The arm's geometry and masses are Corke's; its armature, viscous and Coulomb friction are his
//! motor parameters reflected through the gears (`Jm G^2`, `B G^2`, `Tc G`), rounded.
//!
//! ```text
//! cargo run --release --example puma_identify
//! ```

#[path = "support/excite.rs"]
mod excite;
#[path = "support/num.rs"]
mod num;

use std::error::Error;

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;
use planar_arm::reference::spatial as reference;
use planar_arm::spatial::SpatialArm;

use excite::{least_squares, print_estimate, rms, stack, Bounds, Estimate, Excitation, Rng};

/// PUMA 560 (Corke's standard DH model) with its drives' armature and friction, and a payload
/// slot at a tool frame 56 mm out along the last axis (the flange).
#[derive(SpatialArm, Clone)]
#[arm(gravity = (0, 0, -9.81), tool(xyz = (0, 0, 0.056)), payload = self.load)]
struct Puma {
    #[arm(dh(a = 0, alpha = pi/2, d = 0), inertia(yy = 0.35),
          armature = 0.78, damping = 5.8, frictionloss = 24.7)]
    waist: Revolute,
    #[arm(dh(a = 0.4318, alpha = 0, d = 0), mass = 17.4, com = (-0.3638, 0.006, 0.2275),
          inertia(xx = 0.13, yy = 0.524, zz = 0.539), armature = 2.3, damping = 9.5, frictionloss = 13.6)]
    shoulder: Revolute,
    #[arm(dh(a = 0.0203, alpha = -pi/2, d = 0.15005), mass = 4.8, com = (-0.0203, -0.0141, 0.07),
          inertia(xx = 0.066, yy = 0.086, zz = 0.0125), armature = 0.58, damping = 4.0, frictionloss = 7.1)]
    elbow: Revolute,
    #[arm(dh(a = 0, alpha = pi/2, d = 0.4318), mass = 0.82, com = (0, 0.019, 0),
          inertia(xx = 1.8e-3, yy = 1.3e-3, zz = 1.8e-3), armature = 0.19, damping = 0.41, frictionloss = 0.85)]
    wrist1: Revolute,
    #[arm(dh(a = 0, alpha = -pi/2, d = 0), mass = 0.34, inertia(xx = 0.3e-3, yy = 0.4e-3, zz = 0.3e-3),
          armature = 0.17, damping = 0.43, frictionloss = 0.67)]
    wrist2: Revolute,
    #[arm(dh(a = 0, alpha = 0, d = 0), mass = 0.09, com = (0, 0, 0.032),
          inertia(xx = 0.15e-3, yy = 0.15e-3, zz = 0.04e-3), armature = 0.19, damping = 0.22, frictionloss = 0.30)]
    wrist3: Revolute,
    load: f64,
}

/// The base parameters the derive finds for this geometry.
const B: usize = 52;

type V6 = SVector<f64, 6>;

impl Puma {
    fn carrying(load: f64) -> Self {
        Self {
            waist: Revolute,
            shoulder: Revolute,
            elbow: Revolute,
            wrist1: Revolute,
            wrist2: Revolute,
            wrist3: Revolute,
            load,
        }
    }
}

/// Sampling rate of the joint sensors, Hz.
const RATE: f64 = 200.0;
/// Samples of the identification run: two periods of the excitation.
const SAMPLES: u32 = 4000;
/// Samples of the validation run.
const FRESH: u32 = 1000;
/// Standard deviation of each joint's torque measurement noise, N m.
const SIGMA: [f64; 6] = [0.5, 0.5, 0.3, 0.05, 0.05, 0.05];

/// How far the excitation takes each joint from its centre (rad, rad/s, rad/s^2).
const BOUNDS: Bounds<6> = Bounds {
    swing: [1.4, 0.8, 1.0, 1.8, 1.2, 2.0],
    speed: [1.5, 1.5, 1.5, 3.0, 3.0, 3.0],
    acceleration: [4.0, 4.0, 4.0, 8.0, 8.0, 8.0],
};
const CENTRE: [f64; 6] = [0.0, -0.6, 0.4, 0.0, 0.8, 0.0];

/// One run: states and measured (noisy) torques.
struct Run {
    states: Vec<(V6, V6, V6)>,
    measured: Vec<V6>,
}

/// "The real robot": the numeric reference's torques along the trajectory plus sensor noise.
fn measure(robot: &Puma, e: &Excitation<6>, samples: u32, rng: &mut Rng) -> Run {
    let model = robot.model();
    let states: Vec<_> = (0..samples).map(|k| e.state(f64::from(k) / RATE)).collect();
    let measured = states
        .iter()
        .map(|(q, qd, qdd)| {
            reference::inverse_dynamics(&model, q, qd, qdd) + rng.noise(&V6::from(SIGMA))
        })
        .collect();
    Run { states, measured }
}

fn identify(model: &Puma, run: &Run) -> Result<Estimate<B>, Box<dyn Error>> {
    least_squares(&stack(model, &run.states), &run.measured, &V6::from(SIGMA))
}

fn main() -> Result<(), Box<dyn Error>> {
    let robot = Puma::carrying(0.0);
    // The regressor depends on the geometry alone: the model need not know a mass.
    let model = Puma::carrying(0.0);
    let names = Puma::base_parameter_names();
    println!(
        "PUMA 560: {} standard parameters, {} base parameters (found exactly at compile time)",
        Puma::parameter_names().len(),
        names.len()
    );
    let mut rng = Rng(0x5eed_9a5a);

    println!("\n== 1. excitation ==");
    let (excitation, cond, worst) = Excitation::best(&model, &mut rng, 10, CENTRE, &BOUNDS);
    println!(
        "best of 10 random Fourier coefficient sets: column-scaled condition number {cond:.1} (worst {worst:.1})"
    );
    let run = measure(&robot, &excitation, SAMPLES, &mut rng);
    println!(
        "{SAMPLES} samples at {RATE} Hz; noise sigma {SIGMA:?} N m; measured torque RMS {:.2?} N m",
        (0..6)
            .map(|j| rms(run.measured.iter().map(|t| t[j])))
            .collect::<Vec<_>>()
    );

    println!("\n== 2. weighted least squares ==");
    let est = identify(&model, &run)?;
    println!(
        "stacked base regressor {} x {B}, rows divided by their joint's sigma: condition number {:.0}, column-scaled {:.1}; residual {:.3} sigma",
        6 * SAMPLES,
        est.condition,
        est.scaled_condition,
        est.sigma
    );
    let worst_z = print_estimate(names, &robot.base_parameters(), &est);
    assert!(
        worst_z < 5.0,
        "an identified parameter is off by {worst_z:.1} standard deviations"
    );

    println!("\n== 3. validation on a fresh trajectory ==");
    let fresh = Excitation::random(&mut rng, [0.3, -0.4, 0.6, 0.5, -0.7, 0.2], &BOUNDS);
    let check = measure(&robot, &fresh, FRESH, &mut rng);
    for (j, sigma) in SIGMA.iter().enumerate() {
        let e = rms(check
            .states
            .iter()
            .zip(&check.measured)
            .map(|((q, qd, qdd), m)| m[j] - (model.base_regressor(q, qd, qdd) * est.theta)[j]));
        println!(
            "joint {}: RMS(measured - predicted) = {e:.4} N m = {:.3} sigma",
            j + 1,
            e / sigma
        );
        assert!(e < 1.5 * sigma, "joint {}: prediction error {e}", j + 1);
    }

    println!("\n== 4. an unknown payload ==");
    let loaded = Puma::carrying(2.5);
    let carrying = measure(&loaded, &excitation, SAMPLES, &mut rng);
    let est_loaded = identify(&model, &carrying)?;
    // The base parameters are linear in the payload's mass; per kilogram they change by
    // their groupings' coefficients of `mp`, which depend on the geometry alone.
    let per_kg = Puma::carrying(1.0).base_parameters() - model.base_parameters();
    let (mut sum, mut weight) = (0.0, 0.0);
    for b in 0..B {
        if per_kg[b].abs() < 1e-12 {
            continue;
        }
        // Each base parameter's change gives one estimate of the mass; combine them by their
        // variances.
        let change = est_loaded.theta[b] - est.theta[b];
        let std = est_loaded.std[b].hypot(est.std[b]) / per_kg[b].abs();
        sum += change / per_kg[b] / (std * std);
        weight += 1.0 / (std * std);
    }
    let (mass, mass_std) = (sum / weight, weight.sqrt().recip());
    println!(
        "payload mass from the change of the {} base parameters it enters: {mass:.4} +- {mass_std:.4} kg (true {})",
        per_kg.iter().filter(|x| x.abs() >= 1e-12).count(),
        loaded.load
    );
    assert!((mass - loaded.load).abs() < 5.0 * mass_std);
    Ok(())
}
