//! The simulate example's animated picture, written by hand: plotters draws still pictures,
//! and an SVG whose links turn by SMIL `<animateTransform>` is a few kilobytes where a
//! sequence of frames would be megabytes.

use std::fmt::Write as _;

use planar_arm::nalgebra::Vector3;
use planar_arm::prelude::*;
use planar_arm::sim::State;

use crate::num::tick;
use crate::Picker;

/// The links' colours, first to last.
const LINKS: [&str; 3] = ["#466ebe", "#c85028", "#28965a"];
const JOINT: &str = "#23283c";

/// A panel: where its axes are on the page, and its scale.
struct Panel {
    /// The page position (px) of the base, the origin of x and y.
    origin: (f64, f64),
    /// Pixels per metre, both axes.
    scale: f64,
    /// The metres shown, `(x0, x1, y0, y1)`.
    view: (f64, f64, f64, f64),
    /// Metres between ticks.
    step: f64,
}

impl Panel {
    fn page(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.origin.0 + self.scale * x,
            self.origin.1 - self.scale * y,
        )
    }

    /// The frame, ticks labelled in metres, the axis names and a faint grid.
    fn axes(&self, svg: &mut String) {
        let (x0, x1, y0, y1) = self.view;
        let (left, top) = self.page(x0, y1);
        let (right, bottom) = self.page(x1, y0);
        let ticks = |lo: f64, hi: f64| {
            let first = (lo / self.step).ceil() as i32;
            let last = (hi / self.step).floor() as i32;
            (first..=last).map(move |k| f64::from(k) * self.step)
        };
        for x in ticks(x0, x1) {
            let (px, _) = self.page(x, 0.0);
            let _ = write!(
                svg,
                r##"<line x1="{px:.1}" y1="{top:.1}" x2="{px:.1}" y2="{bottom:.1}" stroke="#000" stroke-opacity="0.08"/><line x1="{px:.1}" y1="{bottom:.1}" x2="{px:.1}" y2="{:.1}" stroke="#000"/><text x="{px:.1}" y="{:.1}" font-size="12" text-anchor="middle">{}</text>"##,
                bottom + 5.0,
                bottom + 19.0,
                tick(x)
            );
        }
        for y in ticks(y0, y1) {
            let (_, py) = self.page(0.0, y);
            let _ = write!(
                svg,
                r##"<line x1="{left:.1}" y1="{py:.1}" x2="{right:.1}" y2="{py:.1}" stroke="#000" stroke-opacity="0.08"/><line x1="{:.1}" y1="{py:.1}" x2="{left:.1}" y2="{py:.1}" stroke="#000"/><text x="{:.1}" y="{:.1}" font-size="12" text-anchor="end">{}</text>"##,
                left - 5.0,
                left - 8.0,
                py + 4.0,
                tick(y)
            );
        }
        let _ = writeln!(
            svg,
            r##"<rect x="{left:.1}" y="{top:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="#000" stroke-opacity="0.5"/><text x="{:.1}" y="{:.1}" font-size="13" text-anchor="middle">x (m)</text><text transform="translate({:.1} {:.1}) rotate(-90)" font-size="13" text-anchor="middle">y (m)</text>"##,
            right - left,
            bottom - top,
            0.5 * (left + right),
            bottom + 38.0,
            left - 42.0,
            0.5 * (top + bottom)
        );
    }

    /// Opens a group drawn in metres, y up, about the base.
    fn open(&self, svg: &mut String) {
        let _ = writeln!(
            svg,
            r#"<g transform="translate({} {}) scale({} {})">"#,
            self.origin.0, self.origin.1, self.scale, -self.scale
        );
    }
}

/// One arm as nested SVG groups, each link's rotation animated by SMIL: the angles are
/// relative, so each link turns inside the frame of the one before it.
fn animated_arm<const N: usize>(
    svg: &mut String,
    lengths: [f64; N],
    frames: &[SVector<f64, N>],
    seconds: f64,
    metres_per_pixel: f64,
) {
    let (stroke, joint) = (6.0 * metres_per_pixel, 5.0 * metres_per_pixel);
    for (j, l) in lengths.iter().enumerate() {
        let values: Vec<String> = frames
            .iter()
            .map(|q| format!("{:.2}", q[j].to_degrees()))
            .collect();
        let _ = write!(
            svg,
            r#"<g><animateTransform attributeName="transform" type="rotate" dur="{seconds}s" repeatCount="indefinite" calcMode="linear" values="{}"/><line x1="0" y1="0" x2="{l}" y2="0" stroke="{}" stroke-width="{stroke:.5}" stroke-linecap="round"/><circle r="{joint:.5}" fill="{JOINT}"/><g transform="translate({l} 0)">"#,
            values.join(";"),
            LINKS[j % LINKS.len()]
        );
    }
    let _ = write!(svg, r#"<circle r="{:.5}" fill="{JOINT}"/>"#, joint * 1.2);
    for _ in 0..N {
        svg.push_str("</g></g>");
    }
    svg.push('\n');
}

/// A bar that fills over each loop of `seconds`, with its ends labelled: a still of the
/// animation then shows where in the loop it was taken.
fn clock(svg: &mut String, x: f64, y: f64, width: f64, seconds: f64) {
    let _ = writeln!(
        svg,
        r##"<rect x="{x}" y="{y}" width="{width}" height="8" fill="#eee"/><rect x="{x}" y="{y}" width="0" height="8" fill="#466ebe"><animate attributeName="width" from="0" to="{width}" dur="{seconds}s" repeatCount="indefinite"/></rect><text x="{x}" y="{:.1}" font-size="12">0 s</text><text x="{:.1}" y="{:.1}" font-size="12" text-anchor="middle">time in the loop</text><text x="{:.1}" y="{:.1}" font-size="12" text-anchor="end">{} s, then again</text>"##,
        y + 22.0,
        x + 0.5 * width,
        y + 22.0,
        x + width,
        y + 22.0,
        tick(seconds)
    );
}

/// The key: the links' colours and the dashed line.
fn legend(svg: &mut String, x: f64, y: f64) {
    let entries = [
        (LINKS[0], "link 1 (from the base)"),
        (LINKS[1], "link 2"),
        (LINKS[2], "link 3 (left arm only)"),
    ];
    let mut dx = x;
    for (color, text) in entries {
        let _ = write!(
            svg,
            r#"<line x1="{dx}" y1="{y}" x2="{:.1}" y2="{y}" stroke="{color}" stroke-width="6" stroke-linecap="round"/><text x="{:.1}" y="{:.1}" font-size="13">{text}</text>"#,
            dx + 20.0,
            dx + 28.0,
            y + 4.5
        );
        // About 6.5 pixels a character in 13-pixel sans-serif.
        #[allow(clippy::cast_precision_loss)]
        let width = 6.5 * text.len() as f64;
        dx += 56.0 + width;
    }
    let _ = writeln!(
        svg,
        r##"<line x1="{dx}" y1="{y}" x2="{:.1}" y2="{y}" stroke="#555" stroke-width="2" stroke-dasharray="6 4"/><text x="{:.1}" y="{:.1}" font-size="13">the tip's desired path (a straight line)</text>"##,
        dx + 22.0,
        dx + 30.0,
        y + 4.5
    );
}

/// The three links moving the tip along `line` (left) beside the paper's two rods swinging
/// freely (right), each repeating.
pub fn animate(
    picker: &Picker,
    picker_states: &[State<3>],
    swing: &[State<2>],
    line: (Vector2<f64>, Vector2<f64>),
) -> String {
    let mut svg = String::new();
    let (w, h) = (1100.0, 640.0);
    let _ = write!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">
<rect width="{w}" height="{h}" fill="white"/>
<text x="16" y="30" font-size="20">Two simulated arms in motion</text>
<text x="16" y="54" font-size="14">Left: three links moving the tip along a straight line in 2 s (computed torque, 0.5 kg load). Right: the paper's two 1 m, 1 kg rods swinging freely.</text>
"#
    );
    legend(&mut svg, 16.0, 80.0);
    let links = picker.links();
    let lengths = [links[0].length, links[1].length, links[2].length];
    let frames: Vec<Vector3<f64>> = picker_states.iter().map(|s| s.q).collect();
    let t_picker = picker_states.last().map_or(1.0, |s| s.t);
    let left = Panel {
        origin: (156.0, 340.0),
        scale: 330.0,
        view: (-0.2, 1.0, -0.55, 0.65),
        step: 0.2,
    };
    left.axes(&mut svg);
    left.open(&mut svg);
    let (a, b) = line;
    let _ = writeln!(
        svg,
        r##"<rect x="-0.05" y="-0.03" width="0.1" height="0.03" fill="#999"/>
<line x1="{:.4}" y1="{:.4}" x2="{:.4}" y2="{:.4}" stroke="#555" stroke-width="0.006" stroke-dasharray="0.018 0.012"/>"##,
        a.x, a.y, b.x, b.y
    );
    animated_arm(&mut svg, lengths, &frames, t_picker, 1.0 / left.scale);
    svg.push_str("</g>\n");

    let frames: Vec<Vector2<f64>> = swing.iter().map(|s| s.q).collect();
    let t_swing = swing.last().map_or(1.0, |s| s.t);
    let right = Panel {
        origin: (814.0, 325.0),
        scale: 95.0,
        view: (-2.2, 2.2, -2.2, 2.2),
        step: 1.0,
    };
    right.axes(&mut svg);
    right.open(&mut svg);
    svg.push_str(
        r##"<circle r="2" fill="none" stroke="#bbb" stroke-width="0.01" stroke-dasharray="0.06 0.04"/>
<rect x="-0.15" y="-0.06" width="0.3" height="0.06" fill="#999"/>
"##,
    );
    animated_arm(&mut svg, [1.0, 1.0], &frames, t_swing, 1.0 / right.scale);
    svg.push_str("</g>\n");
    let (_, top) = right.page(0.0, 2.0);
    let _ = writeln!(
        svg,
        r##"<text x="{:.1}" y="{:.1}" font-size="12" fill="#777">reach, 2 m</text>"##,
        right.origin.0 + 4.0,
        top - 4.0
    );
    clock(&mut svg, 100.0, 595.0, 340.0, t_picker);
    clock(&mut svg, 645.0, 595.0, 340.0, t_swing);
    svg.push_str("</svg>\n");
    svg
}
