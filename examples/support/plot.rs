//! Drawing helpers shared by the examples' pictures (plotters' SVG backend): the text style and
//! the samples shown in a chart's key. Included by the examples that draw
//! (`#[path = "support/plot.rs"] mod plot;`); each uses a part of it.
#![allow(dead_code)]

use std::error::Error;

use plotters::coord::types::RangedCoordf64;
use plotters::coord::CoordTranslate;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

/// The pictures' text: sans-serif, `size` pixels.
pub fn font(size: u32) -> TextStyle<'static> {
    ("sans-serif", size).into_font().into()
}

/// A key entry's sample for a line: a short stroke.
pub fn swatch(style: ShapeStyle) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style)
}

/// A key entry's sample for a dashed line.
pub fn dashed_swatch(
    style: ShapeStyle,
) -> impl Fn((i32, i32)) -> DashedPathElement<std::vec::IntoIter<(i32, i32)>, i32> {
    move |(x, y)| DashedPathElement::new(vec![(x, y), (x + 20, y)], 6, 3, style)
}

/// A key entry's sample for dots.
pub fn dot_swatch(style: ShapeStyle) -> impl Fn((i32, i32)) -> Circle<(i32, i32), i32> {
    move |(x, y)| Circle::new((x + 10, y), 3, style)
}

/// A key entry's sample for a shaded area.
pub fn patch_swatch(style: ShapeStyle) -> impl Fn((i32, i32)) -> Rectangle<(i32, i32)> {
    move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], style)
}

/// A chart on two `f64` axes.
pub type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Draws the chart's key at `position`: white, framed, in the pictures' text.
pub fn key<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
) -> Result<(), Box<dyn Error>>
where
    DB::ErrorType: 'static,
{
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.92))
        .border_style(BLACK.mix(0.3))
        .label_font(font(13))
        .draw()?;
    Ok(())
}

/// The sample drawn beside an entry of a side key.
#[derive(Clone, Copy)]
pub enum Sample {
    Line(ShapeStyle),
    Dashed(ShapeStyle),
    Dot(ShapeStyle),
    Patch(ShapeStyle),
    /// No sample: text across the key's whole width.
    Note,
}

/// `text` broken into lines of at most `width` characters, at spaces (not at no-break
/// spaces, `\u{a0}`).
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 1 + word.chars().count() <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// Draws a key in a strip of its own beside the charts, from `top` (px) down, each entry's
/// text wrapped to the strip's width: a key inside a chart hides whatever it covers.
pub fn side_key<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    top: i32,
    entries: &[(Sample, &str)],
) -> Result<(), Box<dyn Error>>
where
    DB::ErrorType: 'static,
{
    let (x, line_height, gap) = (8, 17, 9);
    let width = i32::try_from(area.dim_in_pixel().0)?;
    let mut y = top;
    for (sample, text) in entries {
        let sample_end = (x + 20, y);
        match sample {
            Sample::Line(style) => {
                area.draw(&PathElement::new(vec![(x, y), sample_end], *style))?
            }
            Sample::Dashed(style) => area.draw(&DashedPathElement::new(
                vec![(x, y), sample_end],
                6,
                3,
                *style,
            ))?,
            Sample::Dot(style) => area.draw(&Circle::new((x + 10, y), 3, *style))?,
            Sample::Patch(style) => {
                area.draw(&Rectangle::new([(x, y - 6), (x + 20, y + 6)], *style))?;
            }
            Sample::Note => {}
        }
        let indent = if matches!(sample, Sample::Note) {
            0
        } else {
            28
        };
        // About 6 pixels a character in 13-pixel sans-serif.
        let chars = usize::try_from((width - x - indent - 4) / 6)?;
        for line in wrap(text, chars) {
            area.draw(&Text::new(line, (x + indent, y - 7), font(13)))?;
            y += line_height;
        }
        y += gap;
    }
    Ok(())
}
