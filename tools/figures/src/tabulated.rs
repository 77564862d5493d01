//! Figures and tables of the chapter *Tabulated distributions*.

use std::fmt::Write as _;

use rand::RngExt;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, Panel, Series};
use raylemma::check::max_abs;
use raylemma::rng;
use raylemma::sampling::tabulated::{
    ONE_MINUS_EPSILON, Piecewise1D, emission_table, emission_values, segment_cdf, segment_inverse,
};
use raylemma::stats::{StatsError, chi2, ks, test_alpha};
use raylemma::workload::{TIMING_BINS, timing_tables};

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "tabulated_histogram.svg",
            what: "samples of an emission spectrum against its pdf",
            make: histogram_svg,
        },
        Output {
            file: "tabulated_checks.md",
            what: "KS and chi-squared on the sampler and planted bugs",
            make: checks_md,
        },
        Output {
            file: "tabulated_precision.md",
            what: "round-trip and segment-inverse errors",
            make: precision_md,
        },
        Output {
            file: "tabulated_speed.md",
            what: "ns per sample against table size",
            make: speed_md,
        },
    ]
}

fn histogram_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let table = emission_table();
    let n: usize = if settings.quick { 100_000 } else { 1_000_000 };
    let mut counts = vec![0u64; table.bins()];
    let mut rng = rng::seeded(0x7ab);
    for _ in 0..n {
        counts[table.sample(rng.random::<f64>()).bin] += 1;
    }
    let edges = table.edges();
    // Estimated density: count / (n * width).
    let estimate: Vec<f64> = counts
        .iter()
        .zip(edges.windows(2))
        .map(|(&c, e)| c as f64 / (n as f64 * (e[1] - e[0])))
        .collect();
    let pdf: Vec<f64> = (0..table.bins()).map(|i| table.pdf(edges[i])).collect();
    let floored = |v: &[f64], floor: f64| v.iter().map(|y| y.max(floor)).collect::<Vec<_>>();
    let ymax = pdf.iter().copied().fold(0.0, f64::max) * 1.1;
    let floor = 1e-5;
    let series = |floor: f64| {
        vec![
            Series::bars(
                format!("histogram of {n} samples"),
                edges,
                &floored(&estimate, floor),
            ),
            Series::line("the pdf", plot::steps(edges, &floored(&pdf, floor))),
        ]
    };
    let panels = [
        Panel::new(
            "histogram and pdf",
            "wavelength (nm)",
            "density (1/nm)",
            series(0.0),
        )
        .x_range((380.0, 780.0))
        .y_range((0.0, ymax)),
        Panel::new(
            "the same, logarithmic (zero bins at the floor)",
            "wavelength (nm)",
            "density (1/nm)",
            series(floor),
        )
        .log_y()
        .x_range((380.0, 780.0))
        .y_range((floor, 1.0)),
    ];
    plot::chart(&panels, 2)
}

/// KS and chi-squared (one cell per bin) of `xs` against `table`: the KS p-value, and
/// the chi-squared p-value or why there is none (samples where the pdf is zero, which
/// is itself a rejection).
fn tests_against(table: &Piecewise1D, xs: &[f64]) -> (f64, Result<f64, String>) {
    let ks = ks::one_sample(xs, |x| table.cdf(x)).map_or(f64::NAN, |k| k.p_value);
    let mut observed = vec![0u64; table.bins()];
    let edges = table.edges();
    for &x in xs {
        let x = x.clamp(edges[0], edges[edges.len() - 1].next_down());
        observed[edges[1..].partition_point(|&e| e <= x)] += 1;
    }
    let expected: Vec<f64> = (0..table.bins())
        .map(|i| table.bin_probability(i) * xs.len() as f64)
        .collect();
    let chi = match chi2::pearson(&observed, &expected, 5.0) {
        Ok(c) => Ok(c.p_value),
        Err(StatsError::SamplesWherePdfIsZero { cell, count }) => {
            Err(format!("error: {count} samples in zero bin {cell}"))
        }
        Err(e) => Err(format!("could not run: {e}")),
    };
    (ks, chi)
}

fn checks_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n: usize = if settings.quick { 20_000 } else { 200_000 };
    let table = emission_table();
    let edges = table.edges().to_vec();
    let (lo, hi) = (edges[0], edges[edges.len() - 1]);
    let unnormalised_cdf: Vec<f64> = table
        .cdf_table()
        .iter()
        .map(|c| c * table.integral())
        .collect();
    let heights: Vec<f64> = emission_values()
        .iter()
        .map(|v| (v / 20.0 * 250.0).round().min(250.0))
        .collect();
    let ratio_table = Piecewise1D::uniform(
        lo,
        hi,
        &heights.iter().map(|h| h / (256.0 - h)).collect::<Vec<_>>(),
    )?;
    let drawn = Piecewise1D::uniform(lo, hi, &heights)?;
    type Sampler<'a> = Box<dyn Fn(f64) -> f64 + 'a>;
    // (value name, label, reference table, sampler)
    let rows: Vec<(&str, &str, &Piecewise1D, Sampler)> = vec![
        (
            "sampler",
            "`Piecewise1D::sample`",
            &table,
            Box::new(|u| table.sample(u).x),
        ),
        (
            "uniform_ignoring_table",
            "uniform on [380, 780], ignoring the table",
            &table,
            Box::new(|u| lo + u * (hi - lo)),
        ),
        (
            "cdf_not_normalised",
            "CDF not divided by its total",
            &table,
            Box::new(|u| {
                let c = &unnormalised_cdf;
                let i = c[1..].partition_point(|&x| x <= u).min(table.bins() - 1);
                let t = ((u - c[i]) / (c[i + 1] - c[i])).min(1.0);
                edges[i] + t * (edges[i + 1] - edges[i])
            }),
        ),
        (
            "off_by_one_bin",
            "off by one: bin i + 1",
            &table,
            Box::new(|u| {
                let s = table.sample(u);
                let j = (s.bin + 1).min(table.bins() - 1);
                s.x - edges[s.bin] + edges[j]
            }),
        ),
        (
            "textbook_inverse",
            "textbook inverse inf {x : F(x) ≥ u} (lands in zero bins at plateau levels)",
            &table,
            Box::new(|u| {
                let c = table.cdf_table();
                let i = c[1..].partition_point(|&x| x < u).min(table.bins() - 1);
                let t = (u - c[i]) / (c[i + 1] - c[i]);
                edges[i] + t * (edges[i + 1] - edges[i])
            }),
        ),
        (
            "seed_black_white_ratio",
            "seed, read literally: black/white ratio h/(256 − h)",
            &drawn,
            Box::new(|u| ratio_table.sample(u).x),
        ),
    ];
    let mut md = String::new();
    writeln!(
        md,
        "| sampler | KS p-value | chi-squared p-value | verdict at α = {:.2e} |",
        test_alpha()
    )?;
    writeln!(md, "|---|---:|---:|---|")?;
    // Whether each row was accepted, by value name.
    let mut accepted = Vec::new();
    for (k, (key, name, reference, sample)) in rows.iter().enumerate() {
        let mut rng = rng::seeded(0xc4ec + k as u64);
        let xs: Vec<f64> = (0..n).map(|_| sample(rng.random::<f64>())).collect();
        let (ks, chi) = tests_against(reference, &xs);
        let rejected = ks < test_alpha() || chi.as_ref().map_or(true, |&p| p < test_alpha());
        accepted.push((*key, !rejected));
        let verdict = r.text(
            &format!("{key}.verdict"),
            if rejected { "rejected" } else { "accepted" },
        );
        let chi = chi.map_or_else(|why| why, p_text);
        let ks = r.text(&format!("{key}.ks_p"), p_text(ks));
        writeln!(md, "| {name} | {ks} | {chi} | {verdict} |")?;
    }
    let is_accepted = |key: &str| accepted.iter().any(|&(k, a)| k == key && a);
    // The planted bugs, the source's black/white ratio among them: every one rejected.
    let planted = [
        "uniform_ignoring_table",
        "cdf_not_normalised",
        "off_by_one_bin",
        "seed_black_white_ratio",
    ];
    let verdicts: Vec<String> = planted
        .iter()
        .map(|&k| {
            let found = accepted.iter().find(|&&(key, _)| key == k);
            let v = match found {
                Some((_, true)) => "accepted",
                Some((_, false)) => "rejected",
                None => "missing",
            };
            format!("{k}: {v}")
        })
        .collect();
    r.claim(
        "planted_rejected",
        planted
            .iter()
            .all(|&k| accepted.iter().any(|&(key, a)| key == k && !a)),
        format!("every planted row rejected: {}", verdicts.join(", ")),
    );
    let seed_rejected = accepted
        .iter()
        .any(|&(key, a)| key == "seed_black_white_ratio" && !a);
    r.claim(
        "seed_black_white_ratio_rejected",
        seed_rejected,
        format!(
            "the black/white ratio sampler against the drawn heights: {}",
            if seed_rejected {
                "rejected"
            } else {
                "not rejected"
            }
        ),
    );
    let (textbook, sampler) = (is_accepted("textbook_inverse"), is_accepted("sampler"));
    r.claim(
        "textbook_inverse_accepted",
        textbook && sampler,
        format!("textbook inverse accepted: {textbook}; `Piecewise1D::sample` accepted: {sampler}"),
    );
    writeln!(
        md,
        "\n*{n} samples each from the emission table of the figure (400 bins, 1 nm), against its exact CDF and bin probabilities; the black/white row is tested against the drawn heights. Generated by `tools/figures/src/tabulated.rs`.*"
    )?;
    Ok(md.into_bytes())
}

/// A p-value for a table: `< 1e-300` when it underflows to 0.
fn p_text(p: f64) -> String {
    if p == 0.0 {
        "< 1e-300".into()
    } else {
        format!("{p:.2e}")
    }
}

/// The textbook root of a linear segment's quadratic, for comparison.
fn segment_inverse_textbook(a: f64, b: f64, xi: f64) -> f64 {
    (-a + (a * a + xi * (b * b - a * a)).sqrt()) / (b - a)
}

fn precision_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n: usize = if settings.quick { 20_000 } else { 200_000 };
    let mut md = String::new();
    let table = emission_table();
    let mut rng = rng::seeded(0x9a1);
    let (mut worst, mut at_edge) = (0.0f64, 0.0f64);
    let mut us: Vec<f64> = (0..n).map(|_| rng.random::<f64>()).collect();
    us.extend([0.0, ONE_MINUS_EPSILON]);
    us.extend(table.cdf_table().iter().copied().filter(|&c| c < 1.0));
    for (k, &u) in us.iter().enumerate() {
        let s = table.sample(u);
        let e = table.edges();
        let scale = 1.0 + (e[s.bin].abs() + e[s.bin + 1].abs()) * s.pdf;
        let err = (table.invert(s.x) - u).abs() / (f64::EPSILON * scale);
        // `max_abs`, not `f64::max`, which would drop a NaN.
        if k < n {
            worst = max_abs([worst, err]);
        } else {
            at_edge = max_abs([at_edge, err]);
        }
    }
    writeln!(md, "| quantity | worst | bound asserted by the tests |")?;
    writeln!(md, "|---|---:|---:|")?;
    writeln!(
        md,
        "| \\|invert(sample(u)) − u\\| / (ε (1 + (\\|x_i\\| + \\|x_i+1\\|) p)), random u | {worst:.2} | 4 |"
    )?;
    writeln!(
        md,
        "| the same at u = 0, 1 − 2⁻⁵³ and every CDF entry | {at_edge:.2} | 4 |"
    )?;
    let (a, b) = (1.0, 1.0 + 1e-13);
    let (mut textbook, mut stable) = (0.0f64, 0.0f64);
    for k in 1..1000 {
        let xi = f64::from(k) / 1000.0 + 1e-7;
        let exact = xi + 0.5 * (b - a) * xi * (1.0 - xi);
        textbook = max_abs([textbook, segment_inverse_textbook(a, b, xi) - exact]);
        stable = max_abs([stable, segment_inverse(a, b, xi) - exact]);
    }
    // The bounds of the tests: the textbook root must fail by at least 1e-4, the stable
    // one stay within 2 epsilon.
    let (must_fail, stable_bound) = (1e-4, 2.0 * f64::EPSILON);
    writeln!(
        md,
        "| linear segment, b − a = 1e−13: error of t, textbook root | {} | ≥ 1e−4 (must fail) |",
        r.text("textbook_root.worst", format!("{textbook:.1e}"))
    )?;
    writeln!(
        md,
        "| the same, stable root | {} | 2ε = 4.4e−16 |",
        r.text("stable_root.worst", format!("{stable:.1e}"))
    )?;
    r.claim(
        "textbook_root_fails",
        textbook >= must_fail,
        format!("the textbook root's worst error of t: {textbook:.1e} >= {must_fail:.0e}"),
    );
    r.claim(
        "stable_root_within_bound",
        stable <= stable_bound,
        format!("the stable root's worst error of t: {stable:.1e} <= 2ε = {stable_bound:.2e}"),
    );
    // The segments of `segment_inverse_round_trips` (`check::tabulated::hard_segment`).
    let mut worst_seg = 0.0f64;
    let mut segments = 0;
    while segments < n {
        let Some((a, b)) = raylemma::check::tabulated::hard_segment(&mut rng) else {
            continue;
        };
        segments += 1;
        let xi = rng.random::<f64>();
        let t = segment_inverse(a, b, xi);
        // A t outside [0, 1] is as wrong as a NaN.
        let err = if (0.0..=1.0).contains(&t) {
            (segment_cdf(a, b, t) - xi).abs() / f64::EPSILON
        } else {
            f64::NAN
        };
        worst_seg = max_abs([worst_seg, err]);
    }
    let seg_bound = 6.0;
    writeln!(
        md,
        "| linear segment round trip \\|F(F⁻¹(ξ)) − ξ\\| / ε: a = 0 in 10 %, else from 1e−300 to 1e300; b = a, b = a(1 + 10⁻¹²u) or independent | {} | {seg_bound} |",
        r.number("segment_round_trip.worst", worst_seg, ".2")
    )?;
    r.claim(
        "segment_round_trip_within_bound",
        worst_seg <= seg_bound,
        format!("the linear segment round trip's worst error: {worst_seg:.2} ε <= {seg_bound} ε"),
    );
    writeln!(
        md,
        "\n*{n} random u on the emission table and {n} random segments; generated by `tools/figures/src/tabulated.rs`.*"
    )?;
    Ok(md.into_bytes())
}

fn speed_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let reps = if settings.quick { 5 } else { 201 };
    let us = raylemma::workload::uniform_inputs(4096);
    let mut md = String::new();
    writeln!(
        md,
        "| bins | piecewise constant (ns per sample) | piecewise linear (ns per sample) |"
    )?;
    writeln!(md, "|---:|---:|---:|")?;
    let mut times = Vec::new();
    for bins in TIMING_BINS {
        let (constant, linear) = timing_tables(bins);
        let c = timing::median_ns_per_input(&us, reps, |u| constant.sample(u).x);
        let l = timing::median_ns_per_input(&us, reps, |u| linear.sample(u).x);
        writeln!(
            md,
            "| {bins} | {} | {} |",
            r.number(&format!("bins_{bins}.constant_ns"), c, ".1"),
            r.number(&format!("bins_{bins}.linear_ns"), l, ".1"),
        )?;
        times.push((bins, c, l));
    }
    r.claim(
        "linear_slower_every_row",
        times.iter().all(|&(_, c, l)| l > c),
        format!(
            "piecewise linear > piecewise constant, ns per sample, at every size: {}",
            times
                .iter()
                .map(|(b, c, l)| format!("{b}: {l:.1} > {c:.1}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    // Logarithmic growth would add the same time from 256 to 4096 bins as from 4096 to
    // 65 536 (both sixteen-fold, four more steps of the search); more beyond 4096 is the
    // caches.
    let constant_at = |bins: usize| times.iter().find(|t| t.0 == bins).map_or(f64::NAN, |t| t.1);
    let (t256, t4096, t65536) = (constant_at(256), constant_at(4096), constant_at(65_536));
    r.claim(
        "superlog_growth",
        t65536 - t4096 > t4096 - t256,
        format!(
            "piecewise constant: t(65536) - t(4096) = {:.1} ns > t(4096) - t(256) = {:.1} ns",
            t65536 - t4096,
            t4096 - t256
        ),
    );
    writeln!(
        md,
        "\n*{}; 4096 random u per batch, median of {reps} batches{}. Each sample includes its pdf.*",
        timing::machine(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
