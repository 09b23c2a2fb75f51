//! Step 6: the same identification from the simulator's states. `sim::Run` yields, per control
//! sample, the angles, rates, the torque the controller applied and the acceleration it gave:
//! one regressor row `Y(q, qd, qdd) theta = tau` each, stacked exactly as for the measured
//! run. Differencing the sampled rates instead (what a user without `qdd` would do) averages the
//! acceleration over a control period and biases the friction parameters.

use std::error::Error;

use planar_arm::prelude::*;
use planar_arm::sim::{ComputedTorque, Rk4, Sample, Simulator, Trajectory};

use super::num::fixed;
use super::{identify, Arm, Estimate, Excitation, Rng, Run, SIGMA, V3};

/// The control period of the simulated motor drives, s.
const PERIOD: f64 = 0.01;

impl Trajectory<3> for Excitation {
    fn sample(&self, t: f64) -> Sample<3> {
        let (q, qd, qdd) = self.state(t);
        Sample { q, qd, qdd }
    }
    fn duration(&self) -> f64 {
        1.0 / super::BASE_HZ
    }
}

/// The simulator's run as identification data: each state's `(q, qd, qdd)` and its torque plus
/// sensor noise, or with `difference` the accelerations from successive rates.
fn from_states(states: &[planar_arm::sim::State<3>], difference: bool, rng: &mut Rng) -> Run {
    let usable = if difference {
        states.len() - 1
    } else {
        states.len()
    };
    let rows = states[..usable].iter().enumerate().map(|(k, s)| {
        let qdd = if difference {
            (states[k + 1].qd - s.qd) / PERIOD
        } else {
            s.qdd
        };
        ((s.q, s.qd, qdd), s.tau + rng.noise(&V3::repeat(SIGMA)))
    });
    let (states, measured): (Vec<(V3, V3, V3)>, Vec<V3>) = rows.unzip();
    Run {
        t: (0..usable).map(|k| k as f64 * PERIOD).collect(),
        states,
        measured,
    }
}

/// Simulates the robot tracking the excitation by computed torque, identifies its base
/// parameters from the states, and prints the friction estimates beside those from
/// differenced rates.
pub fn identify_simulated(
    model: &Arm,
    robot: &Arm,
    excitation: &Excitation,
    rng: &mut Rng,
) -> Result<(Estimate, Estimate), Box<dyn Error>> {
    println!("\n== 6. from the simulator's states ==");
    let controller = ComputedTorque::critically_damped(robot, excitation, 15.0);
    let sim = Simulator::new(Rk4, 1e-3)?.with_control_period(PERIOD)?;
    let start = excitation.sample(0.0);
    let states = sim
        .run(robot, start.q, start.qd, 30.0, controller)?
        .into_vec()?;
    println!(
        "{} states of sim::Run, each with q, qd, the applied tau and the qdd it gave",
        states.len()
    );
    let exact = identify(model, &from_states(&states, false, rng))?;
    let differenced = identify(model, &from_states(&states, true, rng))?;
    let truth = robot.base_parameters();
    let names = Arm::base_parameter_names();
    println!(
        "{:12} {:>8} {:>16} {:>22}",
        "parameter", "true", "with state.qdd", "with differenced qd"
    );
    for (i, name) in names.iter().enumerate() {
        if name.starts_with("fv") || name.starts_with("fc") {
            println!(
                "{name:12} {:>8} {:>16} {:>22}",
                fixed(truth[i], 4),
                fixed(exact.theta[i], 4),
                fixed(differenced.theta[i], 4)
            );
        }
    }
    let worst = |e: &Estimate| {
        (0..truth.len())
            .map(|i| ((e.theta[i] - truth[i]) / e.std[i]).abs())
            .fold(0.0_f64, f64::max)
    };
    println!(
        "largest error in standard deviations: {} with state.qdd, {} with differenced rates",
        fixed(worst(&exact), 2),
        fixed(worst(&differenced), 1)
    );
    assert!(
        worst(&exact) < 5.0,
        "the simulated states should identify the arm"
    );
    Ok((exact, differenced))
}
