//! Plotting helpers for the book's figures: charts as SVG, pictures made of pixels as PNG.
//!
//! **Charts** (line charts, scatter plots, histograms) are drawn with plotters' SVG backend:
//! [`chart`] lays out [`Panel`]s, two at most across, each series a line, markers, bars or dots
//! ([`Mark`](series::Mark)); [`svg`] is the frame for a chart drawn by hand. **Pictures** (hit
//! maps, colour strips, swatches) are PNG ([`draw_png`], [`encode_png`]).
//!
//! *Sizes.* The book's column is about 750 CSS px wide and an SVG is scaled to it, so every
//! chart is [`WIDTH`] = 800 units wide and its text is sized in those units (the `px` arguments
//! of [`font`]): tick labels and legends [`TICK_PX`] = 14.5, 13.6 CSS px in the column; axis
//! titles [`LABEL_PX`], panel titles [`TITLE_PX`](text::TITLE_PX). The browser test checks
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
//!
//! The modules: [`text`] (the font and the text sizes), [`look`] (each series' colour, dash
//! and marker), [`series`] (panels and their series), [`layout`] (a chart of panels),
//! [`legend`], [`axes`] (ticks, the chart builder, [`mesh!`]), [`elements`] (the dashed
//! polyline and the markers plotters draws) and [`canvas`] (the SVG and PNG frames).

mod axes;
mod canvas;
mod elements;
mod layout;
mod legend;
mod look;
mod series;
mod text;

pub(crate) use axes::mesh;
pub use axes::{builder, format_linear_tick, format_tick};
pub use canvas::{draw_png, encode_png, svg};
pub use layout::{WIDTH, chart, ranged_chart};
pub use look::PALETTE;
pub use series::{Legend, Panel, Series, steps};
pub use text::{FAMILY, LABEL_PX, TICK_PX, draw_title, font, register_embedded_font};
