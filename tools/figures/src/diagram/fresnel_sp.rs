//! The diagram of s and p polarisation, and of the beam's footprint (`diagram_fresnel_sp.svg`),
//! of the chapter *Fresnel and Schlick* (`chapters/optics/fresnel.md`).

use anyhow::Context;

use super::ensure;
use super::geometry::{V, bisector, dir, meet, to2, to3, v};
use super::style::{BLUE, FAINT, GREEN, GREY, HEAD, INK, LABEL, NOTE, Pen, SKY, VERMILION, font};
use super::svg::Svg;
use crate::{Record, Settings};
use raylemma::optics::reflect::{reflect, refract};

pub(super) fn fresnel_sp(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let (n1, n2) = (1.0, 1.5);
    let theta_i: f64 = 50.0;
    let mut d = Svg::new(430.0);
    // The directions, by the library (page coordinates, y down: the normal up is -y).
    let wi = dir(-90.0 + theta_i);
    let up = v(0.0, -1.0);
    let wr = to2(reflect(to3(wi), to3(up)));
    let wt = to2(refract(to3(wi), to3(up), n1, n2)
        .transmitted()
        .context("no transmitted ray")?);
    let theta_t = wt.x.asin().to_degrees();
    ensure(
        ((n1 * theta_i.to_radians().sin()) - n2 * theta_t.to_radians().sin()).abs() < 1e-12,
        "Snell's law",
    )?;

    // The interface and the plane of incidence.
    let o = v(200.0, 200.0);
    let (left, right) = (22.0, 384.0);
    d.polygon(
        &[v(left, o.y), v(right, o.y), v(right, 350.0), v(left, 350.0)],
        SKY,
        0.14,
    );
    d.line(v(left, o.y), v(right, o.y), Pen::new(GREY, 2.0));
    d.line(v(o.x, 42.0), v(o.x, 348.0), Pen::new(GREY, 1.0).dashed());
    d.text(v(30.0, o.y - 18.0), "*n*₁ = 1", font(LABEL).start());
    d.text(v(30.0, o.y + 20.0), "*n*₂ = 1.5", font(LABEL).start());

    let len = 172.0;
    let (start, refl, trans) = (o - wi * len, o + wr * len, o + wt * (len - 30.0));
    let ray = Pen::new(INK, 2.0);
    d.ray(start, o, 1.0 - 64.0 / len, ray);
    d.ray(o, refl, 64.0 / len, ray);
    d.ray(o, trans, 64.0 / (len - 30.0), ray);
    // The fields: s as dots (out of the page), p as double arrows in the page, across
    // each ray; `w` points away from o along the ray.
    let fields = |d: &mut Svg, w: V, far: f64| {
        let across = v(-w.y, w.x);
        for r in [96.0, far] {
            let c = o + w * r;
            d.arrow2(
                c - across * 13.0,
                c + across * 13.0,
                Pen::new(VERMILION, 1.6),
            );
        }
        d.out_of_page(o + w * (0.5 * (96.0 + far)), BLUE);
    };
    fields(&mut d, -wi, 152.0);
    fields(&mut d, wr, 152.0);
    fields(&mut d, wt, 132.0);
    d.text(start + v(-2.0, -16.0), "incident", font(NOTE).colour(GREY));
    d.text(
        refl + v(2.0, -16.0),
        "reflected: *r*_*s*, *r*_*p*",
        font(NOTE).colour(GREY),
    );
    d.text(
        trans + v(-4.0, 18.0),
        "transmitted: *t*_*s*, *t*_*p*",
        font(NOTE).colour(GREY),
    );

    // The angles, from the normal.
    d.arc(o, 46.0, up, -wi, Pen::new(INK, 1.3));
    d.text(o + bisector(up, -wi) * 62.0, "*θ*_*i*", font(LABEL));
    d.arc(o, 46.0, up, wr, Pen::new(INK, 1.3));
    d.text(o + bisector(up, wr) * 62.0, "*θ*_*i*", font(LABEL));
    d.arc(o, 46.0, -up, wt, Pen::new(INK, 1.3));
    d.text(o + bisector(-up, wt) * 62.0, "*θ*_*t*", font(LABEL));

    // The key.
    d.out_of_page(v(30.0, 392.0), BLUE);
    d.text(
        v(46.0, 392.0),
        "*s*: ~E~ across the plane of incidence (out of the page)",
        font(NOTE).start(),
    );
    d.arrow2(v(17.0, 416.0), v(43.0, 416.0), Pen::new(VERMILION, 1.6));
    d.text(
        v(50.0, 416.0),
        "*p*: ~E~ in the plane of incidence, across the ray",
        font(NOTE).start(),
    );

    // The inset: a beam of width w and its footprint w / cos θi.
    let (x0, x1, y0, y1) = (404.0, 628.0, 40.0, 340.0);
    d.polyline(
        &[v(x0, y0), v(x1, y0), v(x1, y1), v(x0, y1), v(x0, y0)],
        Pen::new(FAINT, 1.0),
    );
    d.text(
        v(0.5 * (x0 + x1), y0 + 18.0),
        "a beam's footprint",
        font(HEAD),
    );
    let ys = 180.0;
    d.polygon(&[v(x0, ys), v(x1, ys), v(x1, y1), v(x0, y1)], SKY, 0.14);
    d.line(v(x0, ys), v(x1, ys), Pen::new(GREY, 2.0));
    let w = 42.0;
    let cos_i = theta_i.to_radians().cos();
    let cos_t = theta_t.to_radians().cos();
    let f1 = v(482.0, ys);
    let f2 = f1 + v(w / cos_i, 0.0);
    let (li, lt) = (95.0, 110.0);
    d.polygon(&[f1 - wi * li, f2 - wi * li, f2, f1], SKY, 0.35);
    d.polygon(&[f1, f2, f2 + wt * lt, f1 + wt * lt], SKY, 0.35);
    for f in [f1, f2] {
        d.ray(f - wi * li, f, 0.45, Pen::new(INK, 1.5));
        d.line(f, f + wt * lt, Pen::new(INK, 1.5));
    }
    // Across the incident beam: width w.
    let across_i = v(wi.y, -wi.x); // from the f1 edge towards the f2 edge
    let a1 = f1 - wi * 70.0;
    d.arrow2(a1, a1 + across_i * w, Pen::new(GREEN, 1.4));
    d.text(
        a1 + across_i * (0.5 * w) + v(-14.0, -14.0),
        "*w*",
        font(LABEL).colour(GREEN),
    );
    // Along the surface: the footprint.
    d.arrow2(
        f1 + v(0.0, -9.0),
        f2 + v(0.0, -9.0),
        Pen::new(VERMILION, 1.4),
    );
    d.text(
        f2 + v(8.0, -22.0),
        "*w* / cos *θ*_*i*",
        font(LABEL).colour(VERMILION).start(),
    );
    // Across the transmitted beam: w cos θt / cos θi.
    let across_t = v(-wt.y, wt.x);
    let b1 = f1 + wt * 80.0;
    let wt_width = w * cos_t / cos_i;
    let b2 = meet(b1, across_t, f2, wt);
    ensure(
        ((b2 - b1).length() - wt_width).abs() < 1e-9,
        "the transmitted beam's width",
    )?;
    d.arrow2(b1, b2, Pen::new(GREEN, 1.4));
    d.text(
        v(0.5 * (x0 + x1), y1 - 42.0),
        "*w* cos *θ*_*t* / cos *θ*_*i*",
        font(LABEL).colour(GREEN),
    );
    d.text(
        v(0.5 * (x0 + x1), y1 - 16.0),
        "power ∝ *n* ~E~² × width",
        font(NOTE).colour(GREY),
    );
    let f = font(LABEL);
    d.text(
        v(0.5 * (x0 + x1), 366.0),
        "*T* = (*n*₂ cos *θ*_*t* / *n*₁ cos *θ*_*i*) *t*²",
        f,
    );
    Ok(d.finish(
        "The plane of incidence with the incident, reflected and transmitted rays and the angles θi and θt from the normal, the s polarisation drawn as dots (the field out of the plane) and p as arrows in the plane across each ray, and an inset of a beam of width w whose footprint on the surface is w / cos θi.",
        "Light arrives in the medium of index n1 = 1 at θi = 50° from the normal and is reflected at θi and refracted into n2 = 1.5 at θt (Snell's law, computed with the library's refract). In s polarisation the electric field is perpendicular to the plane of incidence (dots, pointing out of the page); in p it lies in the plane, perpendicular to each ray (double arrows: the field oscillates). The inset shows why the transmittance is not t²: a beam of width w meets the surface on a footprint w / cos θi and leaves it with the width w cos θt / cos θi, and a wave's intensity is proportional to n E², so T = (n2 cos θt / n1 cos θi) t².",
    ))
}
