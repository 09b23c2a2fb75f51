//! Draws the work-spaces of the paper's arms as SVG, from derived arms (their `workspace()`,
//! [`DexterousWorkspace`], `tip_pose`, `joint_positions` and closed-form inverse kinematics):
//!
//! - `workspace-two-link.svg`: the reachable annulus `|l1 - l2| ..= l1 + l2` of the paper's
//!   two equal links (a disk) and of an unequal pair, with the tips of random configurations;
//! - `workspace-three-link.svg`: the usable (dexterous) work-space of three links, the
//!   points reached with every orientation of the last link, in the paper's three cases
//!   (`l3 < |l1 - l2|`: an annulus; `l3 > |l1 - l2|`: an annulus and a disk; `l1 = l2 = l`: one
//!   disk of radius `2 l - l3`), with the whole reachable annulus outlined. The dots are grid
//!   points that the closed-form inverse kinematics reaches with each of 72 orientations;
//! - `workspace-prismatic.svg`: arms with prismatic joints and joint ranges, from their
//!   `links()`: a polar arm (a hinge with a range carrying a slide with a range, so the tip
//!   reaches both ways along the link: two opposite sectors) and a slider carrying two links
//!   (PRR: the two-link annulus swept along the carriage's travel). The shaded cells are those
//!   whose centre `Workspace::of_links(...).contains`; the dots are `sample_tips` of random
//!   configurations within the ranges, each of them checked to be contained.
//!
//! The pictures go to `target/pictures/`, to `DIR` with `--out DIR`, or with `--docs` to
//! `docs/`, where README.md shows them.
//!
//! ```text
//! cargo run --release --example workspace [-- --out DIR | -- --docs]
//! ```

#[path = "support/num.rs"]
mod num;
#[path = "support/out.rs"]
mod out;
#[path = "support/plot.rs"]
mod plot;

use std::error::Error;

use planar_arm::kinematics::{sample_tips, DexterousWorkspace, Skeleton, Workspace};
use planar_arm::prelude::*;
use plotters::coord::Shift;
use plotters::prelude::*;

use num::tick;
use out::Out;
use plot::{font, side_key, Sample};

/// The paper's two equal links.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Equal2 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
}

/// An unequal pair: the annulus 0.4 ..= 1.6.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Unequal2 {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 3/5, mass = 1)]
    fore: Revolute,
}

/// `l3 < |l1 - l2|`: the usable region is an annulus.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct ShortHand {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 3/5, mass = 1)]
    fore: Revolute,
    #[arm(length = 1/4, mass = 1)]
    hand: Revolute,
}

/// `|l1 - l2| < l3 <= min(l1, l2)`: an annulus and a disk.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct LongHand {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 7/10, mass = 1)]
    fore: Revolute,
    #[arm(length = 1/2, mass = 1)]
    hand: Revolute,
}

/// `l1 = l2`: one disk of radius `2 l - l3`.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct EqualPair {
    #[arm(length = 1, mass = 1)]
    upper: Revolute,
    #[arm(length = 1, mass = 1)]
    fore: Revolute,
    #[arm(length = 1/2, mass = 1)]
    hand: Revolute,
}

/// A polar arm: a 0.2 m link turning within -0.5 ..= 2 rad carries a 0.5 m slide travelling
/// -1.2 ..= 0.3 m, so the tip lies -0.5 ..= 1 m from the base along the link.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct Polar {
    #[arm(length = 0.2, mass = 1, range = (-0.5, 2))]
    turn: Revolute,
    #[arm(length = 0.5, mass = 1, range = (-1.2, 0.3))]
    slide: Prismatic,
}

/// A carriage travelling -0.35 ..= 0.05 m along x carrying links of 0.6 and 0.3 m.
#[derive(PlanarArm, Default)]
#[arm(gravity = 9.81)]
struct SliderArm {
    #[arm(length = 0.2, mass = 1, range = (-0.35, 0.05))]
    carriage: Prismatic,
    #[arm(length = 0.6, mass = 1)]
    upper: Revolute,
    #[arm(length = 0.3, mass = 1)]
    fore: Revolute,
}

type Pt = (f64, f64);

/// Random configurations drawn per two-link panel.
const TIPS: usize = 300;

const REACHABLE: RGBColor = RGBColor(70, 110, 190);
const USABLE: RGBColor = RGBColor(40, 150, 90);
const ARM: RGBColor = RGBColor(200, 80, 40);

/// Deterministic splitmix64 numbers in [0, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        #[allow(clippy::cast_precision_loss)]
        let u = (z >> 11) as f64 / (1u64 << 53) as f64;
        u
    }

    fn angle(&mut self) -> f64 {
        (2.0 * self.next() - 1.0) * std::f64::consts::PI
    }
}

fn circle(radius: f64) -> Vec<Pt> {
    (0..=240)
        .map(|i| {
            let t = f64::from(i) * std::f64::consts::TAU / 240.0;
            (radius * t.cos(), radius * t.sin())
        })
        .collect()
}

/// A filled annulus as one polygon: the outer circle one way, the inner one back (nonzero fill).
fn annulus(inner: f64, outer: f64) -> Vec<Pt> {
    let mut points = circle(outer);
    if inner > 0.0 {
        points.extend(circle(inner).into_iter().rev());
    }
    points
}

/// The arm drawn as a polyline: the joints, then the tip.
fn arm_polyline<A: PlanarArm<N>, const N: usize>(arm: &A, q: &SVector<f64, N>) -> Vec<Pt> {
    let mut points: Vec<Pt> = arm.joint_positions(q).iter().map(|p| (p.x, p.y)).collect();
    let tip = arm.tip_pose(q).translation.vector;
    points.push((tip.x, tip.y));
    points
}

type Chart<'a, 'b> = ChartContext<
    'a,
    SVGBackend<'b>,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// A chart titled `title` whose axes have equal units and show at least `-half ..= half`.
fn square_chart<'a, 'b>(
    area: &'a DrawingArea<SVGBackend<'b>, Shift>,
    title: &str,
    half: f64,
) -> Result<Chart<'a, 'b>, Box<dyn Error>> {
    let (margin, x_labels, y_labels) = (12_u32, 44_u32, 56_u32);
    let (w, h) = area.dim_in_pixel();
    let caption_height = 34;
    let plot_w = f64::from(w - y_labels - 2 * margin);
    let plot_h = f64::from(h - x_labels - 2 * margin - caption_height);
    let (xr, yr) = if plot_w >= plot_h {
        (half * plot_w / plot_h, half)
    } else {
        (half, half * plot_h / plot_w)
    };
    let mut chart = ChartBuilder::on(area)
        .margin(margin)
        .caption(title, font(16))
        .x_label_area_size(x_labels)
        .y_label_area_size(y_labels)
        .build_cartesian_2d(-xr..xr, -yr..yr)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(BLACK.mix(0.08))
        .x_labels(7)
        .y_labels(7)
        .x_desc("x (m)")
        .y_desc("y (m)")
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .label_style(font(12))
        .axis_desc_style(font(13))
        .draw()?;
    Ok(chart)
}

fn two_link_panel<A: PlanarArm<2>>(
    arm: &A,
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    rng: &mut Rng,
) -> Result<(), Box<dyn Error>> {
    let [l1, l2] = arm.links().map(|l| l.length);
    let w = arm.workspace();
    let (inner, outer) = (w.inner_radius(), w.outer_radius());
    let shape = if inner == 0.0 {
        format!("a disk of radius {} m", tick(outer))
    } else {
        format!(
            "an annulus, {} to {} m from the base",
            tick(inner),
            tick(outer)
        )
    };
    let title = format!("links of {} m and {} m: {shape}", tick(l1), tick(l2));
    let mut chart = square_chart(area, &title, 1.1 * outer)?;
    chart.draw_series(std::iter::once(Polygon::new(
        annulus(inner, outer),
        REACHABLE.mix(0.18).filled(),
    )))?;
    for radius in [inner, outer].into_iter().filter(|r| *r > 0.0) {
        chart.draw_series(LineSeries::new(circle(radius), REACHABLE.stroke_width(2)))?;
    }
    // Tips of random configurations: every one lands in the annulus.
    let tips: Vec<Pt> = (0..TIPS)
        .map(|_| {
            let q = SVector::<f64, 2>::new(rng.angle(), rng.angle());
            let t = arm.tip_pose(&q).translation.vector;
            assert!(w.contains(&Point2::from(t)));
            (t.x, t.y)
        })
        .collect();
    chart.draw_series(
        tips.iter()
            .map(|&p| Circle::new(p, 1, BLACK.mix(0.6).filled())),
    )?;
    // One configuration, drawn.
    let pose = arm_polyline(arm, &SVector::<f64, 2>::new(0.5, 2.0));
    chart.draw_series(LineSeries::new(pose.clone(), ARM.stroke_width(3)))?;
    chart.draw_series(pose.iter().map(|&p| Circle::new(p, 3, ARM.filled())))?;
    Ok(())
}

fn three_link_panel<A>(
    arm: &A,
    case: &str,
    area: &DrawingArea<SVGBackend<'_>, Shift>,
) -> Result<(), Box<dyn Error>>
where
    A: PlanarArm<3> + ClosedFormIk<3, Target = Isometry2<f64>>,
{
    let [l1, l2, l3] = arm.links().map(|l| l.length);
    let all = arm.workspace();
    let usable = DexterousWorkspace::of_lengths(l1, l2, l3);
    let outer = all.outer_radius();
    let title = format!(
        "links of {}, {} and {} m: {case}",
        tick(l1),
        tick(l2),
        tick(l3)
    );
    let mut chart = square_chart(area, &title, 1.06 * outer)?;

    // The usable pieces, filled.
    let mut pieces = Vec::new();
    if let Some(r) = usable.disk_radius() {
        pieces.push(annulus(0.0, r));
    }
    if let Some((inner, o)) = usable.annulus() {
        pieces.push(annulus(inner, o));
    }
    chart.draw_series(
        pieces
            .into_iter()
            .map(|piece| Polygon::new(piece, USABLE.mix(0.35).filled())),
    )?;
    // The whole reachable annulus, outlined.
    for radius in [all.inner_radius(), outer].into_iter().filter(|r| *r > 0.0) {
        chart.draw_series(LineSeries::new(circle(radius), REACHABLE.stroke_width(2)))?;
    }
    // Brute force: grid points reached with each of 72 orientations of the last link.
    let n = 22;
    let spacing = 2.0 * outer / f64::from(n);
    let mut dots = Vec::new();
    for i in 0..=n {
        for j in 0..=n {
            let p = Vector2::new(
                -outer + spacing * f64::from(i),
                -outer + spacing * f64::from(j),
            );
            let every = (0..72).all(|k| {
                let phi = f64::from(k) * std::f64::consts::TAU / 72.0;
                arm.inverse_kinematics(&Isometry2::new(p, phi)).is_ok()
            });
            if !on_edge(l1, l2, l3, p.norm()) {
                assert_eq!(every, usable.contains(&Point2::from(p)), "{p}");
            }
            if every {
                dots.push((p.x, p.y));
            }
        }
    }
    chart.draw_series(
        dots.iter()
            .map(|&p| Circle::new(p, 2, BLACK.mix(0.6).filled())),
    )?;
    // The arm reaching a usable point, and the circle of wrist positions about that point.
    let radius = match (usable.annulus(), usable.disk_radius()) {
        (Some((inner, o)), _) => 0.5 * (inner + o),
        (None, Some(r)) => 0.6 * r,
        (None, None) => 0.0,
    };
    let point = Vector2::new(-0.6, 0.8) * radius;
    let [q, _] = arm.inverse_kinematics(&Isometry2::new(point, 2.6))?;
    chart.draw_series(LineSeries::new(
        circle(l3)
            .into_iter()
            .map(|(x, y)| (x + point.x, y + point.y)),
        ARM.mix(0.7).stroke_width(1),
    ))?;
    let pose = arm_polyline(arm, &q);
    chart.draw_series(LineSeries::new(pose.clone(), ARM.stroke_width(3)))?;
    chart.draw_series(pose.iter().map(|&p| Circle::new(p, 3, ARM.filled())))?;
    Ok(())
}

/// An arm with prismatic joints or ranges: the cells of a grid whose centres the work-space
/// contains (merged into runs along each row), tips of random configurations within the
/// ranges, the radii that bound the region, and the arm at `q`.
fn links_panel<A: PlanarArm<N>, const N: usize>(
    arm: &A,
    title: &str,
    q: &SVector<f64, N>,
    area: &DrawingArea<SVGBackend<'_>, Shift>,
) -> Result<(), Box<dyn Error>> {
    let links = arm.links();
    let w = Workspace::of_links(&links);
    assert!(w.is_exact(), "{title}");
    let (inner, outer) = (w.inner_radius(), w.outer_radius());
    let half = 1.08 * outer;
    let mut chart = square_chart(area, title, half)?;
    let n = 180;
    let cell = 2.0 * half / f64::from(n);
    let mut runs = Vec::new();
    for j in 0..n {
        let y = -half + cell * (f64::from(j) + 0.5);
        let mut start = None;
        for i in 0..=n {
            let x = -half + cell * (f64::from(i) + 0.5);
            let inside = i < n && w.contains(&Point2::new(x, y));
            match (inside, start) {
                (true, None) => start = Some(x - 0.5 * cell),
                (false, Some(x0)) => {
                    runs.push(((x0, y - 0.5 * cell), (x - 0.5 * cell, y + 0.5 * cell)));
                    start = None;
                }
                _ => {}
            }
        }
    }
    chart.draw_series(
        runs.into_iter()
            .map(|(a, b)| Rectangle::new([a, b], REACHABLE.mix(0.22).filled())),
    )?;
    for radius in [inner, outer].into_iter().filter(|r| *r > 0.0) {
        chart.draw_series(LineSeries::new(circle(radius), REACHABLE.stroke_width(1)))?;
    }
    let tips: Vec<Pt> = sample_tips(&links, 1.0, 11)
        .take(TIPS * 2)
        .map(|p| {
            assert!(w.contains(&p), "{title}: tip {p} not contained");
            (p.x, p.y)
        })
        .collect();
    chart.draw_series(
        tips.iter()
            .map(|&p| Circle::new(p, 1, BLACK.mix(0.6).filled())),
    )?;
    // A first joint that slides: its rail, the travel of the carriage and its link.
    if let (Joint::Prismatic, Some((lo, hi))) = (links[0].joint, links[0].range) {
        let rail = vec![(lo, 0.0), (hi + links[0].length, 0.0)];
        chart.draw_series(LineSeries::new(rail, BLACK.mix(0.45).stroke_width(6)))?;
    }
    let pose: Vec<Pt> = Skeleton::of_links(&links, q)
        .points()
        .map(|p| (p.x, p.y))
        .collect();
    chart.draw_series(LineSeries::new(pose.clone(), ARM.stroke_width(3)))?;
    chart.draw_series(pose.iter().map(|&p| Circle::new(p, 3, ARM.filled())))?;
    Ok(())
}

/// Whether a point lies near a boundary circle of the usable region, where a finite sample of
/// orientations may miss the few that fail.
fn on_edge(l1: f64, l2: f64, l3: f64, rho: f64) -> bool {
    let (a, b) = ((l1 - l2).abs(), l1 + l2);
    (rho + l3 - b).abs() < 1e-2 || ((rho - l3).abs() - a).abs() < 1e-2
}

/// The two-link arms: a disk and an annulus.
fn draw_two_link(out: &Out) -> Result<(), Box<dyn Error>> {
    let two = out.path("workspace-two-link.svg");
    {
        let root = SVGBackend::new(&two, (1160, 520)).into_drawing_area();
        root.fill(&WHITE)?;
        let (plots, key) = root.split_horizontally(900);
        let panels = plots.split_evenly((1, 2));
        let mut rng = Rng(7);
        two_link_panel(&Equal2::default(), &panels[0], &mut rng)?;
        two_link_panel(&Unequal2::default(), &panels[1], &mut rng)?;
        side_key(
            &key,
            70,
            &[
                (
                    Sample::Patch(REACHABLE.mix(0.3).filled()),
                    "where the tip can reach",
                ),
                (
                    Sample::Line(REACHABLE.stroke_width(2)),
                    "its bounding circles, of radii |l1 - l2| and l1 + l2",
                ),
                (
                    Sample::Dot(BLACK.mix(0.6).filled()),
                    "the tip in 300 random configurations",
                ),
                (
                    Sample::Line(ARM.stroke_width(3)),
                    "the arm at q = (0.5, 2) rad",
                ),
            ],
        )?;
        root.present()?;
    }
    out.wrote(&two);
    Ok(())
}

/// The three-link arms' usable regions, in the paper's three cases.
fn draw_three_link(out: &Out) -> Result<(), Box<dyn Error>> {
    let three = out.path("workspace-three-link.svg");
    {
        let root = SVGBackend::new(&three, (1500, 480)).into_drawing_area();
        root.fill(&WHITE)?;
        let (plots, key) = root.split_horizontally(1240);
        let panels = plots.split_evenly((1, 3));
        three_link_panel(&ShortHand::default(), "l3 < |l1 - l2|", &panels[0])?;
        three_link_panel(&LongHand::default(), "l3 > |l1 - l2|", &panels[1])?;
        three_link_panel(&EqualPair::default(), "l1 = l2 = l", &panels[2])?;
        side_key(
            &key,
            70,
            &[
                (
                    Sample::Line(REACHABLE.stroke_width(2)),
                    "bounds of where the tip can reach",
                ),
                (
                    Sample::Patch(USABLE.mix(0.45).filled()),
                    "usable: reached with the last link at every angle",
                ),
                (
                    Sample::Dot(BLACK.mix(0.6).filled()),
                    "grid points that inverse kinematics reaches at all 72 angles tried",
                ),
                (Sample::Line(ARM.stroke_width(3)), "the arm reaching a usable point"),
                (
                    Sample::Line(ARM.mix(0.7).stroke_width(1)),
                    "where its wrist can be: a circle of radius l3 about that point",
                ),
                (
                    Sample::Note,
                    "Left: an annulus; middle: an annulus and a disk; right: one disk of radius 2l\u{a0}-\u{a0}l3.",
                ),
            ],
        )?;
        root.present()?;
    }
    out.wrote(&three);
    Ok(())
}

/// The arms with prismatic joints and joint ranges.
fn draw_prismatic(out: &Out) -> Result<(), Box<dyn Error>> {
    let prismatic = out.path("workspace-prismatic.svg");
    {
        let root = SVGBackend::new(&prismatic, (1160, 520)).into_drawing_area();
        root.fill(&WHITE)?;
        let (plots, key) = root.split_horizontally(900);
        let panels = plots.split_evenly((1, 2));
        links_panel(
            &Polar::default(),
            "a hinge (-0.5 to 2 rad) carrying a slide (-1.2 to 0.3 m)",
            &SVector::<f64, 2>::new(1.2, 0.1),
            &panels[0],
        )?;
        links_panel(
            &SliderArm::default(),
            "a carriage (-0.35 to 0.05 m) carrying links of 0.6 and 0.3 m",
            &SVector::<f64, 3>::new(-0.1, 1.9, -2.2),
            &panels[1],
        )?;
        side_key(
            &key,
            70,
            &[
                (
                    Sample::Patch(REACHABLE.mix(0.3).filled()),
                    "where the tip can reach (grid cells whose centre is inside)",
                ),
                (
                    Sample::Line(REACHABLE.stroke_width(1)),
                    "its nearest and farthest distance from the base",
                ),
                (
                    Sample::Dot(BLACK.mix(0.6).filled()),
                    "the tip in random configurations within the joint ranges",
                ),
                (Sample::Line(ARM.stroke_width(3)), "the arm in one configuration"),
                (Sample::Line(BLACK.mix(0.45).stroke_width(6)), "the carriage's rail"),
                (
                    Sample::Note,
                    "Left: the slide passes through the base, so the tip reaches both ways: two opposite sectors, of radii 1 m and 0.5 m.",
                ),
                (
                    Sample::Note,
                    "Right: the annulus 0.3 to 0.9 m from the carriage, swept along its 0.4 m of travel.",
                ),
            ],
        )?;
        root.present()?;
    }
    out.wrote(&prismatic);
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let out = Out::from_args("workspace");
    draw_two_link(&out)?;
    draw_three_link(&out)?;
    draw_prismatic(&out)
}
