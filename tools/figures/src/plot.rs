//! Plotting helpers for the book's figures: PNG line charts drawn with plotters.
//!
//! Text is drawn with DejaVu Sans embedded in the binary (`assets/fonts/`, Bitstream Vera
//! licence), registered with plotters' `ab_glyph` backend, so figures render the same on a
//! machine with no system fonts and no fontconfig. PNG encoding is the library's one
//! encoder, from plotters' RGB buffer.

use std::error::Error;
use std::sync::Once;

use plotters::prelude::*;
use plotters::style::{FontStyle, register_font};

/// A boxed error, for figure code.
pub type BoxError = Box<dyn Error + Send + Sync>;

static FONT: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

/// Registers the embedded font as plotters' `sans-serif` (once per process).
pub fn register_embedded_font() {
    REGISTER.call_once(|| {
        // The font is a fixed, known-good file; failure here is a build defect.
        register_font("sans-serif", FontStyle::Normal, FONT)
            .unwrap_or_else(|_| panic!("embedded DejaVuSans.ttf failed to load"));
    });
}

/// The palette of the book's plots (colour-blind safe, Okabe-Ito).
pub const PALETTE: [RGBColor; 6] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
];

/// One named curve.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// Points `(x, y)`; non-finite or (on a log axis) non-positive points are skipped.
    pub points: Vec<(f64, f64)>,
}

/// Axis scale.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    /// Linear.
    Linear,
    /// Base-10 logarithmic.
    Log,
}

/// One panel of a chart.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Title above the panel.
    pub title: String,
    /// X axis label.
    pub x_label: String,
    /// Y axis label.
    pub y_label: String,
    /// X scale.
    pub x_scale: Scale,
    /// Y scale.
    pub y_scale: Scale,
    /// The curves.
    pub series: Vec<Series>,
}

fn usable(p: (f64, f64), xs: Scale, ys: Scale) -> bool {
    p.0.is_finite()
        && p.1.is_finite()
        && (xs == Scale::Linear || p.0 > 0.0)
        && (ys == Scale::Linear || p.1 > 0.0)
}

fn range(values: impl Iterator<Item = f64>, scale: Scale) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !lo.is_finite() {
        return (if scale == Scale::Log { 1e-1 } else { 0.0 }, 1.0);
    }
    match scale {
        Scale::Log => {
            let (lo, hi) = (lo.log10().floor(), hi.log10().ceil());
            (
                10f64.powf(lo),
                10f64.powf(if hi > lo { hi } else { lo + 1.0 }),
            )
        }
        Scale::Linear => {
            let pad = if hi > lo { 0.05 * (hi - lo) } else { 1.0 };
            (lo.min(0.0) - if lo < 0.0 { pad } else { 0.0 }, hi + pad)
        }
    }
}

/// A white `width x height` bitmap, handed to `draw` and then encoded as a PNG: the frame
/// of every figure (the embedded font is registered first).
pub fn draw_png(
    width: u32,
    height: u32,
    draw: impl FnOnce(&DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>) -> Result<(), BoxError>,
) -> Result<Vec<u8>, BoxError> {
    register_embedded_font();
    let mut buffer = vec![255u8; (width * height * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (width, height)).into_drawing_area();
        root.fill(&WHITE)?;
        draw(&root)?;
        root.present()?;
    }
    encode_png(width, height, buffer)
}

/// Draws `panels` side by side into a `width x height` PNG and returns its bytes.
pub fn line_chart_png(panels: &[Panel], width: u32, height: u32) -> Result<Vec<u8>, BoxError> {
    draw_png(width, height, |root| {
        let areas = root.split_evenly((1, panels.len().max(1)));
        for (panel, area) in panels.iter().zip(areas.iter()) {
            draw_panel(panel, area, &Style::default())?;
        }
        Ok(())
    })
}

/// Where a panel's legend goes, when it is not left to [`line_chart_png`]'s choice of the
/// emptiest corner.
#[derive(Clone, Copy, Debug)]
pub enum Legend {
    /// Top right.
    UpperRight,
    /// Bottom right.
    LowerRight,
    /// Top left.
    UpperLeft,
}

/// A linear panel with its own x range, y range and legend position.
pub type RangedPanel = (Panel, (f64, f64), (f64, f64), Legend);

/// Linear panels side by side, each with the axis ranges given, curves as lines without
/// markers. For curves whose interesting variation is a few percent of their value:
/// [`line_chart_png`] starts every linear axis at 0, which would flatten them.
pub fn ranged_chart_png(
    panels: &[RangedPanel],
    width: u32,
    height: u32,
) -> Result<Vec<u8>, BoxError> {
    draw_png(width, height, |root| {
        let areas = root.split_evenly((1, panels.len().max(1)));
        for ((panel, xr, yr, legend), area) in panels.iter().zip(areas.iter()) {
            let linear = Panel {
                x_scale: Scale::Linear,
                y_scale: Scale::Linear,
                ..panel.clone()
            };
            let style = Style {
                ranges: Some((*xr, *yr)),
                legend: Some(match legend {
                    Legend::UpperRight => SeriesLabelPosition::UpperRight,
                    Legend::LowerRight => SeriesLabelPosition::LowerRight,
                    Legend::UpperLeft => SeriesLabelPosition::UpperLeft,
                }),
                lines_only: true,
            };
            draw_panel(&linear, area, &style)?;
        }
        Ok(())
    })
}

/// How a panel departs from the automatic layout.
#[derive(Default)]
struct Style {
    /// Fixed (x, y) ranges instead of ranges fitted to the data.
    ranges: Option<((f64, f64), (f64, f64))>,
    /// A fixed legend position instead of the emptiest corner.
    legend: Option<SeriesLabelPosition>,
    /// No circle at each point.
    lines_only: bool,
}

fn draw_panel(
    panel: &Panel,
    area: &DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>,
    style: &Style,
) -> Result<(), BoxError> {
    let pts = || {
        panel
            .series
            .iter()
            .flat_map(|s| s.points.iter().copied())
            .filter(|&p| usable(p, panel.x_scale, panel.y_scale))
    };
    let ((x0, x1), (y0, y1)) = style.ranges.unwrap_or_else(|| {
        (
            range(pts().map(|p| p.0), panel.x_scale),
            range(pts().map(|p| p.1), panel.y_scale),
        )
    });
    let legend = style.legend.clone().unwrap_or_else(|| {
        emptiest_corner(pts(), (x0, x1, panel.x_scale), (y0, y1, panel.y_scale))
    });
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(&panel.title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70);
    // plotters types linear and log axes differently, hence four arms.
    macro_rules! draw {
        ($xr:expr, $yr:expr) => {{
            let mut chart = builder.build_cartesian_2d($xr, $yr)?;
            chart
                .configure_mesh()
                .x_desc(&panel.x_label)
                .y_desc(&panel.y_label)
                .label_style(("sans-serif", 13))
                .axis_desc_style(("sans-serif", 15))
                .x_label_formatter(&|v| tick(panel.x_scale, *v))
                .y_label_formatter(&|v| tick(panel.y_scale, *v))
                .draw()?;
            for (k, s) in panel.series.iter().enumerate() {
                let color = PALETTE[k % PALETTE.len()];
                let points: Vec<_> = s
                    .points
                    .iter()
                    .copied()
                    .filter(|&p| usable(p, panel.x_scale, panel.y_scale))
                    .collect();
                chart
                    .draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))?
                    .label(&s.label)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                    });
                if !style.lines_only {
                    chart.draw_series(
                        points
                            .into_iter()
                            .map(|p| Circle::new(p, 3, color.filled())),
                    )?;
                }
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 13))
                .position(legend)
                .draw()?;
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

fn tick(scale: Scale, v: f64) -> String {
    if scale == Scale::Linear {
        format_linear_tick(v)
    } else {
        format_tick(v)
    }
}

/// Tick labels: plain numbers in a readable range, else scientific notation.
pub fn format_tick(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if (1e-2..1e4).contains(&a) {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.0e}")
    }
}

/// The corner of the plot (a third of each axis) holding the fewest data points: where
/// the legend hides the least.
fn emptiest_corner(
    points: impl Iterator<Item = (f64, f64)>,
    x: (f64, f64, Scale),
    y: (f64, f64, Scale),
) -> SeriesLabelPosition {
    let unit = |v: f64, (lo, hi, scale): (f64, f64, Scale)| match scale {
        Scale::Linear => (v - lo) / (hi - lo),
        Scale::Log => (v.ln() - lo.ln()) / (hi.ln() - lo.ln()),
    };
    let mut counts = [0usize; 4]; // upper left, upper right, lower left, lower right
    for (px, py) in points {
        let (u, v) = (unit(px, x), unit(py, y));
        let corner = match (u < 1.0 / 3.0, u > 2.0 / 3.0, v > 2.0 / 3.0, v < 1.0 / 3.0) {
            (true, _, true, _) => 0,
            (_, true, true, _) => 1,
            (true, _, _, true) => 2,
            (_, true, _, true) => 3,
            _ => continue,
        };
        counts[corner] += 1;
    }
    match (0..4).min_by_key(|&k| counts[k]).unwrap_or(0) {
        0 => SeriesLabelPosition::UpperLeft,
        1 => SeriesLabelPosition::UpperRight,
        2 => SeriesLabelPosition::LowerLeft,
        _ => SeriesLabelPosition::LowerRight,
    }
}

/// Tick labels on a linear axis: as [`format_tick`], but rounding noise around zero
/// (`-2e-16` for a tick meant to be 0) prints as `0`.
pub fn format_linear_tick(v: f64) -> String {
    if v.abs() < 1e-12 {
        "0".into()
    } else {
        format_tick(v)
    }
}

/// Encodes an RGB8 buffer as PNG, with the library's one encoder
/// ([`raylemma::spectral::display::encode_png`]).
pub fn encode_png(width: u32, height: u32, rgb: Vec<u8>) -> Result<Vec<u8>, BoxError> {
    Ok(raylemma::spectral::display::encode_png(
        width, height, &rgb,
    )?)
}

/// One panel of a scatter plot.
#[derive(Clone, Debug)]
pub struct ScatterPanel {
    /// Title above the panel.
    pub title: String,
    /// X axis label.
    pub x_label: String,
    /// Y axis label.
    pub y_label: String,
    /// X range.
    pub x_range: (f64, f64),
    /// Y range.
    pub y_range: (f64, f64),
    /// The points.
    pub points: Vec<(f64, f64)>,
}

/// Draws scatter `panels` in a grid of `columns` columns into a PNG and returns its bytes.
pub fn scatter_png(
    panels: &[ScatterPanel],
    columns: usize,
    width: u32,
    height: u32,
) -> Result<Vec<u8>, BoxError> {
    draw_png(width, height, |root| {
        let rows = panels.len().div_ceil(columns.max(1));
        let areas = root.split_evenly((rows, columns.max(1)));
        for (panel, area) in panels.iter().zip(areas.iter()) {
            let mut chart = ChartBuilder::on(area)
                .caption(&panel.title, ("sans-serif", 16))
                .margin(10)
                .x_label_area_size(35)
                .y_label_area_size(50)
                .build_cartesian_2d(
                    panel.x_range.0..panel.x_range.1,
                    panel.y_range.0..panel.y_range.1,
                )?;
            chart
                .configure_mesh()
                .disable_mesh()
                .x_desc(&panel.x_label)
                .y_desc(&panel.y_label)
                .label_style(("sans-serif", 12))
                .axis_desc_style(("sans-serif", 13))
                .x_label_formatter(&|v| format_linear_tick(*v))
                .y_label_formatter(&|v| format_linear_tick(*v))
                .draw()?;
            chart.draw_series(
                panel
                    .points
                    .iter()
                    .map(|&p| Circle::new(p, 1, PALETTE[0].filled())),
            )?;
        }
        Ok(())
    })
}
