//! Tests of the chapter *Tangent frames* (`src/sampling/frame.rs`).
//!
//! Deterministic (fixed seeds, constructed normals): no significance level is involved.
//! Frisvad's construction is the planted bug: it must fail the same bound near
//! `(0, 0, -1)` that Duff et al.'s passes everywhere.

use raylemma::check::max_abs;
use raylemma::sampling::sphere::sphere_uniform;
use std::f64::consts::TAU;

use glam::{DVec3, Vec3};
use quickcheck::{Gen, QuickCheck, TestResult};
use raylemma::rng;
use raylemma::sampling::frame::{Construction, Frame, duff, frisvad};
use raylemma::single::sampling::frame as frame32;

// ANCHOR: bound
/// Bound on [`Frame::error`] (lengths, dot products, `t × b - n`), in units of the
/// precision's epsilon. The input normal itself is unit only to within rounding, so the
/// bound covers that too; the measured worst cases are in `figures/frame_errors.md`.
const ORTHO_BOUND: f64 = 4.0;
// ANCHOR_END: bound

/// Normals at `z = -1 + delta`, at `azimuths` evenly spread angles, as f64. The x and y
/// components come from `sqrt(1 - z^2)` as a renderer would compute them, so the normal is
/// unit only to within rounding: exactly the input that breaks Frisvad's construction.
fn ring(delta: f64, azimuths: usize) -> impl Iterator<Item = DVec3> {
    let z = -1.0 + delta;
    let r = (1.0 - z * z).sqrt();
    (0..azimuths).map(move |j| {
        let phi = TAU * (j as f64 + 0.5) / azimuths as f64;
        DVec3::new(r * phi.cos(), r * phi.sin(), z)
    })
}

/// Exactly `(0, 0, -1)`, with every sign of zero, and normals with `-0.0` components.
fn signed_zero_normals() -> Vec<DVec3> {
    let mut v = Vec::new();
    for x in [0.0, -0.0] {
        for y in [0.0, -0.0] {
            v.push(DVec3::new(x, y, -1.0));
            v.push(DVec3::new(x, y, 1.0));
        }
    }
    for z in [0.0, -0.0] {
        for (x, y) in [
            (1.0, 0.0),
            (1.0, -0.0),
            (-1.0, -0.0),
            (0.0, 1.0),
            (-0.0, -1.0),
        ] {
            v.push(DVec3::new(x, y, z));
        }
        let h = std::f64::consts::FRAC_1_SQRT_2;
        v.push(DVec3::new(h, -h, z));
    }
    v
}

fn worst32(normals: impl Iterator<Item = DVec3>, f: frame32::Construction) -> f64 {
    max_abs(normals.map(|n| frame32::Frame::with(n.as_vec3(), f).error() / f64::from(f32::EPSILON)))
}

fn worst64(normals: impl Iterator<Item = DVec3>, f: Construction) -> f64 {
    max_abs(normals.map(|n| Frame::with(n, f).error() / f64::EPSILON))
}

fn random_normals(seed: u64, n: usize) -> Vec<DVec3> {
    let mut r = rng::seeded(seed);
    (0..n).map(|_| sphere_uniform(&mut r)).collect()
}

// ---------------------------------------------------------------------------------------
// Duff et al.: orthonormal and right-handed everywhere.

#[test]
fn duff_is_orthonormal_for_random_normals() {
    let normals = random_normals(1, 100_000);
    let (e32, e64) = (
        worst32(normals.iter().copied(), frame32::duff),
        worst64(normals.iter().copied(), duff),
    );
    assert!(e32 <= ORTHO_BOUND, "f32: {e32} eps");
    assert!(e64 <= ORTHO_BOUND, "f64: {e64} eps");
    println!("random normals, worst error: f32 {e32:.2} eps, f64 {e64:.2} eps");
}

// ANCHOR: near_south_pole
#[test]
fn duff_is_orthonormal_near_the_south_pole() {
    for k in 1..=15 {
        let e = worst64(ring(10f64.powi(-k), 256), duff);
        assert!(e <= ORTHO_BOUND, "f64, z = -1 + 1e-{k}: {e} eps");
    }
    for k in 1..=7 {
        let e = worst32(ring(10f64.powi(-k), 256), frame32::duff);
        assert!(e <= ORTHO_BOUND, "f32, z = -1 + 1e-{k}: {e} eps");
    }
    let zeros = signed_zero_normals();
    assert!(worst64(zeros.iter().copied(), duff) <= ORTHO_BOUND);
    assert!(worst32(zeros.iter().copied(), frame32::duff) <= ORTHO_BOUND);
}

/// The planted bug: Frisvad's construction fails the same bound as `n` approaches
/// `(0, 0, -1)`: from `z = -1 + 1e-2` on, in both precisions. In f32 at
/// `z = -1 + 1e-7` its error exceeds 0.1: it is not a frame at all.
#[test]
fn frisvad_fails_near_the_south_pole() {
    for k in 2..=15 {
        let e = worst64(ring(10f64.powi(-k), 256), frisvad);
        assert!(e > ORTHO_BOUND, "f64, z = -1 + 1e-{k}: only {e} eps");
    }
    for k in 2..=7 {
        let e = worst32(ring(10f64.powi(-k), 256), frame32::frisvad);
        assert!(e > ORTHO_BOUND, "f32, z = -1 + 1e-{k}: only {e} eps");
    }
    let e = worst32(ring(1e-7, 256), frame32::frisvad) * f64::from(f32::EPSILON);
    assert!(e > 0.1, "f32, z = -1 + 1e-7: error only {e}");
    // And it grows like 1 / (1 + z): at least threefold per decade, and by five orders of
    // magnitude over six decades (in f32, whose rings have about the same delta; in f64
    // the delta of the normals varies too much from ring to ring for a ratio).
    let at = |k: i32| worst32(ring(10f64.powi(-k), 256), frame32::frisvad);
    for k in 2..=7 {
        let ratio = at(k) / at(k - 1);
        assert!(
            ratio >= 3.0,
            "f32: only {ratio} times from 1e-{} to 1e-{k}",
            k - 1
        );
    }
    assert!(
        at(7) / at(1) >= 1e5,
        "f32: only {} over six decades",
        at(7) / at(1)
    );
}
// ANCHOR_END: near_south_pole

/// Below Frisvad's threshold the fixed frame ((0, -1, 0), (-1, 0, 0)) is exact only at the
/// pole; at `z = -1 + eta` it is off by `sqrt(2 eta)`, the distance of `n` from the pole.
#[test]
fn frisvad_special_case_is_off_by_the_distance_to_the_pole() {
    for k in 8..=15 {
        let eta = 10f64.powi(-k);
        let e = worst64(ring(eta, 256), frisvad) * f64::EPSILON;
        let ratio = e / (2.0 * eta).sqrt();
        assert!(
            (0.9..=1.1).contains(&ratio),
            "k = {k}: error {e:e}, ratio {ratio}"
        );
    }
}

/// `z` mirrored: `(x, y, z) -> (x, y, -z)`.
fn mirror(v: DVec3) -> DVec3 {
    DVec3::new(v.x, v.y, -v.z)
}

/// Below the equator Duff et al.'s frame is Frisvad's frame of the mirror image, mirrored
/// back, with `b` negated to restore the orientation (exercise 1's identities).
#[test]
fn duff_is_frisvad_mirrored_below_the_equator() {
    for n in random_normals(9, 20_000).into_iter().filter(|n| n.z < 0.0) {
        let (t, b) = duff(n);
        let (t1, b1) = frisvad(mirror(n));
        assert!((t - mirror(t1)).length() <= 4.0 * f64::EPSILON, "{n}");
        assert!((b + mirror(b1)).length() <= 4.0 * f64::EPSILON, "{n}");
    }
}

/// Duff et al.'s frame jumps between `z = +0` and `z = -0`: `t` by `(0, 0, -2x)` and `b` by
/// `(-2xy, 2 - 2y², 0)`, both of length `2|x|` on the equator (exercise 4).
#[test]
fn duff_jumps_across_the_equator() {
    for k in 0..64 {
        let phi = TAU * (f64::from(k) + 0.5) / 64.0;
        let (x, y) = (phi.cos(), phi.sin());
        let (up, down) = (duff(DVec3::new(x, y, 0.0)), duff(DVec3::new(x, y, -0.0)));
        let (dt, db) = (up.0 - down.0, up.1 - down.1);
        assert!((dt - DVec3::new(0.0, 0.0, -2.0 * x)).length() <= 4.0 * f64::EPSILON);
        let want = DVec3::new(-2.0 * x * y, 2.0 - 2.0 * y * y, 0.0);
        assert!((db - want).length() <= 4.0 * f64::EPSILON, "{db} {want}");
        for jump in [dt.length(), db.length()] {
            assert!(
                (jump - 2.0 * x.abs()).abs() <= 4.0 * f64::EPSILON,
                "{jump} at {phi}"
            );
        }
    }
}

/// Away from the south pole the two constructions are the same frame, and both pass.
#[test]
fn frisvad_is_fine_in_the_upper_hemisphere() {
    let upper: Vec<DVec3> = random_normals(2, 20_000)
        .into_iter()
        .map(|n| DVec3::new(n.x, n.y, n.z.abs()))
        .collect();
    assert!(worst64(upper.iter().copied(), frisvad) <= ORTHO_BOUND);
    assert!(worst32(upper.iter().copied(), frame32::frisvad) <= ORTHO_BOUND);
    for n in upper.iter().filter(|n| n.z > 0.0) {
        let (a, b) = (Frame::from_normal(*n), Frame::with(*n, frisvad));
        assert!((a.t - b.t).length() <= 4.0 * f64::EPSILON, "{n}");
        assert!((a.b - b.b).length() <= 4.0 * f64::EPSILON, "{n}");
    }
}

#[test]
fn right_handed_everywhere() {
    let normals: Vec<DVec3> = random_normals(3, 20_000)
        .into_iter()
        .chain((1..=15).flat_map(|k| ring(10f64.powi(-k), 16)))
        .chain(signed_zero_normals())
        .collect();
    for n in normals {
        let f = Frame::from_normal(n);
        assert!(f.t.cross(f.b).dot(n) > 0.0, "{n}: {f:?}");
        let g = frame32::Frame::from_normal(n.as_vec3());
        assert!(g.t.cross(g.b).dot(g.n) > 0.0, "{n}: {g:?}");
    }
}

/// An independent implementation of the same equations: glam's `any_orthonormal_pair`.
#[test]
fn matches_glams_implementation_of_the_same_paper() {
    for n in random_normals(4, 10_000)
        .into_iter()
        .chain(signed_zero_normals())
    {
        let f = Frame::from_normal(n);
        assert_eq!((f.t, f.b), n.any_orthonormal_pair(), "{n}");
        let m = n.as_vec3();
        let g = frame32::Frame::from_normal(m);
        assert_eq!((g.t, g.b), m.any_orthonormal_pair(), "{m}");
    }
}

// ---------------------------------------------------------------------------------------
// Changing coordinates.

#[test]
fn round_trip_and_axes() {
    let mut r = rng::seeded(5);
    let normals = random_normals(6, 10_000)
        .into_iter()
        .chain((1..=15).flat_map(|k| ring(10f64.powi(-k), 8)))
        .chain(signed_zero_normals());
    for n in normals {
        let f = Frame::from_normal(n);
        assert_eq!(f.to_world(DVec3::Z), n);
        let z = f.to_local(n);
        assert!(
            max_abs((z - DVec3::Z).to_array()) <= 4.0 * f64::EPSILON,
            "{n}: {z}"
        );
        let v = sphere_uniform(&mut r) * rng::log_uniform(&mut r, 1e-3, 1e3);
        let back = f.to_world(f.to_local(v));
        assert!(
            (back - v).length() <= 8.0 * f64::EPSILON * v.length(),
            "{n}: {v} -> {back}"
        );
        let g = frame32::Frame::from_normal(n.as_vec3());
        let v32 = v.as_vec3();
        let back32 = g.to_world(g.to_local(v32));
        assert!(
            (back32 - v32).length() <= 8.0 * f32::EPSILON * v32.length(),
            "{n}: {v32} -> {back32}"
        );
    }
}

/// Sampling about the normal: a local direction with positive z maps to the normal's side.
#[test]
fn local_upper_hemisphere_maps_to_the_normals_side() {
    let mut r = rng::seeded(7);
    for n in random_normals(8, 10_000) {
        let mut local = sphere_uniform(&mut r);
        local.z = local.z.abs().max(1e-6);
        let w = Frame::from_normal(n).to_world(local);
        assert!(w.dot(n) > 0.0);
        assert!((w.length() - 1.0).abs() <= 8.0 * f64::EPSILON);
    }
}

// ---------------------------------------------------------------------------------------
// Properties over arbitrary normals (quickcheck, fixed seeds).

fn quickcheck(seed: u64) -> QuickCheck {
    QuickCheck::new()
        .rng(Gen::from_size_and_seed(100, seed))
        .tests(10_000)
        .max_tests(100_000)
}

/// A unit normal from three arbitrary numbers, or `None` if they are degenerate.
fn normal(x: f64, y: f64, z: f64) -> Option<DVec3> {
    let v = DVec3::new(x, y, z);
    let l = v.length();
    (v.is_finite() && l.is_finite() && l > 1e-100).then(|| v / l)
}

fn prop_orthonormal(x: f64, y: f64, z: f64) -> TestResult {
    let Some(n) = normal(x, y, z) else {
        return TestResult::discard();
    };
    let (a, b) = (
        Frame::from_normal(n).error() / f64::EPSILON,
        frame32::Frame::from_normal(n.as_vec3()).error() / f64::from(f32::EPSILON),
    );
    TestResult::from_bool(a <= ORTHO_BOUND && b <= ORTHO_BOUND)
}

#[test]
fn quickcheck_orthonormal() {
    quickcheck(1).quickcheck(prop_orthonormal as fn(f64, f64, f64) -> TestResult);
}

/// Directions near the south pole, where quickcheck's small integers rarely go.
fn prop_orthonormal_near_south_pole(x: i32, y: i32, k: u8) -> TestResult {
    let scale = 10f64.powi(-i32::from(k % 16));
    let Some(n) = normal(f64::from(x) * scale, f64::from(y) * scale, -1.0) else {
        return TestResult::discard();
    };
    let e = Frame::from_normal(n).error() / f64::EPSILON;
    TestResult::from_bool(e <= ORTHO_BOUND)
}

#[test]
fn quickcheck_orthonormal_near_south_pole() {
    quickcheck(2).quickcheck(prop_orthonormal_near_south_pole as fn(i32, i32, u8) -> TestResult);
}

fn prop_round_trip(x: f64, y: f64, z: f64, v: (i16, i16, i16)) -> TestResult {
    let Some(n) = normal(x, y, z) else {
        return TestResult::discard();
    };
    let v = DVec3::new(f64::from(v.0), f64::from(v.1), f64::from(v.2));
    let f = Frame::from_normal(n);
    let back = f.to_world(f.to_local(v));
    TestResult::from_bool((back - v).length() <= 8.0 * f64::EPSILON * v.length())
}

#[test]
fn quickcheck_round_trip() {
    quickcheck(3).quickcheck(prop_round_trip as fn(f64, f64, f64, (i16, i16, i16)) -> TestResult);
}

/// A frame is unchanged, component by component, when built in f32 from the rounded
/// normal and compared with the f64 frame, to within a few f32 epsilons.
fn prop_precisions_agree(x: f64, y: f64, z: f64) -> TestResult {
    let Some(n) = normal(x, y, z) else {
        return TestResult::discard();
    };
    // Near z = 0 the sign of z (and so the frame) may differ between the precisions.
    if n.z.abs() < 1e-3 {
        return TestResult::discard();
    }
    let (a, b) = (
        Frame::from_normal(n),
        frame32::Frame::from_normal(n.as_vec3()),
    );
    let d = (a.t - b.t.as_dvec3()).length() + (a.b - b.b.as_dvec3()).length();
    TestResult::from_bool(d <= 16.0 * f64::from(f32::EPSILON))
}

#[test]
fn quickcheck_precisions_agree() {
    quickcheck(4).quickcheck(prop_precisions_agree as fn(f64, f64, f64) -> TestResult);
}

/// The error measure itself must not pass a broken frame: a NaN in any component, of any
/// vector, makes the error NaN (it used to be dropped by `f64::max` and glam's
/// `max_element`, scoring a NaN frame as perfect).
#[test]
fn orthonormality_error_keeps_a_nan() {
    use raylemma::sampling::frame::orthonormality_error;
    let (t, b, n) = (DVec3::X, DVec3::Y, DVec3::Z);
    assert_eq!(orthonormality_error(t, b, n), 0.0);
    for i in 0..3 {
        let mut bad = [0.0; 3];
        bad[i] = f64::NAN;
        let nan = DVec3::from_array(bad);
        for (tt, bb, nn) in [(t + nan, b, n), (t, b + nan, n), (t, b, n + nan)] {
            let e = orthonormality_error(tt, bb, nn);
            assert!(e.is_nan(), "NaN at {i} scored {e}");
        }
    }
    // A frame whose only fault is the handedness, in its first component.
    assert!(orthonormality_error(DVec3::Y, DVec3::X, DVec3::Z) >= 2.0);
}

#[test]
fn vec3_and_dvec3_frames_are_the_same_type_of_thing() {
    let f: frame32::Frame = frame32::Frame::from_normal(Vec3::Z);
    assert_eq!((f.t, f.b, f.n), (Vec3::X, Vec3::Y, Vec3::Z));
    let g: Frame = Frame::from_normal(-DVec3::Z);
    assert_eq!((g.t, g.b, g.n), (DVec3::X, -DVec3::Y, -DVec3::Z));
}

// ---------------------------------------------------------------------------------------
// Exercises: each is ignored until you fill in its scaffold
// (`cargo test --test book sampling::frame::exercise_ -- --ignored`).

/// Exercise 2 of *Tangent frames*: your prediction of the worst error of Frisvad's frame,
/// in `f32`, on the ring `1 + z = 1e-4`, in units of `f32::EPSILON`.
const YOUR_ANSWER_2: Option<f64> = None;

#[test]
#[ignore = "exercise 2 of Tangent frames: put your prediction in YOUR_ANSWER_2, then run it"]
fn exercise_2_predict_the_figure() {
    let measured = worst32(ring(1e-4, 256), frame32::frisvad);
    let yours = YOUR_ANSWER_2.expect("exercise 2 of Tangent frames: YOUR_ANSWER_2 is still None");
    assert!(
        (yours / measured - 1.0).abs() <= 0.1,
        "you predict {yours:.4e} eps; the ring's worst error is {measured:.4e} eps"
    );
}

/// Exercise 3 of *Tangent frames*: the value of `1 + z` below which your Frisvad uses the
/// fixed frame `((0, -1, 0), (-1, 0, 0))` (Frisvad's own is `1e-7`).
fn your_threshold() -> f64 {
    unimplemented!("exercise 3 of Tangent frames: the threshold that minimises the worst error")
}

/// The worst error, in f64 epsilons, of Frisvad's construction with the fixed frame below
/// `1 + z = threshold`, over rings from `1 + z = 1e-1` to `1e-15`, eight per decade.
fn worst_with_threshold(threshold: f64) -> f64 {
    max_abs(
        (8..=120)
            .flat_map(|k| ring(10f64.powf(-f64::from(k) / 8.0), 64))
            .map(|n| {
                let (t, b) = if 1.0 + n.z < threshold {
                    (DVec3::new(0.0, -1.0, 0.0), DVec3::new(-1.0, 0.0, 0.0))
                } else {
                    frisvad(n)
                };
                Frame { t, b, n }.error() / f64::EPSILON
            }),
    )
}

#[test]
#[ignore = "exercise 3 of Tangent frames: fill in your_threshold, then run it"]
fn exercise_3_move_the_threshold() {
    let best = (0..=60)
        .map(|j| worst_with_threshold(10f64.powf(-4.0 - f64::from(j) / 6.0)))
        .fold(f64::INFINITY, f64::min);
    let yours = worst_with_threshold(your_threshold());
    assert!(
        yours <= 2.0 * best,
        "your threshold's worst error is {yours:.3e} eps; the best of the sweep is {best:.3e} eps"
    );
    // Why it is still far above Duff et al.'s: the two errors it balances, the rounding of
    // the normal divided by 1 + z above and the distance to the pole below, meet far above.
    assert!(best >= 1e10, "best {best:e}");
}

/// Exercise 5 of *Tangent frames*: `(t, b)` for the unit normal `n` by the helper-axis
/// method: a helper vector orthogonal to `n`, normalised, and a second cross product.
fn your_helper_axis_frame(n: DVec3) -> (DVec3, DVec3) {
    let _ = n;
    unimplemented!("exercise 5 of Tangent frames: a frame by the helper-axis method")
}

#[test]
#[ignore = "exercise 5 of Tangent frames: fill in your_helper_axis_frame, then run it"]
fn exercise_5_your_own_frame() {
    let normals: Vec<DVec3> = random_normals(10, 100_000)
        .into_iter()
        .chain((1..=15).flat_map(|k| ring(10f64.powi(-k), 256)))
        .chain(signed_zero_normals())
        .collect();
    let e = worst64(normals.iter().copied(), your_helper_axis_frame);
    assert!(e <= ORTHO_BOUND, "worst error {e} eps");
    let mut r = rng::seeded(11);
    for n in normals {
        let f = Frame::with(n, your_helper_axis_frame);
        assert!(f.t.cross(f.b).dot(n) > 0.0, "{n}: left-handed {f:?}");
        let v = sphere_uniform(&mut r) * rng::log_uniform(&mut r, 1e-3, 1e3);
        let back = f.to_world(f.to_local(v));
        assert!(
            (back - v).length() <= 8.0 * f64::EPSILON * v.length(),
            "{n}: {v} -> {back}"
        );
    }
}
