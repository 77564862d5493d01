//! The diagram of one path of the path tracer, its shadow rays and its last vertex
//! (`diagram_path.svg`), of the chapter *The path tracer* (`chapters/renderer/path-tracer.md`).

use glam::DVec3;

use super::ensure;
use super::geometry::{V, meet, to2, to3, turn, v};
use super::style::{BLUE, GREY, INK, LABEL, NOTE, ORANGE, Pen, SKY, SMALL, font};
use super::svg::Svg;
use crate::{Record, Settings};
use raylemma::optics::reflect::reflect;

/// A camera icon at `c` looking along `dir`: a body and a lens opening forwards.
fn camera_icon(d: &mut Svg, c: V, dir: V) {
    let f = dir.normalize();
    let s = v(-f.y, f.x);
    let body = [
        c - f * 30.0 - s * 11.0,
        c - f * 8.0 - s * 11.0,
        c - f * 8.0 + s * 11.0,
        c - f * 30.0 + s * 11.0,
    ];
    d.polygon(&body, GREY, 1.0);
    let lens = [
        c - f * 8.0 - s * 5.0,
        c + f * 4.0 - s * 10.0,
        c + f * 4.0 + s * 10.0,
        c - f * 8.0 + s * 5.0,
    ];
    d.polygon(&lens, GREY, 1.0);
}

pub(super) fn path(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    let mut d = Svg::new(492.0);
    // A room in section: a diffuse floor, ceiling and walls, a mirror tile on the floor and
    // a quad light on the ceiling (seen edge-on).
    let (l, r, t, b) = (20.0, 620.0, 52.0, 384.0);
    let (light0, light1) = (330.0, 470.0);
    let (mirror0, mirror1) = (290.0, 470.0);
    let wall = Pen::new(GREY, 2.0);
    d.polyline(&[v(l, t), v(r, t), v(r, b), v(l, b), v(l, t)], wall);
    d.line(v(mirror0, b), v(mirror1, b), Pen::new(SKY, 6.0));
    d.line(
        v(light0, t + 3.0),
        v(light1, t + 3.0),
        Pen::new(ORANGE, 6.0),
    );
    for k in 0..8 {
        let x = light0 + 10.0 + f64::from(k) * (light1 - light0 - 20.0) / 7.0;
        d.line(v(x, t + 9.0), v(x, t + 17.0), Pen::new(ORANGE, 1.5));
    }
    d.text(
        v(0.5 * (light0 + light1), t - 16.0),
        "quad light",
        font(NOTE).colour(GREY),
    );

    // The path: camera, x1 on the right wall, x2 on the mirror, x3 on the left wall (where
    // the mirror sends it, by the library's reflect), x4 on the floor.
    let cam = v(112.0, 176.0);
    let x1 = v(r, 251.0);
    let x2 = v(400.0, b);
    let back = to2(reflect(
        to3((x2 - x1).normalize()),
        DVec3::new(0.0, -1.0, 0.0),
    ));
    let x3 = meet(x2, back, v(l, t), v(0.0, 1.0));
    ensure(
        x3.y > t && x3.y < b,
        "the mirror sends the path to the left wall",
    )?;
    let x4 = v(176.0, b);
    let (y1, y3) = (v(452.0, t + 6.0), v(348.0, t + 6.0));

    let segment = Pen::new(INK, 2.0);
    let shadow = Pen::new(ORANGE, 2.0).dashed();
    camera_icon(&mut d, cam, x1 - cam);
    d.ray(cam, x1, 0.5, segment);
    d.line(x1, y1, shadow);
    d.head(y1, y1 - x1, Pen::new(ORANGE, 2.0));
    d.ray(x1, x2, 0.45, segment);
    d.ray(x2, x3, 0.5, segment);
    d.line(x3, y3, shadow);
    d.head(y3, y3 - x3, Pen::new(ORANGE, 2.0));
    d.ray(x3, x4, 0.5, segment);
    // At x4 the BSDF half would be the next bounce, beyond max_depth: not traced.
    let stub = x4 + turn(v(0.0, -1.0), -60.0) * 52.0;
    d.line(x4, stub, Pen::new(GREY, 2.0).dotted());
    d.text(
        stub + v(8.0, -4.0),
        "not traced",
        font(NOTE).colour(GREY).start(),
    );
    for (p, name, off) in [
        (x1, "*x*₁", v(-24.0, -14.0)),
        (x2, "*x*₂", v(0.0, -18.0)),
        (x3, "*x*₃", v(14.0, -18.0)),
        (x4, "*x*₄", v(-16.0, -14.0)),
    ] {
        d.dot(p, INK);
        d.text(p + off, name, font(LABEL));
    }
    d.text(cam + v(-18.0, -26.0), "camera", font(NOTE).colour(GREY));

    // What happens at each vertex.
    let note = font(NOTE);
    let mid1 = x1.lerp(y1, 0.55);
    d.text(
        mid1 + v(-12.0, -8.0),
        "light sample,",
        note.colour(ORANGE).end(),
    );
    d.text(
        mid1 + v(-12.0, 12.0),
        "weight *w*_*L*",
        note.colour(ORANGE).end(),
    );
    for (k, line) in ["BSDF sample,", "weight *w*_*B*", "if it hits the light"]
        .iter()
        .enumerate()
    {
        d.text(v(r - 8.0, 322.0 + 20.0 * k as f64), line, note.end());
    }
    d.text(
        v(0.5 * (mirror0 + mirror1), b + 20.0),
        "*x*₂ on a mirror (delta): no shadow ray",
        note.colour(BLUE),
    );
    d.text(v(l, b + 20.0), "*x*₄ at depth max\\_depth:", note.start());
    d.text(v(l, b + 40.0), "no shadow ray", note.start());
    let f = font(SMALL).colour(GREY).start();
    d.text(
        v(l, b + 72.0),
        "Next-event estimation only where the BSDF continuation is also traced:",
        f,
    );
    d.text(
        v(l, b + 92.0),
        "every diffuse vertex before max\\_depth (here max\\_depth = 3; *x*₁ is at depth 0).",
        f,
    );
    Ok(d.finish(
        "One path of the path tracer: from the camera to x1 on a diffuse wall, a mirror bounce at x2, x3 on a diffuse wall and x4 at the maximum depth; a dashed shadow ray to a point of the quad light at x1 and x3, weighted w_L, none at the mirror vertex and none at the last vertex, whose BSDF continuation is not traced.",
        "A room in section with a quad light on the ceiling and a mirror tile on the floor. At each diffuse vertex before the last (x1, x3) the path tracer samples a point on the light and casts a shadow ray (dashed), weighted w_L by the power heuristic, and samples the BSDF for the next direction, whose contribution, if it hits the light, is weighted w_B. At the mirror vertex x2 (a delta bounce) there is no light sample, and a light hit next counts in full. At x4, at depth max_depth (x1 is depth 0), there is no shadow ray either, because the BSDF half of the same paths, one bounce longer, is never traced: next-event estimation only where the BSDF continuation is also traced.",
    ))
}
