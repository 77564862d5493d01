//! The diagrams' look: the sizes of their text, their colours (the charts' Okabe-Ito
//! palette, by name), the pens lines are drawn with and the fonts texts are set in.

use std::fmt::Write as _;

use super::svg::num;

/// Width of every diagram, in SVG units (CSS px at the book's natural size).
pub const WIDTH: f64 = 640.0;

/// Labels of points, vectors and angles.
pub(super) const LABEL: f64 = 15.0;
/// Notes and formulas.
pub(super) const NOTE: f64 = 14.0;
/// Panel headings.
pub(super) const HEAD: f64 = 16.0;
/// Tick labels, the smallest text.
pub(super) const SMALL: f64 = 13.5;
/// The family of names from the code and the scene files.
pub(super) const MONO: &str = "DejaVu Sans Mono, Menlo, Consolas, monospace";
/// Subscripts and superscripts, as a fraction of their text's size.
pub(super) const SCRIPT: f64 = 0.8;

/// Text, and the lines of what is drawn in black.
pub(super) const INK: &str = "#000000";
/// Surfaces and construction lines: black at 0.7, as the charts' axes.
pub(super) const GREY: &str = "#4D4D4D";
/// Guides: black at 0.35.
pub(super) const FAINT: &str = "#A6A6A6";
/// The Okabe-Ito palette of `plot::PALETTE`, by name.
pub(super) const BLUE: &str = "#0072B2";
pub(super) const VERMILION: &str = "#D55E00";
pub(super) const GREEN: &str = "#009E73";
pub(super) const PURPLE: &str = "#CC79A7";
pub(super) const ORANGE: &str = "#E69F00";
pub(super) const SKY: &str = "#56B4E9";

/// A stroke: colour, width, dash pattern (empty: solid) and opacity.
#[derive(Clone, Copy, Debug)]
pub(super) struct Pen {
    pub(super) colour: &'static str,
    pub(super) width: f64,
    dash: &'static str,
    pub(super) opacity: f64,
}

impl Pen {
    pub(super) const fn new(colour: &'static str, width: f64) -> Self {
        Pen {
            colour,
            width,
            dash: "",
            opacity: 1.0,
        }
    }

    pub(super) const fn dashed(self) -> Self {
        Pen {
            dash: "7 5",
            ..self
        }
    }

    pub(super) const fn dotted(self) -> Self {
        Pen {
            dash: "0.5 4.5",
            ..self
        }
    }

    pub(super) const fn faded(self, opacity: f64) -> Self {
        Pen { opacity, ..self }
    }

    pub(super) fn attributes(&self) -> String {
        let mut a = format!(
            " fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linecap=\"round\" stroke-linejoin=\"round\"",
            self.colour,
            num(self.width)
        );
        if !self.dash.is_empty() {
            let _ = write!(a, " stroke-dasharray=\"{}\"", self.dash);
        }
        if self.opacity < 1.0 {
            let _ = write!(a, " stroke-opacity=\"{}\"", num(self.opacity));
        }
        a
    }
}

/// Where a text's position is along its line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Anchor {
    Start,
    Middle,
    End,
}

/// How a text is drawn: size, anchor, colour, and a white halo that keeps it legible over
/// lines.
#[derive(Clone, Copy, Debug)]
pub(super) struct Font {
    pub(super) size: f64,
    pub(super) anchor: Anchor,
    pub(super) colour: &'static str,
    pub(super) halo: bool,
}

pub(super) const fn font(size: f64) -> Font {
    Font {
        size,
        anchor: Anchor::Middle,
        colour: INK,
        halo: true,
    }
}

impl Font {
    pub(super) const fn start(self) -> Self {
        Font {
            anchor: Anchor::Start,
            ..self
        }
    }

    pub(super) const fn end(self) -> Self {
        Font {
            anchor: Anchor::End,
            ..self
        }
    }

    pub(super) const fn colour(self, colour: &'static str) -> Self {
        Font { colour, ..self }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::PALETTE;

    #[test]
    fn the_named_colours_are_the_charts_palette() {
        let hex: Vec<String> = PALETTE
            .iter()
            .map(|c| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2))
            .collect();
        assert_eq!(hex, [BLUE, VERMILION, GREEN, PURPLE, ORANGE, SKY]);
    }
}
