//! The charts' text: the embedded font and the family list the SVG names, the sizes of
//! tick labels, axis titles and panel titles, and text measured, wrapped and set as a title.

use std::sync::Once;

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontStyle, register_font};

use super::canvas::SvgArea;

static FONT: &[u8] = include_bytes!("../../../../assets/fonts/DejaVuSans.ttf");

static REGISTER: Once = Once::new();

/// The font family the SVG names: the embedded font first (most Linux machines have it),
/// then fonts of similar width that Windows and macOS have.
pub const FAMILY: &str = "DejaVu Sans, Verdana, Arial, sans-serif";

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
pub(super) fn text_width(text: &str, px: f64) -> i32 {
    register_embedded_font();
    font(px).box_size(text).map_or(0, |(w, _)| w as i32)
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
pub fn draw_title<'a>(area: &SvgArea<'a>, title: &str) -> anyhow::Result<SvgArea<'a>> {
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
