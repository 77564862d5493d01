//! How a series looks: its colour of the Okabe-Ito palette, its dash pattern and its marker
//! shape, one look per series of a panel; and the fill and edge of bars.

use plotters::prelude::*;

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
pub(super) const DASHES: [&[f64]; 6] = [
    &[],
    &[10.0, 5.0],
    &[2.5, 3.5],
    &[12.0, 4.0, 2.5, 4.0],
    &[20.0, 6.0],
    &[6.0, 3.0, 2.0, 3.0, 2.0, 3.0],
];

/// Marker shapes of the series, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Shape {
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
pub(super) fn look(k: usize) -> (RGBColor, &'static [f64], Shape) {
    (
        PALETTE[k % PALETTE.len()],
        DASHES[k % DASHES.len()],
        SHAPES[k % SHAPES.len()],
    )
}

/// Stroke width of the series' lines.
pub(super) const LINE_WIDTH: u32 = 2;

/// The fill and outline of bars in `colour`: the fill a third as saturated.
pub(super) fn bar_colours(colour: RGBColor) -> (RGBColor, RGBColor) {
    let RGBColor(r, g, b) = colour;
    let light = |c: u8| ((u16::from(c) + 2 * 255) / 3) as u8;
    (RGBColor(light(r), light(g), light(b)), colour)
}
