//! The identify example's pictures: predicted against measured torques on the fresh
//! trajectory, and the identified base parameters' errors and standard deviations.

use std::error::Error;
use std::path::Path;

use planar_arm::nalgebra::SVector;
use planar_arm::prelude::*;
use plotters::coord::ranged1d::SegmentValue;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::num::{fixed, tick};
use crate::plot::font;
use crate::{Arm, Estimate, Run, B, RATE, SAMPLES, SIGMA, V3};

const MEASURED: RGBColor = RGBColor(110, 110, 110);
const PREDICTED: RGBColor = RGBColor(200, 80, 40);
const BAND: RGBColor = RGBColor(70, 110, 190);

/// Seconds of the validation run drawn: enough for the shape, few enough to see the noise.
const WINDOW: f64 = 5.0;

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// An entry of a key drawn in a picture's heading.
enum Sample {
    Dot,
    Line,
    Band,
    DotWithWhisker,
}

/// A row of key entries at height `y`, each `(sample, text, x)`.
fn key_row(area: &Area<'_>, y: i32, entries: &[(Sample, &str, i32)]) -> Result<(), Box<dyn Error>> {
    for (sample, text, x) in entries {
        match sample {
            Sample::Dot => area.draw(&Circle::new((x + 10, y), 3, MEASURED.filled()))?,
            Sample::Line => area.draw(&PathElement::new(
                vec![(*x, y), (x + 22, y)],
                PREDICTED.stroke_width(2),
            ))?,
            Sample::Band => area.draw(&Rectangle::new(
                [(*x, y - 6), (x + 22, y + 6)],
                BAND.mix(0.2).filled(),
            ))?,
            Sample::DotWithWhisker => {
                area.draw(&PathElement::new(
                    vec![(*x, y), (x + 22, y)],
                    PREDICTED.stroke_width(2),
                ))?;
                area.draw(&Circle::new((x + 11, y), 4, PREDICTED.filled()))?;
            }
        }
        area.draw(&Text::new(text.to_string(), (x + 30, y - 7), font(13)))?;
    }
    Ok(())
}

/// Per joint: measured against predicted torque, and their difference against the noise band.
pub fn draw_torques(
    path: &Path,
    run: &Run,
    predicted: &[V3],
    errors: &[f64; 3],
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1200, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(76);
    head.draw(&Text::new(
        "Identified model against measured torques on a fresh trajectory (the steps: Coulomb friction as a joint reverses)",
        (16, 10),
        font(21),
    ))?;
    let measured = format!(
        "measured torque (simulated: exact dynamics plus noise of \u{3c3} = {SIGMA} N m, {RATE} Hz)"
    );
    key_row(
        &head,
        52,
        &[
            (Sample::Dot, &measured, 16),
            (Sample::Line, "predicted by the identified model", 500),
            (
                Sample::Band,
                "\u{b1}2\u{3c3}: where 95% of the noise falls",
                780,
            ),
        ],
    )?;

    let shown: Vec<usize> = (0..run.t.len()).filter(|&k| run.t[k] <= WINDOW).collect();
    for (j, row) in body.split_evenly((3, 1)).iter().enumerate() {
        let (left, right) = row.split_horizontally(790);
        let drawn = Drawn {
            run,
            predicted,
            shown: &shown,
            joint: j,
        };
        torque_panel(&left, &drawn)?;
        difference_panel(&right, &drawn, errors[j])?;
    }
    root.present()?;
    Ok(())
}

/// What a torque panel draws: one joint's samples of the fresh run within the window.
struct Drawn<'a> {
    run: &'a Run,
    predicted: &'a [V3],
    shown: &'a [usize],
    joint: usize,
}

/// One joint's measured torques and the identified model's prediction against time.
fn torque_panel(area: &Area<'_>, d: &Drawn<'_>) -> Result<(), Box<dyn Error>> {
    let (run, predicted, shown, j) = (d.run, d.predicted, d.shown, d.joint);
    let (lo, hi) = shown.iter().fold((f64::MAX, f64::MIN), |(lo, hi), &k| {
        let (m, p) = (run.measured[k][j], predicted[k][j]);
        (lo.min(m).min(p), hi.max(m).max(p))
    });
    let pad = 0.08 * (hi - lo);
    let mut chart = ChartBuilder::on(area)
        .margin(8)
        .caption(format!("joint {}: torque", j + 1), font(16))
        .x_label_area_size(38)
        .y_label_area_size(62)
        .build_cartesian_2d(0.0..WINDOW, (lo - pad)..(hi + pad))?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("torque (N m)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    chart.draw_series(
        shown
            .iter()
            .map(|&k| Circle::new((run.t[k], run.measured[k][j]), 1, MEASURED.filled())),
    )?;
    chart.draw_series(LineSeries::new(
        shown.iter().map(|&k| (run.t[k], predicted[k][j])),
        PREDICTED.stroke_width(2),
    ))?;
    Ok(())
}

/// One joint's measured minus predicted torques against the band the noise should fill.
fn difference_panel(area: &Area<'_>, d: &Drawn<'_>, rms: f64) -> Result<(), Box<dyn Error>> {
    let (run, predicted, shown, j) = (d.run, d.predicted, d.shown, d.joint);
    let lim = 4.0 * SIGMA;
    let mut chart = ChartBuilder::on(area)
        .margin(8)
        .margin_right(18)
        .caption(
            format!("measured - predicted: RMS {} N m", fixed(rms, 3)),
            font(16),
        )
        .x_label_area_size(38)
        .y_label_area_size(62)
        .build_cartesian_2d(0.0..WINDOW, -lim..lim)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc("difference (N m)")
        .x_labels(6)
        .y_labels(5)
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    chart.draw_series(std::iter::once(Rectangle::new(
        [(0.0, -2.0 * SIGMA), (WINDOW, 2.0 * SIGMA)],
        BAND.mix(0.2).filled(),
    )))?;
    chart.draw_series(shown.iter().map(|&k| {
        let e = run.measured[k][j] - predicted[k][j];
        Circle::new((run.t[k], e), 1, MEASURED.filled())
    }))?;
    Ok(())
}

/// Per base parameter: its error in standard deviations, and its relative standard deviation.
pub fn draw_parameters(
    path: &Path,
    truth: &SVector<f64, B>,
    est: &Estimate,
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1200, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(110);
    head.draw(&Text::new(
        format!("Identified base parameters: {SAMPLES} samples, noise \u{3c3} = {SIGMA} N m"),
        (16, 12),
        font(21),
    ))?;
    head.draw(&Text::new(
        "Each base parameter is a sum of the arm's standard ones (1, 2, 3: the link or joint; p: the payload): zz = inertia about the joint (kg m\u{b2}),",
        (16, 42),
        font(13),
    ))?;
    head.draw(&Text::new(
        "mx, my = mass times centre-of-mass offset (kg m), m = mass (kg), ia = armature, the motor's inertia at the joint (kg m\u{b2}), fv = viscous friction (N m s/rad), fc = Coulomb friction (N m);",
        (16, 60),
        font(13),
    ))?;
    key_row(
        &head,
        92,
        &[
            (
                Sample::DotWithWhisker,
                "identified - true, with \u{b1}1 standard deviation",
                16,
            ),
            (Sample::Band, "\u{b1}2 standard deviations", 380),
        ],
    )?;
    let (left, right) = body.split_horizontally(800);
    errors_panel(&left, truth, est)?;
    spread_panel(&right, truth, est)?;
    root.present()?;
    Ok(())
}

/// Row `i` of the parameter charts: the first parameter on top.
fn row(i: usize) -> SegmentValue<i32> {
    SegmentValue::CenterOf(i32::try_from(B - 1 - i).unwrap_or(0))
}

/// The parameter charts' rows: plotters' integer ranges include their end, so B of them.
fn rows() -> std::ops::Range<i32> {
    0..i32::try_from(B - 1).unwrap_or(0)
}

/// Each parameter's error in its standard deviations, named on the left.
fn errors_panel(
    area: &Area<'_>,
    truth: &SVector<f64, B>,
    est: &Estimate,
) -> Result<(), Box<dyn Error>> {
    let names = Arm::base_parameter_names();
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .caption(
            "error of each identified parameter, in its standard deviations",
            font(16),
        )
        .x_label_area_size(40)
        .y_label_area_size(215)
        .build_cartesian_2d(-4.0..4.0, rows().into_segmented())?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .y_labels(B)
        .y_label_formatter(&|v| match v {
            SegmentValue::CenterOf(i) => usize::try_from(*i)
                .ok()
                .and_then(|i| (B - 1).checked_sub(i))
                .and_then(|i| names.get(i))
                .map_or_else(String::new, |n| (*n).to_string()),
            _ => String::new(),
        })
        .x_label_formatter(&|x| tick(*x))
        .x_desc("(identified - true) / standard deviation")
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    chart.draw_series(std::iter::once(Rectangle::new(
        [(-2.0, SegmentValue::Exact(0)), (2.0, SegmentValue::Last)],
        BAND.mix(0.2).filled(),
    )))?;
    chart.draw_series(std::iter::once(PathElement::new(
        vec![(0.0, SegmentValue::Exact(0)), (0.0, SegmentValue::Last)],
        BLACK.mix(0.5),
    )))?;
    // plotters' ErrorBar needs a feature this crate does not enable: a whisker and a dot.
    let z = |i: usize| (est.theta[i] - truth[i]) / est.std[i];
    chart.draw_series((0..B).map(|i| {
        PathElement::new(
            vec![(z(i) - 1.0, row(i)), (z(i) + 1.0, row(i))],
            PREDICTED.stroke_width(2),
        )
    }))?;
    chart.draw_series((0..B).map(|i| Circle::new((z(i), row(i)), 4, PREDICTED.filled())))?;
    Ok(())
}

/// Each parameter's standard deviation relative to its true value, on a log scale.
fn spread_panel(
    area: &Area<'_>,
    truth: &SVector<f64, B>,
    est: &Estimate,
) -> Result<(), Box<dyn Error>> {
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .caption("standard deviation relative to the true value", font(16))
        .x_label_area_size(40)
        .y_label_area_size(10)
        .margin_right(24)
        .build_cartesian_2d((0.01..30.0).log_scale(), rows().into_segmented())?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .y_labels(B)
        .y_label_formatter(&|_| String::new())
        .x_label_formatter(&|x| format!("{}%", tick(*x)))
        .x_desc("standard deviation / |true value| (log scale)")
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    let pct = |i: usize| 100.0 * est.std[i] / truth[i].abs();
    chart.draw_series((0..B).map(|i| {
        PathElement::new(
            vec![(0.01, row(i)), (pct(i), row(i))],
            BAND.mix(0.7).stroke_width(12),
        )
    }))?;
    chart.draw_series((0..B).map(|i| {
        let p = pct(i);
        let text = if p < 0.1 {
            format!("{}%", fixed(p, 3))
        } else {
            format!("{}%", fixed(p, 2))
        };
        EmptyElement::at((p, row(i)))
            + Text::new(
                text,
                (6, 0),
                font(13).pos(Pos::new(HPos::Left, VPos::Center)),
            )
    }))?;
    Ok(())
}
