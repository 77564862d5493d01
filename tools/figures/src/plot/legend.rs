//! Legends: one shared by panels of the same series or one per panel, as a box in the
//! panel's emptiest corner or as a strip below it, each key a sample of its series' look.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::elements::{Marker, Styled};
use super::look::{Shape, bar_colours, look};
use super::series::{Key, Legend, Mark, Panel, Scale};
use super::text::{TICK_PX, font, text_width};

/// Height of one legend row, in SVG units.
pub(super) const LEGEND_ROW: i32 = 22;

/// Length of a legend's line sample.
const SAMPLE: i32 = 36;

/// The legend entries shared by all panels, when there are two or more panels and they
/// have the same entries.
pub(super) fn shared_keys(panels: &[Panel]) -> Option<Vec<Key>> {
    let first = panels.first()?.keys();
    (panels.len() > 1 && !first.is_empty() && panels.iter().all(|p| p.keys() == first))
        .then_some(first)
}

/// Width of a legend entry: sample, gap, label.
fn key_width(key: &Key) -> i32 {
    SAMPLE + 8 + text_width(&key.label, TICK_PX)
}

/// `keys` flowed into rows no wider than `width`.
pub(super) fn legend_rows(keys: &[Key], width: i32) -> Vec<Vec<Key>> {
    let mut rows: Vec<Vec<Key>> = Vec::new();
    let mut used = 0;
    for key in keys {
        let w = key_width(key) + 24;
        match rows.last_mut() {
            Some(row) if used + w <= width => {
                row.push(key.clone());
                used += w;
            }
            _ => {
                rows.push(vec![key.clone()]);
                used = w;
            }
        }
    }
    rows
}

/// Size of a legend box listing `keys` one per row.
pub(super) fn legend_box_size(keys: &[Key]) -> (i32, i32) {
    let w = keys.iter().map(key_width).max().unwrap_or(0);
    (w + 16, keys.len() as i32 * LEGEND_ROW + 10)
}

/// A legend box with its top left corner at `at` (pixels of `area`): white, thin border.
pub(super) fn draw_legend_box<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    keys: &[Key],
    at: (i32, i32),
) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let (w, h) = legend_box_size(keys);
    let (x, y) = at;
    area.draw(&Rectangle::new(
        [(x, y), (x + w, y + h)],
        WHITE.mix(0.9).filled(),
    ))?;
    area.draw(&Rectangle::new(
        [(x, y), (x + w, y + h)],
        BLACK.mix(0.4).stroke_width(1),
    ))?;
    for (row, key) in keys.iter().enumerate() {
        let cy = y + 5 + row as i32 * LEGEND_ROW + LEGEND_ROW / 2;
        draw_key(area, key, (x + 8, cy))?;
    }
    Ok(())
}

/// The legend of a whole chart below its panels, rows centred.
pub(super) fn draw_legend_strip<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    keys: &[Key],
) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let (width, _) = area.dim_in_pixel();
    for (r, row) in legend_rows(keys, width as i32 - 40).iter().enumerate() {
        let total: i32 = row.iter().map(|k| key_width(k) + 24).sum::<i32>() - 24;
        let mut x = (width as i32 - total) / 2;
        let y = 4 + r as i32 * LEGEND_ROW + LEGEND_ROW / 2;
        for key in row {
            draw_key(area, key, (x, y))?;
            x += key_width(key) + 24;
        }
    }
    Ok(())
}

/// One legend entry, its sample starting at `(x, y)` (the row's middle).
fn draw_key<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    key: &Key,
    (x, y): (i32, i32),
) -> anyhow::Result<()>
where
    DB::ErrorType: 'static,
{
    let (colour, dash, shape) = look(key.index);
    let middle = (x + SAMPLE / 2, y);
    match key.mark {
        Mark::Line | Mark::LinePoints => {
            area.draw(&Styled::line(vec![(x, y), (x + SAMPLE, y)], colour, dash))?;
        }
        Mark::Bars => {
            let (fill, edge) = bar_colours(colour);
            area.draw(&Rectangle::new(
                [(x + 6, y - 7), (x + SAMPLE - 6, y + 7)],
                fill.filled(),
            ))?;
            area.draw(&Rectangle::new(
                [(x + 6, y - 7), (x + SAMPLE - 6, y + 7)],
                edge.stroke_width(1),
            ))?;
        }
        Mark::Points | Mark::Dots => {}
    }
    match key.mark {
        Mark::Points | Mark::LinePoints => area.draw(&Marker::new(middle, shape, colour, 4))?,
        Mark::Dots => area.draw(&Marker::new(middle, Shape::Circle, colour, 2))?,
        Mark::Line | Mark::Bars => {}
    }
    area.draw(&Text::new(
        key.label.clone(),
        (x + SAMPLE + 8, y),
        font(TICK_PX)
            .color(&BLACK)
            .pos(Pos::new(HPos::Left, VPos::Center)),
    ))?;
    Ok(())
}

/// The corner of the plot (a third of each axis) holding the fewest data points: where
/// the legend hides the least.
pub(super) fn emptiest_corner(
    points: impl Iterator<Item = (f64, f64)>,
    x: (f64, f64, Scale),
    y: (f64, f64, Scale),
) -> Legend {
    let unit = |v: f64, (lo, hi, scale): (f64, f64, Scale)| match scale {
        Scale::Linear => (v - lo) / (hi - lo),
        Scale::Log => (v.ln() - lo.ln()) / (hi.ln() - lo.ln()),
    };
    let mut counts = [0usize; 4]; // upper right, upper left, lower right, lower left
    for (px, py) in points {
        let (u, v) = (unit(px, x), unit(py, y));
        let corner = match (u < 1.0 / 3.0, u > 2.0 / 3.0, v > 2.0 / 3.0, v < 1.0 / 3.0) {
            (_, true, true, _) => 0,
            (true, _, true, _) => 1,
            (_, true, _, true) => 2,
            (true, _, _, true) => 3,
            _ => continue,
        };
        counts[corner] += 1;
    }
    match (0..4).min_by_key(|&k| counts[k]).unwrap_or(0) {
        0 => Legend::UpperRight,
        1 => Legend::UpperLeft,
        2 => Legend::LowerRight,
        _ => Legend::LowerLeft,
    }
}
