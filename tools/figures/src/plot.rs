//! Plotting helpers for the book's figures: charts as SVG, pictures made of pixels as PNG.
//!
//! **Charts** (line charts, scatter plots, histograms) are drawn with plotters' SVG backend:
//! [`chart`] lays out [`Panel`]s, two at most across, each series a line, markers, bars or
//! dots ([`Mark`]); [`svg`] is the frame for a chart drawn by hand. **Pictures** (hit maps,
//! colour strips, swatches) are PNG ([`draw_png`], [`encode_png`]).
//!
//! *Sizes.* The book's column is about 750 CSS px wide and an SVG is scaled to it, so every
//! chart is [`WIDTH`] = 800 units wide and its text is sized in those units (the `px`
//! arguments of [`font`]): tick labels and legends [`TICK_PX`] = 14.5, 13.6 CSS px in the
//! column; axis titles [`LABEL_PX`], panel titles [`TITLE_PX`]. The browser test checks
//! every text of every SVG at its displayed size (`tools/browser/check.mjs`).
//!
//! *Text.* Layout (legend boxes, wrapping of titles) measures text with DejaVu Sans embedded
//! in the binary (`assets/fonts/`, Bitstream Vera licence), registered with plotters'
//! `ab_glyph` backend, so figures come out the same on a machine with no system fonts. The
//! SVG embeds no font: it names the family list [`FAMILY`], which browsers resolve; the PNG
//! pictures are drawn with the embedded font.
//!
//! *Colour.* The Okabe-Ito palette ([`PALETTE`]), and for each series also a dash pattern
//! and a marker shape of its own, so that series stay apart without colour (in grey, or for
//! a colour-blind reader). Every figure is drawn on a white card with dark text: it reads the
//! same on mdBook's light and dark themes.

use std::error::Error;
use std::sync::Once;

use plotters::coord::Shift;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontStyle, register_font};
use plotters_backend::{BackendCoord, DrawingErrorKind};

/// A boxed error, for figure code.
pub type BoxError = Box<dyn Error + Send + Sync>;

static FONT: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

/// The font family the SVG names: the embedded font first (most Linux machines have it),
/// then fonts of similar width that Windows and macOS have.
pub const FAMILY: &str = "DejaVu Sans, Verdana, Arial, sans-serif";

/// Width of every chart, in SVG units (CSS px before the book scales it to its column).
pub const WIDTH: u32 = 800;
/// Tick labels, legends and notes.
pub const TICK_PX: f64 = 14.5;
/// Axis titles.
pub const LABEL_PX: f64 = 16.0;
/// Panel titles.
pub const TITLE_PX: f64 = 16.5;

/// plotters' SVG backend writes `font-size` as a text style's size / 1.24 (its size is a
/// line height, the SVG's an em).
const SIZE_PER_PX: f64 = 1.24;

/// Registers the embedded font under [`FAMILY`], and under `sans-serif` for the PNG
/// pictures that name that family (once per process).
pub fn register_embedded_font() {
    REGISTER.call_once(|| {
        // The font is a fixed, known-good file; failure here is a build defect.
        for family in [FAMILY, "sans-serif"] {
            register_font(family, FontStyle::Normal, FONT)
                .unwrap_or_else(|_| panic!("embedded DejaVuSans.ttf failed to load"));
        }
    });
}

/// The figures' font at `px` SVG units (in a PNG: about `px` pixels to the em).
pub fn font(px: f64) -> FontDesc<'static> {
    FontDesc::new(
        FontFamily::Name(FAMILY),
        px * SIZE_PER_PX,
        FontStyle::Normal,
    )
}

/// Width of `text` in [`font`]`(px)`, in SVG units (DejaVu's advance widths, slightly
/// more than a browser's with the same font: boxes sized by it do not clip).
fn text_width(text: &str, px: f64) -> i32 {
    register_embedded_font();
    font(px).box_size(text).map_or(0, |(w, _)| w as i32)
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

/// Dash patterns of the series, in order (on, off, ... in SVG units; empty: solid).
const DASHES: [&[f64]; 6] = [
    &[],
    &[10.0, 5.0],
    &[2.5, 3.5],
    &[12.0, 4.0, 2.5, 4.0],
    &[20.0, 6.0],
    &[6.0, 3.0, 2.0, 3.0, 2.0, 3.0],
];

/// Marker shapes of the series, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shape {
    Circle,
    Square,
    Triangle,
    Diamond,
    Cross,
    Ring,
}

const SHAPES: [Shape; 6] = [
    Shape::Circle,
    Shape::Square,
    Shape::Triangle,
    Shape::Diamond,
    Shape::Cross,
    Shape::Ring,
];

/// The colour, dash pattern and marker of the `k`-th series of a panel.
fn look(k: usize) -> (RGBColor, &'static [f64], Shape) {
    (
        PALETTE[k % PALETTE.len()],
        DASHES[k % DASHES.len()],
        SHAPES[k % SHAPES.len()],
    )
}

/// Stroke width of the series' lines.
const LINE_WIDTH: u32 = 2;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mark {
    /// A line through the points, in the series' dash pattern: curves.
    Line,
    /// A marker at each point: a few measurements.
    Points,
    /// A line and a marker at each point: a few measurements in order.
    LinePoints,
    /// Bars: the points are the corners of a step outline (see [`Series::bars`]), filled
    /// down to the bottom of the panel.
    Bars,
    /// A small dot at each point: a scatter plot of many points.
    Dots,
}

/// One named series of a panel. A point that cannot be drawn (not finite, or not positive
/// on a log axis) breaks a line: a `NaN` point separates the pieces of one series.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend label; an empty label is left out of the legend.
    pub label: String,
    /// Points `(x, y)`.
    pub points: Vec<(f64, f64)>,
    /// How it is drawn.
    pub mark: Mark,
}

impl Series {
    fn new(label: impl Into<String>, points: Vec<(f64, f64)>, mark: Mark) -> Self {
        Series {
            label: label.into(),
            points,
            mark,
        }
    }

    /// A curve: a line, no markers.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Mark::Line)
    }

    /// Measured points: markers only.
    pub fn points(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Mark::Points)
    }

    /// A few measured points in order: a line and markers.
    pub fn measured(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Mark::LinePoints)
    }

    /// A histogram: bar `i` spans `edges[i]..edges[i + 1]` with height `heights[i]`.
    pub fn bars(label: impl Into<String>, edges: &[f64], heights: &[f64]) -> Self {
        Self::new(label, steps(edges, heights), Mark::Bars)
    }

    /// A scatter plot.
    pub fn dots(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Mark::Dots)
    }
}

/// The outline of a histogram: for each bar its two top corners.
pub fn steps(edges: &[f64], heights: &[f64]) -> Vec<(f64, f64)> {
    edges
        .windows(2)
        .zip(heights)
        .flat_map(|(e, &h)| [(e[0], h), (e[1], h)])
        .collect()
}

/// Axis scale.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    /// Linear.
    Linear,
    /// Base-10 logarithmic.
    Log,
}

/// Where a panel's legend goes when it is not the emptiest corner of the panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Legend {
    /// Top right.
    UpperRight,
    /// Bottom right.
    LowerRight,
    /// Top left.
    UpperLeft,
    /// Bottom left.
    LowerLeft,
    /// Below the panel, outside it (the panel's cell grows to hold it).
    Below,
}

/// One panel of a chart.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Title above the panel (wrapped onto two lines when it is too long for one).
    pub title: String,
    /// X axis label.
    pub x_label: String,
    /// Y axis label.
    pub y_label: String,
    /// X scale.
    pub x_scale: Scale,
    /// Y scale.
    pub y_scale: Scale,
    /// The series.
    pub series: Vec<Series>,
    /// A fixed x range instead of one fitted to the data.
    pub x_range: Option<(f64, f64)>,
    /// A fixed y range instead of one fitted to the data (a fitted linear range starts at
    /// 0: give one for curves whose variation is a few percent of their value).
    pub y_range: Option<(f64, f64)>,
    /// A fixed legend position instead of the emptiest corner.
    pub legend: Option<Legend>,
}

impl Panel {
    /// A panel with linear axes fitted to the data.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
        series: Vec<Series>,
    ) -> Self {
        Panel {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series,
            x_range: None,
            y_range: None,
            legend: None,
        }
    }

    /// A logarithmic x axis.
    pub fn log_x(mut self) -> Self {
        self.x_scale = Scale::Log;
        self
    }

    /// A logarithmic y axis.
    pub fn log_y(mut self) -> Self {
        self.y_scale = Scale::Log;
        self
    }

    /// A fixed x range.
    pub fn x_range(mut self, range: (f64, f64)) -> Self {
        self.x_range = Some(range);
        self
    }

    /// A fixed y range.
    pub fn y_range(mut self, range: (f64, f64)) -> Self {
        self.y_range = Some(range);
        self
    }

    /// A fixed legend position.
    pub fn legend(mut self, at: Legend) -> Self {
        self.legend = Some(at);
        self
    }

    fn usable(&self, p: (f64, f64)) -> bool {
        p.0.is_finite()
            && p.1.is_finite()
            && (self.x_scale == Scale::Linear || p.0 > 0.0)
            && (self.y_scale == Scale::Linear || p.1 > 0.0)
    }

    /// The legend's entries: label and series index, empty labels left out.
    fn keys(&self) -> Vec<Key> {
        self.series
            .iter()
            .enumerate()
            .filter(|(_, s)| !s.label.is_empty())
            .map(|(k, s)| Key {
                label: s.label.clone(),
                index: k,
                mark: s.mark,
            })
            .collect()
    }
}

/// One legend entry.
#[derive(Clone, Debug, PartialEq)]
struct Key {
    label: String,
    index: usize,
    mark: Mark,
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

/// A drawing area of an SVG chart.
pub type SvgArea<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// SVG elements written as text, for what plotters' backend has no call for (many dots as
/// one path); [`svg`] puts them after plotters' drawing.
#[derive(Default)]
pub struct Overlay(Vec<String>);

impl Overlay {
    /// Dots of diameter `size` at the backend coordinates `at`, in `colour`: one path of
    /// zero-length round-capped segments (a tenth of the size of a circle per point).
    pub fn dots(&mut self, at: &[BackendCoord], size: f64, colour: RGBColor) {
        let mut d = String::new();
        for (x, y) in at {
            d.push_str(&format!("M{x} {y}h0"));
        }
        let RGBColor(r, g, b) = colour;
        self.0.push(format!(
            "<path d=\"{d}\" fill=\"none\" stroke=\"#{r:02X}{g:02X}{b:02X}\" stroke-width=\"{size}\" stroke-linecap=\"round\"/>\n"
        ));
    }
}

/// A white `width x height` SVG, handed to `draw` (with an [`Overlay`] for elements written
/// as text): the frame of every chart. Returns the SVG's bytes.
pub fn svg(
    width: u32,
    height: u32,
    draw: impl FnOnce(&SvgArea<'_>, &mut Overlay) -> Result<(), BoxError>,
) -> Result<Vec<u8>, BoxError> {
    register_embedded_font();
    let mut text = String::new();
    let mut overlay = Overlay::default();
    {
        let root = SVGBackend::with_string(&mut text, (width, height)).into_drawing_area();
        root.fill(&WHITE)?;
        draw(&root, &mut overlay)?;
        root.present()?;
    }
    let end = text.rfind("</svg>").ok_or("plotters wrote no </svg>")?;
    text.insert_str(end, &overlay.0.concat());
    // Opacity 1 is SVG's default: a tenth of the file on dense charts.
    Ok(text.replace(" opacity=\"1\"", "").into_bytes())
}

/// A white `width x height` bitmap, handed to `draw` and then encoded as a PNG: the frame
/// of the pictures made of pixels (the embedded font is registered first).
pub fn draw_png(
    width: u32,
    height: u32,
    draw: impl FnOnce(&DrawingArea<BitMapBackend<'_>, Shift>) -> Result<(), BoxError>,
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

/// Encodes an RGB8 buffer as PNG, with the library's one encoder
/// ([`raylemma::spectral::display::encode_png`]).
pub fn encode_png(width: u32, height: u32, rgb: Vec<u8>) -> Result<Vec<u8>, BoxError> {
    Ok(raylemma::spectral::display::encode_png(
        width, height, &rgb,
    )?)
}

// ---------------------------------------------------------------------------------------
// Layout.

/// Height of a panel: alone, stacked in one column, or two across.
fn panel_height(columns: usize, panels: usize) -> u32 {
    match (columns, panels) {
        (1, 1) => 440,
        (1, _) => 330,
        _ => 360,
    }
}

/// Height of one legend row, in SVG units.
const LEGEND_ROW: i32 = 22;
/// Length of a legend's line sample.
const SAMPLE: i32 = 36;

/// `panels` as one SVG [`WIDTH`] units wide, in `columns` columns (1 or 2), and returns
/// its bytes. When the panels have the same series (same labels in the same order) they
/// share one legend, in the grid's empty cell if it has one, else below the panels; else
/// each panel has its own, in its emptiest corner or where [`Panel::legend`] says.
pub fn chart(panels: &[Panel], columns: usize) -> Result<Vec<u8>, BoxError> {
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
pub fn ranged_chart(panels: &[RangedPanel]) -> Result<Vec<u8>, BoxError> {
    let panels: Vec<Panel> = panels
        .iter()
        .map(|(p, x, y, at)| p.clone().x_range(*x).y_range(*y).legend(*at))
        .collect();
    chart(&panels, 2)
}

/// The legend entries shared by all panels, when there are two or more panels and they
/// have the same entries.
fn shared_keys(panels: &[Panel]) -> Option<Vec<Key>> {
    let first = panels.first()?.keys();
    (panels.len() > 1 && !first.is_empty() && panels.iter().all(|p| p.keys() == first))
        .then_some(first)
}

/// Width of a legend entry: sample, gap, label.
fn key_width(key: &Key) -> i32 {
    SAMPLE + 8 + text_width(&key.label, TICK_PX)
}

/// `keys` flowed into rows no wider than `width`.
fn legend_rows(keys: &[Key], width: i32) -> Vec<Vec<Key>> {
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
fn legend_box_size(keys: &[Key]) -> (i32, i32) {
    let w = keys.iter().map(key_width).max().unwrap_or(0);
    (w + 16, keys.len() as i32 * LEGEND_ROW + 10)
}

/// A legend box with its top left corner at `at` (pixels of `area`): white, thin border.
fn draw_legend_box<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    keys: &[Key],
    at: (i32, i32),
) -> Result<(), BoxError>
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
fn draw_legend_strip<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    keys: &[Key],
) -> Result<(), BoxError>
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
) -> Result<(), BoxError>
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

/// The fill and outline of bars in `colour`: the fill a third as saturated.
fn bar_colours(colour: RGBColor) -> (RGBColor, RGBColor) {
    let RGBColor(r, g, b) = colour;
    let light = |c: u8| ((u16::from(c) + 2 * 255) / 3) as u8;
    (RGBColor(light(r), light(g), light(b)), colour)
}

/// `text` broken at spaces into lines no wider than `width` at `px`.
fn wrap(text: &str, px: f64, width: i32) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if text_width(&format!("{line} {word}"), px) <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// Draws `title` centred at the top of `area`, wrapped to its width, and returns the rest
/// of the area.
pub fn draw_title<'a>(area: &SvgArea<'a>, title: &str) -> Result<SvgArea<'a>, BoxError> {
    let (width, _) = area.dim_in_pixel();
    let lines = wrap(title, TITLE_PX, width as i32 - 16);
    let line = (TITLE_PX * 1.25) as i32;
    for (k, text) in lines.iter().enumerate() {
        area.draw(&Text::new(
            text.clone(),
            (width as i32 / 2, 6 + k as i32 * line),
            font(TITLE_PX)
                .color(&BLACK)
                .pos(Pos::new(HPos::Center, VPos::Top)),
        ))?;
    }
    let used = 10 + lines.len() as i32 * line;
    Ok(area.split_vertically(used).1)
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

/// Tick labels on a linear axis: as [`format_tick`], but rounding noise around zero
/// (`-2e-16` for a tick meant to be 0) prints as `0`.
pub fn format_linear_tick(v: f64) -> String {
    if v.abs() < 1e-12 {
        "0".into()
    } else {
        format_tick(v)
    }
}

fn tick(scale: Scale, v: f64) -> String {
    if scale == Scale::Linear {
        format_linear_tick(v)
    } else {
        format_tick(v)
    }
}

/// Space for the x axis's tick labels and title, and the y axis's.
const X_AXIS: u32 = 50;
const Y_AXIS: u32 = 80;

/// A chart builder on `area` with the book's axis areas and margins.
pub fn builder<'a, 'b>(area: &'a SvgArea<'b>) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
    let mut b = ChartBuilder::on(area);
    b.margin(10)
        .margin_right(16)
        .x_label_area_size(X_AXIS)
        .y_label_area_size(Y_AXIS);
    b
}

/// The book's grid and axes on `chart`: thin light grid lines, tick labels at [`TICK_PX`],
/// axis titles at [`LABEL_PX`], as many ticks as fit the panel's width.
macro_rules! mesh {
    ($chart:expr, $x_label:expr, $y_label:expr, $xf:expr, $yf:expr) => {{
        let (w, _) = $chart.plotting_area().dim_in_pixel();
        $chart
            .configure_mesh()
            .x_desc($x_label)
            .y_desc($y_label)
            .x_labels(if w < 450 { 5 } else { 9 })
            .y_labels(6)
            .bold_line_style(BLACK.mix(0.12).stroke_width(1))
            .light_line_style(TRANSPARENT)
            .axis_style(BLACK.mix(0.7).stroke_width(1))
            .label_style($crate::plot::font($crate::plot::TICK_PX))
            .axis_desc_style($crate::plot::font($crate::plot::LABEL_PX))
            .x_label_formatter($xf)
            .y_label_formatter($yf)
            .draw()?;
    }};
}
pub(crate) use mesh;

/// Draws `panel` on `area`, with its own legend when `own_legend`: where
/// [`Panel::legend`] says, [`Legend::Below`] in the bottom `legend_below` units of `area`.
fn draw_panel(
    panel: &Panel,
    area: &SvgArea<'_>,
    own_legend: bool,
    legend_below: i32,
    overlay: &mut Overlay,
) -> Result<(), BoxError> {
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

/// The corner of the plot (a third of each axis) holding the fewest data points: where
/// the legend hides the least.
fn emptiest_corner(
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

// ---------------------------------------------------------------------------------------
// Elements.

/// A polyline in a dash pattern (empty: solid). Dashes run on across the points, so a
/// dense curve is dashed like a straight line.
pub struct Styled<Coord> {
    points: Vec<Coord>,
    colour: RGBColor,
    dash: &'static [f64],
}

impl<Coord> Styled<Coord> {
    fn line(points: Vec<Coord>, colour: RGBColor, dash: &'static [f64]) -> Self {
        Styled {
            points,
            colour,
            dash,
        }
    }
}

impl<'a, Coord> PointCollection<'a, Coord> for &'a Styled<Coord> {
    type Point = &'a Coord;
    type IntoIter = &'a [Coord];
    fn point_iter(self) -> &'a [Coord] {
        &self.points
    }
}

impl<Coord, DB: DrawingBackend> Drawable<DB> for Styled<Coord> {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        points: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let style = self.colour.stroke_width(LINE_WIDTH);
        let mut points: Vec<BackendCoord> = points.collect();
        points.dedup();
        if self.dash.is_empty() {
            return backend.draw_path(points, &style);
        }
        let f = |p: BackendCoord| (f64::from(p.0), f64::from(p.1));
        let round = |(x, y): (f64, f64)| (x.round() as i32, y.round() as i32);
        // `k`: the pattern's current entry (even: on); `left`: what remains of it.
        let (mut k, mut left) = (0, self.dash[0]);
        let mut dash = vec![points[0]];
        for w in points.windows(2) {
            let (mut a, b) = (f(w[0]), f(w[1]));
            let mut seg = (b.0 - a.0).hypot(b.1 - a.1);
            while seg > left {
                let t = left / seg;
                a = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
                seg -= left;
                if k % 2 == 0 {
                    dash.push(round(a));
                    backend.draw_path(std::mem::take(&mut dash), &style)?;
                } else {
                    dash = vec![round(a)];
                }
                k = (k + 1) % self.dash.len();
                left = self.dash[k];
            }
            left -= seg;
            if k % 2 == 0 {
                dash.push(w[1]);
            }
        }
        if k % 2 == 0 && dash.len() > 1 {
            backend.draw_path(dash, &style)?;
        }
        Ok(())
    }
}

/// A marker of one of the six shapes, `size` units from its centre to its edge.
pub struct Marker<Coord> {
    at: Coord,
    shape: Shape,
    colour: RGBColor,
    size: i32,
}

impl<Coord> Marker<Coord> {
    fn new(at: Coord, shape: Shape, colour: RGBColor, size: i32) -> Self {
        Marker {
            at,
            shape,
            colour,
            size,
        }
    }
}

impl<'a, Coord> PointCollection<'a, Coord> for &'a Marker<Coord> {
    type Point = &'a Coord;
    type IntoIter = std::iter::Once<&'a Coord>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<Coord, DB: DrawingBackend> Drawable<DB> for Marker<Coord> {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        mut points: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let Some((x, y)) = points.next() else {
            return Ok(());
        };
        let (s, fill, line) = (self.size, self.colour.filled(), self.colour.stroke_width(2));
        match self.shape {
            Shape::Circle => backend.draw_circle((x, y), s as u32, &fill, true),
            Shape::Ring => backend.draw_circle((x, y), s as u32, &line, false),
            Shape::Square => backend.draw_rect((x - s, y - s), (x + s, y + s), &fill, true),
            Shape::Triangle => backend.fill_polygon(
                [(x, y - s - 1), (x + s + 1, y + s), (x - s - 1, y + s)],
                &fill,
            ),
            Shape::Diamond => backend.fill_polygon(
                [
                    (x, y - s - 1),
                    (x + s + 1, y),
                    (x, y + s + 1),
                    (x - s - 1, y),
                ],
                &fill,
            ),
            Shape::Cross => {
                backend.draw_line((x - s, y - s), (x + s, y + s), &line)?;
                backend.draw_line((x - s, y + s), (x + s, y - s), &line)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn dashes_run_on_across_points() {
        // A dashed line along x from 0 to 40 drawn through points 1 apart has the dashes of
        // the same line through its two ends: on 0-10, 15-25, 30-40.
        let mut lines = Vec::new();
        for points in [vec![(0, 0), (40, 0)], (0..=40).map(|x| (x, 0)).collect()] {
            let svg = String::from_utf8(
                svg(50, 10, |root, _| {
                    root.draw(&Styled::line(points, PALETTE[0], DASHES[1]))?;
                    Ok(())
                })
                .unwrap(),
            )
            .unwrap();
            let ends: Vec<String> = svg
                .split("points=\"")
                .skip(1)
                .map(|s| {
                    let p: Vec<&str> = s[..s.find('"').unwrap()].split_whitespace().collect();
                    format!("{}-{}", p[0], p[p.len() - 1])
                })
                .collect();
            lines.push(ends);
        }
        assert_eq!(lines[0], ["0,0-10,0", "15,0-25,0", "30,0-40,0"]);
        assert_eq!(lines[0], lines[1]);
    }
}
