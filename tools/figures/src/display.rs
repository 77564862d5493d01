//! Figures and tables of the chapter *From spectrum to display*.

use std::fmt::Write as _;

use glam::DVec3;
use plotters::prelude::*;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, Legend, Panel, Series};
use raylemma::spectral::display::*;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "display_curves.svg",
            what: "sRGB curve vs gamma 2.2, and their difference in 8-bit codes",
            make: curves_svg,
        },
        Output {
            file: "display_codes.md",
            what: "largest code difference of power laws vs the sRGB curve",
            make: codes_md,
        },
        Output {
            file: "display_ramps.png",
            what: "over-exposure ramps: clipping, the source notes' desaturation, equal-luminance grey",
            make: ramps_png,
        },
        Output {
            file: "display_hue.md",
            what: "hue and luminance after clipping and the two desaturations",
            make: hue_md,
        },
        Output {
            file: "display_speed.md",
            what: "time per pixel of to_display_rgb8",
            make: speed_md,
        },
    ]
}

fn curves_svg(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    // Linear inputs spaced evenly in log from 1e-4 to 1, so that the dark end shows.
    let xs: Vec<f64> = (0..=120)
        .map(|i| 10f64.powf(-4.0 + 4.0 * f64::from(i) / 120.0))
        .collect();
    let curve = |label: &str, f: &dyn Fn(f64) -> f64| {
        Series::line(label, xs.iter().map(|&x| (x, f(x))).collect())
    };
    let encoded = Panel::new(
        "encoded value V of linear light x",
        "linear x (log scale)",
        "V",
        vec![
            curve("sRGB (IEC 61966-2-1)", &srgb_encode),
            curve("gamma 2.2: x^(1/2.2)", &|x| gamma_encode(x, 2.2)),
            curve("sqrt: x^(1/2)", &|x| gamma_encode(x, 2.0)),
        ],
    )
    .log_x();
    let difference = |hi: f64, n: u32, rounded: bool| {
        let exact = Series::line(
            "255 (x^(1/2.2) − sRGB(x))",
            (0..=n)
                .map(|i| {
                    let x = hi * f64::from(i) / f64::from(n);
                    (x, 255.0 * (gamma_encode(x, 2.2) - srgb_encode(x)))
                })
                .collect(),
        );
        let mut series = vec![exact];
        if rounded {
            series.push(Series::line(
                "both rounded to 8 bits",
                (0..=n)
                    .map(|i| {
                        let x = hi * f64::from(i) / f64::from(n);
                        (x, f64::from(gamma8(x, 2.2)) - f64::from(srgb8(x)))
                    })
                    .collect(),
            ));
        }
        series
    };
    let dark = Panel::new(
        "gamma 2.2 minus sRGB, codes, dark end",
        "linear x",
        "codes",
        difference(0.02, 2000, true),
    );
    let whole = Panel::new(
        "gamma 2.2 minus sRGB, codes, 0 ≤ x ≤ 1",
        "linear x",
        "codes",
        difference(1.0, 1000, false),
    );
    plot::chart(
        &[
            encoded,
            dark.x_range((0.0, 0.02))
                .y_range((-2.0, 14.0))
                .legend(Legend::UpperRight),
            whole
                .x_range((0.0, 1.0))
                .y_range((-2.0, 10.0))
                .legend(Legend::UpperRight),
        ],
        2,
    )
}

/// Stacks PNGs of equal width vertically.
/// An encoder of linear light to an 8-bit code.
type Encoder = fn(f64) -> u8;

/// One row of the codes table: the worst code difference of `f` against sRGB over every
/// sRGB code (decoded to linear light, then encoded by `f`).
fn worst_codes(f: impl Fn(f64) -> u8) -> (i32, Vec<u8>, i32) {
    let d: Vec<i32> = (0..=255u8)
        .map(|c| i32::from(f(srgb_decode(f64::from(c) / 255.0))) - i32::from(c))
        .collect();
    let worst = *d.iter().max_by_key(|x| x.abs()).unwrap_or(&0);
    let at = (0..=255u8).filter(|&c| d[c as usize] == worst).collect();
    let lowest = *d.iter().min().unwrap_or(&0);
    (worst, at, lowest)
}

/// The darkest codes: "the deepest shadows".
const SHADOWS: std::ops::Range<u8> = 0..32;
/// The middle half of the codes: "the mid-tones".
const MID_TONES: std::ops::Range<u8> = 64..192;

fn codes_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::new();
    writeln!(
        md,
        "| encoder | largest difference from sRGB, codes | at sRGB codes | most negative difference | codes that differ |"
    )?;
    writeln!(md, "|---|---:|---|---:|---:|")?;
    let rows: [(&str, &str, Encoder); 3] = [
        (
            "gamma_2_2",
            "gamma 2.2, x^(1/2.2) (the source notes)",
            |x| gamma8(x, 2.2),
        ),
        (
            "sqrt",
            "sqrt, x^(1/2) (the source notes' approximation)",
            |x| gamma8(x, 2.0),
        ),
        ("wrong_way", "x^2.2 (exponent the wrong way round)", |x| {
            quantise(gamma_decode(x, 2.2))
        }),
    ];
    // (worst, its codes, most negative, its codes) per encoder
    let mut found = Vec::new();
    for (key, name, f) in rows {
        let (worst, at, lowest) = worst_codes(f);
        let differ = (0..=255u8)
            .filter(|&c| f(srgb_decode(f64::from(c) / 255.0)) != c)
            .count();
        let lowest_at: Vec<u8> = (0..=255u8)
            .filter(|&c| i32::from(f(srgb_decode(f64::from(c) / 255.0))) - i32::from(c) == lowest)
            .collect();
        r.number(
            &format!("{key}.largest_difference"),
            f64::from(worst),
            "int",
        );
        r.number(
            &format!("{key}.most_negative_abs"),
            f64::from(lowest.abs()),
            "int",
        );
        r.number(
            &format!("{key}.largest_difference_abs"),
            f64::from(worst.abs()),
            "int",
        );
        if let (Some(&first), Some(&last)) = (at.first(), at.last()) {
            r.number(&format!("{key}.at_first"), f64::from(first), "int");
            r.number(&format!("{key}.at_last"), f64::from(last), "int");
        }
        let at_text: Vec<String> = at.iter().map(u8::to_string).collect();
        writeln!(
            md,
            "| {name} | {worst:+} | {} | {lowest:+} | {differ} of 256 |",
            at_text.join(", ")
        )?;
        found.push((worst, at, lowest, lowest_at));
    }
    let (gamma, sqrt) = (&found[0], &found[1]);
    let all_in = |codes: &[u8], range: &std::ops::Range<u8>| {
        !codes.is_empty() && codes.iter().all(|c| range.contains(c))
    };
    let some_in =
        |codes: &[u8], range: &std::ops::Range<u8>| codes.iter().any(|c| range.contains(c));
    let span = |codes: &[u8]| match (codes.first(), codes.last()) {
        (Some(a), Some(b)) => format!("{a}–{b}"),
        _ => "none".into(),
    };
    // Gamma 2.2: brighter in the deepest shadows, darker in the mid-tones; sqrt: darker
    // still in the mid-tones, and worse overall.
    r.claim(
        "gamma_bright_in_shadows_dark_in_mid_tones_sqrt_worse",
        gamma.0 > 0
            && all_in(&gamma.1, &SHADOWS)
            && gamma.2 < 0
            && some_in(&gamma.3, &MID_TONES)
            && sqrt.0 < 0
            && all_in(&sqrt.1, &MID_TONES)
            && sqrt.0.abs() > gamma.0.abs()
            && sqrt.2 < gamma.2,
        format!(
            "gamma 2.2: largest difference {:+} (> 0) at codes {} (in {SHADOWS:?}), most negative {:+} (< 0) at codes {} (some in {MID_TONES:?}); \
             sqrt: largest difference {:+} (< 0) at codes {} (in {MID_TONES:?}), |{}| > |{}|, most negative {:+} < {:+}",
            gamma.0,
            span(&gamma.1),
            gamma.2,
            span(&gamma.3),
            sqrt.0,
            span(&sqrt.1),
            sqrt.0,
            gamma.0,
            sqrt.2,
            gamma.2
        ),
    );
    let xs = (2.2f64 * 12.92).powf(-2.2 / 1.2);
    let d = xs.powf(1.0 / 2.2) - 12.92 * xs;
    writeln!(
        md,
        "\n*Every sRGB code c is decoded to linear light and re-encoded by each curve. The \
         analytic peak of 255 (x^(1/2.2) − 12.92 x) is {:.2} codes at x* = {xs:.6} \
         (sRGB code {:.1}).*",
        255.0 * d,
        255.0 * 12.92 * xs
    )?;
    Ok(md.into_bytes())
}

// ---------------------------------------------------------------------------------------
// Over-exposure ramps.

/// The colours of the ramps, in linear sRGB, peak 1 at exposure 1.
const RAMP_COLOURS: [(&str, DVec3); 3] = [
    ("orange", DVec3::new(1.0, 0.33, 0.05)),
    ("blue", DVec3::new(0.05, 0.1, 1.0)),
    ("green", DVec3::new(0.1, 1.0, 0.15)),
];

type Method = (&'static str, fn(DVec3) -> DVec3);

const METHODS: [Method; 3] = [
    ("clip", clip),
    ("source notes: mix with white by peak", desaturate_seed),
    ("ours: toward equal-Y grey", fit_to_gamut),
];

fn ramps_png(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    plot::register_embedded_font();
    let (label_w, cell_h, cols) = (250u32, 34u32, 600u32);
    let rows = (RAMP_COLOURS.len() * METHODS.len()) as u32;
    let (w, h) = (
        label_w + cols + 10,
        40 + rows * cell_h + 12 * RAMP_COLOURS.len() as u32,
    );
    let mut buffer = vec![255u8; (w * h * 3) as usize];
    // Exposure k from 0.1 to 20, log-spaced across the strip.
    let k_of = |i: u32| 0.1 * 200f64.powf(f64::from(i) / f64::from(cols - 1));
    let mut y = 40u32;
    let mut labels = Vec::new();
    for (cname, colour) in RAMP_COLOURS {
        for (mname, method) in METHODS {
            let row: Vec<u8> = (0..cols)
                .flat_map(|i| {
                    let c = method(colour * k_of(i));
                    [srgb8(c.x), srgb8(c.y), srgb8(c.z)]
                })
                .collect();
            for dy in 2..cell_h - 2 {
                let start = (((y + dy) * w + label_w) * 3) as usize;
                buffer[start..start + row.len()].copy_from_slice(&row);
            }
            labels.push((format!("{cname}, {mname}"), y));
            y += cell_h;
        }
        y += 12;
    }
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (w, h)).into_drawing_area();
        let style = ("sans-serif", 14).into_font().color(&BLACK);
        for (text, y) in labels {
            root.draw_text(&text, &style, (6, y as i32 + 9))?;
        }
        for k in [0.1, 0.3, 1.0, 3.0, 10.0, 20.0] {
            let x = label_w as f64 + (k / 0.1f64).ln() / 200f64.ln() * f64::from(cols - 1);
            root.draw_text(&format!("{k}x"), &style, (x as i32 - 10, 4))?;
            root.draw(&PathElement::new(
                vec![(x as i32, 22), (x as i32, 36)],
                BLACK.stroke_width(1),
            ))?;
        }
        root.present()?;
    }
    plot::encode_png(w, h, buffer)
}

fn hue_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::new();
    writeln!(
        md,
        "| colour × exposure | luminance Y in | method | result (linear) | Y out | xy hue shift, ° | CIELAB hue shift, ° |"
    )?;
    writeln!(md, "|---|---:|---|---|---:|---:|---:|")?;
    let mut clip_orange_xy = f64::NEG_INFINITY;
    // The source notes' rows: (colour, exposure, Y in, Y out, xy hue shift)
    let mut source_rows = Vec::new();
    for (cname, colour) in RAMP_COLOURS {
        for k in [2.0, 4.0] {
            let c = colour * k;
            for (mname, method) in METHODS {
                let out = method(c);
                let shift = |h: fn(DVec3) -> Option<f64>| match (h(c), h(out)) {
                    (Some(a), Some(b)) => Some(hue_difference(b, a)),
                    _ => None,
                };
                let show = |d: Option<f64>| d.map_or("— (grey)".into(), |d| format!("{d:+.2}"));
                let (xy, lab) = (shift(hue_xy_degrees), shift(hue_lab_degrees));
                let (y_in, y_out) = (luminance(c), luminance(out));
                if cname == "orange" && mname == "clip" {
                    clip_orange_xy = clip_orange_xy.max(xy.unwrap_or(f64::NAN));
                }
                if mname.starts_with("source") {
                    source_rows.push((cname, k, y_in, y_out, xy));
                    if k == 2.0 && cname == "blue" {
                        r.number("blue_x2.source.y_out_over_in", y_out / y_in, "s2");
                    }
                    if k == 2.0 && cname == "orange" {
                        r.number(
                            "orange_x2.source.lab_hue_shift_abs",
                            lab.map_or(f64::NAN, f64::abs),
                            "int",
                        );
                    }
                }
                writeln!(
                    md,
                    "| {cname} × {k} | {y_in:.3} | {mname} | ({:.3}, {:.3}, {:.3}) | {y_out:.3} | {} | {} |",
                    out.x,
                    out.y,
                    out.z,
                    show(xy),
                    show(lab),
                )?;
            }
        }
    }
    r.number("orange.clip.worst_xy_hue_shift", clip_orange_xy, "int");
    r.claim(
        "clip_moves_orange_hue_over_10",
        clip_orange_xy > 10.0,
        format!("orange, clipped: largest xy hue shift {clip_orange_xy:.2}° > 10°"),
    );
    // The source notes' mix keeps the xy hue (of every row, to rounding), and at 2x shows
    // the blue too bright and the orange too dark.
    let moved: Vec<String> = source_rows
        .iter()
        .filter(|row| row.4.is_none_or(|d| d.abs() > 1e-6))
        .map(|(c, k, _, _, d)| format!("{c} × {k}: {d:?}"))
        .collect();
    let at_2 = |name: &str| {
        source_rows
            .iter()
            .find(|row| row.0 == name && row.1 == 2.0)
            .map_or((f64::NAN, f64::NAN), |row| (row.2, row.3))
    };
    let (blue, orange) = (at_2("blue"), at_2("orange"));
    r.claim(
        "source_keeps_xy_hue_blue_too_bright_orange_too_dark",
        moved.is_empty() && blue.1 > blue.0 && orange.1 < orange.0,
        format!(
            "the source notes' rows whose xy hue moves by more than 1e-6°: {}; blue × 2: Y out {:.4} > Y in {:.4}; orange × 2: Y out {:.4} < Y in {:.4}",
            if moved.is_empty() { "none".to_string() } else { moved.join(", ") },
            blue.1,
            blue.0,
            orange.1,
            orange.0
        ),
    );
    writeln!(
        md,
        "\n*Hue shifts are the result's hue minus the input's: the angle of the CIE xy \
         chromaticity about D65, and the CIELAB hue angle h_ab (D65 white, Y = 1). Inputs with \
         Y > 1 cannot be shown at their luminance; the equal-luminance rule then gives white.*"
    )?;
    Ok(md.into_bytes())
}

fn speed_md(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n = 1 << 16;
    let pixels: Vec<DVec3> = (0..n)
        .map(|i| {
            let t = f64::from(i) / f64::from(n);
            DVec3::new(3.0 * t, (7.0 * t).fract(), 1.0 - t)
        })
        .collect();
    let reps = if settings.quick { 3 } else { 15 };
    let ns = timing::median_ns_per_item(n as usize, reps, || {
        to_display_rgb8(&pixels, 0.5)
            .iter()
            .map(|&b| u64::from(b))
            .sum()
    });
    let mut md = String::new();
    writeln!(md, "| step | ns per pixel |")?;
    writeln!(md, "|---|---:|")?;
    writeln!(
        md,
        "| to_display_rgb8 (exposure, gamut, sRGB curve, rounding) | {ns:.1} |"
    )?;
    writeln!(md, "\n*{}; {n} pixels per batch.*", timing::machine())?;
    Ok(md.into_bytes())
}
