//! The layout of a chart: [`WIDTH`] units wide, its panels in one or two columns with their
//! heights, each panel drawn in its cell with its series and its legend.

use plotters::prelude::*;

use super::axes::{builder, mesh, tick};
use super::canvas::{Overlay, SvgArea, svg};
use super::elements::{Marker, Styled};
use super::legend::{
    LEGEND_ROW, draw_legend_box, draw_legend_strip, emptiest_corner, legend_box_size, legend_rows,
    shared_keys,
};
use super::look::{bar_colours, look};
use super::series::{Legend, Mark, Panel, Scale, range};
use super::text::draw_title;

/// Width of every chart, in SVG units (CSS px before the book scales it to its column).
pub const WIDTH: u32 = 800;

/// Height of a panel: alone, stacked in one column, or two across.
fn panel_height(columns: usize, panels: usize) -> u32 {
    match (columns, panels) {
        (1, 1) => 440,
        (1, _) => 330,
        _ => 360,
    }
}

/// `panels` as one SVG [`WIDTH`] units wide, in `columns` columns (1 or 2), and returns
/// its bytes. When the panels have the same series (same labels in the same order) they
/// share one legend, in the grid's empty cell if it has one, else below the panels; else
/// each panel has its own, in its emptiest corner or where [`Panel::legend`] says.
pub fn chart(panels: &[Panel], columns: usize) -> anyhow::Result<Vec<u8>> {
    let columns = columns.clamp(1, 2).min(panels.len().max(1));
    let rows = panels.len().div_ceil(columns);
    let shared = shared_keys(panels).or_else(|| match panels {
        [one] if one.legend == Some(Legend::Below) && !one.keys().is_empty() => Some(one.keys()),
        _ => None,
    });
    // Panels of their own legends placed below them: the cells grow by the tallest of these.
    let cell_width = WIDTH as i32 / columns as i32;
    let below = |p: &Panel| match (&shared, p.legend, p.keys()) {
        (None, Some(Legend::Below), keys) if !keys.is_empty() => {
            legend_rows(&keys, cell_width - 40).len() as i32 * LEGEND_ROW + 10
        }
        _ => 0,
    };
    let legend_below = panels.iter().map(below).max().unwrap_or(0);
    let cell_height = panel_height(columns, panels.len()) + legend_below as u32;
    let spare = rows * columns > panels.len();
    let strip = match &shared {
        Some(keys) if !spare => legend_rows(keys, WIDTH as i32 - 40).len() as i32 * LEGEND_ROW + 14,
        _ => 0,
    };
    let height = rows as u32 * cell_height + strip as u32;
    svg(WIDTH, height, |root, overlay| {
        let (grid, below) = root.split_vertically(rows as u32 * cell_height);
        let cells = grid.split_evenly((rows, columns));
        for (panel, cell) in panels.iter().zip(&cells) {
            draw_panel(panel, cell, shared.is_none(), legend_below, overlay)?;
        }
        if let Some(keys) = &shared {
            if spare {
                let cell = &cells[panels.len()];
                let (w, h) = legend_box_size(keys);
                let (cw, ch) = cell.dim_in_pixel();
                let at = ((cw as i32 - w) / 2, (ch as i32 - h) / 2);
                draw_legend_box(cell, keys, at)?;
            } else {
                draw_legend_strip(&below, keys)?;
            }
        }
        Ok(())
    })
}

/// A panel with its own x range, y range and legend position.
pub type RangedPanel = (Panel, (f64, f64), (f64, f64), Legend);

/// [`chart`] of panels with the axis ranges and legend positions given, two across.
pub fn ranged_chart(panels: &[RangedPanel]) -> anyhow::Result<Vec<u8>> {
    let panels: Vec<Panel> = panels
        .iter()
        .map(|(p, x, y, at)| p.clone().x_range(*x).y_range(*y).legend(*at))
        .collect();
    chart(&panels, 2)
}

/// Draws `panel` on `area`, with its own legend when `own_legend`: where
/// [`Panel::legend`] says, [`Legend::Below`] in the bottom `legend_below` units of `area`.
fn draw_panel(
    panel: &Panel,
    area: &SvgArea<'_>,
    own_legend: bool,
    legend_below: i32,
    overlay: &mut Overlay,
) -> anyhow::Result<()> {
    let pts = || {
        panel
            .series
            .iter()
            .flat_map(|s| s.points.iter().copied())
            .filter(|&p| panel.usable(p))
    };
    let (x0, x1) = panel
        .x_range
        .unwrap_or_else(|| range(pts().map(|p| p.0), panel.x_scale));
    let (y0, y1) = panel
        .y_range
        .unwrap_or_else(|| range(pts().map(|p| p.1), panel.y_scale));
    let below = own_legend && panel.legend == Some(Legend::Below) && legend_below > 0;
    let (_, height) = area.dim_in_pixel();
    let (top, strip) = area.split_vertically(height as i32 - if below { legend_below } else { 0 });
    let rest = draw_title(&top, &panel.title)?;
    let mut builder = builder(&rest);
    // plotters types linear and log axes differently, hence four arms.
    macro_rules! draw {
        ($xr:expr, $yr:expr) => {{
            let mut chart = builder.build_cartesian_2d($xr, $yr)?;
            mesh!(
                chart,
                &panel.x_label,
                &panel.y_label,
                &|v| tick(panel.x_scale, *v),
                &|v| tick(panel.y_scale, *v)
            );
            for (k, s) in panel.series.iter().enumerate() {
                let (colour, dash, shape) = look(k);
                // Pieces between unusable points.
                let pieces: Vec<Vec<(f64, f64)>> = s
                    .points
                    .split(|&p| !panel.usable(p))
                    .filter(|piece| !piece.is_empty())
                    .map(<[_]>::to_vec)
                    .collect();
                for piece in pieces {
                    match s.mark {
                        Mark::Line | Mark::LinePoints => {
                            chart.draw_series(std::iter::once(Styled::line(
                                piece.clone(),
                                colour,
                                dash,
                            )))?;
                        }
                        Mark::Bars => {
                            let (fill, edge) = bar_colours(colour);
                            let (first, last) = (piece[0].0, piece[piece.len() - 1].0);
                            let floor = |p: (f64, f64)| (p.0, p.1.max(y0));
                            let mut outline: Vec<_> = piece.iter().copied().map(floor).collect();
                            outline.insert(0, (first, y0));
                            outline.push((last, y0));
                            chart.draw_series(std::iter::once(Polygon::new(
                                outline.clone(),
                                fill.filled(),
                            )))?;
                            chart.draw_series(std::iter::once(PathElement::new(
                                outline,
                                edge.stroke_width(1),
                            )))?;
                        }
                        Mark::Points | Mark::Dots => {}
                    }
                    match s.mark {
                        Mark::Points | Mark::LinePoints => {
                            chart.draw_series(
                                piece.iter().map(|&p| Marker::new(p, shape, colour, 4)),
                            )?;
                        }
                        Mark::Dots => {
                            let at: Vec<_> = piece.iter().map(|p| chart.backend_coord(p)).collect();
                            overlay.dots(&at, 2.6, colour);
                        }
                        Mark::Line | Mark::Bars => {}
                    }
                }
            }
            let keys = panel.keys();
            if below {
                draw_legend_strip(&strip, &keys)?;
            } else if own_legend && !keys.is_empty() {
                let corner = panel.legend.unwrap_or_else(|| {
                    emptiest_corner(pts(), (x0, x1, panel.x_scale), (y0, y1, panel.y_scale))
                });
                let (xs, ys) = chart.plotting_area().get_pixel_range();
                let base = area.get_base_pixel();
                let (w, h) = legend_box_size(&keys);
                let x = match corner {
                    Legend::UpperLeft | Legend::LowerLeft => xs.start + 8,
                    Legend::UpperRight | Legend::LowerRight | Legend::Below => xs.end - 8 - w,
                };
                let y = match corner {
                    Legend::UpperLeft | Legend::UpperRight | Legend::Below => ys.start + 8,
                    Legend::LowerLeft | Legend::LowerRight => ys.end - 8 - h,
                };
                draw_legend_box(area, &keys, (x - base.0, y - base.1))?;
            }
        }};
    }
    match (panel.x_scale, panel.y_scale) {
        (Scale::Log, Scale::Log) => draw!((x0..x1).log_scale(), (y0..y1).log_scale()),
        (Scale::Log, Scale::Linear) => draw!((x0..x1).log_scale(), y0..y1),
        (Scale::Linear, Scale::Log) => draw!(x0..x1, (y0..y1).log_scale()),
        (Scale::Linear, Scale::Linear) => draw!(x0..x1, y0..y1),
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::{FAMILY, Series, TICK_PX};

    #[test]
    fn a_chart_is_an_svg_of_the_book_width_with_legible_text() {
        let panel = |title: &str| {
            Panel::new(
                title,
                "x",
                "y",
                vec![
                    Series::line(
                        "a",
                        vec![(0.0, 1.0), (1.0, 2.0), (f64::NAN, 0.0), (2.0, 3.0)],
                    ),
                    Series::measured("b", vec![(0.0, 2.0), (1.0, 1.0)]),
                    Series::bars("c", &[0.0, 1.0, 2.0], &[0.5, 1.5]),
                ],
            )
        };
        let svg = String::from_utf8(chart(&[panel("one"), panel("two")], 2).unwrap()).unwrap();
        assert!(svg.starts_with("<svg width=\"800\""), "{}", &svg[..80]);
        assert!(svg.contains(&format!("font-family=\"{FAMILY}\"")));
        // Every text at least the tick size (plotters rounds the size to a float).
        let sizes: Vec<f64> = svg
            .split("font-size=\"")
            .skip(1)
            .map(|s| s[..s.find('"').unwrap()].parse().unwrap())
            .collect();
        assert!(!sizes.is_empty());
        assert!(sizes.iter().all(|&s| s >= TICK_PX - 0.01), "{sizes:?}");
        // The two panels share one legend: each label once.
        assert_eq!(svg.matches(">\nb\n</text>").count(), 1, "{svg}");
    }

    #[test]
    fn a_legend_below_its_panel_makes_the_cell_taller() {
        let panel = |label: &str| {
            Panel::new(
                "t",
                "x",
                "y",
                vec![Series::line(label, vec![(0.0, 1.0), (1.0, 2.0)])],
            )
        };
        let height = |panels: &[Panel]| {
            let svg = String::from_utf8(chart(panels, 2).unwrap()).unwrap();
            let h = svg.split("height=\"").nth(1).unwrap();
            h[..h.find('"').unwrap()].parse::<u32>().unwrap()
        };
        let inside = height(&[panel("a"), panel("b")]);
        let below = height(&[panel("a").legend(Legend::Below), panel("b")]);
        assert_eq!(inside, panel_height(2, 2));
        assert!(below > inside, "{below} vs {inside}");
    }
}
