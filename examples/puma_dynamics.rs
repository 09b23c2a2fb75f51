//! The PUMA 560's dynamics with `#[derive(SpatialArm)]` and the simulator planar arms use:
//! gravity compensation (the torques that hold a pose, and PD with gravity compensation
//! recovering from a push), then computed-torque control of the tool along a straight line,
//! the joint path from the closed-form inverse kinematics, and a picture of the tool's error
//! and the joint torques (`puma-tracking.svg`).
//!
//! ```text
//! cargo run --example puma_dynamics [-- --out DIR | -- --docs]
//! ```

#[path = "support/num.rs"]
mod num;
#[path = "support/out.rs"]
mod out;
#[path = "support/plot.rs"]
mod plot;
#[path = "support/puma_arm.rs"]
mod puma_arm;

use std::cell::Cell;
use std::error::Error;
use std::path::Path;

use planar_arm::nalgebra::{Isometry3, SMatrix, Translation3, Vector3};
use planar_arm::prelude::*;
use planar_arm::sim::{
    ComputedTorque, PdGravity, Quintic, Rk4, Sample as Desired, Simulator, Trajectory,
};
use planar_arm::Jet;
use plotters::prelude::*;

use num::{fixed, log_tick, sig, tick};
use out::Out;
use plot::{font, side_key, Sample};
use puma_arm::Puma560;

type Q = SVector<f64, 6>;

/// The tool along a straight line at a fixed orientation, rest to rest with minimum jerk; the
/// joints from the closed-form inverse kinematics, the solution nearest the last one, their
/// rates `J^-1 v` and accelerations `J^-1 (a - Jdot qd)` (`Jdot qd` from the Jacobian in a
/// one-dimensional jet along `qd`).
struct ToolLine<'a> {
    arm: &'a Puma560,
    start: Isometry3<f64>,
    travel: Vector3<f64>,
    duration: f64,
    last: Cell<Q>,
}

impl ToolLine<'_> {
    fn sample_checked(&self, t: f64) -> Result<Desired<6>, ArmError> {
        let u = (t / self.duration).clamp(0.0, 1.0);
        let s = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
        let ds = 30.0 * u * u * (1.0 - u) * (1.0 - u) / self.duration;
        let dds = 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u) / (self.duration * self.duration);
        let target = Isometry3::from_parts(
            Translation3::from(self.start.translation.vector + self.travel * s),
            self.start.rotation,
        );
        let solutions = self.arm.inverse_kinematics(&target)?;
        let last = self.last.get();
        let q = *solutions
            .iter()
            .min_by(|a, b| (*a - last).norm().total_cmp(&(*b - last).norm()))
            .ok_or(ArmError::NoClosedForm {
                what: "no solution on the line",
            })?;
        self.last.set(q);
        let j = self.arm.jacobian(&q);
        let lu = j.lu();
        let twist = |linear: Vector3<f64>| {
            SVector::<f64, 6>::from_iterator(linear.iter().copied().chain([0.0; 3]))
        };
        let qd = lu
            .solve(&twist(self.travel * ds))
            .ok_or(ArmError::Singular {
                measure: 0.0,
                threshold: 0.0,
            })?;
        let seeded = SVector::<Jet<1>, 6>::from_fn(|i, _| Jet {
            re: q[i],
            eps: [qd[i]],
        });
        let j_dot: SMatrix<f64, 6, 6> = self.arm.jacobian(&seeded).map(|x| x.eps[0]);
        let qdd = lu
            .solve(&(twist(self.travel * dds) - j_dot * qd))
            .ok_or(ArmError::Singular {
                measure: 0.0,
                threshold: 0.0,
            })?;
        Ok(Desired { q, qd, qdd })
    }
}

impl Trajectory<6> for ToolLine<'_> {
    fn sample(&self, t: f64) -> Desired<6> {
        self.sample_checked(t).unwrap_or(Desired {
            q: Q::repeat(f64::NAN),
            qd: Q::repeat(f64::NAN),
            qdd: Q::repeat(f64::NAN),
        })
    }
    fn duration(&self) -> f64 {
        self.duration
    }
}

/// One recorded instant of the tracking run.
struct Record {
    t: f64,
    /// How far the tool is from where the line wants it, mm.
    error_mm: f64,
    tau: Q,
}

fn main() -> Result<(), Box<dyn Error>> {
    let out = Out::from_args("puma_dynamics");
    let arm = Puma560::default();

    println!("== holding a pose against gravity ==");
    let pose = Q::from([0.0, 0.6, -0.9, 0.0, 0.7, 0.0]);
    let g = arm.gravity(&pose);
    let still = arm.forward_dynamics(&pose, &Q::zeros(), &g);
    println!(
        "g(q) = [{}] N m; with tau = g the accelerations are at most {} rad/s^2",
        g.iter()
            .map(|x| fixed(*x, 3))
            .collect::<Vec<_>>()
            .join(", "),
        sig(still.amax(), 2)
    );
    assert!(still.amax() < 1e-9);
    // PD on top of gravity compensation, gains sized to each joint's inertia (20 rad/s,
    // critically damped), after a push of 0.1 rad on every joint.
    let inertia = arm.mass_matrix(&pose).diagonal();
    let hold = Quintic::rest_to_rest(pose, pose, 1.0)?;
    let pd = PdGravity::new(&arm, hold, inertia * 400.0, inertia * 40.0);
    let run = Simulator::new(Rk4, 1e-3)?.run(&arm, pose + Q::repeat(0.1), Q::zeros(), 1.5, pd)?;
    let settled = run
        .into_vec()?
        .last()
        .map_or(f64::NAN, |s| (s.q - pose).amax());
    println!(
        "PD with gravity compensation, 1.5 s after a 0.1 rad push: {} rad from the pose",
        sig(settled, 2)
    );
    assert!(settled < 1e-3);

    println!("\n== computed torque along a straight tool path ==");
    let q0 = Q::from([0.2, 0.5, -0.6, 0.3, 0.6, -0.2]);
    let start = arm.tip_pose(&q0);
    // To where another configuration puts the tool, keeping the tool's orientation.
    let end = arm
        .tip_pose(&Q::from([-0.5, 0.3, -0.3, -0.2, 0.9, 0.3]))
        .translation
        .vector;
    let line = ToolLine {
        arm: &arm,
        start,
        travel: end - start.translation.vector,
        duration: 2.0,
        last: Cell::new(q0),
    };
    // Every point of the line is reachable away from singularities: check before flying.
    for k in 0..=40 {
        line.sample_checked(2.0 * f64::from(k) / 40.0)?;
    }
    line.last.set(q0);
    let controller = ComputedTorque::critically_damped(&arm, &line, 20.0);
    let initial = q0 + Q::from([0.02, -0.02, 0.02, 0.0, 0.0, 0.0]);
    let run = Simulator::new(Rk4, 1e-3)?.run(&arm, initial, Q::zeros(), 2.5, controller)?;
    let mut records = Vec::new();
    for state in run {
        let s = state?;
        let want = start.translation.vector
            + line.travel * {
                let u = (s.t / line.duration).clamp(0.0, 1.0);
                u * u * u * (10.0 - 15.0 * u + 6.0 * u * u)
            };
        let error_mm = (arm.tip_pose(&s.q).translation.vector - want).norm() * 1e3;
        records.push(Record {
            t: s.t,
            error_mm,
            tau: s.tau,
        });
    }
    let worst_late = records
        .iter()
        .filter(|r| r.t >= 1.0)
        .map(|r| r.error_mm)
        .fold(0.0_f64, f64::max);
    let peak = records.iter().map(|r| r.tau.amax()).fold(0.0_f64, f64::max);
    println!(
        "a {} m line; start {} mm off it; after 1 s within {} mm; largest torque {} N m",
        fixed(line.travel.norm(), 3),
        sig(records[0].error_mm, 3),
        sig(worst_late, 2),
        sig(peak, 3)
    );
    assert!(worst_late < 0.1);

    let path = out.path("puma-tracking.svg");
    draw(&path, &records, worst_late, line.travel.norm())?;
    out.wrote(&path);
    Ok(())
}

/// The joints' colours (colour-blind safe), and their names.
const JOINTS: [(RGBColor, &str); 6] = [
    (RGBColor(0, 114, 178), "joint 1 (waist)"),
    (RGBColor(213, 94, 0), "joint 2 (shoulder)"),
    (RGBColor(0, 158, 115), "joint 3 (elbow)"),
    (RGBColor(204, 121, 167), "joint 4 (wrist roll)"),
    (RGBColor(230, 159, 0), "joint 5 (wrist bend)"),
    (RGBColor(86, 180, 233), "joint 6 (flange)"),
];

fn draw(
    path: &Path,
    records: &[Record],
    worst_late: f64,
    length: f64,
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1100, 860)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(70);
    head.draw(&Text::new(
        format!(
            "PUMA 560: computed-torque control of the tool along a {} m straight line in 2 s",
            fixed(length, 2)
        ),
        (16, 10),
        font(20),
    ))?;
    head.draw(&Text::new(
        format!(
            "Started 0.02 rad off on joints 1-3; gains 400/s^2 and 40/s per unit inertia; RK4 at 1 ms. \
             After 1 s the tool is within {} mm of the line.",
            sig(worst_late, 2)
        ),
        (16, 40),
        font(13),
    ))?;
    let (charts, keys) = body.split_horizontally(880);
    let (top, bottom) = charts.split_vertically(390);
    let t_end = records.last().map_or(1.0, |r| r.t);
    let e_max = records.iter().map(|r| r.error_mm).fold(0.0_f64, f64::max) * 2.0;
    // A log scale: the start's centimetre and the micrometres of the motion on one chart.
    let floor = 1e-5;
    let mut chart = ChartBuilder::on(&top)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..t_end, (floor..e_max).log_scale())?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("tool position error (mm, log scale)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| log_tick(*v))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    chart.draw_series(LineSeries::new(
        records.iter().map(|r| (r.t, r.error_mm.max(floor))),
        BLACK.stroke_width(2),
    ))?;
    let tau_max = records.iter().map(|r| r.tau.amax()).fold(0.0_f64, f64::max) * 1.1;
    let mut chart = ChartBuilder::on(&bottom)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..t_end, -tau_max..tau_max)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("joint torque (N m)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    for (i, (colour, _)) in JOINTS.iter().enumerate() {
        chart.draw_series(LineSeries::new(
            records.iter().map(|r| (r.t, r.tau[i])),
            colour.stroke_width(2),
        ))?;
    }
    let (top_key, bottom_key) = keys.split_vertically(390);
    side_key(
        &top_key,
        30,
        &[(
            Sample::Line(BLACK.stroke_width(2)),
            "distance from the tool to where the line wants it",
        )],
    )?;
    let mut entries: Vec<(Sample, &str)> = JOINTS
        .iter()
        .map(|(c, name)| (Sample::Line(c.stroke_width(3)), *name))
        .collect();
    let wrist = records
        .iter()
        .map(|r| r.tau.rows(3, 3).amax())
        .fold(0.0_f64, f64::max);
    let note = format!(
        "The wrist's torques (joints 4-6) stay below {} N m: on the zero line at this scale.",
        sig(wrist, 2)
    );
    entries.push((Sample::Note, &note));
    side_key(&bottom_key, 30, &entries)?;
    root.present()?;
    Ok(())
}
