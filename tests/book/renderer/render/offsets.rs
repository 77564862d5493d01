//! Ray offsets: no acne and no leaks in a closed box, rays without an offset hit their own
//! surface, and offsets have the stated size on the stated side.

use super::*;

/// The Cornell box closed at z = 0 by a white wall: no ray may leave it.
fn closed_box() -> Scene {
    let mut s = load("cornell.toml");
    let front = Parallelogram::new(
        DVec3::ZERO,
        DVec3::new(0.0, 555.0, 0.0),
        DVec3::new(555.0, 0.0, 0.0),
    )
    .unwrap();
    s.shapes.push(scene::Shape {
        geometry: Geometry::Quad(front),
        material: 0,
    });
    s
}

/// Rays leaving random points of every shape of the closed box, cosine-distributed
/// about the normal on a random side that faces into the box (and, at a fraction of
/// them, almost tangent): `(self hits, escapes, rays)`.
fn offset_failures(offset: impl Fn(DVec3, DVec3, DVec3) -> DVec3) -> (usize, usize, usize) {
    let s = closed_box();
    let mut rng = rng::seeded(17);
    let (mut self_hits, mut escapes, mut rays) = (0, 0, 0);
    let centre = DVec3::splat(277.5);
    for (i, shape) in s.shapes.iter().enumerate() {
        for k in 0..4000 {
            let u = DVec2::new(
                rng::uniform(&mut rng, 0.0, 1.0),
                rng::uniform(&mut rng, 0.0, 1.0),
            );
            let (p, n) = match &shape.geometry {
                Geometry::Quad(q) => {
                    let [c, a, _, b] = q.vertices();
                    let p = c + u.x * (a - c) + u.y * (b - c);
                    let n = q.normal();
                    (p, if n.dot(centre - p) > 0.0 { n } else { -n })
                }
                Geometry::Sphere(sp) => {
                    let n = raylemma::sampling::sphere::sphere_inverse_cdf(u);
                    let p = sp.center + sp.radius * n;
                    if p.y < 0.0 {
                        continue; // below the floor
                    }
                    (p, n)
                }
            };
            let v = DVec2::new(
                rng::uniform(&mut rng, 0.0, 1.0),
                rng::uniform(&mut rng, 0.0, 1.0),
            );
            let mut local = cosine_malley(v);
            if k % 8 == 0 {
                // Grazing: 1e-7 rad above the tangent plane.
                local = DVec3::new(local.x, local.y, 0.0).normalize_or(DVec3::X) + DVec3::Z * 1e-7;
            }
            let dir = Frame::from_normal(n).to_world(local).normalize();
            rays += 1;
            match s.intersect(offset(p, n, dir), dir) {
                None => escapes += 1,
                Some(h) if h.surface == Surface::Shape(i) => self_hits += 1,
                Some(_) => {}
            }
        }
    }
    (self_hits, escapes, rays)
}

#[test]
fn offset_rays_neither_hit_their_own_surface_nor_leak() {
    let (self_hits, escapes, rays) = offset_failures(offset_origin);
    assert!(rays > 30_000);
    assert_eq!((self_hits, escapes), (0, 0), "of {rays} rays");
}

#[test]
fn rays_without_an_offset_do_hit_their_own_surface() {
    // Planted bug: the hit point itself as the origin. The test above must be able to fail.
    let (self_hits, _, rays) = offset_failures(|p, _, _| p);
    assert!(
        self_hits > rays / 100,
        "only {self_hits} self hits of {rays}"
    );
}

/// Whether `offset` moves points by the chapter's amount: along the normal, to the side
/// `dir` points to, by `1e-9 (1 + max |p_i|)` within a factor of ten either way, at scales
/// from the origin to a million units (the self-hit test above cannot see a move that is
/// too small but still escapes the rounding, or one that vanishes at the origin).
fn offset_has_the_stated_size(offset: impl Fn(DVec3, DVec3, DVec3) -> DVec3) -> Result<(), String> {
    let n = DVec3::new(2.0, -3.0, 6.0) / 7.0;
    for scale in [0.0, 1e-3, 1.0, 555.0, 1e6] {
        let p = DVec3::new(0.3, -1.0, 0.7) * scale;
        let stated = 1e-9 * (1.0 + p.abs().max_element());
        for (dir, side) in [(n + DVec3::X * 0.1, 1.0), (-n + DVec3::Y * 0.1, -1.0)] {
            let moved = offset(p, n, dir.normalize()) - p;
            let along = side * moved.dot(n);
            let across = (moved - moved.dot(n) * n).length();
            let ok = along >= 0.1 * stated
                && along <= 10.0 * stated
                && across <= 1e-3 * stated + 1e-12 * scale;
            if !ok {
                return Err(format!(
                    "p = {p}, side {side}: moved {along:e} along the normal and {across:e} across it; stated {stated:e}"
                ));
            }
        }
    }
    Ok(())
}

#[test]
fn offsets_have_the_stated_size_on_the_stated_side() {
    assert_eq!(offset_has_the_stated_size(offset_origin), Ok(()));
}

#[test]
fn offsets_of_the_wrong_size_are_rejected() {
    // Planted twins: divided by the scale instead of multiplied; proportional to the scale
    // alone (nothing at the origin); always to the front.
    let small = |p: DVec3, n: DVec3, d: DVec3| {
        let eps = 1e-9 / (1.0 + p.abs().max_element());
        if d.dot(n) >= 0.0 {
            p + eps * n
        } else {
            p - eps * n
        }
    };
    let relative_only = |p: DVec3, n: DVec3, d: DVec3| {
        let eps = 1e-9 * p.abs().max_element();
        if d.dot(n) >= 0.0 {
            p + eps * n
        } else {
            p - eps * n
        }
    };
    let front = |p: DVec3, n: DVec3, _: DVec3| p + 1e-9 * (1.0 + p.abs().max_element()) * n;
    assert!(offset_has_the_stated_size(small).is_err());
    assert!(offset_has_the_stated_size(relative_only).is_err());
    assert!(offset_has_the_stated_size(front).is_err());
}
