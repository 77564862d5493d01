//! Figures and tables of the chapter *Tangent frames*.

use raylemma::sampling::sphere::sphere_uniform;
use std::f64::consts::TAU;
use std::fmt::Write as _;
use std::hint::black_box;

use glam::{DVec3, Vec3};

use super::{Output, Record, Settings, timing};
use crate::plot::{self, BoxError, Panel, Series};
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

fn error_svg(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let azimuths = if settings.quick { 64 } else { 1024 };
    // 1 + z from 1 down to 1e-7 (f32) and 1e-15 (f64), four points per decade.
    let deltas = |decades: i32| -> Vec<f64> {
        (0..=4 * decades)
            .map(|k| 10f64.powf(-f64::from(k) / 4.0))
            .collect()
    };
    let series32 = |label: &str, f: frame32::Construction| {
        Series::line(
            label,
            deltas(7)
                .into_iter()
                .map(|d| {
                    // The distance the rounded normals really have from z = -1.
                    let normals = ring(d, azimuths);
                    let dz = 1.0 + f64::from(normals[0].as_vec3().z);
                    (dz, worst32(&normals, f))
                })
                .collect(),
        )
    };
    let series64 = |label: &str, f: Construction| {
        Series::line(
            label,
            deltas(15)
                .into_iter()
                .map(|d| {
                    let normals = ring(d, azimuths);
                    (1.0 + normals[0].z, worst64(&normals, f))
                })
                .collect(),
        )
    };
    let panels = [
        Panel::new(
            "f32: worst error over a ring of normals",
            "1 + z (distance from (0, 0, −1))",
            "worst error (f32 epsilons)",
            vec![
                series32("Frisvad 2012", frame32::frisvad),
                series32("Duff et al. 2017", frame32::duff),
            ],
        )
        .log_x()
        .log_y(),
        Panel::new(
            "f64",
            "1 + z",
            "worst error (f64 epsilons)",
            vec![
                series64("Frisvad 2012", frisvad),
                series64("Duff et al. 2017", duff),
            ],
        )
        .log_x()
        .log_y(),
    ];
    plot::chart(&panels, 2)
}

fn errors_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let n = if settings.quick { 10_000 } else { 100_000 };
    let mut r = rng::seeded(1);
    let random: Vec<DVec3> = (0..n).map(|_| sphere_uniform(&mut r)).collect();
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
    for (name, n32, n64) in [
        ("random, whole sphere", &random, &random),
        ("random, upper hemisphere (z ≥ 0)", &upper, &upper),
        (
            "z = −1 + 10⁻ᵏ, k = 1…7 (f32) and 1…15 (f64)",
            &pole32,
            &pole64,
        ),
    ] {
        writeln!(
            md,
            "| {name} | {:.2} | {:.3e} | {:.2} | {:.3e} |",
            worst32(n32, frame32::duff),
            worst32(n32, frame32::frisvad),
            worst64(n64, duff),
            worst64(n64, frisvad)
        )?;
    }
    writeln!(
        md,
        "\n*Worst of \\|\\|t\\| − 1\\|, \\|\\|b\\| − 1\\|, \\|t·b\\|, \\|t·n\\|, \\|b·n\\| and \\|t × b − n\\| in units of the precision's ε; {n} random normals, 256 per ring. The tests assert 4 ε. Generated by `tools/figures/src/frame.rs`.*"
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

fn speed_md(settings: &Settings, _: &mut Record<'_>) -> Result<Vec<u8>, BoxError> {
    let reps = if settings.quick { 5 } else { 201 };
    let n64 = timing_normals(4096);
    let n32: Vec<Vec3> = n64.iter().map(|n| n.as_vec3()).collect();
    // Direct calls (not through a function pointer), so each construction is inlined.
    let rows = [
        (
            "Duff et al. 2017 (`Frame::from_normal`)",
            "f32",
            time_frames(&n32, reps, |n| {
                let f = frame32::Frame::from_normal(n);
                f64::from(f.t.x + f.b.y)
            }),
        ),
        (
            "Frisvad 2012",
            "f32",
            time_frames(&n32, reps, |n| {
                let (t, b) = frame32::frisvad(n);
                f64::from(t.x + b.y)
            }),
        ),
        (
            "Duff et al. 2017 (`Frame::from_normal`)",
            "f64",
            time_frames(&n64, reps, |n| {
                let f = Frame::from_normal(n);
                f.t.x + f.b.y
            }),
        ),
        (
            "Frisvad 2012",
            "f64",
            time_frames(&n64, reps, |n| {
                let (t, b) = frisvad(n);
                t.x + b.y
            }),
        ),
        (
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
    for (name, precision, ns) in rows {
        writeln!(md, "| {name} | {precision} | {ns:.2} |")?;
    }
    writeln!(
        md,
        "\n*{}; 4096 random normals per batch, median of {reps} batches{}.*",
        timing::machine(),
        timing::quick_note(settings.quick)
    )?;
    Ok(md.into_bytes())
}
