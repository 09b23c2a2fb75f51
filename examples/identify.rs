//! Identifies a three-link arm's base parameters from simulated noisy joint torques, the way
//! robot makers calibrate a dynamic model, with the derived [`Identification`] trait:
//!
//! 1. an exciting trajectory: per joint a finite Fourier series (Swevers et al.: five harmonics
//!    of 0.1 Hz), the best of a few random coefficient sets by the condition number of the
//!    stacked base regressor;
//! 2. "measured" torques along it from the independent numeric reference
//!    ([`planar_arm::reference::inverse_dynamics`], not the generated code) plus Gaussian noise;
//! 3. least squares on the base regressor stacked over the samples (SVD), with each
//!    parameter's standard deviation from the covariance `sigma^2 (W^T W)^-1`;
//! 4. validation: torques predicted with the identified parameters on a fresh trajectory
//!    against fresh measurements, whose RMS error should be the noise level;
//! 5. an unknown payload: the same regressor identifies the loaded arm's base parameters, and
//!    the change from the empty arm's gives the payload's mass;
//! 6. the same from a simulation: the states of `sim::Run` (angles, rates, applied torque and
//!    the acceleration it gave) are the regressor's rows as they stand, where accelerations
//!    differenced from the sampled rates bias the friction parameters.
//!
//! It prints the tables and draws `identify-torques.svg` (measured against predicted torques on
//! the fresh trajectory) and `identify-parameters.svg` (identification errors against their
//! standard deviations). The pictures go to `target/pictures/`, to `DIR` with `--out DIR`, or
//! with `--docs` to `docs/`, where README.md shows them.
//!
//! ```text
//! cargo run --release --example identify [-- --out DIR | -- --docs]
//! ```

#[path = "support/excite.rs"]
mod excite;
#[path = "support/num.rs"]
mod num;
#[path = "support/out.rs"]
mod out;
#[path = "identify/pictures.rs"]
mod pictures;
#[path = "support/plot.rs"]
mod plot;
#[path = "identify/simulated.rs"]
mod simulated;

use std::error::Error;

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;
use planar_arm::reference;

use excite::{least_squares, print_estimate, rms, stack, Bounds, Rng, BASE_HZ};
use num::fixed;
use out::Out;

/// A 3-link arm with realistic masses, geared joints (armature, viscous and Coulomb friction)
/// and a payload slot; the values the factory does not know precisely are run-time parameters.
#[derive(PlanarArm, Clone)]
#[arm(
    gravity = 9.81,
    payload = self.load,
    payload_inertia = self.load_inertia,
    payload_com = (self.load_x, self.load_y)
)]
struct Arm {
    #[arm(length = 0.4, mass = 4.2, inertia = 0.065, com = (0.17, 0.006),
          armature = 0.12, damping = 0.8, frictionloss = self.f1)]
    shoulder: Revolute,
    #[arm(length = 0.35, mass = self.m2, inertia = self.i2, com = (0.15, -0.004),
          armature = 0.05, damping = 0.4, frictionloss = 0.6)]
    elbow: Revolute,
    #[arm(length = 0.25, mass = self.m3, inertia = 0.006, com = (self.c3, 0.012),
          armature = 0.02, damping = 0.15, frictionloss = 0.25)]
    wrist: Revolute,
    f1: f64,
    m2: f64,
    i2: f64,
    m3: f64,
    c3: f64,
    load: f64,
    load_inertia: f64,
    load_x: f64,
    load_y: f64,
}

/// Base parameters (of 25 standard ones: zz, mx, my per link and the payload's, four masses,
/// three armatures, three dampings, three Coulomb frictions): three per link, the armatures of joints 2 and 3 (joint 1's joins zz1),
/// damping and Coulomb friction per joint.
const B: usize = 17;

impl Arm {
    /// The arm as it left the factory, without a payload.
    fn empty() -> Self {
        Self {
            shoulder: Revolute,
            elbow: Revolute,
            wrist: Revolute,
            f1: 1.2,
            m2: 2.6,
            i2: 0.031,
            m3: 1.1,
            c3: 0.09,
            load: 0.0,
            load_inertia: 0.0,
            load_x: 0.0,
            load_y: 0.0,
        }
    }
}

type V3 = SVector<f64, 3>;

/// Sampling rate of the joint sensors, Hz.
const RATE: f64 = 100.0;
/// Samples of the identification run: three periods of the excitation.
const SAMPLES: u32 = 3000;
/// Samples of the validation run.
const FRESH: u32 = 1000;
/// Standard deviation of the torque measurement noise, N m (motor-current noise).
const SIGMA: f64 = 0.1;

type Excitation = excite::Excitation<3>;
type Estimate = excite::Estimate<B>;

/// Bounds of the motion about the centre, rad, rad/s, rad/s^2: the arm sweeps most of its
/// range while the motors stay within their speed and torque.
const BOUNDS: Bounds<3> = Bounds {
    swing: [1.5; 3],
    speed: [3.0; 3],
    acceleration: [10.0; 3],
};

/// One run: sample times, states and measured (noisy) torques.
struct Run {
    t: Vec<f64>,
    states: Vec<(V3, V3, V3)>,
    measured: Vec<V3>,
}

/// "The real robot": the numeric reference's torques along the trajectory plus sensor noise.
fn measure(robot: &Arm, e: &Excitation, samples: u32, rng: &mut Rng) -> Run {
    let model = robot.model();
    let t: Vec<f64> = (0..samples).map(|k| f64::from(k) / RATE).collect();
    let states: Vec<_> = t.iter().map(|&t| e.state(t)).collect();
    let measured = states
        .iter()
        .map(|(q, qd, qdd)| {
            reference::inverse_dynamics(&model, q, qd, qdd) + rng.noise(&V3::repeat(SIGMA))
        })
        .collect();
    Run {
        t,
        states,
        measured,
    }
}

/// Least squares on the base regressor stacked over the run (see `excite::least_squares`).
fn identify(model: &Arm, run: &Run) -> Result<Estimate, Box<dyn Error>> {
    least_squares(&stack(model, &run.states), &run.measured, &V3::repeat(1.0))
}

/// Steps 1 and 2: the excitation, its measurements and the identified base parameters.
fn identify_empty(
    model: &Arm,
    robot: &Arm,
    rng: &mut Rng,
) -> Result<(Excitation, Estimate), Box<dyn Error>> {
    println!("== 1. excitation ==");
    let (excitation, cond, worst) = Excitation::best(model, rng, 20, [0.0, 0.4, -0.3], &BOUNDS);
    println!(
        "best of 20 random Fourier coefficient sets: column-scaled condition number {cond:.2} (worst {worst:.2})"
    );
    let run = measure(robot, &excitation, SAMPLES, rng);
    // Coulomb friction is only told from viscous friction and inertia when the speeds change
    // sign, and the inertias only when the arm sweeps its range.
    let extent = |pick: fn(&(V3, V3, V3)) -> V3| {
        let (lo, hi) = run.states.iter().fold(
            (V3::repeat(f64::MAX), V3::repeat(f64::MIN)),
            |(lo, hi), s| (lo.inf(&pick(s)), hi.sup(&pick(s))),
        );
        let pairs: Vec<String> = (0..3)
            .map(|j| format!("({}, {})", fixed(lo[j], 2), fixed(hi[j], 2)))
            .collect();
        pairs.join(", ")
    };
    let torque_rms: Vec<f64> = (0..3)
        .map(|j| rms(run.measured.iter().map(|t| t[j])))
        .collect();
    println!(
        "{SAMPLES} samples at {RATE} Hz over {} s",
        f64::from(SAMPLES) / RATE
    );
    println!("joint angles (min, max): {} rad", extent(|s| s.0));
    println!("joint speeds (min, max): {} rad/s", extent(|s| s.1));
    println!("measured torque RMS {torque_rms:.2?} N m; noise sigma {SIGMA} N m");

    println!("\n== 2. least squares ==");
    let est = identify(model, &run)?;
    println!(
        "stacked base regressor {} x {B}: condition number {:.1}, column-scaled {:.2}",
        3 * SAMPLES,
        est.condition,
        est.scaled_condition
    );
    println!(
        "noise estimated from the residual: {:.4} N m (true {SIGMA}); std dev = sqrt of the diagonal of sigma^2 (W^T W)^-1\n",
        est.sigma
    );
    let worst_z = print_estimate(Arm::base_parameter_names(), &robot.base_parameters(), &est);
    assert!(
        worst_z < 5.0,
        "an identified parameter is off by {worst_z:.1} standard deviations"
    );
    Ok((excitation, est))
}

/// Step 3: the identified model's torques on a fresh trajectory against fresh measurements.
fn validate(model: &Arm, robot: &Arm, est: &Estimate, rng: &mut Rng) -> (Run, Vec<V3>, [f64; 3]) {
    println!("\n== 3. validation on a fresh trajectory ==");
    let fresh = Excitation::random(rng, [0.6, -0.5, 0.8], &BOUNDS);
    let check = measure(robot, &fresh, FRESH, rng);
    let predicted: Vec<V3> = check
        .states
        .iter()
        .map(|(q, qd, qdd)| model.base_regressor(q, qd, qdd) * est.theta)
        .collect();
    let errors: [f64; 3] = std::array::from_fn(|j| {
        rms(check
            .measured
            .iter()
            .zip(&predicted)
            .map(|(m, p)| m[j] - p[j]))
    });
    for (j, e) in errors.iter().enumerate() {
        println!(
            "joint {}: RMS(measured - predicted) = {e:.4} N m = {:.3} sigma",
            j + 1,
            e / SIGMA
        );
        assert!(*e < 1.5 * SIGMA, "joint {}: prediction error {e}", j + 1);
    }
    (check, predicted, errors)
}

/// Step 4: the arm carries a payload the model does not know; the same regressor identifies
/// the loaded arm's base parameters, and their change from the empty arm's gives its mass.
fn identify_payload(
    model: &Arm,
    robot: &Arm,
    excitation: &Excitation,
    empty: &Estimate,
    rng: &mut Rng,
) -> Result<(), Box<dyn Error>> {
    println!("\n== 4. an unknown payload ==");
    let loaded = Arm {
        load: 1.5,
        load_inertia: 0.004,
        load_x: 0.06,
        load_y: 0.02,
        ..robot.clone()
    };
    let carrying = measure(&loaded, excitation, SAMPLES, rng);
    let est = identify(model, &carrying)?;
    let (before, after) = (robot.base_parameters(), loaded.base_parameters());
    let names = Arm::base_parameter_names();
    let width = names.iter().map(|n| n.len()).max().unwrap_or(0);
    println!(
        "{:width$}  {:>10} {:>10} {:>10} {:>9} {:>12} {:>12}",
        "changed by the payload",
        "empty",
        "loaded",
        "identified",
        "std dev",
        "vs loaded",
        "vs empty"
    );
    let mut worst = 0.0_f64;
    for i in 0..B {
        let z_loaded = (est.theta[i] - after[i]) / est.std[i];
        worst = worst.max(z_loaded.abs());
        // The base parameters without a payload term evaluate the same expression.
        if (after[i] - before[i]).abs() <= 1e-12 {
            continue;
        }
        let z_empty = (est.theta[i] - before[i]) / est.std[i];
        println!(
            "{:width$}  {:>10} {:>10} {:>10} {:>9} {:>10} sd {:>9} sd",
            names[i],
            fixed(before[i], 5),
            fixed(after[i], 5),
            fixed(est.theta[i], 5),
            fixed(est.std[i], 5),
            fixed(z_loaded, 2),
            fixed(z_empty, 1)
        );
        assert!(
            z_empty.abs() > 10.0,
            "{}: the payload should show",
            names[i]
        );
    }
    println!("all {B} within {worst:.2} standard deviations of the loaded arm's base parameters");
    assert!(worst < 5.0, "loaded: off by {worst:.1} standard deviations");
    // mx2 + l2 m3 + l2 mp: the payload's mass is its change over l2, between two independent
    // identifications.
    let i = names
        .iter()
        .position(|n| n.starts_with("mx2"))
        .ok_or("mx2")?;
    let l2 = robot.links()[1].length;
    let mass = (est.theta[i] - empty.theta[i]) / l2;
    let mass_std = est.std[i].hypot(empty.std[i]) / l2;
    println!(
        "payload mass from the change of {}: {mass:.4} +- {mass_std:.4} kg (true {})",
        names[i], loaded.load
    );
    assert!((mass - loaded.load).abs() < 5.0 * mass_std);
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let out = Out::from_args("identify");
    let robot = Arm::empty();
    // The base regressor depends on the lengths and gravity only: the model it comes from
    // need not know any mass, inertia or friction.
    let model = Arm::empty();
    let mut rng = Rng(0x1de7_1f1e);

    let (excitation, est) = identify_empty(&model, &robot, &mut rng)?;
    let (check, predicted, errors) = validate(&model, &robot, &est, &mut rng);
    identify_payload(&model, &robot, &excitation, &est, &mut rng)?;
    simulated::identify_simulated(&model, &robot, &excitation, &mut rng)?;

    println!();
    let torques = out.path("identify-torques.svg");
    pictures::draw_torques(&torques, &check, &predicted, &errors)?;
    out.wrote(&torques);
    let parameters = out.path("identify-parameters.svg");
    pictures::draw_parameters(&parameters, &robot.base_parameters(), &est)?;
    out.wrote(&parameters);
    Ok(())
}
