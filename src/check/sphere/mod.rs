//! Checks for any ray-sphere intersection routine. Chapter: *Ray-sphere intersection*
//! (`chapters/geometry/sphere.md`).
//!
//! * [`intersection`]: six claims on constructed rays, in either precision;
//! * [`far`]: the hard case, a unit sphere `1e2` to `1e4` radii away, in either
//!   precision ([`far_row`] measures one distance, for the chapter's table and figure);
//! * [`self_hit_rate`]: how often a ray leaving the surface finds its own sphere with
//!   `t_min = 0` (the source notes' rule);
//! * [`planted`]: the intersectors with the classic mistakes, which the checker must
//!   reject.
//!
//! Every case is *constructed* with a known answer rather than solved by a reference
//! routine: a ray is aimed at a chosen point of the sphere, or passes the centre at a
//! chosen distance, so the expected hit, miss and `t` follow from the construction.
//! Errors are measured along the ray (`|t - t*| |D|`) in units of
//! `eps (|O| + |C| + r)`, the size of the rounding already present in the inputs.

pub mod planted;

use crate::sampling::sphere::sphere_uniform;
use glam::DVec3;

use super::{Finding, Options, Verdict};
use crate::real::Real;
use crate::rng::{self, Rng, log_uniform, uniform};

/// Anything that intersects a ray with a sphere: returns the smallest `t > t_min` with
/// `|O + tD - C| = r`, or `None`.
///
/// Implemented for every `Fn(&R::Ray, &R::Sphere, R) -> Option<R>`, so a plain function
/// such as `raylemma::single::geometry::sphere::intersect_stable` (`f32`) or
/// `raylemma::geometry::sphere::intersect_stable` (`f64`) is an intersector.
pub trait SphereIntersector<R: Real> {
    /// The first intersection beyond `t_min`.
    fn intersect(&self, ray: &R::Ray, sphere: &R::Sphere, t_min: R) -> Option<R>;
}

impl<R: Real, F: Fn(&R::Ray, &R::Sphere, R) -> Option<R>> SphereIntersector<R> for F {
    fn intersect(&self, ray: &R::Ray, sphere: &R::Sphere, t_min: R) -> Option<R> {
        self(ray, sphere, t_min)
    }
}

// ANCHOR: bounds
/// Bound on the error of `t` (along the ray) for well-conditioned hits, in units of
/// `eps (|O| + |C| + r)`.
pub const T_ERROR_BOUND: f64 = 16.0;
/// Bound on `| |P - C| - r |` at the returned hit point `P`, same units.
pub const ON_SPHERE_BOUND: f64 = 16.0;
/// Rays passing within this many units of the silhouette (`| h - r |`, `h` the distance of
/// the centre from the ray's line) may be reported as hit or miss.
pub const SILHOUETTE_BAND: f64 = 16.0;
// ANCHOR_END: bounds

/// The default seed of [`intersection`] and [`far`].
pub const SEED: u64 = 0x5eed_5fe7e;

/// The default number of random cases per claim of [`intersection`].
pub const CASES: usize = 20_000;

/// A constructed case: a ray, a sphere, and their widened (`f64`) values.
struct Case<R: Real> {
    ray: R::Ray,
    sphere: R::Sphere,
    /// `eps (|O| + |C| + r)`: one unit of error for this case.
    unit: f64,
}

impl<R: Real> Case<R> {
    fn new(origin: DVec3, dir: DVec3, center: DVec3, radius: f64) -> Self {
        let ray = R::ray(origin, dir);
        let sphere = R::sphere(center, radius);
        let eps = R::EPSILON.wide();
        let unit = eps
            * (R::wide3(R::origin(&ray)).length()
                + R::wide3(R::center(&sphere)).length()
                + R::radius(&sphere).wide());
        Self { ray, sphere, unit }
    }

    fn dir_len(&self) -> f64 {
        R::wide3(R::dir(&self.ray)).length()
    }

    fn describe(&self, t_min: f64, got: Option<R>, expected: &str) -> String {
        format!(
            "ray O={:?} D={:?}, sphere C={:?} r={}, t_min={t_min:e}: got {got:?}, expected {expected}",
            R::origin(&self.ray),
            R::dir(&self.ray),
            R::center(&self.sphere),
            R::radius(&self.sphere)
        )
    }
}

/// A random scene: a radius `r` log-uniform in `[0.01, 100]` (four decades), a centre
/// uniform in the cube of half-side `10 r` around the origin, and a ray direction of
/// log-uniform length in `[0.01, 100]` (four decades).
fn random_frame(rng: &mut Rng) -> (DVec3, f64, DVec3) {
    let radius = log_uniform(rng, 1e-2, 1e2);
    let center = DVec3::new(
        uniform(rng, -10.0, 10.0),
        uniform(rng, -10.0, 10.0),
        uniform(rng, -10.0, 10.0),
    ) * radius;
    let dir = sphere_uniform(rng) * log_uniform(rng, 1e-2, 1e2);
    (center, radius, dir)
}

/// Runs every check of the chapter on `f` and returns the verdict: `options` sets the
/// number of random cases per claim (default [`CASES`]) and their seed (default [`SEED`]).
pub fn intersection<R: Real>(f: &impl SphereIntersector<R>, options: &Options) -> Verdict {
    let cases = options.cases_or(CASES);
    let mut rng = rng::seeded(options.seed_or(SEED));
    let mut verdict = Verdict::new(format!("ray-sphere intersection ({})", R::NAME));
    verdict.findings.push(hits(f, &mut rng, cases));
    verdict.findings.push(misses(f, &mut rng, cases));
    verdict.findings.push(tangents(f, &mut rng, cases));
    verdict.findings.push(nearest_root(f, &mut rng, cases));
    verdict.findings.push(surface_origin(f, &mut rng, cases));
    verdict.findings.push(direction_scale(f, &mut rng, cases));
    verdict
}

/// Rays aimed at a known entry point `P = C + r u` from outside: the routine must hit,
/// with `t` within [`T_ERROR_BOUND`] and the hit point within [`ON_SPHERE_BOUND`].
fn hits<R: Real>(f: &impl SphereIntersector<R>, rng: &mut Rng, n: usize) -> Finding {
    let mut finding = Finding::new(
        "hits",
        "a ray aimed at a point of the sphere from outside hits it: \
         |t - t*||D| <= 16 eps (|O|+|C|+r) and | |P-C| - r | <= 16 eps (|O|+|C|+r)",
    )
    .in_unit("multiples of eps (|O| + |C| + r)");
    for _ in 0..n {
        let (center, radius, dir) = random_frame(rng);
        let u = sphere_uniform(rng);
        let dir = if dir.dot(u) > 0.0 { -dir } else { dir }; // entering through the front
        // The angle to the inward normal is at most ~84 degrees, keeping the entry
        // well-conditioned (tangents are checked separately).
        if -dir.normalize().dot(u) < 0.1 {
            continue;
        }
        let t_star = log_uniform(rng, 0.1, 10.0) * radius / dir.length();
        let origin = center + u * radius - dir * t_star;
        let case = Case::<R>::new(origin, dir, center, radius);
        let got = f.intersect(&case.ray, &case.sphere, R::ZERO);
        let describe = || case.describe(0.0, got, &format!("t = {t_star:e}"));
        match got {
            Some(t) => {
                let t_err = (t.wide() - t_star).abs() * case.dir_len() / case.unit;
                let p = R::wide3(R::at(&case.ray, t));
                let c = R::wide3(R::center(&case.sphere));
                let off = ((p - c).length() - R::radius(&case.sphere).wide()).abs() / case.unit;
                finding.measure(t_err.max(off), T_ERROR_BOUND.max(ON_SPHERE_BOUND), describe);
            }
            None => finding.record(false, describe),
        }
    }
    finding
}

/// Lines that pass the centre at distance `h = r (1 + m)`, `m` from 1e-3 to 10: no hit.
fn misses<R: Real>(f: &impl SphereIntersector<R>, rng: &mut Rng, n: usize) -> Finding {
    let mut finding = Finding::new(
        "misses",
        "a line passing farther than r from the centre (by 0.1% of r or more) never hits",
    )
    .in_unit("multiples of eps (|O| + |C| + r)");
    for _ in 0..n {
        let (center, radius, dir) = random_frame(rng);
        let h = radius * (1.0 + log_uniform(rng, 1e-3, 10.0));
        let side = dir.normalize().any_orthonormal_pair();
        let phi = uniform(rng, 0.0, std::f64::consts::TAU);
        let offset = (side.0 * phi.cos() + side.1 * phi.sin()) * h;
        // Start anywhere along the line, before, beside or past the sphere.
        let t_c = uniform(rng, -20.0, 20.0) * radius / dir.length();
        let origin = center + offset - dir * t_c;
        let case = Case::<R>::new(origin, dir, center, radius);
        if (h - radius) <= SILHOUETTE_BAND * case.unit {
            continue;
        }
        let got = f.intersect(&case.ray, &case.sphere, R::lit(f64::MIN));
        finding.record(got.is_none(), || case.describe(f64::MIN, got, "no hit"));
    }
    finding
}

/// Exactly tangent lines: either answer is right, but the routine must not produce NaN,
/// and a reported hit must lie near the point of tangency.
fn tangents<R: Real>(f: &impl SphereIntersector<R>, rng: &mut Rng, n: usize) -> Finding {
    let mut finding = Finding::new(
        "tangents",
        "a tangent ray gives no NaN, and a hit (if any) at the tangent point: \
         |t - t*||D| <= 4 sqrt(eps) (|O|+|C|+r)",
    )
    .in_unit("multiples of eps (|O| + |C| + r)");
    for _ in 0..n {
        let (center, radius, dir) = random_frame(rng);
        let u = dir.normalize().any_orthonormal_vector();
        let t_star = log_uniform(rng, 0.1, 10.0) * radius / dir.length();
        let origin = center + u * radius - dir * t_star;
        let case = Case::<R>::new(origin, dir, center, radius);
        let got = f.intersect(&case.ray, &case.sphere, R::ZERO);
        let bound = 4.0 * R::EPSILON.wide().sqrt() / R::EPSILON.wide();
        let describe = || case.describe(0.0, got, &format!("none, or t near {t_star:e}"));
        match got {
            Some(t) => {
                let err = (t.wide() - t_star).abs() * case.dir_len() / case.unit;
                finding.measure(err, bound, describe);
            }
            None => finding.record(true, describe),
        }
    }
    finding
}

/// A chord through the sphere with known roots `t_c -+ w`; the origin is placed before,
/// inside and past the sphere, and `t_min` between the roots.
fn nearest_root<R: Real>(f: &impl SphereIntersector<R>, rng: &mut Rng, n: usize) -> Finding {
    let mut finding = Finding::new(
        "nearest_root",
        "the smallest root above t_min is returned: the entry from outside, the exit from \
         inside or when t_min lies between the roots, nothing when both are below t_min",
    )
    .in_unit("multiples of eps (|O| + |C| + r)");
    for i in 0..n {
        let (center, radius, dir) = random_frame(rng);
        let d_len = dir.length();
        let h = radius * uniform(rng, 0.0, 0.9);
        let w = (radius * radius - h * h).sqrt() / d_len; // half-chord, in units of t
        let side = dir.normalize().any_orthonormal_vector();
        // Where along the chord the origin sits, and where t_min is.
        let (t_c, t_min, expected) = match i % 4 {
            0 => (w * uniform(rng, 1.5, 20.0), 0.0, Some(-1.0)), // outside, sphere ahead
            1 => (w * uniform(rng, -0.8, 0.8), 0.0, Some(1.0)),  // inside
            2 => {
                let t_c = w * uniform(rng, 1.5, 20.0);
                (t_c, t_c + w * uniform(rng, -0.8, 0.8), Some(1.0)) // t_min between roots
            }
            _ => (-w * uniform(rng, 1.5, 20.0), 0.0, None), // sphere behind
        };
        let origin = center + side * h - dir * t_c;
        let case = Case::<R>::new(origin, dir, center, radius);
        let got = f.intersect(&case.ray, &case.sphere, R::lit(t_min));
        let want = expected.map(|s| t_c + s * w);
        let which = [
            "origin outside, sphere ahead: the entry (near root) is the answer",
            "origin inside: the exit (far root) is the answer",
            "t_min between the roots: the far root is the answer",
            "sphere behind the origin: no hit",
        ][i % 4];
        let describe = || {
            format!(
                "{which}; {}",
                case.describe(t_min, got, &format!("{want:?}"))
            )
        };
        match (got, want) {
            (None, None) => finding.record(true, describe),
            (Some(t), Some(t_star)) => {
                let err = (t.wide() - t_star).abs() * d_len / case.unit;
                finding.measure(err, T_ERROR_BOUND, describe);
            }
            _ => finding.record(false, describe),
        }
    }
    finding
}

/// Rays starting on the surface. With a small `t_min` (here `1e-3 r / |D|`) a ray
/// leaving the sphere finds nothing and a ray entering it finds the far side.
fn surface_origin<R: Real>(f: &impl SphereIntersector<R>, rng: &mut Rng, n: usize) -> Finding {
    let mut finding = Finding::new(
        "surface_origin",
        "from a point on the surface, with t_min = 1e-3 r/|D|: outward rays miss, \
         inward rays hit the far side at t = 2 r cos(theta) / |D|",
    )
    .in_unit("multiples of eps (|O| + |C| + r)");
    for i in 0..n {
        let (center, radius, dir) = random_frame(rng);
        let u = sphere_uniform(rng);
        let d_len = dir.length();
        let cos = dir.dot(u) / d_len;
        if cos.abs() < 0.1 {
            continue;
        }
        // Alternate outward and inward rays.
        let dir = if (cos > 0.0) == (i % 2 == 0) {
            dir
        } else {
            -dir
        };
        let cos = dir.dot(u) / d_len;
        let case = Case::<R>::new(center + u * radius, dir, center, radius);
        let t_min = 1e-3 * radius / d_len;
        let got = f.intersect(&case.ray, &case.sphere, R::lit(t_min));
        let want = (cos < 0.0).then(|| -2.0 * radius * cos / d_len);
        let describe = || case.describe(t_min, got, &format!("{want:?}"));
        match (got, want) {
            (None, None) => finding.record(true, describe),
            (Some(t), Some(t_star)) => {
                let err = (t.wide() - t_star).abs() * d_len / case.unit;
                finding.measure(err, T_ERROR_BOUND, describe);
            }
            _ => finding.record(false, describe),
        }
    }
    finding
}

/// Scaling `D` by `s` must scale `t` by `1/s`: the ray's points do not change.
fn direction_scale<R: Real>(f: &impl SphereIntersector<R>, rng: &mut Rng, n: usize) -> Finding {
    let mut finding = Finding::new(
        "direction_scale",
        "unnormalised directions: D -> sD gives t -> t/s (s from 1e-3 to 1e3, powers of two \
         and not), the same point within the t-error bound",
    )
    .in_unit("multiples of eps (|O| + |C| + r)");
    let scales = [1e-3, 0.5, 3.0, 1e3];
    for i in 0..n {
        let (center, radius, dir) = random_frame(rng);
        let u = sphere_uniform(rng);
        let dir = if dir.dot(u) > 0.0 { -dir } else { dir };
        if -dir.normalize().dot(u) < 0.1 {
            continue;
        }
        let t_star = log_uniform(rng, 0.1, 10.0) * radius / dir.length();
        let origin = center + u * radius - dir * t_star;
        let s = scales[i % scales.len()];
        let case = Case::<R>::new(origin, dir * s, center, radius);
        let got = f.intersect(&case.ray, &case.sphere, R::ZERO);
        let want = t_star / s;
        let describe = || case.describe(0.0, got, &format!("t = {want:e}"));
        match got {
            Some(t) => {
                let err = (t.wide() - want).abs() * case.dir_len() / case.unit;
                finding.measure(err, T_ERROR_BOUND, describe);
            }
            None => finding.record(false, describe),
        }
    }
    finding
}

// ANCHOR: far_row
/// What one form does to a unit sphere seen from `distance` away by a bundle of parallel
/// rays (inputs in the form's precision, answers from an `f64` computation on the same
/// inputs).
#[derive(Clone, Copy, Debug)]
pub struct FarRow {
    /// Distance from the ray origins to the centre, in radii.
    pub distance: f64,
    /// Rays whose hit/miss is unambiguous (outside the silhouette band).
    pub rays: usize,
    /// Of those, rays reported as hit when they miss or the reverse.
    pub wrong: usize,
    /// Hits (within 0.9 r of the centre) whose `t` error exceeds [`T_ERROR_BOUND`].
    pub over_bound: usize,
    /// Worst `|t - t*|` (in radii) over rays passing within 0.9 r of the centre.
    pub worst_t_error: f64,
    /// The same, in units of `eps (|O - C| + r)`.
    pub worst_t_units: f64,
}
// ANCHOR_END: far_row

/// The centre of the far-sphere test's unit sphere (exact in f32).
const FAR_CENTER: DVec3 = DVec3::new(1.25, -0.5, 2.0);

/// Shoots a `grid x grid` bundle of parallel rays, in `f`'s precision, at a unit sphere
/// `distance` radii away, over offsets in `[-1.25, 1.25]^2` across the direction, and
/// counts wrong answers and the worst `t` error. The grid is [`far_grid`]`(options)`
/// (default [`FAR_GRID`]); the bundle's direction is drawn from the seed (default
/// [`SEED`]) and the distance.
///
/// The answers are computed in `f64` from the rounded inputs (exactly representable in
/// `f64`), from the distance `h` of the centre to the line: its error is a few
/// `eps_64 (distance + r)`. For an `f32` routine that is about 1e-9 of the routine's own
/// errors. For an `f64` routine it is still well inside the silhouette band, so the
/// hit/miss answers are right at any distance; the `t` reference is only as good as the
/// stable form in `f64`, enough to measure errors far above it (the textbook form's),
/// not to judge the stable form's.
pub fn far_row<R: Real>(f: &impl SphereIntersector<R>, distance: f64, options: &Options) -> FarRow {
    let grid = far_grid(options);
    let mut rng = rng::seeded(options.seed_or(SEED) ^ distance.to_bits());
    let d_hat = sphere_uniform(&mut rng);
    let (e1, e2) = d_hat.any_orthonormal_pair();
    let sphere = R::sphere(FAR_CENTER, 1.0);
    let c = FAR_CENTER;
    let mut row = FarRow {
        distance,
        rays: 0,
        wrong: 0,
        over_bound: 0,
        worst_t_error: 0.0,
        worst_t_units: 0.0,
    };
    for i in 0..grid {
        for j in 0..grid {
            let x = -1.25 + 2.5 * (i as f64 + 0.5) / grid as f64;
            let y = -1.25 + 2.5 * (j as f64 + 0.5) / grid as f64;
            let ray = R::ray(c - d_hat * distance + e1 * x + e2 * y, d_hat);
            // The exact geometry of the rounded ray, in f64.
            let (o, d) = (R::wide3(R::origin(&ray)), R::wide3(R::dir(&ray)));
            let fo = o - c;
            let a = d.dot(d);
            let t_c = -fo.dot(d) / a;
            let h = (fo + d * t_c).length();
            let unit = R::EPSILON.wide() * (fo.length() + 1.0);
            let got = f.intersect(&ray, &sphere, R::ZERO);
            if (h - 1.0).abs() <= SILHOUETTE_BAND * unit {
                continue; // grazing the silhouette: either answer is acceptable
            }
            row.rays += 1;
            let should_hit = h < 1.0;
            if got.is_some() != should_hit {
                row.wrong += 1;
                continue;
            }
            if let (Some(t), true) = (got, h <= 0.9) {
                let t_star = t_c - ((1.0 - h * h) / a).sqrt();
                let err = (t.wide() - t_star).abs() * a.sqrt();
                let err = if err.is_nan() { f64::INFINITY } else { err };
                row.worst_t_error = row.worst_t_error.max(err);
                row.worst_t_units = row.worst_t_units.max(err / unit);
                if err.is_nan() || err / unit > T_ERROR_BOUND {
                    row.over_bound += 1;
                }
            }
        }
    }
    row
}

/// The distances of the hard-case test: a unit sphere 1e2 to 1e4 radii away.
pub const FAR_DISTANCES: [f64; 5] = [1e2, 3e2, 1e3, 3e3, 1e4];

/// Grid size of the hard-case test by default (`grid^2` rays per distance).
pub const FAR_GRID: usize = 101;

/// The default number of rays per distance of [`far`] and [`far_row`]: `FAR_GRID^2`.
pub const FAR_RAYS: usize = FAR_GRID * FAR_GRID;

/// The side of the square bundle of the far-sphere test: the largest `grid` with
/// `grid^2` at most the number of cases (default [`FAR_RAYS`], so [`FAR_GRID`]), and at
/// least 1.
pub fn far_grid(options: &Options) -> usize {
    options.cases_or(FAR_RAYS).isqrt().max(1)
}

/// The hard case as a verdict: at every distance in [`FAR_DISTANCES`], no wrong hit/miss
/// outside the silhouette band and the `t` error within [`T_ERROR_BOUND`]. `options`
/// sets the rays per distance (default [`FAR_RAYS`], see [`far_grid`]) and the seed
/// (default [`SEED`]).
pub fn far<R: Real>(f: &impl SphereIntersector<R>, options: &Options) -> Verdict {
    let mut verdict = Verdict::new(format!(
        "ray-sphere intersection, far-away unit sphere ({})",
        R::NAME
    ));
    for &distance in &FAR_DISTANCES {
        let row = far_row(f, distance, options);
        let mut finding = Finding::new(
            format!("far_{distance:.0e}"),
            format!(
                "parallel rays at a unit sphere {distance:.0e} radii away: no wrong hit/miss, \
                 t error <= 16 eps (|O-C|+r) where the ray passes within 0.9 r of the centre"
            ),
        );
        finding.cases = row.rays;
        finding.failures = row.wrong + row.over_bound;
        finding.worst = Some((row.worst_t_units, T_ERROR_BOUND));
        if finding.failures > 0 {
            finding.example = Some(format!(
                "{} of {} rays answered hit/miss wrongly; {} hits beyond the t bound \
                 (worst t error {:.3e} radii)",
                row.wrong, row.rays, row.over_bound, row.worst_t_error
            ));
        }
        verdict.findings.push(finding);
    }
    verdict
}

/// Rays leaving a sphere from a point on its surface, with `t_min = 0` as the source
/// notes prescribe: the fraction that "hits" the sphere again at a tiny `t`. `options` sets
/// the number of rays (default [`SELF_HIT_RAYS`]) and their seed (default
/// [`SELF_HIT_SEED`]).
pub fn self_hit_rate<R: Real>(f: &impl SphereIntersector<R>, options: &Options) -> f64 {
    let rays = options.cases_or(SELF_HIT_RAYS);
    let mut rng = rng::seeded(options.seed_or(SELF_HIT_SEED));
    let mut hits = 0;
    for _ in 0..rays {
        let radius = log_uniform(&mut rng, 1e-1, 1e1);
        let center = DVec3::new(
            uniform(&mut rng, -10.0, 10.0),
            uniform(&mut rng, -10.0, 10.0),
            uniform(&mut rng, -10.0, 10.0),
        );
        let u = sphere_uniform(&mut rng);
        let mut dir = sphere_uniform(&mut rng);
        if dir.dot(u) < 0.0 {
            dir = -dir; // outward
        }
        let ray = R::ray(center + u * radius, dir);
        let sphere = R::sphere(center, radius);
        if f.intersect(&ray, &sphere, R::ZERO).is_some() {
            hits += 1;
        }
    }
    hits as f64 / rays as f64
}

/// The default seed of [`self_hit_rate`] (its test and the chapter's table use it).
pub const SELF_HIT_SEED: u64 = 0x5e1f;

/// The default number of rays of [`self_hit_rate`].
pub const SELF_HIT_RAYS: usize = 20_000;
