//! The PUMA 560 with `#[derive(SpatialArm)]`: its tool pose at a few configurations, every
//! inverse-kinematics solution of one target (each checked by the forward kinematics), the
//! gravity torques against the numeric reference, and a picture of the eight solutions in three
//! orthographic views (`puma-ik.svg`).
//!
//! ```text
//! cargo run --example puma [-- --out DIR | -- --docs]
//! ```

#[path = "support/num.rs"]
mod num;
#[path = "support/out.rs"]
mod out;
#[path = "support/plot.rs"]
mod plot;
#[path = "support/puma_arm.rs"]
mod puma_arm;

use std::error::Error;
use std::ops::Range;

use planar_arm::nalgebra::{Isometry3, Point3, SVector, Translation3, UnitQuaternion};
use planar_arm::prelude::*;
use planar_arm::reference;
use planar_arm::spatial::SpatialArm;
use plotters::prelude::*;

use num::{fixed, sig};
use out::Out;
use plot::{font, side_key, Sample};
use puma_arm::Puma560;

type Q = SVector<f64, 6>;

fn show_pose(label: &str, pose: &Isometry3<f64>) {
    let t = pose.translation.vector;
    let (roll, pitch, yaw) = pose.rotation.euler_angles();
    println!(
        "{label:>22}: p = ({}, {}, {}) m, roll {} pitch {} yaw {} rad",
        fixed(t.x, 4),
        fixed(t.y, 4),
        fixed(t.z, 4),
        fixed(roll, 4),
        fixed(pitch, 4),
        fixed(yaw, 4)
    );
}

/// The points a solution's skeleton passes through: the base, each link frame's origin, the
/// tool.
fn skeleton(arm: &Puma560, q: &Q) -> Vec<Point3<f64>> {
    let mut points = vec![Point3::origin()];
    points.extend(
        arm.link_poses(q)
            .iter()
            .map(|p| Point3::from(p.translation.vector)),
    );
    points.push(Point3::from(arm.tip_pose(q).translation.vector));
    points
}

fn main() -> Result<(), Box<dyn Error>> {
    let out = Out::from_args("puma");
    let arm = Puma560::default();
    println!("== tool poses ==");
    // The named configurations of Corke's Robotics Toolbox: zero, ready (straight up),
    // stretch (reaching forward) and nominal.
    let (half, quarter) = (core::f64::consts::FRAC_PI_2, core::f64::consts::FRAC_PI_4);
    for (label, q) in [
        ("zero", Q::zeros()),
        ("ready", Q::from([0.0, half, -half, 0.0, 0.0, 0.0])),
        ("stretch", Q::from([0.0, 0.0, -half, 0.0, 0.0, 0.0])),
        (
            "nominal",
            Q::from([0.0, quarter, core::f64::consts::PI, 0.0, quarter, 0.0]),
        ),
    ] {
        show_pose(label, &arm.tip_pose(&q));
        let reference = reference::spatial::tip_pose(&arm.model(), &q);
        let d = arm.tip_pose(&q).inverse() * reference;
        assert!(d.translation.vector.norm() < 1e-12 && d.rotation.angle() < 1e-12);
    }

    println!("\n== every solution for one target ==");
    let q_true = Q::from([0.3, 0.6, -0.4, 0.5, 0.8, -0.2]);
    let target = arm.tip_pose(&q_true);
    show_pose("target", &target);
    let solutions = arm.inverse_kinematics(&target)?;
    let mut worst = 0.0_f64;
    for (k, q) in solutions.iter().enumerate() {
        let d = arm.tip_pose(q).inverse() * target;
        let error = d.translation.vector.norm().max(d.rotation.angle());
        worst = worst.max(error);
        let angles: Vec<String> = q.iter().map(|x| format!("{:>7}", fixed(*x, 3))).collect();
        println!(
            "  solution {}: q = [{}] rad, pose error {}",
            k + 1,
            angles.join(","),
            sig(error, 2)
        );
    }
    assert_eq!(solutions.len(), 8);
    assert!(worst < 1e-9, "{worst}");
    println!(
        "{} solutions, each reaching the target within {} (m and rad)",
        solutions.len(),
        sig(worst, 2)
    );

    println!("\n== holding the arm against gravity ==");
    let q = Q::from([0.0, 0.4, -0.3, 0.0, 0.5, 0.0]);
    let g = arm.gravity(&q);
    let g_reference = reference::spatial::gravity(&arm.model(), &q);
    let torques: Vec<String> = g.iter().map(|x| fixed(*x, 3)).collect();
    println!("g(q) = [{}] N m", torques.join(", "));
    println!(
        "largest difference from the numeric reference: {} N m",
        sig((g - g_reference).amax(), 2)
    );
    assert!((g - g_reference).amax() < 1e-10);

    println!("\n== a target given as position and roll, pitch, yaw ==");
    // Roll, pitch and yaw about the fixed x, y and z axes, as URDF writes them: nalgebra's
    // `from_euler_angles` is that convention.
    let down_target = Isometry3::from_parts(
        Translation3::new(0.45, 0.2, 0.1),
        UnitQuaternion::from_euler_angles(core::f64::consts::PI, 0.0, 0.3),
    );
    show_pose("tool pointing down", &down_target);
    let down = arm.inverse_kinematics(&down_target)?;
    for q in down.iter() {
        let d = arm.tip_pose(q).inverse() * down_target;
        assert!(d.translation.vector.norm() < 1e-9 && d.rotation.angle() < 1e-9);
    }
    println!(
        "{} solutions, each checked by the forward kinematics",
        down.len()
    );

    let path = out.path("puma-ik.svg");
    draw(&path, &arm, &solutions, &target)?;
    out.wrote(&path);
    Ok(())
}

const COLOURS: [RGBColor; 4] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
];

/// The solutions grouped by arm posture (waist, shoulder, elbow): the two wrist solutions of
/// one posture put every link frame's origin at the same points.
fn postures(solutions: &[Q]) -> Vec<Vec<&Q>> {
    let mut groups: Vec<Vec<&Q>> = Vec::new();
    for q in solutions {
        let same = |g: &Vec<&Q>| (0..3).all(|i| (g[0][i] - q[i]).abs() < 1e-9);
        match groups.iter_mut().find(|g| same(g)) {
            Some(g) => g.push(q),
            None => groups.push(vec![q]),
        }
    }
    groups
}

/// Axis ranges around `points` with one metre the same length on both axes of a plotting
/// area `pixels` wide and high.
fn equal_aspect(points: &[(f64, f64)], pixels: (u32, u32)) -> (Range<f64>, Range<f64>) {
    let (mut lo, mut hi) = ((f64::MAX, f64::MAX), (f64::MIN, f64::MIN));
    for &(x, y) in points {
        lo = (lo.0.min(x), lo.1.min(y));
        hi = (hi.0.max(x), hi.1.max(y));
    }
    let scale =
        ((hi.0 - lo.0) / f64::from(pixels.0)).max((hi.1 - lo.1) / f64::from(pixels.1)) * 1.15;
    let half = (
        f64::from(pixels.0) * scale / 2.0,
        f64::from(pixels.1) * scale / 2.0,
    );
    let mid = ((lo.0 + hi.0) / 2.0, (lo.1 + hi.1) / 2.0);
    (
        mid.0 - half.0..mid.0 + half.0,
        mid.1 - half.1..mid.1 + half.1,
    )
}

/// A tick label to the centimetre, with no "-0.00".
fn tick(v: f64) -> String {
    let rounded = (v * 100.0).round() / 100.0;
    format!("{:.2}", if rounded == 0.0 { 0.0 } else { rounded })
}

/// The arm postures as three orthographic views: front (x, z), side (y, z), top (x, y).
fn draw(
    path: &std::path::Path,
    arm: &Puma560,
    solutions: &[Q],
    target: &Isometry3<f64>,
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1260, 520)).into_drawing_area();
    root.fill(&WHITE)?;
    let (title, rest) = root.split_vertically(60);
    title.draw(&Text::new(
        "PUMA 560: the arm postures that put the tool at one pose",
        (12, 10),
        font(20),
    ))?;
    title.draw(&Text::new(
        "every solution of the closed-form inverse kinematics, drawn from the forward kinematics; \
         the black cross is the tool position asked for",
        (12, 36),
        font(13),
    ))?;
    let (views, key) = rest.split_horizontally(990);
    let panels = views.split_evenly((1, 3));
    let groups = postures(solutions);
    let skeletons: Vec<Vec<Point3<f64>>> = groups.iter().map(|g| skeleton(arm, g[0])).collect();
    let goal = target.translation.vector;
    let views_spec: [(&str, usize, usize, &str, &str); 3] = [
        ("front view (looking along +y)", 0, 2, "x (m)", "z (m)"),
        ("side view (looking along -x)", 1, 2, "y (m)", "z (m)"),
        ("top view (looking down -z)", 0, 1, "x (m)", "y (m)"),
    ];
    for (panel, (name, a, b, xl, yl)) in panels.iter().zip(views_spec) {
        let panel = panel.titled(name, font(15))?;
        let lines: Vec<Vec<(f64, f64)>> = skeletons
            .iter()
            .map(|points| points.iter().map(|p| (p[a], p[b])).collect())
            .collect();
        let mut all: Vec<(f64, f64)> = lines.iter().flatten().copied().collect();
        all.push((goal[a], goal[b]));
        let build = |x: Range<f64>, y: Range<f64>| {
            ChartBuilder::on(&panel)
                .margin(10)
                .x_label_area_size(36)
                .y_label_area_size(44)
                .build_cartesian_2d(x, y)
        };
        let pixels = build(0.0..1.0, 0.0..1.0)?.plotting_area().dim_in_pixel();
        let (x, y) = equal_aspect(&all, pixels);
        let mut chart = build(x, y)?;
        chart
            .configure_mesh()
            .x_desc(xl)
            .y_desc(yl)
            .label_style(font(12))
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
            .light_line_style(BLACK.mix(0.05))
            .draw()?;
        for (k, line) in lines.iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            chart.draw_series(LineSeries::new(line.clone(), colour.stroke_width(2)))?;
            chart.draw_series(line.iter().map(|&c| Circle::new(c, 3, colour.filled())))?;
        }
        let g = (goal[a], goal[b]);
        chart.draw_series(std::iter::once(Cross::new(g, 7, BLACK.stroke_width(2))))?;
        chart.draw_series(std::iter::once(Circle::new((0.0, 0.0), 5, BLACK.filled())))?;
    }
    let mut entries: Vec<(Sample, String)> = groups
        .iter()
        .enumerate()
        .map(|(k, g)| {
            let arm_angles: Vec<String> = g[0].iter().take(3).map(|x| fixed(*x, 2)).collect();
            let wrists: Vec<String> = g
                .iter()
                .map(|q| {
                    let w: Vec<String> = q.iter().skip(3).map(|x| fixed(*x, 2)).collect();
                    format!("({})", w.join(",\u{a0}"))
                })
                .collect();
            (
                Sample::Line(COLOURS[k % COLOURS.len()].stroke_width(2)),
                format!(
                    "q1..q3 = ({}), wrist q4..q6 = {} rad",
                    arm_angles.join(",\u{a0}"),
                    wrists.join(" or ")
                ),
            )
        })
        .collect();
    entries.push((
        Sample::Dot(BLACK.filled()),
        "the base (the origin)".to_string(),
    ));
    entries.push((
        Sample::Note,
        "Dots mark the link frames' origins, joined from the base to the tool. The two wrist \
         solutions of a posture (q4 + pi, -q5, q6 + pi) turn the last links about the same \
         points, so each posture is drawn once."
            .to_string(),
    ));
    let borrowed: Vec<(Sample, &str)> = entries.iter().map(|(s, t)| (*s, t.as_str())).collect();
    side_key(&key, 30, &borrowed)?;
    root.present()?;
    Ok(())
}
