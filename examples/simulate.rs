//! Simulation and control with `planar_arm::sim`, and pictures of it:
//!
//! 1. the energy of the paper's two rods swinging freely for 100 s under each integrator, with
//!    what each step costs (`sim-energy.svg`);
//! 2. a three-link arm carrying 0.5 kg that its controller's model does not know about, through
//!    via-points: dead reckoning alone (the model's inverse dynamics), computed torque (the
//!    same plus PD feedback), PD with the model's gravity, and computed torque with the exact
//!    model (`sim-tracking.svg`: joint angles and tracking error against time);
//! 3. the same arm moving its tip along a straight line (inverse kinematics), drawn as a strobe
//!    picture (`sim-strobe.svg`) and, with the free rods beside it, as an animated SVG
//!    (`sim-animated.svg`, SMIL `<animateTransform>` on nested links);
//! 4. the step size a six-link arm with a light last link needs, free and under PD: printed.
//!
//! The pictures go to `target/pictures/`, to `DIR` with `--out DIR`, or with `--docs` to
//! `docs/`, where README.md shows them.
//!
//! ```text
//! cargo run --release --example simulate [-- --out DIR | -- --docs]
//! ```

#[path = "simulate/animation.rs"]
mod animation;
#[path = "support/num.rs"]
mod num;
#[path = "support/out.rs"]
mod out;
#[path = "simulate/pictures.rs"]
mod pictures;
#[path = "support/plot.rs"]
mod plot;

use std::error::Error;
use std::f64::consts::PI;
use std::time::Instant;

use planar_arm::nalgebra::{SVector, Vector3};
use planar_arm::prelude::*;
use planar_arm::sim::{
    fastest_rate, from_fn, ComputedTorque, Controller, Integrator, PdGravity, Rk4,
    SemiImplicitEuler, SimError, Simulator, State, TipLine, Trajectory, Variational4,
    VariationalMidpoint, ViaPoints,
};
use plotters::style::RGBColor;

use num::{fixed, sig};
use out::Out;

/// The paper's two equal links: uniform rods, 1 m and 1 kg.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Rods {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

/// A three-link arm with a gripper whose load is known only at run time.
#[derive(PlanarArm)]
#[arm(gravity = 9.81, payload = self.load)]
struct Picker {
    #[arm(length = 0.5, mass = 3, damping = 0.1)]
    upper: Revolute,
    #[arm(length = 0.4, mass = 2, damping = 0.1)]
    fore: Revolute,
    #[arm(length = 0.15, mass = 0.5, damping = 0.02)]
    hand: Revolute,
    load: f64,
}

impl Picker {
    fn holding(load: f64) -> Self {
        Self {
            upper: Revolute,
            fore: Revolute,
            hand: Revolute,
            load,
        }
    }
}

/// Six links, the last one light (5 cm, 20 g): the arm of the step-size question.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Six {
    #[arm(length = 0.4, mass = 4)]
    a: Revolute,
    #[arm(length = 0.35, mass = 3)]
    b: Revolute,
    #[arm(length = 0.3, mass = 2)]
    c: Revolute,
    #[arm(length = 0.2, mass = 1)]
    d: Revolute,
    #[arm(length = 0.1, mass = 0.3)]
    e: Revolute,
    #[arm(length = 0.05, mass = 0.02)]
    f: Revolute,
}

type V2 = Vector2<f64>;
/// The load the three-link arm carries, kg.
const LOAD: f64 = 0.5;
type V3 = Vector3<f64>;

fn energy<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> f64 {
    arm.kinetic_energy(q, qd) + arm.potential_energy(q)
}

// ---------------------------------------------------------------------------------------------
// 1. Energy of a free swing

/// The free rods' `|E(t) - E(0)|` sampled every 0.1 s.
fn free_energy<I: Integrator>(
    integrator: &I,
    dt: f64,
    seconds: f64,
) -> Result<Vec<(f64, f64)>, SimError> {
    let arm = Rods::default();
    let (mut q, mut qd) = (V2::new(-1.0, 0.4), V2::zeros());
    let e0 = energy(&arm, &q, &qd);
    let steps = (seconds / dt).round() as u64;
    let every = (0.1 / dt).round() as u64;
    let mut out = Vec::new();
    for k in 1..=steps {
        (q, qd) = integrator.step(&arm, &q, &qd, &V2::zeros(), dt)?;
        if k % every == 0 {
            out.push((k as f64 * dt, (energy(&arm, &q, &qd) - e0).abs()));
        }
    }
    Ok(out)
}

/// Wall time of one step of `integrator` on the free swing at `dt`, averaged over 100 steps.
fn time_steps<I: Integrator>(integrator: &I, dt: f64) -> Result<f64, SimError> {
    let arm = Rods::default();
    let (mut q, mut qd) = (V2::new(-1.0, 0.4), V2::zeros());
    let clock = Instant::now();
    for _ in 0..100 {
        (q, qd) = integrator.step(&arm, &q, &qd, &V2::zeros(), dt)?;
    }
    std::hint::black_box(q);
    Ok(clock.elapsed().as_secs_f64() / 100.0)
}

/// Wall time per step of semi-implicit Euler, RK4, the variational midpoint and the
/// fourth-order variational integrator: each the least of 30 rounds, the four timed in turn
/// within a round, so that other work on the machine weighs on all of them alike.
fn costs(dt: f64) -> Result<[f64; 4], SimError> {
    let mut best = [f64::INFINITY; 4];
    for _ in 0..30 {
        let round = [
            time_steps(&SemiImplicitEuler, dt)?,
            time_steps(&Rk4, dt)?,
            time_steps(&VariationalMidpoint::default(), dt)?,
            time_steps(&Variational4::default(), dt)?,
        ];
        for (b, r) in best.iter_mut().zip(round) {
            *b = b.min(r);
        }
    }
    Ok(best)
}

/// The mean number of fixed-point iterations of the midpoint step over a free swing.
fn midpoint_iterations(dt: f64, seconds: f64) -> Result<(f64, u32), SimError> {
    let arm = Rods::default();
    let (mut q, mut qd) = (V2::new(-1.0, 0.4), V2::zeros());
    let steps = (seconds / dt).round() as u64;
    let (mut total, mut most) = (0_u64, 0_u32);
    for _ in 0..steps {
        let (q1, qd1, n) =
            VariationalMidpoint::default().step_counted(&arm, &q, &qd, &V2::zeros(), dt)?;
        (q, qd) = (q1, qd1);
        total += u64::from(n);
        most = most.max(n);
    }
    Ok((total as f64 / steps as f64, most))
}

struct EnergyCurve {
    name: String,
    points: Vec<(f64, f64)>,
    color: RGBColor,
}

/// The largest `|dE|` of a curve over 0-10 s and over 90-100 s.
fn early_late(points: &[(f64, f64)]) -> (f64, f64) {
    let largest = |from: f64, to: f64| {
        points
            .iter()
            .filter(|p| p.0 > from && p.0 <= to)
            .fold(0.0_f64, |m, p| m.max(p.1))
    };
    (largest(0.0, 10.0), largest(90.0, 100.0))
}

/// RK4's short step in the picture: about what one fourth-order variational step costs, 12 to
/// 13 RK4 steps in a release build. Fixed, so that the picture is the same on every machine;
/// the step at this machine's measured cost is printed.
const DT_SHORT: f64 = 0.8e-3;

fn energy_section(out: &Out) -> Result<(), Box<dyn Error>> {
    println!("== 1. the free rods for 100 s from q = (-1, 0.4) at rest: |E(t) - E(0)| ==");
    let (dt, seconds) = (0.01, 100.0);
    let mut curves = Vec::new();
    let mut rows = Vec::new();
    let palette = [
        RGBColor(150, 150, 150),
        RGBColor(200, 80, 40),
        RGBColor(70, 110, 190),
        RGBColor(40, 150, 90),
    ];
    let [t_euler, t_rk4, t_mid, t_v4] = costs(dt)?;
    let euler = free_energy(&SemiImplicitEuler, dt, seconds)?;
    let rk4 = free_energy(&Rk4, dt, seconds)?;
    let mid = free_energy(&VariationalMidpoint::default(), dt, seconds)?;
    let v4 = free_energy(&Variational4::default(), dt, seconds)?;
    let (iters, most) = midpoint_iterations(dt, 10.0)?;
    let row = |name: &str, (early, late): (f64, f64)| {
        format!(
            "    {name:53}   max |dE| 0-10 s {:>8} J   90-100 s {:>8} J",
            sig(early, 3),
            sig(late, 3)
        )
    };
    for (name, points, per_step, color) in [
        ("semi-implicit Euler", euler, t_euler, palette[0]),
        ("RK4", rk4, t_rk4, palette[1]),
        ("variational midpoint", mid, t_mid, palette[2]),
        ("variational 4th order", v4, t_v4, palette[3]),
    ] {
        let (early, late) = early_late(&points);
        rows.push(row(
            &format!(
                "{name:24} {:>9} us/step ({:>4}x RK4)",
                fixed(per_step * 1e6, 2),
                fixed(per_step / t_rk4, 1)
            ),
            (early, late),
        ));
        curves.push(EnergyCurve {
            name: format!(
                "{name}, step {} ms: {} J at 90-100 s",
                sig(dt * 1e3, 2),
                sig(late, 2)
            ),
            points,
            color,
        });
    }
    // RK4 again with its step shortened to the fourth-order variational one's cost per second:
    // on this machine (printed), and at a typical release build's ratio (drawn).
    let dt_equal = (dt * t_rk4 / t_v4).min(dt);
    let dt_equal = seconds / (seconds / dt_equal).round();
    rows.push(row(
        &format!(
            "RK4, step {} ms: the 4th-order one's cost here",
            fixed(dt_equal * 1e3, 2)
        ),
        early_late(&free_energy(&Rk4, dt_equal, seconds)?),
    ));
    let rk4_short = free_energy(&Rk4, DT_SHORT, seconds)?;
    let (early, late) = early_late(&rk4_short);
    rows.push(row(
        &format!(
            "RK4, step {} ms: that cost in a release build, drawn",
            sig(DT_SHORT * 1e3, 1)
        ),
        (early, late),
    ));
    curves.push(EnergyCurve {
        name: format!(
            "RK4, step {} ms (about the 4th-order variational step's cost): {} J at 90-100 s",
            sig(DT_SHORT * 1e3, 1),
            sig(late, 2)
        ),
        points: rk4_short,
        color: RGBColor(235, 160, 60),
    });
    println!(
        "step {} ms; wall time per step in this build (the least of 30 interleaved rounds of 100 steps):",
        sig(dt * 1e3, 2)
    );
    for r in &rows {
        println!("{r}");
    }
    println!(
        "the midpoint step's fixed-point iteration: {iters:.2} iterations on average, at most {most} (tolerance 1e-14)"
    );
    let e_scale = {
        let arm = Rods::default();
        let q = V2::new(-1.0, 0.4);
        energy(&arm, &q, &V2::zeros()) - energy(&arm, &V2::new(-PI / 2.0, 0.0), &V2::zeros())
    };
    println!("(the swing's energy above hanging still: {e_scale:.3} J)");
    let path = out.path("sim-energy.svg");
    pictures::draw_energy(&path, &curves, e_scale)?;
    out.wrote(&path);
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// 2. Tracking with a model that does not know the payload

/// The via-points: out, up, over and back, 4 s.
fn via_points() -> Result<ViaPoints<3, 5>, SimError> {
    ViaPoints::new(
        [0.0, 1.0, 2.0, 3.0, 4.0],
        [
            V3::new(-1.2, 1.2, 0.3),
            V3::new(-0.3, 0.9, -0.4),
            V3::new(0.6, 0.8, 0.5),
            V3::new(1.2, -0.4, 0.9),
            V3::new(0.2, 0.6, -0.3),
        ],
    )
}

/// A controller's run, sampled every control period.
struct Tracked {
    name: &'static str,
    /// The name in a title.
    short: &'static str,
    states: Vec<State<3>>,
    color: RGBColor,
}

/// The loaded arm from `q0` at rest for `duration` under `controller`, every control period.
fn track<C: Controller<3>>(
    q0: V3,
    duration: f64,
    controller: C,
) -> Result<Vec<State<3>>, SimError> {
    let sim = Simulator::new(Rk4, 1e-3)?.with_control_period(5e-3)?;
    sim.run(
        &Picker::holding(LOAD),
        q0,
        V3::zeros(),
        duration,
        controller,
    )?
    .into_vec()
}

fn tracking_section(out: &Out) -> Result<(), Box<dyn Error>> {
    println!(
        "\n== 2. three links carrying 0.5 kg that the model does not know, through via-points =="
    );
    let real = Picker::holding(LOAD);
    let model = Picker::holding(0.0);
    let path = via_points()?;
    let (q0, duration) = (path.sample(0.0).q, 5.0);
    let omega = 20.0;
    let kp = V3::new(300.0, 150.0, 20.0);
    let kd = V3::new(30.0, 12.0, 1.5);
    let mut summary = Vec::new();
    // Colours that the joints in the picture's angle panel do not use.
    let runs = [
        Tracked {
            name: "dead reckoning (the model's inverse dynamics alone)",
            short: "dead reckoning",
            states: track(
                q0,
                duration,
                ComputedTorque::critically_damped(&model, path, 0.0),
            )?,
            color: RGBColor(213, 94, 0),
        },
        Tracked {
            name: "PD with the model's gravity",
            short: "PD with the model's gravity",
            states: track(q0, duration, PdGravity::new(&model, path, kp, kd))?,
            color: RGBColor(110, 70, 170),
        },
        Tracked {
            name: "computed torque, wrong model (dead reckoning + PD, 20 rad/s)",
            short: "computed torque with the wrong model",
            states: track(
                q0,
                duration,
                ComputedTorque::critically_damped(&model, path, omega),
            )?,
            color: RGBColor(30, 70, 160),
        },
        Tracked {
            name: "computed torque, exact model",
            short: "computed torque with the exact model",
            states: track(
                q0,
                duration,
                ComputedTorque::critically_damped(&real, path, omega),
            )?,
            color: RGBColor(20, 140, 60),
        },
    ];
    println!("RK4 at 1 ms, torques held for 5 ms; largest |q* - q| (rad) over 0-4 s (moving) and 4-5 s (holding):");
    for r in &runs {
        let worst = |from: f64, to: f64| {
            r.states
                .iter()
                .filter(|s| s.t >= from && s.t <= to)
                .map(|s| (s.q - path.sample(s.t).q).amax())
                .fold(0.0, f64::max)
        };
        println!(
            "    {:62} {:>9}   {:>9}",
            r.name,
            sig(worst(0.0, 4.0), 3),
            sig(worst(4.0, 5.0), 3)
        );
        summary.push(worst(0.0, 5.0));
    }
    println!(
        "computed torque's gains are per unit inertia: on the hand (0.5 kg, 15 cm) the model's \
         inertia about the joint is {:.4} kg m^2 against {:.4} with the load, so its feedback is \
         that much softer there than PD's absolute gains",
        model.mass_matrix(&q0)[(2, 2)],
        real.mass_matrix(&q0)[(2, 2)]
    );
    let file = out.path("sim-tracking.svg");
    pictures::draw_tracking(&file, &path, &runs, &summary)?;
    out.wrote(&file);
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// 3. A straight tip line: strobe and animation

fn line_section(out: &Out) -> Result<(), Box<dyn Error>> {
    println!("\n== 3. the tip along a straight line, by inverse kinematics, tracked by computed torque ==");
    let real = Picker::holding(LOAD);
    let model = Picker::holding(LOAD);
    let q0 = V3::new(-0.9, 1.9, 0.6);
    let to = Point2::new(0.75, 0.45);
    let line = TipLine::new(&model, q0, to, 2.0)?;
    let states = track(
        q0,
        2.5,
        ComputedTorque::critically_damped(&model, &line, 20.0),
    )?;
    let from = real.tip_pose(&q0).translation.vector;
    let dir = (to.coords - from).normalize();
    let off = states
        .iter()
        .map(|s| {
            let p = real.tip_pose(&s.q).translation.vector - from;
            (p.x * dir.y - p.y * dir.x).abs()
        })
        .fold(0.0, f64::max);
    let last = states.last().map_or(f64::NAN, |s| {
        (real.tip_pose(&s.q).translation.vector - to.coords).norm()
    });
    println!(
        "from ({:.3}, {:.3}) to ({}, {}) in 2 s: the tip strays at most {} m from the line, ends {} m from the target",
        from.x,
        from.y,
        to.x,
        to.y,
        sig(off, 2),
        sig(last, 2)
    );
    let file = out.path("sim-strobe.svg");
    pictures::draw_strobe(&file, &real, &states, (from, to.coords))?;
    out.wrote(&file);

    // The free rods beside it, for the animation: 10 s of a chaotic double pendulum.
    let rods = Rods::default();
    let free = from_fn(|_, _: &V2, _: &V2| V2::zeros());
    let swing = Simulator::new(Rk4, 1e-3)?
        .with_control_period(0.04)?
        .run(&rods, V2::new(0.3, 1.0), V2::zeros(), 10.0, free)?
        .into_vec()?;
    // Every 50 ms, the last at the end of the run: the animation's loop is the run's length.
    let picker: Vec<State<3>> = states.iter().step_by(10).copied().collect();
    let svg = animation::animate(&real, &picker, &swing, (from, to.coords));
    let file = out.path("sim-animated.svg");
    std::fs::write(&file, svg)?;
    out.wrote(&file);
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// 4. Step size for six links with a light last link

/// A step in milliseconds, for a table.
fn ms(dt: f64) -> String {
    sig(dt * 1e3, 1)
}

fn step_size_section() -> Result<(), Box<dyn Error>> {
    println!("\n== 4. step size: six links, the last 5 cm and 20 g ==");
    let arm = Six::default();
    let q0 = SVector::<f64, 6>::from_column_slice(&[-0.8, 0.6, 0.5, -0.4, 0.7, 0.9]);
    let zero = SVector::<f64, 6>::zeros();
    println!("free swing from rest for 2 s, RK4: largest |E - E0| relative to the energy swing");
    let e0 = energy(&arm, &q0, &zero);
    let hanging = SVector::<f64, 6>::from_fn(|i, _| if i == 0 { -PI / 2.0 } else { 0.0 });
    let scale = e0 - energy(&arm, &hanging, &zero);
    for dt in [1e-2_f64, 3e-3, 1e-3, 3e-4, 1e-4] {
        let (mut q, mut qd) = (q0, zero);
        let mut worst = 0.0_f64;
        let steps = (2.0 / dt).round() as u32;
        let mut failed = None;
        for k in 0..steps {
            match Rk4.step(&arm, &q, &qd, &zero, dt) {
                Ok((a, b)) => (q, qd) = (a, b),
                Err(e) => {
                    failed = Some((f64::from(k) * dt, e));
                    break;
                }
            }
            worst = worst.max((energy(&arm, &q, &qd) - e0).abs());
        }
        match failed {
            Some((t, e)) => println!("    step {:>4} ms: fails at t = {t:.3} s ({e})", ms(dt)),
            None => println!(
                "    step {:>4} ms: {:>9}",
                ms(dt),
                sig(worst / scale.abs(), 3)
            ),
        }
    }
    let kp = SVector::<f64, 6>::from_element(200.0);
    let kd = SVector::<f64, 6>::from_element(10.0);
    let rate = fastest_rate(&arm, &q0, &kp, &kd)?;
    println!(
        "PD + gravity with the same gains on every joint (kp = 200 N m/rad, kd = 10 N m s/rad): fastest_rate {} 1/s, so RK4 needs a step under {} s to be stable",
        sig(rate, 3),
        sig(2.8 / rate, 2)
    );
    let hold = planar_arm::sim::Quintic::rest_to_rest(q0, q0, 1.0)?;
    for dt in [1e-3, 1e-4, 3e-5] {
        let sim = Simulator::new(Rk4, dt)?;
        let result = sim
            .run(
                &arm,
                q0 + SVector::from_element(0.05),
                zero,
                0.5,
                PdGravity::new(&arm, hold, kp, kd),
            )?
            .last();
        match result {
            Some(Ok(s)) => println!(
                "    step {:>4} ms: error after 0.5 s {:>9} rad",
                ms(dt),
                sig((s.q - q0).amax(), 3)
            ),
            Some(Err(e)) => println!("    step {:>4} ms: {e}", ms(dt)),
            None => {}
        }
    }
    // Computed torque's gains are per unit inertia: the light link gets a torque scaled to it.
    let omega = 20.0;
    println!(
        "computed torque, {omega} rad/s on every joint (kp = omega^2, kd = 2 omega per unit inertia): rate sqrt(kp) + kd = {:.0} 1/s, RK4 stable below {} s",
        3.0 * omega,
        sig(2.8 / (3.0 * omega), 2)
    );
    for dt in [1e-2, 1e-3] {
        let sim = Simulator::new(Rk4, dt)?;
        let ct = ComputedTorque::critically_damped(&arm, hold, omega);
        match sim
            .run(&arm, q0 + SVector::from_element(0.05), zero, 0.5, ct)?
            .last()
        {
            Some(Ok(s)) => println!(
                "    step {:>4} ms: error after 0.5 s {:>9} rad",
                ms(dt),
                sig((s.q - q0).amax(), 3)
            ),
            Some(Err(e)) => println!("    step {:>4} ms: {e}", ms(dt)),
            None => {}
        }
    }
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let out = Out::from_args("simulate");
    energy_section(&out)?;
    tracking_section(&out)?;
    line_section(&out)?;
    step_size_section()?;
    Ok(())
}
