//! Figures and tables of the chapter *Tangent frames*.

use raylemma::sampling::sphere::sphere_uniform;
use std::f64::consts::TAU;
use std::fmt::Write as _;
use std::hint::black_box;

use glam::{DVec3, Vec3};

use super::{Output, Record, Settings, timing};
use crate::plot::{self, Panel, Series};
use raylemma::rng;
use raylemma::sampling::frame::{Construction, Frame, cross_product_frame, duff, frisvad};
use raylemma::single::sampling::frame as frame32;
use raylemma::workload::timing_normals;

/// The outputs of this chapter.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "frame_error.svg",
            what: "orthonormality error near (0, 0, -1)",
            make: error_svg,
        },
        Output {
            file: "frame_errors.md",
            what: "worst orthonormality errors",
            make: errors_md,
        },
        Output {
            file: "frame_rings.md",
            what: "worst orthonormality error per ring near (0, 0, -1)",
            make: rings_md,
        },
        Output {
            file: "frame_speed.md",
            what: "ns per frame",
            make: speed_md,
        },
    ]
}

/// Normals at `z = -1 + delta` on a ring of `azimuths` angles, with `x, y` from
/// `sqrt(1 - z^2)` as a renderer computes them (unit only to within rounding).
pub fn ring(delta: f64, azimuths: usize) -> Vec<DVec3> {
    let z = -1.0 + delta;
    let r = (1.0 - z * z).sqrt();
    (0..azimuths)
        .map(|j| {
            let phi = TAU * (j as f64 + 0.5) / azimuths as f64;
            DVec3::new(r * phi.cos(), r * phi.sin(), z)
        })
        .collect()
}

/// Worst [`Frame::error`] over `normals` rounded to f32, in units of `f32::EPSILON`.
pub fn worst32(normals: &[DVec3], f: frame32::Construction) -> f64 {
    normals
        .iter()
        .map(|n| frame32::Frame::with(n.as_vec3(), f).error() / f64::from(f32::EPSILON))
        .fold(0.0, f64::max)
}

/// Worst [`Frame::error`] over `normals`, in units of `f64::EPSILON`.
pub fn worst64(normals: &[DVec3], f: Construction) -> f64 {
    normals
        .iter()
        .map(|n| Frame::with(*n, f).error() / f64::EPSILON)
        .fold(0.0, f64::max)
}

/// The orthonormality bound the tests assert, in units of the precision's epsilon.
const BOUND_EPS: f64 = 4.0;

/// One point of the approach to the south pole: `1 + z` of the (rounded) normals, and the
/// worst error of Frisvad's and of Duff et al.'s frame over their ring.
struct PolePoint {
    dz: f64,
    frisvad: f64,
    duff: f64,
}

/// The figure's approach to `(0, 0, -1)`: `1 + z` from 1 down to 1e-7 (f32) and 1e-15
/// (f64), four points per decade, each a ring of normals.
fn pole_sweep(settings: &Settings) -> (Vec<PolePoint>, Vec<PolePoint>) {
    let azimuths = if settings.quick { 64 } else { 1024 };
    let deltas = |decades: i32| -> Vec<f64> {
        (0..=4 * decades)
            .map(|k| 10f64.powf(-f64::from(k) / 4.0))
            .collect()
    };
    let f32s = deltas(7)
        .into_iter()
        .map(|d| {
            let normals = ring(d, azimuths);
            PolePoint {
                // The distance the rounded normals really have from z = -1.
                dz: 1.0 + f64::from(normals[0].as_vec3().z),
                frisvad: worst32(&normals, frame32::frisvad),
                duff: worst32(&normals, frame32::duff),
            }
        })
        .collect();
    let f64s = deltas(15)
        .into_iter()
        .map(|d| {
            let normals = ring(d, azimuths);
            PolePoint {
                dz: 1.0 + normals[0].z,
                frisvad: worst64(&normals, frisvad),
                duff: worst64(&normals, duff),
            }
        })
        .collect();
    (f32s, f64s)
}

fn error_svg(settings: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (sweep32, sweep64) = pole_sweep(settings);
    fn line(label: &str, sweep: &[PolePoint], pick: fn(&PolePoint) -> f64) -> Series {
        Series::line(label, sweep.iter().map(|p| (p.dz, pick(p))).collect())
    }
    let panels = [
        Panel::new(
            "f32: worst error over a ring of normals",
            "1 + z (distance from (0, 0, −1))",
            "worst error (f32 epsilons)",
            vec![
                line("Frisvad 2012", &sweep32, |p| p.frisvad),
                line("Duff et al. 2017", &sweep32, |p| p.duff),
            ],
        )
        .log_x()
        .log_y(),
        Panel::new(
            "f64",
            "1 + z",
            "worst error (f64 epsilons)",
            vec![
                line("Frisvad 2012", &sweep64, |p| p.frisvad),
                line("Duff et al. 2017", &sweep64, |p| p.duff),
            ],
        )
        .log_x()
        .log_y(),
    ];
    plot::chart(&panels, 2)
}

fn errors_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let n = if settings.quick { 10_000 } else { 100_000 };
    let mut g = rng::seeded(1);
    let random: Vec<DVec3> = (0..n).map(|_| sphere_uniform(&mut g)).collect();
    let upper: Vec<DVec3> = random
        .iter()
        .map(|v| DVec3::new(v.x, v.y, v.z.abs()))
        .collect();
    let pole32: Vec<DVec3> = (1..=7).flat_map(|k| ring(10f64.powi(-k), 256)).collect();
    let pole64: Vec<DVec3> = (1..=15).flat_map(|k| ring(10f64.powi(-k), 256)).collect();
    let mut md = String::new();
    writeln!(
        md,
        "| normals | Duff et al., f32 | Frisvad, f32 | Duff et al., f64 | Frisvad, f64 |"
    )?;
    writeln!(md, "|---|---:|---:|---:|---:|")?;
    // Per row: (value name, Duff f32, Frisvad f32, Duff f64, Frisvad f64).
    let mut rows = Vec::new();
    for (key, name, n32, n64) in [
        ("random_sphere", "random, whole sphere", &random, &random),
        (
            "random_upper_hemisphere",
            "random, upper hemisphere (z ≥ 0)",
            &upper,
            &upper,
        ),
        (
            "near_south_pole",
            "z = −1 + 10⁻ᵏ, k = 1…7 (f32) and 1…15 (f64)",
            &pole32,
            &pole64,
        ),
    ] {
        let e = (
            worst32(n32, frame32::duff),
            worst32(n32, frame32::frisvad),
            worst64(n64, duff),
            worst64(n64, frisvad),
        );
        rows.push((key, e));
        writeln!(
            md,
            "| {name} | {} | {} | {} | {} |",
            r.number(&format!("{key}.duff_f32"), e.0, ".2"),
            r.text(&format!("{key}.frisvad_f32"), format!("{:.3e}", e.1)),
            r.number(&format!("{key}.duff_f64"), e.2, ".2"),
            r.text(&format!("{key}.frisvad_f64"), format!("{:.3e}", e.3)),
        )?;
    }
    let duff_rows = rows
        .iter()
        .map(|(k, e)| format!("{k}: f32 {:.2}, f64 {:.2}", e.0, e.2))
        .collect::<Vec<_>>()
        .join("; ");
    let rows_within = rows
        .iter()
        .all(|(_, e)| e.0 <= BOUND_EPS && e.2 <= BOUND_EPS);
    r.claim(
        "duff_within_bound_every_row",
        rows_within,
        format!("Duff et al.'s worst error <= {BOUND_EPS} ε on every row ({duff_rows})"),
    );
    // "All the way": the rows and every point of the figure's approach to the pole.
    let (sweep32, sweep64) = pole_sweep(settings);
    let worst_sweep = |sweep: &[PolePoint]| sweep.iter().map(|p| p.duff).fold(0.0, f64::max);
    let (s32, s64) = (worst_sweep(&sweep32), worst_sweep(&sweep64));
    r.claim(
        "duff_within_bound_all_the_way",
        rows_within && s32 <= BOUND_EPS && s64 <= BOUND_EPS,
        format!(
            "Duff et al.'s worst error <= {BOUND_EPS} ε on every row ({duff_rows}) and along the figure's approach to the pole (f32 {s32:.2}, f64 {s64:.2})"
        ),
    );
    // Frisvad's error near the pole against away from it (the upper hemisphere).
    let (away, pole) = (rows[1].1, rows[2].1);
    let (g32, g64) = (pole.1 / away.1, pole.3 / away.3);
    r.claim(
        "frisvad_grows_by_orders_of_magnitude_towards_the_pole",
        g32 >= 100.0 && g64 >= 100.0,
        format!(
            "Frisvad's worst error near the south pole over that on the upper hemisphere: f32 {:.3e}/{:.3e} = {g32:.1e} >= 100, f64 {:.3e}/{:.3e} = {g64:.1e} >= 100",
            pole.1, away.1, pole.3, away.3
        ),
    );
    r.claim(
        "frisvad_orders_above_duff_near_pole",
        pole.1 >= 100.0 * pole.0 && pole.3 >= 100.0 * pole.2,
        format!(
            "near the south pole, Frisvad's worst error over Duff et al.'s: f32 {:.3e}/{:.2} >= 100, f64 {:.3e}/{:.2} >= 100",
            pole.1, pole.0, pole.3, pole.2
        ),
    );
    writeln!(
        md,
        "\n*Worst of \\|\\|t\\| − 1\\|, \\|\\|b\\| − 1\\|, \\|t·b\\|, \\|t·n\\|, \\|b·n\\| and \\|t × b − n\\| in units of the precision's ε; {n} random normals, 256 per ring. The tests assert 4 ε. Generated by `tools/figures/src/frame.rs`.*"
    )?;
    Ok(md.into_bytes())
}

/// The worst error on each ring `1 + z = 10^-k` of the error table, for both constructions
/// and precisions: Frisvad's grows like `1 / (1 + z)` (in f32 at least threefold per decade,
/// as `frisvad_fails_near_the_south_pole` asserts) until its special case takes over below
/// `1 + z = 1e-7`, where in f64 the fixed frame is off by `sqrt(2 (1 + z))`
/// (`frisvad_special_case_is_off_by_the_distance_to_the_pole`, within 10 %).
fn rings_md(_: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut md = String::new();
    writeln!(
        md,
        "| 1 + z | Frisvad, f32 | Duff et al., f32 | Frisvad, f64 | Duff et al., f64 | Frisvad, f64: error / √(2(1 + z)) |"
    )?;
    writeln!(md, "|---:|---:|---:|---:|---:|---:|")?;
    let (mut frisvad32, mut off_by) = (Vec::new(), Vec::new());
    let mut duff_worst = 0.0f64;
    for k in 1..=15 {
        let eta = 10f64.powi(-k);
        let normals = ring(eta, 256);
        let f32_cells = if k <= 7 {
            let (f, d) = (
                worst32(&normals, frame32::frisvad),
                worst32(&normals, frame32::duff),
            );
            frisvad32.push((k, f));
            duff_worst = duff_worst.max(d);
            (
                r.text(&format!("k{k}.frisvad_f32"), format!("{f:.2e}")),
                format!("{d:.2}"),
            )
        } else {
            ("—".to_string(), "—".to_string())
        };
        let (f, d) = (worst64(&normals, frisvad), worst64(&normals, duff));
        duff_worst = duff_worst.max(d);
        let off = f * f64::EPSILON / (2.0 * eta).sqrt();
        let off_cell = if k >= 8 {
            off_by.push((k, off));
            format!("{off:.3}")
        } else {
            "—".to_string()
        };
        writeln!(
            md,
            "| 1e−{k} | {} | {} | {} | {d:.2} | {off_cell} |",
            f32_cells.0,
            f32_cells.1,
            r.text(&format!("k{k}.frisvad_f64"), format!("{f:.2e}")),
        )?;
    }
    let steps: Vec<(i32, f64)> = frisvad32
        .windows(2)
        .map(|p| (p[1].0, p[1].1 / p[0].1))
        .collect();
    let least = steps.iter().map(|s| s.1).fold(f64::INFINITY, f64::min);
    r.number("frisvad_f32.least_growth_per_decade", least, ".1");
    r.claim(
        "frisvad_f32_grows",
        steps.len() == 6 && least >= 3.0,
        format!(
            "Frisvad f32, worst(1e-k) / worst(1e-(k-1)) for k = 2..7, each >= 3: {}",
            steps
                .iter()
                .map(|(k, g)| format!("k = {k}: {g:.2}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    r.claim(
        "frisvad_f64_special_case_off_by_distance",
        off_by.len() == 8 && off_by.iter().all(|&(_, x)| (0.9..=1.1).contains(&x)),
        format!(
            "Frisvad f64 below its threshold, worst error / sqrt(2(1 + z)) for k = 8..15, each in [0.9, 1.1]: {}",
            off_by
                .iter()
                .map(|(k, x)| format!("k = {k}: {x:.3}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    );
    r.claim(
        "duff_within_bound_every_ring",
        duff_worst <= BOUND_EPS,
        format!("Duff et al.'s worst error over every ring and both precisions: {duff_worst:.2} ε <= {BOUND_EPS} ε"),
    );
    writeln!(
        md,
        "\n*Worst error of the frame (as in `frame_errors`) over a ring of 256 normals at z = −1 + 10⁻ᵏ, in units of the precision's ε (f32 rings only to k = 7: beyond, z rounds to −1). The last column is the f64 error in absolute terms over √(2(1 + z)), the distance of the ring from the pole, for the rings below Frisvad's threshold. Generated by `tools/figures/src/frame.rs`.*"
    )?;
    Ok(md.into_bytes())
}

/// Median ns per frame. `f` returns one component of each frame, stored in a buffer:
/// the work is kept, and the frames of a batch are independent of one another.
fn time_frames<V: Copy>(normals: &[V], reps: usize, f: impl Fn(V) -> f64) -> f64 {
    let mut out = vec![0.0; normals.len()];
    timing::median_ns_per_item(normals.len(), reps, || {
        for (o, &n) in out.iter_mut().zip(normals) {
            *o = f(black_box(n));
        }
        black_box(&out);
        out[0].to_bits()
    })
}

fn speed_md(settings: &Settings, r: &mut Record) -> anyhow::Result<Vec<u8>> {
    let reps = if settings.quick { 5 } else { 201 };
    let n64 = timing_normals(4096);
    let n32: Vec<Vec3> = n64.iter().map(|n| n.as_vec3()).collect();
    // Direct calls (not through a function pointer), so each construction is inlined.
    let rows = [
        (
            "duff",
            "Duff et al. 2017 (`Frame::from_normal`)",
            "f32",
            time_frames(&n32, reps, |n| {
                let f = frame32::Frame::from_normal(n);
                f64::from(f.t.x + f.b.y)
            }),
        ),
        (
            "frisvad",
            "Frisvad 2012",
            "f32",
            time_frames(&n32, reps, |n| {
                let (t, b) = frame32::frisvad(n);
                f64::from(t.x + b.y)
            }),
        ),
        (
            "duff",
            "Duff et al. 2017 (`Frame::from_normal`)",
            "f64",
            time_frames(&n64, reps, |n| {
                let f = Frame::from_normal(n);
                f.t.x + f.b.y
            }),
        ),
        (
            "frisvad",
            "Frisvad 2012",
            "f64",
            time_frames(&n64, reps, |n| {
                let (t, b) = frisvad(n);
                t.x + b.y
            }),
        ),
        (
            "helper_axis",
            "helper axis, cross product, normalise",
            "f64",
            time_frames(&n64, reps, |n| {
                let (t, b) = cross_product_frame(n);
                t.x + b.y
            }),
        ),
    ];
    let mut md = String::new();
    writeln!(md, "| construction | precision | ns per frame (median) |")?;
    writeln!(md, "|---|---|---:|")?;
    for (key, name, precision, ns) in rows {
        writeln!(
            md,
            "| {name} | {precision} | {} |",
            r.number(&format!("{key}.{precision}_ns"), ns, ".2")
        )?;
    }
    writeln!(
        md,
        "\n*{}; 4096 random normals per batch, median of {reps} batches{}.*",
        timing::machine(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
