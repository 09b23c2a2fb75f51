//! The balance example's pictures: angle errors and torques against time beside a strobe
//! picture of the arm.

use std::error::Error;
use std::path::Path;

use planar_arm::prelude::*;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::num::tick;
use crate::plot::{dashed_swatch, font, key, swatch};
use crate::{upright, Rods, Run, PERIOD, V2};

/// The joints in the time panels. Neither is orange, the strobe's colour for early frames.
const JOINT: [RGBColor; 2] = [RGBColor(70, 110, 190), RGBColor(170, 60, 150)];
const ARM: RGBColor = RGBColor(35, 40, 60);
const EARLY: RGBColor = RGBColor(235, 140, 60);
const TIP: RGBColor = RGBColor(40, 150, 90);

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// One quantity per joint against time; `steps` draws it held between samples.
fn time_panel(
    area: &Area<'_>,
    caption: &str,
    y_desc: &str,
    t: &[f64],
    values: [(&str, Vec<f64>); 2],
    steps: bool,
) -> Result<(), Box<dyn Error>> {
    let (lo, hi) = values
        .iter()
        .flat_map(|(_, v)| v.iter())
        .fold((0.0_f64, 0.0_f64), |(lo, hi), v| (lo.min(*v), hi.max(*v)));
    let pad = 0.08 * (hi - lo).max(1e-9);
    let end = t.last().copied().unwrap_or(1.0);
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .margin_right(20)
        .caption(caption, font(16))
        .x_label_area_size(40)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..end, (lo - pad)..(hi + pad))?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("time (s)")
        .y_desc(y_desc)
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    for ((name, v), color) in values.iter().zip(JOINT) {
        let points: Vec<(f64, f64)> = if steps {
            // Zero-order hold: each torque lasts until the next sample.
            t.windows(2)
                .zip(v)
                .flat_map(|(w, &v)| [(w[0], v), (w[1], v)])
                .collect()
        } else {
            t.iter().copied().zip(v.iter().copied()).collect()
        };
        chart
            .draw_series(LineSeries::new(points, color.stroke_width(2)))?
            .label(*name)
            .legend(swatch(color.stroke_width(2)));
    }
    key(&mut chart, SeriesLabelPosition::UpperRight)
}

/// The arm as drawn: base, elbow, tip.
fn pose(arm: &Rods, q: &V2) -> Vec<(f64, f64)> {
    let mut points: Vec<(f64, f64)> = arm.joint_positions(q).iter().map(|p| (p.x, p.y)).collect();
    let tip = arm.tip_pose(q).translation.vector;
    points.push((tip.x, tip.y));
    points
}

/// A frame's colour: from `EARLY` at the first frame to `ARM` at the last.
fn shade(f: f64) -> RGBColor {
    // Between two u8 values, so in 0..=255.
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    RGBColor(
        mix(EARLY.0, ARM.0),
        mix(EARLY.1, ARM.1),
        mix(EARLY.2, ARM.2),
    )
}

/// The x and y ranges (m) that show at least `left ..= right` and `bottom ..= top` in equal
/// units on `area` with `key` pixels to spare on the right for the key; spare height goes to
/// both ends.
fn equal_units(
    area: &Area<'_>,
    (left, right): (f64, f64),
    (bottom, top): (f64, f64),
    key: f64,
) -> ((f64, f64), (f64, f64)) {
    let (margin, x_labels, y_labels, caption) = (10_u32, 40_u32, 52_u32, 30_u32);
    let (w, h) = area.dim_in_pixel();
    let plot_w = f64::from(w - y_labels - 2 * margin);
    let plot_h = f64::from(h - x_labels - 2 * margin - caption);
    let pixels_per_metre = ((plot_w - key) / (right - left)).min(plot_h / (top - bottom));
    let extra = plot_h / pixels_per_metre - (top - bottom);
    (
        (left, left + plot_w / pixels_per_metre),
        (bottom - 0.5 * extra, top + 0.5 * extra),
    )
}

/// The arm at the `strobe` times, from orange (start) to dark (end), with the tip's path
/// and the upright pose, on axes of equal units.
fn strobe_panel(
    area: &Area<'_>,
    arm: &Rods,
    run: &Run,
    strobe: &[f64],
) -> Result<(), Box<dyn Error>> {
    let frames: Vec<(f64, Vec<(f64, f64)>)> = strobe
        .iter()
        .filter_map(|&t| {
            let i = run.t.iter().position(|s| (s - t).abs() < 0.5 * PERIOD)?;
            Some((t, pose(arm, &run.q[i])))
        })
        .collect();
    let path: Vec<(f64, f64)> = run.q.iter().filter_map(|q| pose(arm, q).pop()).collect();
    // The arm on the left, the key on the right below the elbow, where it covers nothing.
    let (lo, hi) = path
        .iter()
        .chain(frames.iter().flat_map(|(_, p)| p))
        .fold((-0.15_f64, 0.15_f64), |(lo, hi), p| {
            (lo.min(p.0), hi.max(p.0))
        });
    let (x, y) = equal_units(area, (lo - 0.15, hi + 0.05), (-0.5, 2.2), 0.0);
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .caption("the arm in motion (axes in equal units)", font(16))
        .x_label_area_size(40)
        .y_label_area_size(52)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_desc("x (m)")
        .y_desc("y (m)")
        .y_label_formatter(&|v| tick(*v))
        .x_label_formatter(&|v| tick(*v))
        .label_style(font(13))
        .axis_desc_style(font(13))
        .draw()?;
    chart.draw_series(std::iter::once(Rectangle::new(
        [(-0.12, -0.05), (0.12, 0.0)],
        BLACK.mix(0.25).filled(),
    )))?;
    chart
        .draw_series(DashedLineSeries::new(
            pose(arm, &upright()),
            8,
            6,
            BLACK.mix(0.6).stroke_width(2),
        ))?
        .label("upright, the goal")
        .legend(dashed_swatch(BLACK.mix(0.6).stroke_width(2)));
    // In the key here, drawn over the arms below, where it can be seen.
    chart
        .draw_series(std::iter::empty::<Circle<(f64, f64), u32>>())?
        .label("the tip's path")
        .legend(swatch(TIP.stroke_width(2)));
    // The time of each frame by its colour in the key: labels by the poses would collide
    // where the arm comes back over itself.
    let n = frames.len().max(2) - 1;
    for (i, (t, points)) in frames.iter().enumerate() {
        #[allow(clippy::cast_precision_loss)]
        let color = shade(i as f64 / n as f64);
        chart
            .draw_series(LineSeries::new(
                points.clone(),
                color.mix(0.8).stroke_width(4),
            ))?
            .label(if i == 0 {
                format!("the arm at t = {} s", tick(*t))
            } else {
                format!("t = {} s", tick(*t))
            })
            .legend(swatch(color.stroke_width(4)));
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 4, color.filled())))?;
    }
    chart.draw_series(LineSeries::new(path, TIP.stroke_width(2)))?;
    key(&mut chart, SeriesLabelPosition::LowerRight)
}

/// Angle errors and torques against time (left), the strobe picture (right).
pub fn draw(
    path: &Path,
    arm: &Rods,
    run: &Run,
    titles: [&str; 2],
    torques: [&str; 2],
    strobe: &[f64],
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1200, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let (head, body) = root.split_vertically(70);
    head.draw(&Text::new(titles[0], (16, 10), font(21)))?;
    head.draw(&Text::new(titles[1], (16, 42), font(14)))?;
    let (left, right) = body.split_horizontally(730);
    let panels = left.split_evenly((2, 1));
    let angle = |j: usize| run.error.iter().map(|e| e[j]).collect::<Vec<_>>();
    let torque = |j: usize| run.tau.iter().map(|t| t[j]).collect::<Vec<_>>();
    time_panel(
        &panels[0],
        "joint angle errors q - q* (wrapped to [-pi, pi))",
        "angle error (rad)",
        &run.t,
        [
            ("joint 1 (shoulder)", angle(0)),
            ("joint 2 (elbow)", angle(1)),
        ],
        false,
    )?;
    time_panel(
        &panels[1],
        "joint torques, held for each 10 ms control period",
        "torque (N m)",
        &run.t,
        [(torques[0], torque(0)), (torques[1], torque(1))],
        true,
    )?;
    strobe_panel(&right, arm, run, strobe)?;
    root.present()?;
    Ok(())
}
