//! The chapter *Coursework*'s test file of one's own: a student's functions passed to the
//! checkers. Compiled and run with the book's tests, so that every line the chapter shows
//! (by anchor) compiles; in the hand-out, the tests that call the book's functions fail
//! with the stubs' message until those exercises are written.

// ANCHOR: mine
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};
use raylemma::check::warp::{self, Domain, SquareWarp};
use raylemma::check::{self, Options};
use raylemma::optics::fresnel;
use raylemma::optics::reflect::{self, Refraction};
use raylemma::single::geometry::{Ray, Sphere}; // the f32 ray and sphere

// Your ray-sphere intersection: here the book's, in f32; replace the body with your own.
fn my_intersect(ray: &Ray, sphere: &Sphere, t_min: f32) -> Option<f32> {
    raylemma::single::geometry::sphere::intersect_stable(ray, sphere, t_min)
}

#[test]
fn my_sphere() {
    let verdict = check::sphere::intersection(&my_intersect, &Options::default());
    println!("{verdict}");
    verdict.assert_pass();
    check::sphere::far(&my_intersect, &Options::default()).assert_pass();
}

// A sampler given as plain functions: uniform points on the triangle 0 <= y <= x <= 1 of
// the unit square (the warps chapter's exercise), its pdf, and its inverse.
fn my_triangle(u: DVec2) -> DVec3 {
    let x = u.x.sqrt(); // the marginal of x is 2x: its CDF is x^2
    DVec3::new(x, x * u.y, 0.0)
}
fn my_triangle_pdf(p: DVec3) -> f64 {
    if (0.0..=1.0).contains(&p.x) && (0.0..=p.x).contains(&p.y) {
        2.0
    } else {
        0.0
    }
}
fn my_triangle_invert(p: DVec3) -> DVec2 {
    DVec2::new(p.x * p.x, if p.x > 0.0 { p.y / p.x } else { 0.0 })
}

#[test]
fn my_triangle_sampler() {
    let triangle = SquareWarp::new("my triangle", Domain::Square, my_triangle, my_triangle_pdf)
        .inverse(my_triangle_invert);
    warp::check(&triangle, &Options::default().cases(warp::TEST_SAMPLES)).assert_pass();
}

// A sampler with a parameter: closures in a `SquareWarp` (exercise 1 of the cosine chapter).
fn cos_lobe(n: f64) -> SquareWarp<impl Fn(DVec2) -> DVec3 + Sync, impl Fn(DVec3) -> f64 + Sync> {
    SquareWarp {
        name: format!("cos^{n} lobe"),
        domain: Domain::Sphere, // hemisphere samplers use the sphere, pdf 0 below z = 0
        sample: move |u: DVec2| {
            let z = u.x.powf(1.0 / (n + 1.0));
            let r = (1.0 - z * z).max(0.0).sqrt();
            DVec3::new(r * (TAU * u.y).cos(), r * (TAU * u.y).sin(), z)
        },
        pdf: move |w: DVec3| (n + 1.0) / TAU * w.z.max(0.0).powf(n),
        invert: None, // no round-trip check
    }
}

#[test]
fn my_lobes() {
    for n in [1.0, 10.0, 100.0] {
        warp::check(&cos_lobe(n), &Options::default().cases(warp::TEST_SAMPLES)).assert_pass();
    }
}

// Optics: the checkers of *Fresnel and Schlick* and *Reflection and refraction*.
fn my_fresnel(cos_i: f64, n1: f64, n2: f64) -> f64 {
    fresnel::fresnel_dielectric(cos_i, n1, n2) // replace with your own
}
fn my_refract(w_i: DVec3, n: DVec3, n1: f64, n2: f64) -> Refraction {
    reflect::refract(w_i, n, n1, n2) // replace with your own
}

#[test]
fn my_optics() {
    check::fresnel::reflectance(&my_fresnel, &Options::default()).assert_pass();
    check::reflect::refraction(&my_refract, &Options::default()).assert_pass();
}
// ANCHOR_END: mine

/// The chapter's look inside the chi-squared test, on the classic mistake `r = u1`: the
/// central row gets more than four times its share, the outer row half.
#[test]
fn where_is_my_disc_wrong() {
    let text =
        raylemma::exercise::disc_rows::where_is_my_disc_wrong_text(warp::planted::disc_r_equals_u);
    println!("{text}");
    let ratio = |row: &str| -> f64 {
        let line = text.lines().find(|l| l.starts_with(row)).unwrap();
        line.rsplit(' ').next().unwrap().parse().unwrap()
    };
    assert!(ratio("row 0:") > 4.0 && ratio("row 20:") < 0.6, "{text}");
}
