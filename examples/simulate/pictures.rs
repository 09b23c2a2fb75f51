//! The simulate example's plotted pictures: the energy of a free swing, the tracking runs and
//! the strobe picture of the straight tip line.

use std::error::Error;
use std::path::Path;

use planar_arm::prelude::*;
use planar_arm::sim::{State, Trajectory, ViaPoints};
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::num::{log_tick, sig, tick};
use crate::plot::{dashed_swatch, font, key, side_key, swatch, Sample};
use crate::{EnergyCurve, Picker, Tracked};

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// The joints in the angle panel: colours that no controller in the error panel below uses.
const JOINTS: [RGBColor; 3] = [
    RGBColor(230, 159, 0),
    RGBColor(204, 80, 160),
    RGBColor(0, 160, 180),
];
/// What a controller was asked to do: drawn dashed and dark, over the coloured actual paths.
const DESIRED: RGBColor = RGBColor(20, 20, 20);
/// The tip's actual path in the strobe picture.
const TIP: RGBColor = RGBColor(40, 150, 90);

pub fn draw_energy(
    path: &Path,
    curves: &[EnergyCurve],
    e_scale: f64,
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1100, 650)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(64);
    head.draw(&Text::new(
        "Energy of two 1 m, 1 kg rods swinging freely for 100 s, by integrator",
        (16, 10),
        font(20),
    ))?;
    head.draw(&Text::new(
        format!(
            "The error |E(t) - E(0)| on a log scale, sampled every 0.1 s; the swing holds {} J above hanging still. \
             RK4 drifts, the variational ones do not; at equal cost RK4 is more accurate.",
            sig(e_scale, 3)
        ),
        (16, 38),
        font(14),
    ))?;
    let mut chart = ChartBuilder::on(&body)
        .margin(12)
        .margin_right(24)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..100.0, (1e-14..1e6).log_scale())?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("energy error |E(t) - E(0)| (J)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| log_tick(*v))
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
    key(&mut chart, SeriesLabelPosition::UpperRight)?;
    root.present()?;
    Ok(())
}

pub fn draw_tracking(
    path: &Path,
    reference: &ViaPoints<3, 5>,
    runs: &[Tracked],
    worst: &[f64],
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1100, 940)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(84);
    head.draw(&Text::new(
        "Three links carrying 0.5 kg that the controller's model does not know",
        (16, 10),
        font(20),
    ))?;
    head.draw(&Text::new(
        "Five via-points in 4 s, then holding; RK4 at 1 ms, torques held for 5 ms. Dead reckoning: \
         the model's torques for the desired motion, no feedback.",
        (16, 38),
        font(13),
    ))?;
    head.draw(&Text::new(
        format!(
            "Largest errors: {}",
            runs.iter()
                .zip(worst)
                .map(|(r, w)| format!("{} {} rad", r.short, sig(*w, 2)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        (16, 58),
        font(13),
    ))?;
    let (charts, keys) = body.split_horizontally(860);
    let (top, bottom) = charts.split_vertically(430);
    let (top_key, bottom_key) = keys.split_vertically(430);
    angles_panel(&top, reference, &runs[2])?;
    let names = ["joint 1 (shoulder)", "joint 2 (elbow)", "joint 3 (hand)"];
    let mut entries: Vec<(Sample, &str)> = JOINTS
        .iter()
        .zip(names)
        .map(|(c, name)| (Sample::Line(c.stroke_width(3)), name))
        .collect();
    entries.push((
        Sample::Dashed(DESIRED.stroke_width(1)),
        "desired angle (each joint)",
    ));
    entries.push((Sample::Dot(DESIRED.filled()), "via-point"));
    side_key(&top_key, 50, &entries)?;
    error_panel(&bottom, reference, runs)?;
    let entries: Vec<(Sample, &str)> = runs
        .iter()
        .map(|r| (Sample::Line(r.color.stroke_width(3)), r.short))
        .collect();
    side_key(&bottom_key, 50, &entries)?;
    root.present()?;
    Ok(())
}

/// One run's joint angles against the desired ones, with the via-points.
fn angles_panel(
    area: &Area<'_>,
    reference: &ViaPoints<3, 5>,
    run: &Tracked,
) -> Result<(), Box<dyn Error>> {
    let end = run.states.last().map_or(1.0, |s| s.t);
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .margin_right(24)
        .caption(format!("joint angles under {}", run.short), font(15))
        .x_label_area_size(36)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..end, -1.7..1.7)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("joint angle (rad)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    for (j, color) in JOINTS.iter().enumerate() {
        chart.draw_series(LineSeries::new(
            run.states.iter().map(|s| (s.t, s.q[j])),
            color.stroke_width(3),
        ))?;
    }
    // The desired curves last, thin and dark, so that they show where the actual ones lie on
    // them.
    for j in 0..3 {
        let want: Vec<(f64, f64)> = run
            .states
            .iter()
            .map(|s| (s.t, reference.sample(s.t).q[j]))
            .collect();
        chart.draw_series(DashedLineSeries::new(want, 6, 4, DESIRED.stroke_width(1)))?;
    }
    chart.draw_series((0..5).flat_map(|i| {
        let t = f64::from(i);
        let q = reference.sample(t).q;
        (0..3).map(move |j| Circle::new((t, q[j]), 4, DESIRED.filled()))
    }))?;
    Ok(())
}

/// Every run's largest joint error against time, on a log scale.
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
            "tracking error: the largest |desired - actual| over the three joints",
            font(15),
        )
        .x_label_area_size(40)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..end, (1e-10..10.0).log_scale())?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("error (rad, log scale)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| log_tick(*v))
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
                    (s.q - reference.sample(s.t).q).amax().clamp(1e-10, 10.0),
                )
            })
            .collect();
        chart.draw_series(LineSeries::new(points, r.color.stroke_width(2)))?;
    }
    Ok(())
}

/// Base, joints and tip of an arm.
fn outline<A: PlanarArm<N>, const N: usize>(arm: &A, q: &SVector<f64, N>) -> Vec<(f64, f64)> {
    let mut points: Vec<(f64, f64)> = arm.joint_positions(q).iter().map(|p| (p.x, p.y)).collect();
    let tip = arm.tip_pose(q).translation.vector;
    points.push((tip.x, tip.y));
    points
}

/// The arm every 0.25 s from orange (start) to dark (end), the tip's path and, over it, the
/// line it was to follow.
pub fn draw_strobe(
    path: &Path,
    arm: &Picker,
    states: &[State<3>],
    line: (Vector2<f64>, Vector2<f64>),
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
        "Three links holding 0.5 kg; inverse kinematics for the angles, computed torque (20 rad/s, exact model, 5 ms period)",
        (16, 38),
        font(14),
    ))?;
    // Equal units: 1.278 m wide, 1 m high in 808 x 632 pixels.
    let mut chart = ChartBuilder::on(&body)
        .margin(12)
        .margin_right(24)
        .x_label_area_size(40)
        .y_label_area_size(56)
        .build_cartesian_2d(-0.16..1.118, -0.46..0.54)?;
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
    let frames: Vec<&State<3>> = states
        .iter()
        .filter(|s| (s.t * 4.0 - (s.t * 4.0).round()).abs() < 1e-6)
        .collect();
    let n = frames.len().max(2) - 1;
    for (i, s) in frames.iter().enumerate() {
        #[allow(clippy::cast_precision_loss)]
        let f = i as f64 / n as f64;
        // Between two u8 values, so in 0..=255.
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let mix = |x: u8, y: u8| (f64::from(x) + f * (f64::from(y) - f64::from(x))).round() as u8;
        let color = RGBColor(mix(235, 35), mix(140, 40), mix(60, 60));
        let points = outline(arm, &s.q);
        let series = chart.draw_series(LineSeries::new(
            points.clone(),
            color.mix(0.85).stroke_width(4),
        ))?;
        if i == 0 {
            series
                .label("the arm at t = 0 s, then every 0.25 s")
                .legend(swatch(color.stroke_width(4)));
        } else if i == n {
            series
                .label(format!("the arm at t = {} s", tick(s.t)))
                .legend(swatch(color.stroke_width(4)));
        }
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 4, color.filled())))?;
    }
    // One state in 25: the rest lie within a pixel and only make the drawn line ragged.
    let tip: Vec<(f64, f64)> = states
        .iter()
        .step_by(25)
        .chain(states.last())
        .map(|s| {
            let p = arm.tip_pose(&s.q).translation.vector;
            (p.x, p.y)
        })
        .collect();
    chart
        .draw_series(LineSeries::new(tip, TIP.stroke_width(5)))?
        .label("the tip's actual path")
        .legend(swatch(TIP.stroke_width(5)));
    // Over the path and thin: the two coincide to a few hundredths of a millimetre.
    let (a, b) = line;
    chart
        .draw_series(DashedLineSeries::new(
            vec![(a.x, a.y), (b.x, b.y)],
            8,
            5,
            DESIRED.stroke_width(2),
        ))?
        .label("the desired path: a straight line")
        .legend(dashed_swatch(DESIRED.stroke_width(2)));
    key(&mut chart, SeriesLabelPosition::LowerRight)?;
    root.present()?;
    Ok(())
}
