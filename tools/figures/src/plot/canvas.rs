//! The surfaces drawn on: an SVG for a chart drawn by hand ([`svg`], with an [`Overlay`]
//! for elements written as text) and a PNG for pictures made of pixels ([`draw_png`],
//! [`encode_png`]).

use anyhow::Context;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters_backend::BackendCoord;

use super::text::register_embedded_font;

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
    draw: impl FnOnce(&SvgArea<'_>, &mut Overlay) -> anyhow::Result<()>,
) -> anyhow::Result<Vec<u8>> {
    register_embedded_font();
    let mut text = String::new();
    let mut overlay = Overlay::default();
    {
        let root = SVGBackend::with_string(&mut text, (width, height)).into_drawing_area();
        root.fill(&WHITE)?;
        draw(&root, &mut overlay)?;
        root.present()?;
    }
    let end = text.rfind("</svg>").context("plotters wrote no </svg>")?;
    text.insert_str(end, &overlay.0.concat());
    // Opacity 1 is SVG's default: a tenth of the file on dense charts.
    Ok(text.replace(" opacity=\"1\"", "").into_bytes())
}

/// A white `width x height` bitmap, handed to `draw` and then encoded as a PNG: the frame
/// of the pictures made of pixels (the embedded font is registered first).
pub fn draw_png(
    width: u32,
    height: u32,
    draw: impl FnOnce(&DrawingArea<BitMapBackend<'_>, Shift>) -> anyhow::Result<()>,
) -> anyhow::Result<Vec<u8>> {
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
/// ([`raylemma::image::png::encode_png`]).
pub fn encode_png(width: u32, height: u32, rgb: Vec<u8>) -> anyhow::Result<Vec<u8>> {
    Ok(raylemma::image::png::encode_png(width, height, &rgb)?)
}
