//! The diagram of the shadow-ray pdfs, from area to solid angle (`diagram_solid_angle.svg`), of
//! the chapter *Shadow-ray pdfs* (`chapters/transport/shadow.md`).

use super::geometry::{V, bisector, meet, turn, v};
use super::style::{BLUE, FAINT, GREEN, GREY, INK, LABEL, NOTE, ORANGE, Pen, SKY, VERMILION, font};
use super::svg::Svg;
use crate::{Record, Settings};

pub(super) fn solid_angle(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut d = Svg::new(380.0);
    let p = v(130.0, 250.0);
    let unit = 84.0;
    let q = v(492.0, 150.0);
    let r = (q - p).length();
    let r_hat = (q - p) / r;
    let m = v(r_hat.y, -r_hat.x); // across the line of sight, upwards
    let theta = 50.0;
    // The light's normal faces p: the reversed line of sight turned by θ_ℓ.
    let n = turn(-r_hat, -theta);
    let t = v(-n.y, n.x);
    let half = 46.0;
    let (a, b) = (q - t * half, q + t * half);
    // The patch foreshortened: its central projection across the line of sight at q.
    let (fa, fb) = (meet(p, a - p, q, m), meet(p, b - p, q, m));
    let far = |x: V, y: V| {
        if (x - p).length() > (y - p).length() {
            x
        } else {
            y
        }
    };

    // The cone from p through the patch, and its trace on the unit sphere.
    d.polygon(&[p, a, q, b], SKY, 0.16);
    d.circle(p, unit, None, Some(Pen::new(FAINT, 1.2).dashed()));
    d.line(p, far(a, fa), Pen::new(GREY, 1.0));
    d.line(p, far(b, fb), Pen::new(GREY, 1.0));
    d.arc(p, unit, a - p, b - p, Pen::new(VERMILION, 4.5));
    let on_sphere = p + bisector(a - p, b - p) * unit;
    d.text(on_sphere + m * 22.0, "d*ω*", font(LABEL).colour(VERMILION));
    d.text(
        p + v(0.0, unit + 20.0),
        "the unit sphere around ~p~",
        font(NOTE).colour(GREY),
    );

    // The light, its patch dA and the patch foreshortened across the line of sight.
    d.line(
        q - t * 120.0,
        q + t * 130.0,
        Pen::new(ORANGE, 6.0).faded(0.4),
    );
    d.text(
        q + t * 130.0 + v(10.0, 0.0),
        "light",
        font(NOTE).colour(GREY).start(),
    );
    d.line(a, b, Pen::new(ORANGE, 6.0));
    d.text(q.lerp(b, 0.75) - n * 24.0, "d*A*", font(LABEL));
    d.line(fa, fb, Pen::new(GREEN, 3.0));
    d.right_angle(q, -r_hat, -m, Pen::new(GREEN, 1.2));
    let low = if fa.y > fb.y { fa } else { fb };
    d.text(
        low + v(8.0, 16.0),
        "|cos *θ*_ℓ| d*A*",
        font(LABEL).colour(GREEN).start(),
    );

    // The line of sight: r̂ from p to the unit sphere, then the distance r.
    let s = p + r_hat * unit;
    d.arrow(p, s, Pen::new(INK, 2.0));
    d.text(p + r_hat * (unit * 0.5) - m * 14.0, "~r̂~", font(LABEL));
    d.line(s, q, Pen::new(GREY, 1.2));
    d.text(s.lerp(q, 0.5) + m * 30.0, "*r*", font(LABEL));

    // The normal and its angle with the line of sight.
    d.arrow(q, q + n * 70.0, Pen::new(BLUE, 2.0));
    d.text(q + n * 84.0, "~n̂~", font(LABEL).colour(BLUE));
    d.arc(q, 40.0, n, -r_hat, Pen::new(INK, 1.3));
    d.text(q + bisector(n, -r_hat) * 56.0, "*θ*_ℓ", font(LABEL));

    d.dot(p, INK);
    d.text(p + v(-16.0, 8.0), "~p~", font(LABEL));
    d.dot(q, INK);
    d.text(q + v(16.0, 4.0), "~q~", font(LABEL));

    // The change of variables.
    let f = font(LABEL).start();
    d.text(
        v(24.0, 34.0),
        "d*ω* = |cos *θ*_ℓ| d*A* / *r*²,   |cos *θ*_ℓ| = |~n̂~ · ~r̂~|",
        f,
    );
    d.text(
        v(24.0, 62.0),
        "*p*_*ω* d*ω* = *p*_*A* d*A*   ⇒   *p*_*ω* = *p*_*A* *r*² / |cos *θ*_ℓ|",
        f,
    );
    Ok(d.finish(
        "A patch dA of a light at distance r from the shading point p, its normal at the angle θℓ to the line of sight, the patch foreshortened to |cos θℓ| dA across that line, and the solid angle dω it subtends on the unit sphere around p.",
        "The solid angle of a small patch is the area of its shadow on the unit sphere around p: the patch is first foreshortened by |cos θℓ| (θℓ is the angle between its normal n̂ and the line of sight r̂), then shrunk by r² on the way to the unit sphere, so dω = |cos θℓ| dA / r². Since probability is conserved, pω dω = pA dA, and pω = pA r² / |cos θℓ|.",
    ))
}
