//! The diagram of Malley's method, a disc lifted onto the hemisphere (`diagram_malley.svg`), of
//! the chapter *Cosine-weighted hemisphere* (`chapters/sampling/cosine.md`).

use glam::DVec2;

use super::geometry::{V, bisector, dir, v};
use super::style::{BLUE, GREY, HEAD, INK, LABEL, NOTE, Pen, SKY, VERMILION, font};
use super::svg::Svg;
use crate::{Record, Settings};
use raylemma::sampling::disc::disc_concentric;

pub(super) fn malley(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut d = Svg::new(370.0);
    // Side view: the section y = 0 through the disc and the hemisphere above it.
    let o = v(190.0, 300.0);
    let rad = 150.0;
    let at = |x: f64, z: f64| o + v(x * rad, -z * rad);
    let lift = |x: f64| at(x, (1.0 - x * x).max(0.0).sqrt());
    let (x0, x1) = (0.52, 0.66);
    let xm = 0.5 * (x0 + x1);
    let arc_pts = |a: f64, b: f64| -> Vec<V> {
        (0..=24)
            .map(|k| lift(a + (b - a) * f64::from(k) / 24.0))
            .collect()
    };
    d.text(v(190.0, 22.0), "side view", font(HEAD));
    let mut strip = vec![at(x0, 0.0), at(x1, 0.0)];
    strip.extend(arc_pts(x1, x0));
    d.polygon(&strip, SKY, 0.22);
    let half: Vec<V> = (0..=96)
        .map(|k| o + dir(180.0 * f64::from(k) / 96.0) * rad)
        .collect();
    d.polyline(&half, Pen::new(GREY, 1.5));
    d.line(at(-1.0, 0.0), at(1.0, 0.0), Pen::new(GREY, 3.0));
    d.text(
        at(-0.62, 0.0) + v(0.0, 18.0),
        "unit disc",
        font(NOTE).colour(GREY),
    );
    d.arrow(o, at(0.0, 1.22), Pen::new(GREY, 1.5));
    d.text(
        at(0.0, 1.22) + v(16.0, 4.0),
        "~n~",
        font(LABEL).colour(GREY),
    );
    for x in [x0, x1] {
        d.line(at(x, 0.0), lift(x), Pen::new(BLUE, 1.2).dashed());
    }
    d.line(at(x0, 0.0), at(x1, 0.0), Pen::new(BLUE, 5.0));
    d.text(at(xm, 0.0) + v(0.0, 20.0), "d*A*", font(LABEL).colour(BLUE));
    d.polyline(&arc_pts(x0, x1), Pen::new(VERMILION, 5.0));
    let w = (lift(xm) - o) / rad;
    d.text(
        lift(x1) + v(12.0, 10.0),
        "d*ω*",
        font(LABEL).colour(VERMILION).start(),
    );
    d.text(
        v(24.0, 70.0),
        "lift: *z* = √(1 − *x*² − *y*²)",
        font(NOTE).start(),
    );
    // ω and its angle θ with the normal, at the centre and again at the patch: the patch
    // is tilted by θ from the disc, so seen from above it covers cos θ of its area.
    d.arrow(o, o + w * (rad - 4.0), Pen::new(INK, 1.8));
    d.text(o + w * (0.55 * rad) + v(12.0, 8.0), "*ω*", font(LABEL));
    d.arc(o, 46.0, v(0.0, -1.0), w, Pen::new(INK, 1.3));
    d.text(o + bisector(v(0.0, -1.0), w) * 60.0, "*θ*", font(LABEL));
    let top = lift(xm);
    d.line(top, top + w * 46.0, Pen::new(GREY, 1.0).dashed());
    d.line(top, top + v(0.0, -46.0), Pen::new(GREY, 1.0).dashed());
    d.arc(top, 32.0, v(0.0, -1.0), w, Pen::new(INK, 1.3));
    d.text(top + bisector(v(0.0, -1.0), w) * 45.0, "*θ*", font(LABEL));
    d.dot(o, INK);

    // Top view: uniform points on the disc (the library's concentric map of a grid of
    // the square), and the same area element dA.
    let c = v(520.0, 140.0);
    let rt = 92.0;
    d.text(v(520.0, 22.0), "top view", font(HEAD));
    d.circle(c, rt, Some("#FFFFFF"), Some(Pen::new(GREY, 1.5)));
    let grid = 14;
    for i in 0..grid {
        for j in 0..grid {
            let u = DVec2::new(
                (f64::from(i) + 0.5) / f64::from(grid),
                (f64::from(j) + 0.5) / f64::from(grid),
            );
            let p = disc_concentric(u);
            d.circle(c + v(p.x, -p.y) * rt, 1.6, Some(GREY), None);
        }
    }
    let hy = 0.5 * (x1 - x0);
    let cell: Vec<V> = [(x0, -hy), (x1, -hy), (x1, hy), (x0, hy)]
        .iter()
        .map(|&(x, y)| c + v(x, -y) * rt)
        .collect();
    d.polygon(&cell, BLUE, 0.35);
    d.polyline(
        &[cell[0], cell[1], cell[2], cell[3], cell[0]],
        Pen::new(BLUE, 2.0),
    );
    d.text(
        c + v(xm * rt, -hy * rt - 14.0),
        "d*A*",
        font(LABEL).colour(BLUE),
    );
    d.text(
        c + v(0.0, rt + 18.0),
        "uniform points: *p*(d*A*) = d*A* / π",
        font(NOTE).colour(GREY),
    );

    // The Jacobian.
    let f = font(LABEL).start();
    d.text(v(420.0, 292.0), "d*A* = cos *θ* d*ω*", f);
    d.text(v(420.0, 320.0), "*p*(*ω*) d*ω* = d*A* / π", f);
    d.text(v(420.0, 348.0), "⇒  *p*(*ω*) = cos *θ* / π", f);
    Ok(d.finish(
        "Malley's method: a uniform point of the unit disc lifted vertically onto the hemisphere, a small disc area dA and its image dω on the hemisphere, tilted by θ, so that dA = cos θ dω and p(ω) = cos θ / π.",
        "Side view: the section through the unit disc and the hemisphere above it. A small area dA of the disc is lifted vertically onto the hemisphere, where it becomes the patch dω in the direction ω at the angle θ from the normal n. The patch is tilted by θ from the disc, so seen from above it covers cos θ dω: its projected solid angle is dA. Top view: uniform points on the disc (the concentric map of a grid) and the same area element dA. Uniform points have p(dA) = dA / π, so p(ω) dω = cos θ dω / π and p(ω) = cos θ / π.",
    ))
}
