//! The diagram of the path difference in a thin film, and of the Airy sum as phasors
//! (`diagram_thinfilm.svg`), of the chapter *Thin-film interference*
//! (`chapters/optics/thinfilm.md`).

use std::f64::consts::PI;

use anyhow::Context;
use num_complex::Complex64;

use super::ensure;
use super::geometry::{V, bisector, dir, to2, to3, turn, v};
use super::style::{
    BLUE, FAINT, GREEN, GREY, HEAD, INK, LABEL, NOTE, PURPLE, Pen, SKY, SMALL, VERMILION, font,
};
use super::svg::Svg;
use crate::{Record, Settings};
use raylemma::optics::reflect::{reflect, refract};
use raylemma::optics::thinfilm::{self, Film};

/// The film of the diagram: a free-standing film of index 2.4 (diamond's, the Fresnel
/// chapter's densest medium) in air, strongly enough reflecting that the phasors spiral.
const FILM: (f64, f64, f64) = (1.0, 2.4, 1.0);
const FILM_THETA1_DEG: f64 = 60.0;
const FILM_NM: f64 = 150.0;
const FILM_LAMBDA_NM: f64 = 550.0;

/// The first `count` terms of the Airy sum of the film's reflected s amplitude, from the
/// library's Fresnel coefficients and phase: `r12`, then
/// `t12 r23 t21 e^{2iδ} (r21 r23 e^{2iδ})^k`. Also returns the round trip's phase `2δ`
/// (mod 2π), its factor `r21 r23 e^{2iδ}`, and the film's `r_s` as the library evaluates
/// it (the rearranged sum), which the terms must add up to.
fn airy_terms(count: usize) -> (Vec<Complex64>, f64, Complex64, Complex64) {
    let (n1, n2, n3) = FILM;
    let cos1 = FILM_THETA1_DEG.to_radians().cos();
    let c1 = Complex64::new(cos1, 0.0);
    let c2 = thinfilm::cos_theta(n1, cos1, n2);
    let c3 = thinfilm::cos_theta(n1, cos1, n3);
    let i12 = thinfilm::interface(n1, c1, n2, c2);
    let i21 = thinfilm::interface(n2, c2, n1, c1);
    let i23 = thinfilm::interface(n2, c2, n3, c3);
    let delta = thinfilm::phase(n2, FILM_NM, c2, FILM_LAMBDA_NM);
    let z = (2.0 * Complex64::i() * delta).exp();
    let round_trip = i21.r_s * i23.r_s * z;
    let mut terms = vec![i12.r_s];
    let mut t = i12.t_s * i23.r_s * i21.t_s * z;
    for _ in 1..count {
        terms.push(t);
        t *= round_trip;
    }
    let film =
        Film::new(n1, n2, n3, FILM_NM).response(FILM_LAMBDA_NM, FILM_THETA1_DEG.to_radians());
    let two_delta = (2.0 * delta.re).rem_euclid(2.0 * PI);
    (terms, two_delta, round_trip, film.r_s)
}

pub(super) fn thinfilm_diagram(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (n1, n2, n3) = FILM;
    let mut d = Svg::new(380.0);

    // Left: the film, and the two rays of a parallel beam that leave it together at B.
    let (yt, yb) = (150.0, 250.0);
    let (x0, x1) = (14.0, 340.0);
    d.text(
        v(0.5 * (x0 + x1), 22.0),
        "two rays that meet at B",
        font(HEAD),
    );
    d.polygon(&[v(x0, yt), v(x1, yt), v(x1, yb), v(x0, yb)], SKY, 0.22);
    d.line(v(x0, yt), v(x1, yt), Pen::new(GREY, 1.5));
    d.line(v(x0, yb), v(x1, yb), Pen::new(GREY, 1.5));
    d.text(v(x0 + 6.0, yt - 16.0), "*n*₁", font(LABEL).start());
    d.text(v(x0 + 30.0, 0.5 * (yt + yb)), "*n*₂", font(LABEL).start());
    d.text(v(x0 + 6.0, yb + 18.0), "*n*₃", font(LABEL).start());
    d.arrow2(v(x0 + 14.0, yt), v(x0 + 14.0, yb), Pen::new(GREY, 1.2));
    d.text(
        v(x0 + 30.0, 0.5 * (yt + yb) + 24.0),
        "*d*",
        font(LABEL).start(),
    );

    let (up, down) = (v(0.0, -1.0), v(0.0, 1.0));
    let wi = dir(-90.0 + FILM_THETA1_DEG);
    let wr = to2(reflect(to3(wi), to3(up)));
    let w2 = to2(refract(to3(wi), to3(up), n1, n2)
        .transmitted()
        .context("no ray in the film")?);
    let w_back = to2(reflect(to3(w2), to3(up)));
    let w_out = to2(refract(to3(w_back), to3(down), n2, n1)
        .transmitted()
        .context("no ray out of the film")?);
    let w3 = to2(refract(to3(w2), to3(up), n2, n3)
        .transmitted()
        .context("no ray into the substrate")?);
    ensure(
        (w_out - wr).length() < 1e-12,
        "the ray out of the film is parallel to the reflected one",
    )?;
    let a = v(100.0, yt);
    let c = a + w2 * ((yb - yt) / w2.y);
    let b = c + w_back * ((yb - yt) / -w_back.y);
    let dd = b - wi * (b - a).dot(wi);
    let l2 = 95.0;
    let l1 = l2 + (b - a).dot(wi);
    let (blue, red) = (Pen::new(BLUE, 2.0), Pen::new(VERMILION, 2.0));
    // The wavefront through A, and the stretch DB ray 1 travels while ray 2 is in the film.
    d.line(a, dd, Pen::new(GREY, 1.2).dashed());
    d.right_angle(dd, a - dd, -wi, Pen::new(GREY, 1.0));
    d.ray(b - wi * l1, dd, 0.5, blue);
    d.line(dd, b, Pen::new(BLUE, 2.0));
    d.line(dd, b, Pen::new(PURPLE, 7.0).faded(0.45));
    d.ray(a - wi * l2, a, 0.5, red);
    d.line(a, c, red);
    d.line(c, b, red);
    d.line(a, c, Pen::new(PURPLE, 7.0).faded(0.45));
    d.line(c, b, Pen::new(PURPLE, 7.0).faded(0.45));
    d.line(c, c + w3 * 36.0, Pen::new(VERMILION, 1.5).faded(0.4));
    // Both leave B along the reflected direction: drawn side by side.
    let out = 110.0;
    let across = v(-wr.y, wr.x);
    d.ray(b - across * 1.6, b + wr * out - across * 1.6, 0.6, blue);
    d.line(b + across * 1.6, b + wr * out + across * 1.6, red);
    // The next round trip, fainter.
    let c2 = b + w2 * ((yb - yt) / w2.y);
    let b2 = c2 + w_back * ((yb - yt) / -w_back.y);
    let faint = Pen::new(VERMILION, 1.5).faded(0.45);
    d.line(b, c2, faint);
    d.line(c2, b2, faint);
    d.line(b2, b2 + wr * 70.0, faint);
    d.text(
        v(c2.x, yb + 40.0),
        "each round trip: × *r*₂₁*r*₂₃*e*^{2*iδ*}",
        font(NOTE).colour(VERMILION),
    );
    let end = b + wr * out;
    d.text(
        end + v(-64.0, -22.0),
        "*r*₁₂",
        font(LABEL).colour(BLUE).end(),
    );
    d.text(
        end + v(-56.0, -22.0),
        "+ *t*₁₂*r*₂₃*t*₂₁*e*^{2*iδ*}",
        font(LABEL).colour(VERMILION).start(),
    );
    // The normals and the angles.
    d.line(a + up * 60.0, a + down * 20.0, Pen::new(GREY, 1.0).dashed());
    d.line(b + up * 60.0, b + down * 20.0, Pen::new(GREY, 1.0).dashed());
    d.arc(b, 40.0, up, -wi, Pen::new(INK, 1.3));
    d.text(b + bisector(up, -wi) * 54.0, "*θ*₁", font(LABEL));
    d.arc(a, 44.0, down, w2, Pen::new(INK, 1.3));
    d.text(a + bisector(down, w2) * 58.0, "*θ*₂", font(LABEL));
    for (p, name, off) in [
        (a, "A", v(-10.0, -14.0)),
        (b, "B", v(14.0, -14.0)),
        (c, "C", v(0.0, 16.0)),
        (dd, "D", v(-12.0, -10.0)),
    ] {
        d.dot(p, INK);
        d.text(p + off, name, font(LABEL));
    }
    let f = font(LABEL);
    d.text(
        v(0.5 * (x0 + x1), 322.0),
        "*n*₂ (AC + CB) − *n*₁ DB = 2*n*₂*d* cos *θ*₂",
        f,
    );
    d.text(
        v(0.5 * (x0 + x1), 350.0),
        "a phase 2*δ*,   *δ* = 2π*n*₂*d* cos *θ*₂ / *λ*",
        f,
    );

    // Right: the Airy sum in the complex plane, each round trip turning its term by 2δ
    // and shrinking it by r21 r23.
    let (terms, two_delta, round_trip, r_film) = airy_terms(40);
    let sum: Complex64 = terms.iter().sum();
    let r12 = terms[0];
    ensure(
        (sum - r_film).norm() < 1e-12,
        "the Airy sum of the terms is the film's r_s",
    )?;
    ensure(
        (round_trip.arg().rem_euclid(2.0 * PI) - two_delta).abs() < 1e-9,
        "each round trip turns by 2δ",
    )?;
    // r as the round-trip phase runs over a whole turn (every thickness gives a point of
    // it): the Airy sum r12 + t12 t21 r23 z / (1 - r21 r23 z) on the unit circle |z| = 1.
    let turn_back = Complex64::from_polar(1.0, -two_delta);
    let (q, t) = (round_trip * turn_back, terms[1] * turn_back);
    let locus: Vec<Complex64> = (0..=180)
        .map(|k| {
            let z = Complex64::from_polar(1.0, 2.0 * PI * f64::from(k) / 180.0);
            r12 + t * z / (1.0 - q * z)
        })
        .collect();
    let mut partial = vec![Complex64::new(0.0, 0.0)];
    for t in &terms {
        let last = *partial.last().unwrap_or(&Complex64::new(0.0, 0.0));
        partial.push(last + t);
    }
    let (bx0, bx1, by0, by1) = (384.0, 600.0, 60.0, 282.0);
    let pts = partial.iter().chain(&locus);
    let (mut lo, mut hi) = (v(f64::MAX, f64::MAX), v(f64::MIN, f64::MIN));
    for z in pts {
        lo = lo.min(v(z.re, z.im));
        hi = hi.max(v(z.re, z.im));
    }
    lo = lo.min(v(0.0, 0.0));
    hi = hi.max(v(0.0, 0.0));
    let scale = ((bx1 - bx0) / (hi.x - lo.x)).min((by1 - by0) / (hi.y - lo.y));
    let origin = v(
        0.5 * (bx0 + bx1) - 0.5 * (lo.x + hi.x) * scale,
        0.5 * (by0 + by1) + 0.5 * (lo.y + hi.y) * scale,
    );
    let at = |z: Complex64| origin + v(z.re, -z.im) * scale;
    let page = |z: Complex64| v(z.re, -z.im);
    d.text(
        v(0.5 * (bx0 + bx1), 22.0),
        "the Airy sum as phasors",
        font(HEAD),
    );
    d.arrow(
        v(bx0 - 8.0, origin.y),
        v(bx1 + 8.0, origin.y),
        Pen::new(FAINT, 1.0),
    );
    d.text(
        v(bx1 + 8.0, origin.y + 15.0),
        "Re",
        font(SMALL).colour(GREY).end(),
    );
    d.arrow(
        v(origin.x, by1 + 10.0),
        v(origin.x, by0 - 16.0),
        Pen::new(FAINT, 1.0),
    );
    d.text(
        v(origin.x - 8.0, by0 - 12.0),
        "Im",
        font(SMALL).colour(GREY).end(),
    );
    let loc: Vec<V> = locus.iter().map(|&z| at(z)).collect();
    d.polyline(&loc, Pen::new(FAINT, 1.3).dashed());
    for (k, w) in partial.windows(2).enumerate() {
        let (p, q) = (at(w[0]), at(w[1]));
        if (q - p).length() < 5.0 {
            break;
        }
        let pen = if k == 0 {
            Pen::new(BLUE, 2.2)
        } else {
            Pen::new(VERMILION, (2.2 - 0.25 * k as f64).max(1.2))
        };
        d.arrow(p, q, pen);
    }
    let (p0, p1, p2) = (at(partial[0]), at(partial[1]), at(partial[2]));
    d.text(
        p0.lerp(p1, 0.5) + v(0.0, 16.0),
        "*r*₁₂",
        font(LABEL).colour(BLUE),
    );
    let left_of_1 = turn(page(terms[1]).normalize(), 90.0);
    d.text(
        p1.lerp(p2, 0.5) + left_of_1 * 14.0,
        "*t*₁₂*r*₂₃*t*₂₁*e*^{2*iδ*}",
        font(LABEL).colour(VERMILION).end(),
    );
    let d1 = page(terms[1]).normalize();
    let d2 = page(terms[2]).normalize();
    d.line(p2, p2 + d1 * 34.0, Pen::new(GREY, 1.0).dashed());
    d.arc(p2, 24.0, d1, d2, Pen::new(INK, 1.2));
    d.text(p2 + bisector(d1, d2) * 38.0, "2*δ*", font(LABEL));
    d.arrow(origin, at(sum), Pen::new(GREEN, 2.6));
    let mid = origin.lerp(at(sum), 0.5);
    d.text(
        mid + turn(page(sum).normalize(), 90.0) * 16.0,
        "*r*",
        font(LABEL).colour(GREEN),
    );
    let centre = loc.iter().fold(V::ZERO, |a, &b| a + b) / loc.len() as f64;
    let radius = (loc[0] - centre).length();
    d.text(
        centre + v(0.0, 0.55 * radius),
        "*r* for every *d*",
        font(NOTE).colour(GREY),
    );
    let f = font(SMALL).colour(GREY);
    let mid = 0.5 * (bx0 + bx1);
    d.text(
        v(mid, 318.0),
        &format!("*s* polarisation, *n*₂ = {n2} in air, *θ*₁ = {FILM_THETA1_DEG}°"),
        f,
    );
    d.text(
        v(mid, 340.0),
        &format!("*λ* = {FILM_LAMBDA_NM} nm, *d* = {FILM_NM} nm"),
        f,
    );
    d.text(
        v(mid, 362.0),
        &format!(
            "|*r*₂₁*r*₂₃| = {:.2},  2*δ* ≡ {:.0}° (mod 360°)",
            round_trip.norm(),
            two_delta.to_degrees()
        ),
        f,
    );
    Ok(d.finish(
        "Thin-film interference: left, a film of index n2 and thickness d between n1 and n3, a ray reflected at B and a parallel ray that entered at A and returns to B, their optical path difference 2 n2 d cos θ2; right, the Airy sum of the reflected amplitude as phasors, r12, then t12 r23 t21 e^(2iδ), each next term turned by 2δ and shrunk by r21 r23, spiralling to the total r.",
        "Left: two rays of a parallel beam. One reflects at B; the other enters at A at the refraction angle θ2, reflects at C on the lower face and leaves at B, along the first reflected ray. Past the wavefront AD, the second ray's optical path n2 (AC + CB) exceeds the first's n1 DB by 2 n2 d cos θ2, a phase 2δ with δ = 2π n2 d cos θ2 / λ; each further round trip in the film multiplies the amplitude by r21 r23 e^(2iδ). Right: the terms of the Airy sum for s polarisation, computed with the library's Fresnel coefficients and phase for a free-standing film of index 2.4 in air at 60°, 550 nm and 150 nm thick: r12, then t12 r23 t21 e^(2iδ), each next term turned by 2δ and shrunk by |r21 r23|, head to tail, summing to the film's reflected amplitude r (green). The dashed circle is r for every thickness.",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_airy_terms_sum_to_the_films_reflection() {
        let (terms, two_delta, round_trip, r_s) = airy_terms(60);
        let sum: Complex64 = terms.iter().sum();
        assert!((sum - r_s).norm() < 1e-12, "{sum} against {r_s}");
        // Each term after the first is the one before turned by 2δ and shrunk by r21 r23.
        for w in terms[1..].windows(2) {
            assert!((w[1] / w[0] - round_trip).norm() < 1e-12);
        }
        assert!(round_trip.norm() > 0.3 && round_trip.norm() < 0.5);
        assert!((round_trip.arg().rem_euclid(2.0 * PI) - two_delta).abs() < 1e-9);
    }
}
