//! Simulation and control with `planar_arm::sim`, and pictures of it:
//!
//! 1. the energy of the paper's two rods swinging freely for 100 s under each integrator, with
//!    what each step costs (`docs/sim-energy.svg`);
//! 2. a three-link arm carrying 1 kg that its controller's model does not know about, through
//!    via-points: dead reckoning alone (the model's inverse dynamics), computed torque (the
//!    same plus PD feedback), PD with the model's gravity, and computed torque with the exact
//!    model (`docs/sim-tracking.svg`: joint angles and tracking error against time);
//! 3. the same arm moving its tip along a straight line (inverse kinematics), drawn as a strobe
//!    picture (`docs/sim-strobe.svg`) and, with the free rods beside it, as an animated SVG
//!    (`docs/sim-animated.svg`, SMIL `<animateTransform>` on nested links);
//! 4. the step size a six-link arm with a light last link needs, free and under PD: printed.
//!
//! The pictures go to `target/pictures/`, to `DIR` with `--out DIR`, or with `--docs` to
//! `docs/`, where README.md shows them.
//!
//! ```text
//! cargo run --release --example simulate [-- --out DIR | -- --docs]
//! ```

#[path = "support/num.rs"]
mod num;
#[path = "support/out.rs"]
mod out;

use std::error::Error;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

use planar_arm::nalgebra::{SVector, Vector3};
use planar_arm::prelude::*;
use planar_arm::sim::{
    fastest_rate, from_fn, ComputedTorque, Integrator, PdGravity, Rk4, SemiImplicitEuler, SimError,
    Simulator, State, TipLine, Trajectory, Variational4, VariationalMidpoint, ViaPoints,
};
use plotters::coord::Shift;
use plotters::prelude::*;

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
    draw_energy(&path, &curves, e_scale)?;
    out.wrote(&path);
    Ok(())
}

fn font(size: u32) -> TextStyle<'static> {
    ("sans-serif", size).into_font().into()
}

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

fn swatch(style: ShapeStyle) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style)
}

/// A tick label without "-0" and without rounding noise.
fn tick(v: f64) -> String {
    format!("{}", (v * 1e6).round() / 1e6 + 0.0)
}

fn draw_energy(path: &Path, curves: &[EnergyCurve], e_scale: f64) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1100, 650)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(64);
    head.draw(&Text::new(
        "Energy of two 1 m, 1 kg rods swinging freely for 100 s, by integrator",
        (16, 10),
        font(20),
    ))?;
    head.draw(&Text::new(
        format!("|E(t) - E(0)|, log scale, sampled every 0.1 s; the swing holds {e_scale:.2} J above hanging still. RK4 drifts, the variational ones do not; at equal cost RK4 is more accurate."),
        (16, 38),
        font(14),
    ))?;
    let mut chart = ChartBuilder::on(&body)
        .margin(12)
        .margin_right(24)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..100.0, (1e-14..1e4).log_scale())?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("|E - E0| (J)")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    for c in curves {
        // Log scale: a sample that happens to be exact would be off the chart.
        let points: Vec<(f64, f64)> = c.points.iter().map(|&(t, e)| (t, e.max(1e-14))).collect();
        chart
            .draw_series(LineSeries::new(points, c.color.stroke_width(2)))?
            .label(c.name.clone())
            .legend(swatch(c.color.stroke_width(3)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK.mix(0.3))
        .label_font(font(13))
        .draw()?;
    root.present()?;
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
    states: Vec<State<3>>,
    color: RGBColor,
}

fn tracking_section(out: &Out) -> Result<(), Box<dyn Error>> {
    println!(
        "\n== 2. three links carrying 0.5 kg that the model does not know, through via-points =="
    );
    let real = Picker::holding(LOAD);
    let model = Picker::holding(0.0);
    let path = via_points()?;
    let sim = Simulator::new(Rk4, 1e-3)?.with_control_period(5e-3)?;
    let (q0, duration) = (path.sample(0.0).q, 5.0);
    let omega = 20.0;
    let kp = V3::new(300.0, 150.0, 20.0);
    let kd = V3::new(30.0, 12.0, 1.5);
    let mut summary = Vec::new();
    let runs = [
        Tracked {
            name: "dead reckoning (the model's inverse dynamics alone)",
            states: sim
                .run(
                    &real,
                    q0,
                    V3::zeros(),
                    duration,
                    ComputedTorque::critically_damped(&model, path, 0.0),
                )?
                .into_vec()?,
            color: RGBColor(200, 80, 40),
        },
        Tracked {
            name: "PD with the model's gravity",
            states: sim
                .run(
                    &real,
                    q0,
                    V3::zeros(),
                    duration,
                    PdGravity::new(&model, path, kp, kd),
                )?
                .into_vec()?,
            color: RGBColor(150, 110, 190),
        },
        Tracked {
            name: "computed torque, wrong model (dead reckoning + PD, 20 rad/s)",
            states: sim
                .run(
                    &real,
                    q0,
                    V3::zeros(),
                    duration,
                    ComputedTorque::critically_damped(&model, path, omega),
                )?
                .into_vec()?,
            color: RGBColor(70, 110, 190),
        },
        Tracked {
            name: "computed torque, exact model",
            states: sim
                .run(
                    &real,
                    q0,
                    V3::zeros(),
                    duration,
                    ComputedTorque::critically_damped(&real, path, omega),
                )?
                .into_vec()?,
            color: RGBColor(40, 150, 90),
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
    draw_tracking(&file, &path, &runs, &summary)?;
    out.wrote(&file);
    Ok(())
}

fn draw_tracking(
    path: &Path,
    reference: &ViaPoints<3, 5>,
    runs: &[Tracked],
    worst: &[f64],
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1100, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(64);
    head.draw(&Text::new(
        "Three links carrying 0.5 kg that the controller's model does not know",
        (16, 10),
        font(20),
    ))?;
    head.draw(&Text::new(
        format!(
            "five via-points in 4 s, then holding; RK4 at 1 ms, torques held for 5 ms. Largest errors: {}",
            runs.iter()
                .zip(worst)
                .map(|(r, w)| format!("{} {w:.1e}", r.name.split(" (").next().unwrap_or(r.name)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        (16, 38),
        font(13),
    ))?;
    let (top, bottom) = body.split_vertically(430);
    angles_panel(&top, reference, &runs[2])?;
    error_panel(&bottom, reference, runs)?;
    root.present()?;
    Ok(())
}

const JOINTS: [RGBColor; 3] = [
    RGBColor(70, 110, 190),
    RGBColor(200, 80, 40),
    RGBColor(40, 150, 90),
];

fn angles_panel(
    area: &Area<'_>,
    reference: &ViaPoints<3, 5>,
    run: &Tracked,
) -> Result<(), Box<dyn Error>> {
    let end = run.states.last().map_or(1.0, |s| s.t);
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .margin_right(24)
        .caption(
            format!("joint angles: desired (dashed) and under {}", run.name),
            font(15),
        )
        .x_label_area_size(36)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..end, -1.6..1.6)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("angle (rad)")
        .y_label_formatter(&|v| tick(*v))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    for (j, color) in JOINTS.iter().enumerate() {
        let want: Vec<(f64, f64)> = run
            .states
            .iter()
            .map(|s| (s.t, reference.sample(s.t).q[j]))
            .collect();
        chart.draw_series(DashedLineSeries::new(
            want,
            7,
            5,
            color.mix(0.7).stroke_width(2),
        ))?;
        chart
            .draw_series(LineSeries::new(
                run.states.iter().map(|s| (s.t, s.q[j])),
                color.stroke_width(2),
            ))?
            .label(format!("q{}", j + 1))
            .legend(swatch(color.stroke_width(2)));
    }
    chart.draw_series(
        [1.0, 2.0, 3.0, 4.0]
            .iter()
            .map(|&t| PathElement::new(vec![(t, -1.6), (t, 1.6)], BLACK.mix(0.15))),
    )?;
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK.mix(0.3))
        .label_font(font(13))
        .draw()?;
    Ok(())
}

fn error_panel(
    area: &Area<'_>,
    reference: &ViaPoints<3, 5>,
    runs: &[Tracked],
) -> Result<(), Box<dyn Error>> {
    let end = runs[0].states.last().map_or(1.0, |s| s.t);
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .margin_right(24)
        .caption(
            "tracking error: the largest |q* - q| over the three joints (log scale)",
            font(15),
        )
        .x_label_area_size(40)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..end, (1e-8..10.0).log_scale())?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("error (rad)")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    for r in runs {
        let points: Vec<(f64, f64)> = r
            .states
            .iter()
            .map(|s| {
                (
                    s.t,
                    (s.q - reference.sample(s.t).q).amax().clamp(1e-8, 10.0),
                )
            })
            .collect();
        chart
            .draw_series(LineSeries::new(points, r.color.stroke_width(2)))?
            .label(r.name)
            .legend(swatch(r.color.stroke_width(3)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK.mix(0.3))
        .label_font(font(13))
        .draw()?;
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// 3. A straight tip line: strobe and animation

/// Base, joints and tip of an arm.
fn outline<A: PlanarArm<N>, const N: usize>(arm: &A, q: &SVector<f64, N>) -> Vec<(f64, f64)> {
    let mut points: Vec<(f64, f64)> = arm.joint_positions(q).iter().map(|p| (p.x, p.y)).collect();
    let tip = arm.tip_pose(q).translation.vector;
    points.push((tip.x, tip.y));
    points
}

fn line_section(out: &Out) -> Result<(), Box<dyn Error>> {
    println!("\n== 3. the tip along a straight line, by inverse kinematics, tracked by computed torque ==");
    let real = Picker::holding(LOAD);
    let model = Picker::holding(LOAD);
    let q0 = V3::new(-0.9, 1.9, 0.6);
    let to = Point2::new(0.75, 0.45);
    let line = TipLine::new(&model, q0, to, 2.0)?;
    let sim = Simulator::new(Rk4, 1e-3)?.with_control_period(5e-3)?;
    let states = sim
        .run(
            &real,
            q0,
            V3::zeros(),
            2.5,
            ComputedTorque::critically_damped(&model, &line, 20.0),
        )?
        .into_vec()?;
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
    draw_strobe(&file, &real, &states, (from, to.coords))?;
    out.wrote(&file);

    // The free rods beside it, for the animation: 10 s of a chaotic double pendulum.
    let rods = Rods::default();
    let free = from_fn(|_, _: &V2, _: &V2| V2::zeros());
    let swing = Simulator::new(Rk4, 1e-3)?
        .with_control_period(0.04)?
        .run(&rods, V2::new(0.3, 1.0), V2::zeros(), 10.0, free)?
        .into_vec()?;
    let picker: Vec<State<3>> = states.iter().step_by(8).copied().collect();
    let svg = animate(&real, &picker, &rods, &swing, (from, to.coords));
    let file = out.path("sim-animated.svg");
    std::fs::write(&file, svg)?;
    out.wrote(&file);
    Ok(())
}

fn draw_strobe(
    path: &Path,
    arm: &Picker,
    states: &[State<3>],
    line: (V2, V2),
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (900, 760)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(64);
    head.draw(&Text::new(
        "The tip along a straight line: a strobe picture every 0.25 s",
        (16, 10),
        font(20),
    ))?;
    head.draw(&Text::new(
        "three links holding 0.5 kg, inverse kinematics for the angles, computed torque (20 rad/s, exact model, 5 ms period)",
        (16, 38),
        font(14),
    ))?;
    // Equal units: 1.57 m wide, 1.2 m high in about 810 x 620 pixels.
    let mut chart = ChartBuilder::on(&body)
        .margin(12)
        .margin_right(24)
        .x_label_area_size(36)
        .y_label_area_size(56)
        .build_cartesian_2d(-0.45..1.12, -0.45..0.75)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("x (m)")
        .y_desc("y (m)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    chart.draw_series(std::iter::once(Rectangle::new(
        [(-0.05, -0.03), (0.05, 0.0)],
        BLACK.mix(0.3).filled(),
    )))?;
    let (a, b) = line;
    chart
        .draw_series(DashedLineSeries::new(
            vec![(a.x, a.y), (b.x, b.y)],
            8,
            6,
            BLACK.mix(0.5).stroke_width(2),
        ))?
        .label("the desired line")
        .legend(swatch(BLACK.mix(0.5).stroke_width(2)));
    let frames: Vec<&State<3>> = states
        .iter()
        .filter(|s| (s.t * 4.0 - (s.t * 4.0).round()).abs() < 1e-6)
        .collect();
    let n = frames.len().max(2) - 1;
    for (i, s) in frames.iter().enumerate() {
        let f = i as f64 / n as f64;
        let mix = |x: u8, y: u8| (f64::from(x) + f * (f64::from(y) - f64::from(x))).round() as u8;
        let color = RGBColor(mix(235, 35), mix(140, 40), mix(60, 60));
        let points = outline(arm, &s.q);
        let series = chart.draw_series(LineSeries::new(
            points.clone(),
            color.mix(0.85).stroke_width(4),
        ))?;
        if i == 0 || i == n {
            series
                .label(format!("the arm at t = {} s", s.t))
                .legend(swatch(color.stroke_width(4)));
        }
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 4, color.filled())))?;
    }
    let tip: Vec<(f64, f64)> = states
        .iter()
        .map(|s| {
            let p = arm.tip_pose(&s.q).translation.vector;
            (p.x, p.y)
        })
        .collect();
    chart
        .draw_series(LineSeries::new(tip, RGBColor(40, 150, 90).stroke_width(2)))?
        .label("the tip's path")
        .legend(swatch(RGBColor(40, 150, 90).stroke_width(2)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK.mix(0.3))
        .label_font(font(13))
        .draw()?;
    root.present()?;
    Ok(())
}

/// One arm as nested SVG groups, each link's rotation animated by SMIL: the angles are
/// relative, so each link turns inside the frame of the one before it.
fn animated_arm<const N: usize>(
    svg: &mut String,
    lengths: [f64; N],
    frames: &[SVector<f64, N>],
    seconds: f64,
    color: &str,
    metres_per_pixel: f64,
) {
    let (stroke, joint) = (6.0 * metres_per_pixel, 5.0 * metres_per_pixel);
    let colors = ["#466ebe", "#c85028", "#28965a", "#8c6ebe"];
    for (j, l) in lengths.iter().enumerate() {
        let values: Vec<String> = frames
            .iter()
            .map(|q| format!("{:.2}", q[j].to_degrees()))
            .collect();
        let _ = write!(
            svg,
            r#"<g><animateTransform attributeName="transform" type="rotate" dur="{seconds}s" repeatCount="indefinite" calcMode="linear" values="{}"/><line x1="0" y1="0" x2="{l}" y2="0" stroke="{}" stroke-width="{stroke:.5}" stroke-linecap="round"/><circle r="{joint:.5}" fill="{color}"/><g transform="translate({l} 0)">"#,
            values.join(";"),
            colors[j % colors.len()]
        );
    }
    let _ = write!(svg, r#"<circle r="{:.5}" fill="{color}"/>"#, joint * 1.2);
    for _ in 0..N {
        svg.push_str("</g></g>");
    }
}

fn animate(
    picker: &Picker,
    picker_states: &[State<3>],
    rods: &Rods,
    swing: &[State<2>],
    line: (V2, V2),
) -> String {
    let mut svg = String::new();
    let (w, h) = (1100.0, 560.0);
    let _ = write!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">
<rect width="{w}" height="{h}" fill="white"/>
<text x="16" y="30" font-size="20">planar_arm::sim, animated (SMIL): each link's angle is an animateTransform inside the link before it</text>
<text x="16" y="54" font-size="14">left: three links moving the tip along the dashed line (2.5 s, repeating); right: the paper's two rods swinging freely (10 s, repeating)</text>
"#
    );
    let links = picker.links();
    let lengths = [links[0].length, links[1].length, links[2].length];
    let frames: Vec<V3> = picker_states.iter().map(|s| s.q).collect();
    let t_picker = picker_states.last().map_or(1.0, |s| s.t);
    // Left panel: 1 m = 330 px, base at (150, 330).
    let (a, b) = line;
    let _ = write!(
        svg,
        r##"<g transform="translate(150 330) scale(330 -330)">
<rect x="-0.05" y="-0.03" width="0.1" height="0.03" fill="#999"/>
<line x1="{:.4}" y1="{:.4}" x2="{:.4}" y2="{:.4}" stroke="#777" stroke-width="0.006" stroke-dasharray="0.02 0.015"/>
"##,
        a.x, a.y, b.x, b.y
    );
    animated_arm(&mut svg, lengths, &frames, t_picker, "#23283c", 1.0 / 330.0);
    svg.push_str("</g>\n");
    // Right panel: 1 m = 105 px, base at (820, 300).
    let frames: Vec<V2> = swing.iter().map(|s| s.q).collect();
    let t_swing = swing.last().map_or(1.0, |s| s.t);
    let _ = write!(
        svg,
        r##"<g transform="translate(820 300) scale(105 -105)">
<circle r="2" fill="none" stroke="#ddd" stroke-width="0.01"/>
<rect x="-0.15" y="-0.06" width="0.3" height="0.06" fill="#999"/>
"##
    );
    animated_arm(
        &mut svg,
        [1.0, 1.0],
        &frames,
        t_swing,
        "#23283c",
        1.0 / 105.0,
    );
    svg.push_str("</g>\n");
    // A progress bar per panel: the frames of a screenshot differ even where an arm is still.
    for (x, seconds, label) in [
        (60.0, t_picker, "t mod 2.5 s"),
        (630.0, t_swing, "t mod 10 s"),
    ] {
        let _ = writeln!(
            svg,
            r##"<rect x="{x}" y="520" width="380" height="8" fill="#eee"/><rect x="{x}" y="520" width="0" height="8" fill="#466ebe"><animate attributeName="width" from="0" to="380" dur="{seconds}s" repeatCount="indefinite"/></rect><text x="{x}" y="545" font-size="12">{label}</text>"##
        );
    }
    let _ = rods;
    svg.push_str("</svg>\n");
    svg
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
