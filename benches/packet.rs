//! Criterion benchmark of a lever not yet built: tracing the rays of four paths at once
//! (a packet: rays in the lanes of a 256-bit vector, one shape at a time), against the
//! renderer's tracer, which takes one ray at a time (`raylemma::render::tracer`; chapter
//! *Speed*, the wide-vector section).
//!
//! The rays are those of the `cornell` box as the path tracer makes them: four paths in
//! lockstep from the camera, each bouncing off what it hits in a cosine-weighted direction
//! (the book's `cosine_malley` and `Frame`, `offset_origin`), up to five bounces; a path
//! that leaves the box or reaches the light starts again at the camera. Ray `4 k + j` is
//! path `j`'s ray in step `k`, so a packet holds four paths at the same step, as a driver
//! stepping four paths together would.
//!
//! The packet repeats, lane by lane, the tracer's operations in the tracer's order (the
//! walls' `AxisQuad` test with the reciprocal direction, and `intersect_stable` for the
//! spheres), so it finds the same surface at the same distance to the bit; the bench checks
//! that on every ray before timing. It needs AVX2 and an all-wall, all-sphere scene (the
//! `cornell` box); elsewhere it times the tracer alone.
//!
//! Run with `cargo bench -p raylemma-bench --bench packet`.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::{DVec2, DVec3};
use rand::{Rng, RngExt};
use raylemma::render::camera::Camera;
use raylemma::render::integrator::offset_origin;
use raylemma::render::pixel_rng;
use raylemma::render::scene::{Geometry, Hit, LightShape, Scene, Surface};
use raylemma::render::tracer::Tracer;
use raylemma::sampling::cosine::cosine_malley;
use raylemma::sampling::frame::Frame;

/// Rays in a packet.
const LANES: usize = 4;

/// A wall whose normal is axis `k`: the plane `p[k] = at` and the box `lo <= p <= hi`
/// (infinite along `k`), as the tracer's `AxisQuad`; `id` names its surface.
struct Wall {
    k: usize,
    at: f64,
    lo: [f64; 3],
    hi: [f64; 3],
    id: f64,
}

/// A sphere: centre, squared radius, surface id.
struct Ball {
    c: [f64; 3],
    r2: f64,
    id: f64,
}

/// Four rays, one array per coordinate.
#[derive(Clone, Copy)]
struct Packet {
    o: [[f64; LANES]; 3],
    d: [[f64; LANES]; 3],
}

/// A surface as a number for the packet's lanes.
fn id(s: Surface) -> f64 {
    match s {
        Surface::Shape(i) => i as f64,
        Surface::Light(i) => 1000.0 + i as f64,
    }
}

/// The scene's surfaces as walls and balls, or `None` if one is neither (a tilted quad,
/// a spherical light).
fn walls_and_balls(scene: &Scene) -> Option<(Vec<Wall>, Vec<Ball>)> {
    let wall = |q: &raylemma::geometry::parallelogram::Parallelogram, id: f64| {
        let n = q.normal().to_array();
        let k = n.iter().position(|&x| x != 0.0)?;
        if n.iter().filter(|&&x| x != 0.0).count() != 1 {
            return None;
        }
        let [e1, e2] = q.edges();
        let (c, far) = (q.corner(), q.corner() + e1 + e2);
        let (mut lo, mut hi) = (c.min(far).to_array(), c.max(far).to_array());
        (lo[k], hi[k]) = (f64::NEG_INFINITY, f64::INFINITY);
        let axis = |v: DVec3| v.to_array().iter().filter(|&&x| x != 0.0).count() == 1;
        (axis(e1) && axis(e2)).then_some(Wall {
            k,
            at: c.to_array()[k],
            lo,
            hi,
            id,
        })
    };
    let (mut walls, mut balls) = (Vec::new(), Vec::new());
    for (i, s) in scene.shapes.iter().enumerate() {
        match &s.geometry {
            Geometry::Quad(q) => walls.push(wall(q, i as f64)?),
            Geometry::Sphere(b) => balls.push(Ball {
                c: b.center.to_array(),
                r2: b.radius * b.radius,
                id: i as f64,
            }),
        }
    }
    for (i, l) in scene.lights.iter().enumerate() {
        match &l.shape {
            LightShape::Quad(q) => walls.push(wall(q.shape(), id(Surface::Light(i)))?),
            LightShape::Sphere(_) => return None,
        }
    }
    Some((walls, balls))
}

/// `packets` packets of the rays of four paths in lockstep through `scene` (module doc).
fn cornell_rays(scene: &Scene, tracer: &Tracer, packets: usize) -> Vec<Packet> {
    let camera = Camera::new(&scene.camera);
    let mut rng = pixel_rng(7, 0);
    let from_camera = |rng: &mut dyn Rng| {
        let (w, h) = (scene.camera.width, scene.camera.height);
        let (x, y) = (rng.random_range(0..w), rng.random_range(0..h));
        let r = camera.ray(x, y, DVec2::new(rng.random(), rng.random()));
        (r.origin, r.dir, 0)
    };
    let mut paths: Vec<(DVec3, DVec3, u32)> = (0..LANES).map(|_| from_camera(&mut rng)).collect();
    let mut out = Vec::with_capacity(packets);
    while out.len() < packets {
        let mut p = Packet {
            o: [[0.0; LANES]; 3],
            d: [[0.0; LANES]; 3],
        };
        for (j, path) in paths.iter_mut().enumerate() {
            let (o, d, depth) = *path;
            for k in 0..3 {
                (p.o[k][j], p.d[k][j]) = (o.to_array()[k], d.to_array()[k]);
            }
            *path = match tracer.intersect(o, d) {
                Some(Hit {
                    t,
                    surface: Surface::Shape(i),
                }) if depth < 5 => {
                    let (q, n) = scene.surface_point(i, o, d, t);
                    let n = if n.dot(d) < 0.0 { n } else { -n };
                    let local = cosine_malley(DVec2::new(rng.random(), rng.random()));
                    let next = Frame::from_normal(n).to_world(local).normalize();
                    (offset_origin(q, n, next), next, depth + 1)
                }
                _ => from_camera(&mut rng),
            };
        }
        out.push(p);
    }
    out
}

/// The nearest hit of each of the packet's rays: `(t, id)`, `id` negative for a miss.
/// The tracer's operations, in its order, on four lanes at once.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn packet_hit(walls: &[Wall], balls: &[Ball], p: &Packet) -> ([f64; LANES], [f64; LANES]) {
    use std::arch::x86_64::*;
    let v = |a: &[f64; LANES]| unsafe { _mm256_loadu_pd(a.as_ptr()) };
    let s = _mm256_set1_pd;
    let dot = |a: [__m256d; 3], b: [__m256d; 3]| {
        _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(a[0], b[0]), _mm256_mul_pd(a[1], b[1])),
            _mm256_mul_pd(a[2], b[2]),
        )
    };
    let (o, d) = (p.o.each_ref().map(v), p.d.each_ref().map(v));
    let inv = d.map(|x| _mm256_div_pd(s(1.0), x));
    let (zero, minus) = (_mm256_setzero_pd(), s(-0.0));
    let (mut nearest, mut hit) = (s(f64::INFINITY), s(-1.0));
    for w in walls {
        let t = _mm256_mul_pd(_mm256_sub_pd(s(w.at), o[w.k]), inv[w.k]);
        let mut ok = _mm256_and_pd(
            _mm256_cmp_pd::<_CMP_GT_OQ>(t, zero),
            _mm256_cmp_pd::<_CMP_LT_OQ>(t, nearest),
        );
        for k in 0..3 {
            let x = _mm256_add_pd(o[k], _mm256_mul_pd(t, d[k]));
            ok = _mm256_and_pd(ok, _mm256_cmp_pd::<_CMP_GE_OQ>(x, s(w.lo[k])));
            ok = _mm256_and_pd(ok, _mm256_cmp_pd::<_CMP_LE_OQ>(x, s(w.hi[k])));
        }
        nearest = _mm256_blendv_pd(nearest, t, ok);
        hit = _mm256_blendv_pd(hit, s(w.id), ok);
    }
    for b in balls {
        let a = dot(d, d);
        let f = [0, 1, 2].map(|k| _mm256_sub_pd(o[k], s(b.c[k])));
        let bp = _mm256_xor_pd(minus, dot(f, d));
        let ba = _mm256_div_pd(bp, a);
        let l = [0, 1, 2].map(|k| _mm256_add_pd(f[k], _mm256_mul_pd(d[k], ba)));
        let delta = _mm256_sub_pd(s(b.r2), dot(l, l));
        let c = _mm256_sub_pd(dot(f, f), s(b.r2));
        let root = _mm256_sqrt_pd(_mm256_mul_pd(a, delta));
        let signed = _mm256_or_pd(_mm256_andnot_pd(minus, root), _mm256_and_pd(minus, bp));
        let q = _mm256_add_pd(bp, signed);
        let (t0, t1) = (_mm256_div_pd(c, q), _mm256_div_pd(q, a));
        let first = _mm256_cmp_pd::<_CMP_LE_OQ>(t0, t1);
        let (near, far) = (
            _mm256_blendv_pd(t1, t0, first),
            _mm256_blendv_pd(t0, t1, first),
        );
        let t = _mm256_blendv_pd(far, near, _mm256_cmp_pd::<_CMP_GT_OQ>(near, zero));
        let ok = _mm256_and_pd(
            _mm256_cmp_pd::<_CMP_GE_OQ>(delta, zero),
            _mm256_and_pd(
                _mm256_cmp_pd::<_CMP_GT_OQ>(t, zero),
                _mm256_cmp_pd::<_CMP_LT_OQ>(t, nearest),
            ),
        );
        nearest = _mm256_blendv_pd(nearest, t, ok);
        hit = _mm256_blendv_pd(hit, s(b.id), ok);
    }
    let (mut t, mut ids) = ([0.0; LANES], [0.0; LANES]);
    unsafe {
        _mm256_storeu_pd(t.as_mut_ptr(), nearest);
        _mm256_storeu_pd(ids.as_mut_ptr(), hit);
    }
    (t, ids)
}

/// Every packet through [`packet_hit`]: the sum of the distances hit (for `black_box`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn all_packets(walls: &[Wall], balls: &[Ball], packets: &[Packet]) -> f64 {
    let mut sum = 0.0;
    for p in packets {
        let (t, ids) = packet_hit(walls, balls, black_box(p));
        for j in 0..LANES {
            if ids[j] >= 0.0 {
                sum += t[j];
            }
        }
    }
    sum
}

fn packets(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/cornell.toml");
    let scene = raylemma::render::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let tracer = Tracer::new(&scene);
    let packets = cornell_rays(&scene, &tracer, 1 << 16);
    let ray = |p: &Packet, j: usize| {
        let at = |v: &[[f64; LANES]; 3]| DVec3::new(v[0][j], v[1][j], v[2][j]);
        (at(&p.o), at(&p.d))
    };
    let mut group = c.benchmark_group("packet");
    group.throughput(Throughput::Elements((packets.len() * LANES) as u64));
    group.bench_function("tracer, one ray at a time", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for p in &packets {
                for j in 0..LANES {
                    let (o, d) = ray(black_box(p), j);
                    sum += tracer.intersect(o, d).map_or(0.0, |h| h.t);
                }
            }
            sum
        })
    });
    #[cfg(target_arch = "x86_64")]
    if let (true, Some((walls, balls))) = (
        std::arch::is_x86_feature_detected!("avx2"),
        walls_and_balls(&scene),
    ) {
        for p in &packets {
            // SAFETY: AVX2 was detected above.
            let (t, ids) = unsafe { packet_hit(&walls, &balls, p) };
            for j in 0..LANES {
                let (o, d) = ray(p, j);
                let want = tracer
                    .intersect(o, d)
                    .map(|h| (h.t.to_bits(), id(h.surface)));
                let got = (ids[j] >= 0.0).then_some((t[j].to_bits(), ids[j]));
                assert_eq!(
                    got, want,
                    "the packet differs from the tracer on ({o}, {d})"
                );
            }
        }
        group.bench_function("packet of four rays (AVX2)", |b| {
            // SAFETY: AVX2 was detected above.
            b.iter(|| unsafe { all_packets(&walls, &balls, &packets) })
        });
    }
    group.finish();
}

criterion_group!(benches, packets);
criterion_main!(benches);
