//! Figures and tables of the chapter *Ray-sphere intersection*.

use std::fmt::Write as _;
use std::hint::black_box;

use glam::DVec3;

use super::{Output, Record, Settings, timing};
use crate::plot::{self, BoxError, Panel, Series};
use raylemma::check::sphere::{self as check, FAR_DISTANCES, FarRow, SphereIntersector};
use raylemma::check::{Options, Real};
use raylemma::geometry::sphere::{intersect_stable, intersect_textbook};
use raylemma::single::geometry::sphere::{
    intersect_stable as stable32, intersect_textbook as textbook32,
};
use raylemma::single::geometry::{Ray, Sphere};
use raylemma::workload::timing_rays;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "sphere_far_error.svg",
            what: "error against distance",
            make: far_error_svg,
        },
        Output {
            file: "sphere_far_table.md",
            what: "far-sphere table",
            make: far_table_md,
        },
        Output {
            file: "sphere_silhouette.png",
            what: "hit maps of a far sphere",
            make: silhouette_png,
        },
        Output {
            file: "sphere_self_hit.md",
            what: "self-intersection rates",
            make: self_hit_md,
        },
        Output {
            file: "sphere_verdicts.md",
            what: "checker verdicts",
            make: verdicts_md,
        },
        Output {
            file: "sphere_speed.md",
            what: "ns per intersection",
            make: speed_md,
        },
    ]
}

/// Distances of the figure: 1.8 to 1e5 radii, four per decade (the bundle's origins
/// must lie outside the sphere, so the first is beyond `sqrt(1 + 2 * 1.25^2)`).
fn figure_distances() -> Vec<f64> {
    (1..=20).map(|k| 10f64.powf(k as f64 / 4.0)).collect()
}

/// The far-sphere bundle: the checker's default ([`check::FAR_RAYS`] rays per distance),
/// or a 41 x 41 bundle in quick mode.
fn far_options(settings: &Settings) -> Options {
    if settings.quick {
        Options::default().cases(41 * 41)
    } else {
        Options::default()
    }
}

fn far_error_svg(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let options = far_options(settings);
    let forms: [(&str, &dyn Fn(f64) -> FarRow); 2] = [
        ("textbook (seed)", &|d| {
            check::far_row(&textbook32, d, &options)
        }),
        ("stable (RTG ch. 7)", &|d| {
            check::far_row(&stable32, d, &options)
        }),
    ];
    let distances = figure_distances();
    let mut error = Vec::new();
    let mut wrong = Vec::new();
    for (label, run) in forms {
        let rows: Vec<FarRow> = distances.iter().map(|&d| run(d)).collect();
        error.push(Series::line(
            label,
            rows.iter().map(|r| (r.distance, r.worst_t_error)).collect(),
        ));
        wrong.push(Series::line(
            label,
            rows.iter()
                .map(|r| (r.distance, 100.0 * r.wrong as f64 / r.rays as f64))
                .collect(),
        ));
    }
    let panels = [
        Panel::new(
            "worst error of t (f32, rays within 0.9 r of the centre)",
            "distance to the sphere (radii)",
            "|t − t*| (radii)",
            error,
        )
        .log_x()
        .log_y(),
        Panel::new(
            "wrong hit/miss answers (f32)",
            "distance to the sphere (radii)",
            "% of rays",
            wrong,
        )
        .log_x(),
    ];
    plot::chart(&panels, 2)
}

fn far_table_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let options = far_options(settings);
    let grid = check::far_grid(&options);
    let mut md = String::new();
    writeln!(
        md,
        "| distance (radii) | form | rays | wrong hit/miss | worst \\|t − t*\\| (radii) | in units of ε(\\|O−C\\|+r) |"
    )?;
    writeln!(md, "|---:|---|---:|---:|---:|---:|")?;
    let (mut stable_wrong, mut textbook_wrong) = (Vec::new(), Vec::new());
    for &d in &FAR_DISTANCES {
        for (name, row) in [
            ("textbook", check::far_row(&textbook32, d, &options)),
            ("stable", check::far_row(&stable32, d, &options)),
        ] {
            let distance = format!("{d:.0e}");
            let wrong = r.number(
                &format!("d{distance}.{name}.wrong"),
                row.wrong as f64,
                "int",
            );
            let tally = if name == "stable" {
                &mut stable_wrong
            } else {
                &mut textbook_wrong
            };
            tally.push((distance.clone(), row.wrong));
            writeln!(
                md,
                "| {distance} | {name} | {} | {wrong} | {:.2e} | {:.1} |",
                row.rays, row.worst_t_error, row.worst_t_units
            )?;
        }
    }
    let list = |rows: &[(String, usize)]| {
        rows.iter()
            .map(|(d, w)| format!("{d}: {w}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    r.claim(
        "stable_alone_never_wrong",
        stable_wrong.iter().all(|(_, w)| *w == 0) && textbook_wrong.iter().any(|(_, w)| *w > 0),
        format!(
            "wrong hit/miss answers at each distance, stable (all 0): {}; textbook (some > 0): {}",
            list(&stable_wrong),
            list(&textbook_wrong)
        ),
    );
    writeln!(
        md,
        "\n*{grid}×{grid} parallel f32 rays per distance; generated by `cargo run --release` (`tools/figures/src/sphere.rs`).*"
    )?;
    Ok(md.into_bytes())
}

/// Hit maps: each pixel is one ray of a parallel bundle aimed at a unit sphere `distance`
/// radii away. Light grey: correct hit; dark grey: correct miss; orange: wrong answer.
/// Rays within the silhouette band ([`check::SILHOUETTE_BAND`]) accept either answer.
fn silhouette_png(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    use plotters::prelude::*;
    let n: u32 = if settings.quick { 100 } else { 200 };
    let distances = [1e3, 3e3, 1e4];
    let (gap, caption) = (20u32, 40u32);
    let width = 2 * n + 3 * gap;
    let height = distances.len() as u32 * (n + caption) + gap;
    plot::register_embedded_font();
    let mut buffer = vec![255u8; (width * height * 3) as usize];
    let d_hat = DVec3::new(0.48, -0.6, 0.64).normalize();
    let (e1, e2) = d_hat.any_orthonormal_pair();
    let center = DVec3::new(1.25, -0.5, 2.0);
    let sphere = Sphere::new(f32::narrow3(center), 1.0);
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (width, height)).into_drawing_area();
        root.fill(&WHITE)?;
        let forms: [(&str, &dyn SphereIntersector<f32>); 2] =
            [("textbook", &textbook32), ("stable", &stable32)];
        for (row, &distance) in distances.iter().enumerate() {
            for (col, (name, form)) in forms.iter().enumerate() {
                let x0 = (gap + col as u32 * (n + gap)) as i32;
                let y0 = (row as u32 * (n + caption) + caption) as i32;
                let mut wrong = 0;
                for i in 0..n {
                    for j in 0..n {
                        let x = -1.25 + 2.5 * (f64::from(i) + 0.5) / f64::from(n);
                        let y = -1.25 + 2.5 * (f64::from(j) + 0.5) / f64::from(n);
                        let ray = Ray::new(
                            f32::narrow3(center - d_hat * distance + e1 * x + e2 * y),
                            f32::narrow3(d_hat),
                        );
                        let o = f32::wide3(ray.origin) - center;
                        let d = f32::wide3(ray.dir);
                        let h = (o - d * (o.dot(d) / d.dot(d))).length();
                        let unit = f64::from(f32::EPSILON) * (o.length() + 1.0);
                        let ambiguous = (h - 1.0).abs() <= check::SILHOUETTE_BAND * unit;
                        let got = form.intersect(&ray, &sphere, 0.0).is_some();
                        let truth = if ambiguous { got } else { h < 1.0 };
                        let color = match (got == truth, got) {
                            (true, true) => RGBColor(235, 235, 235),
                            (true, false) => RGBColor(60, 60, 60),
                            (false, _) => RGBColor(230, 120, 0),
                        };
                        wrong += usize::from(got != truth);
                        root.draw_pixel((x0 + i as i32, y0 + (n - 1 - j) as i32), &color)?;
                    }
                }
                let style = ("sans-serif", 13).into_font().color(&BLACK);
                root.draw_text(
                    &format!("{name}, {distance:.0e} radii"),
                    &style,
                    (x0, y0 - 34),
                )?;
                root.draw_text(
                    &format!("{wrong} of {} wrong", n * n),
                    &style,
                    (x0, y0 - 18),
                )?;
            }
        }
        root.present()?;
    }
    plot::encode_png(width, height, buffer)
}

fn self_hit_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let rays = if settings.quick { 20_000 } else { 200_000 };
    let options = Options::default().cases(rays); // seed: check::SELF_HIT_SEED
    let mut md = String::new();
    writeln!(
        md,
        "| form | precision | outward rays that hit their own sphere with t_min = 0 |"
    )?;
    writeln!(md, "|---|---|---:|")?;
    let rows = [
        (
            "textbook",
            "f32",
            check::self_hit_rate(&textbook32, &options),
        ),
        ("stable", "f32", check::self_hit_rate(&stable32, &options)),
        (
            "textbook",
            "f64",
            check::self_hit_rate(&intersect_textbook, &options),
        ),
        (
            "stable",
            "f64",
            check::self_hit_rate(&intersect_stable, &options),
        ),
    ];
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (form, precision, rate) in rows {
        let percent = 100.0 * rate;
        (lo, hi) = (lo.min(percent), hi.max(percent));
        let shown = r.number(
            &format!("{form}.{precision}.outward_percent"),
            percent,
            ".1",
        );
        writeln!(md, "| {form} | {precision} | {shown} % |")?;
    }
    r.number("outward_percent.min", lo, ".1");
    r.number("outward_percent.max", hi, ".1");
    writeln!(
        md,
        "\n*{rays} rays leaving random points of spheres of radius 0.1 to 10 placed within 10 units of the origin.*"
    )?;
    Ok(md.into_bytes())
}

fn verdicts_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let options = if settings.quick {
        Options::default().cases(2_000)
    } else {
        Options::default() // check::CASES = 20 000 cases per claim
    };
    let textbook = check::intersection(&textbook32, &options);
    let hits = textbook.finding("hits");
    let (failures, cases) = (hits.failures, hits.cases);
    r.number("textbook.f32.hits.failures", failures as f64, "int");
    r.number("textbook.f32.hits.cases", cases as f64, "int");
    r.claim(
        "textbook_f32_hits_fail_occasionally",
        0 < failures && failures * 100 < cases,
        format!(
            "the textbook form in f32 fails {failures} of {cases} hits: more than 0, under 1 %"
        ),
    );
    let mut md = String::from("```text\n");
    for verdict in [
        check::intersection(&stable32, &options),
        textbook,
        check::intersection(&intersect_stable, &options),
        check::intersection(&intersect_textbook, &options),
        check::far(&stable32, &Options::default()),
        check::far(&textbook32, &Options::default()),
    ] {
        writeln!(md, "{verdict}")?;
    }
    md.push_str("```\n");
    Ok(md.into_bytes())
}

fn time_form<R: Real>(f: fn(&R::Ray, &R::Sphere, R) -> Option<R>, quick: bool) -> (f64, f64) {
    let (rays, sphere) = timing_rays::<R>(4096);
    let hits = rays
        .iter()
        .filter(|r| f(r, &sphere, R::ZERO).is_some())
        .count();
    let reps = if quick { 5 } else { 201 };
    let ns = timing::median_ns_per_item(rays.len(), reps, || {
        let mut count = 0u64;
        for ray in &rays {
            if f(black_box(ray), black_box(&sphere), R::ZERO).is_some() {
                count += 1;
            }
        }
        count
    });
    (ns, hits as f64 / rays.len() as f64)
}

fn speed_md(settings: &Settings, r: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let q = settings.quick;
    let rows = [
        ("textbook", "f32", time_form::<f32>(textbook32, q)),
        ("stable", "f32", time_form::<f32>(stable32, q)),
        ("textbook", "f64", time_form::<f64>(intersect_textbook, q)),
        ("stable", "f64", time_form::<f64>(intersect_stable, q)),
    ];
    let mut md = String::new();
    writeln!(
        md,
        "| form | precision | ns per intersection (median) | hit rate |"
    )?;
    writeln!(md, "|---|---|---:|---:|")?;
    for (form, precision, (ns, hit)) in rows {
        writeln!(
            md,
            "| {form} | {precision} | {} | {:.0} % |",
            r.number(&format!("{form}.{precision}.ns"), ns, ".2"),
            100.0 * hit
        )?;
    }
    let ns = |k: usize| rows[k].2.0;
    let (price32, price64) = (ns(1) - ns(0), ns(3) - ns(2));
    r.number("stable_minus_textbook.f32_ns", price32, ".1");
    r.number("stable_minus_textbook.f64_ns", price64, ".1");
    r.claim(
        "stable_costs_more",
        price32 > 0.0 && price64 > 0.0,
        format!(
            "stable - textbook, ns per intersection: f32 {:.2} - {:.2}, f64 {:.2} - {:.2}, both > 0",
            ns(1),
            ns(0),
            ns(3),
            ns(2)
        ),
    );
    writeln!(
        md,
        "\n*{}; 4096 rays per batch, median of {} batches{}.*",
        timing::machine(),
        if q { 5 } else { 201 },
        if q { " (quick mode: noisy)" } else { "" }
    )?;
    Ok(md.into_bytes())
}
