//! The diagram of where each wavelength strategy puts its lanes (`diagram_hero_lanes.svg`), of
//! the chapter *Wavelength sampling and hero wavelengths* (`chapters/spectral/wavelength.md`).

use super::geometry::{V, v};
use super::style::{
    Anchor, BLUE, Font, GREEN, GREY, HEAD, INK, LABEL, NOTE, Pen, SMALL, VERMILION, font,
};
use super::svg::Svg;
use crate::{Record, Settings};
use raylemma::spectral::wavelength::{self, N, WavelengthStrategy};
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN, cie};

/// The uniform number every row of the lanes diagram is drawn with.
const LANES_U: f64 = 0.3;

/// What each lane of a strategy is weighted by, in the chapter's notation.
fn lane_weights(s: WavelengthStrategy) -> &'static str {
    match s {
        WavelengthStrategy::Uniform => "one lane, *p* = 1/470",
        WavelengthStrategy::Visible => "one lane, *p*(*λ*₀)",
        WavelengthStrategy::HeroUniform => "each *p*_*j* = 1/470",
        WavelengthStrategy::HeroVisible => "each *p*_*j* = *p*(*λ*_*j*)",
        WavelengthStrategy::HeroBalance => "each *p*_*j* = Σ_*k* *p*(*λ*_*k*) / *N*",
        WavelengthStrategy::SeedBand => "each *p*_*j* = 1/400, 5 nm apart",
    }
}

pub(super) fn hero_lanes(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let rows = WavelengthStrategy::ALL.len();
    let row_gap = 44.0;
    let first_row = 262.0;
    let mut d = Svg::new(first_row + row_gap * (rows as f64 - 1.0) + 62.0);
    let (x0, x1) = (40.0, 610.0);
    let x = |nm: f64| x0 + (nm - LAMBDA_MIN) / (LAMBDA_MAX - LAMBDA_MIN) * (x1 - x0);
    let (base, top) = (200.0, 44.0);
    let y = |value: f64| base - value / 1.8 * (base - top);

    // The colour-matching functions and the visible pdf, over 360-830 nm.
    let last_row = first_row + row_gap * (rows as f64 - 1.0);
    for nm in [400.0, 500.0, 600.0, 700.0, 800.0] {
        d.line(
            v(x(nm), top),
            v(x(nm), last_row + 10.0),
            Pen::new(INK, 1.0).faded(0.12),
        );
        d.line(v(x(nm), base), v(x(nm), base + 5.0), Pen::new(GREY, 1.0));
        let label = if nm == 800.0 {
            "800 nm".to_string()
        } else {
            format!("{nm}")
        };
        d.text(v(x(nm), base + 17.0), &label, font(SMALL).colour(GREY));
    }
    d.line(v(x0, base), v(x1, base), Pen::new(GREY, 1.0));
    let nms: Vec<f64> = (0..=470).map(|k| LAMBDA_MIN + f64::from(k)).collect();
    let peak = wavelength::visible_pdf(wavelength::VISIBLE_C) / 1.3;
    let pdf: Vec<V> = nms
        .iter()
        .map(|&nm| v(x(nm), y(wavelength::visible_pdf(nm) / peak)))
        .collect();
    d.polyline(&pdf, Pen::new(GREY, 1.5).dashed());
    let curves = [
        (0, VERMILION, "*x̄*", v(630.0, 1.04), Anchor::Start),
        (1, GREEN, "*ȳ*", v(528.0, 1.0), Anchor::End),
        (2, BLUE, "*z̄*", v(462.0, 1.74), Anchor::Start),
    ];
    for (k, colour, name, at, anchor) in curves {
        let pts: Vec<V> = nms.iter().map(|&nm| v(x(nm), y(cie::cmf(nm)[k]))).collect();
        d.polyline(&pts, Pen::new(colour, 2.0));
        let f = Font {
            anchor,
            ..font(LABEL).colour(colour)
        };
        d.text(v(x(at.x), y(at.y)), name, f);
    }
    d.text(
        v(x1, y(0.82)),
        "*p*(*λ*): the visible pdf, scaled",
        font(NOTE).colour(GREY).end(),
    );
    d.text(
        v(x0, 22.0),
        "the colour-matching functions",
        font(HEAD).start(),
    );

    // One row per strategy: the lanes of one sample.
    for (row, &s) in WavelengthStrategy::ALL.iter().enumerate() {
        let yr = first_row + row_gap * row as f64;
        d.text(v(x0, yr - 15.0), s.name(), font(NOTE).start());
        d.text(
            v(x1, yr - 15.0),
            lane_weights(s),
            font(NOTE).colour(GREY).end(),
        );
        let (lo, hi) = if s == WavelengthStrategy::SeedBand {
            let band = wavelength::SEED_BAND;
            (band.lo, band.hi + (N as f64 - 1.0) * band.spacing)
        } else {
            (LAMBDA_MIN, LAMBDA_MAX)
        };
        d.line(v(x(lo), yr), v(x(hi), yr), Pen::new(GREY, 1.5));
        for end in [lo, hi] {
            d.line(
                v(x(end), yr - 5.0),
                v(x(end), yr + 5.0),
                Pen::new(GREY, 1.5),
            );
        }
        let w = s.sample(LANES_U);
        for j in (1..N).rev() {
            if w.pdf[j] > 0.0 {
                d.circle(
                    v(x(w.lambda[j]), yr),
                    5.0,
                    Some("#FFFFFF"),
                    Some(Pen::new(BLUE, 2.0)),
                );
            }
        }
        d.circle(v(x(w.lambda[0]), yr), 5.5, Some(BLUE), None);
    }

    // The key.
    let yk = last_row + 40.0;
    d.circle(v(x0 + 6.0, yk), 5.5, Some(BLUE), None);
    d.text(v(x0 + 18.0, yk), "the hero *λ*₀", font(NOTE).start());
    d.circle(
        v(x0 + 128.0, yk),
        5.0,
        Some("#FFFFFF"),
        Some(Pen::new(BLUE, 2.0)),
    );
    d.text(v(x0 + 140.0, yk), "the other lanes", font(NOTE).start());
    d.text(
        v(x1, yk),
        &format!("*N* = {N}, one sample at *u* = {LANES_U} in every row"),
        font(NOTE).colour(GREY).end(),
    );
    Ok(d.finish(
        "The CIE colour-matching functions over 360–830 nm with the visible pdf, and below them, for each wavelength strategy, where the lanes of one sample fall: one uniform wavelength, one from the visible pdf, hero wavelengths uniform, rotated in sample space through the visible pdf, rotated in wavelength space (the balance heuristic over the rotations of the pdf), and the source notes' band.",
        "Top: the CIE 1931 colour-matching functions x̄, ȳ, z̄ and the visible-range pdf p(λ) (scaled to the height of ȳ), over the sampled range 360–830 nm. Below: the wavelengths of one path, drawn by the library's samplers at the same uniform number u = 0.3, one row per strategy, the hero lane filled and the others hollow, with the density each lane is weighted by. A single wavelength has one live lane; uniform hero lanes are equally spaced over the range; rotated in sample space through the visible pdf they crowd where the pdf is large; rotated in wavelength space the lanes are equally spaced in wavelength from a hero drawn from the pdf; the source notes' four lanes lie within 15 nm of each other, from a first lane drawn on 380–780 nm.",
    ))
}
