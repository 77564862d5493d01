//! The tracer (flat arrays, axis-aligned box walls) against the book's loop over the shapes
//! and lights.

use super::*;

#[test]
fn the_tracer_finds_the_first_surface_the_book_loop_finds() {
    // The tracer (flat arrays, the axis-aligned form of a box's walls) against the book's
    // loop over the shapes and lights, on rays from random points in every canonical
    // scene's bounds towards random directions, and from the camera; and its any-hit test
    // for shadow rays against the same loop's answer.
    use raylemma::render::tracer::Tracer;
    let mut rng = rng::seeded(0x7ace);
    for name in [
        "cornell.toml",
        "dispersion.toml",
        "bubble.toml",
        "furnace-grey.toml",
    ] {
        let s = load(name);
        let tracer = Tracer::new(&s);
        if name == "cornell.toml" {
            // Its five walls and its light lie along the axes: all six take the fast form.
            assert_eq!(tracer.axis_aligned_quads(), (6, 6));
        }
        let camera = raylemma::render::camera::Camera::new(&s.camera);
        let mut agree = 0;
        for k in 0..20_000 {
            let (o, d) = if k % 2 == 0 {
                let r = camera.ray(
                    (k / 2) as u32 % s.camera.width,
                    (k / 2) as u32 / s.camera.width % s.camera.height,
                    DVec2::new(rng.random(), rng.random()),
                );
                (r.origin, r.dir)
            } else {
                let c = s.camera.look_at;
                let o = c + 300.0
                    * raylemma::sampling::sphere::sphere_uniform(&mut rng)
                    * rng.random::<f64>();
                (o, raylemma::sampling::sphere::sphere_uniform(&mut rng))
            };
            let (book, fast) = (s.intersect(o, d), tracer.intersect(o, d));
            // The shadow ray's question, any surface before t_max, from the first-hit
            // loop: before, at and just past the nearest hit, and with nothing near.
            let near = book.map_or(1e3, |b| b.t);
            for t_max in [
                near * 0.5,
                near * (1.0 - 1e-9),
                near * (1.0 + 1e-9),
                2.0 * near,
            ] {
                assert_eq!(
                    tracer.occluded(o, d, t_max),
                    s.intersect_before(o, d, t_max).is_some(),
                    "{name}: ray {o} {d}, t_max {t_max}: occluded disagrees with the book's loop"
                );
            }
            match (book, fast) {
                (Some(b), Some(f))
                    if b.surface == f.surface && (b.t - f.t).abs() <= 4.0 * f64::EPSILON * b.t =>
                {
                    agree += 1
                }
                (None, None) => agree += 1,
                _ => panic!(
                    "{name}: ray {o} {d}: the book's loop finds {book:?}, the tracer {fast:?}"
                ),
            }
        }
        assert_eq!(agree, 20_000);
    }
}
