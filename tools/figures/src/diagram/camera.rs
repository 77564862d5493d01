//! The diagram of the reference renderer's camera convention (`diagram_camera.svg`), of the
//! chapter *The path tracer* (`chapters/renderer/path-tracer.md`).

use glam::{DVec2, DVec3};

use super::ensure;
use super::geometry::{turn, v};
use super::style::{
    BLUE, FAINT, GREEN, GREY, HEAD, INK, LABEL, NOTE, Pen, SKY, SMALL, VERMILION, font,
};
use super::svg::Svg;
use crate::{Record, Settings};
use raylemma::render::camera::Camera;
use raylemma::render::scene::CameraSpec;

/// The camera of the diagram: the renderer's own, for its convention.
const CAMERA_FOV_DEG: f64 = 50.0;
const CAMERA_PIXELS: (u32, u32) = (8, 6);

/// Checks the convention the diagram draws against the library's camera: pixel (0, 0) at
/// the top left, x to the right (`forward × up`), y down, the top edge at `fov_y / 2` above
/// the view direction.
fn check_camera() -> anyhow::Result<()> {
    let (w, h) = CAMERA_PIXELS;
    let spec = CameraSpec {
        position: DVec3::ZERO,
        look_at: DVec3::Z,
        up: DVec3::new(0.0, 1.0, 0.3),
        fov_y_deg: CAMERA_FOV_DEG,
        width: w,
        height: h,
    };
    let cam = Camera::new(&spec);
    let forward = DVec3::Z;
    let right = forward.cross(spec.up).normalize();
    let up = right.cross(forward);
    ensure(
        right.abs_diff_eq(-DVec3::X, 1e-12),
        "looking down +z with up +y, right is -x",
    )?;
    let corner = cam.ray(0, 0, DVec2::ZERO).dir;
    ensure(
        corner.dot(right) < 0.0 && corner.dot(up) > 0.0,
        "pixel (0, 0) is the top left",
    )?;
    let next = cam.ray(1, 1, DVec2::ZERO).dir;
    ensure(
        next.dot(right) > corner.dot(right) && next.dot(up) < corner.dot(up),
        "x grows to the right, y down",
    )?;
    let top = cam.ray(w / 2, 0, DVec2::ZERO).dir;
    ensure(
        (top.dot(up).atan2(top.dot(forward)).to_degrees() - 0.5 * CAMERA_FOV_DEG).abs() < 1e-9,
        "the top edge is fov_y / 2 above the view direction",
    )?;
    Ok(())
}

pub(super) fn camera(_: &Settings, _: &mut Record) -> anyhow::Result<Vec<u8>> {
    check_camera()?;
    let mut d = Svg::new(356.0);
    let half = (0.5 * CAMERA_FOV_DEG).to_radians().tan();

    // Left: the side view, in the plane of forward and up.
    d.text(v(170.0, 22.0), "side view", font(HEAD));
    let p = v(54.0, 178.0);
    let unit = 176.0;
    let plane = p.x + unit;
    let (top, bottom) = (v(plane, p.y - unit * half), v(plane, p.y + unit * half));
    d.polygon(&[p, top, bottom], SKY, 0.14);
    d.line(p, top, Pen::new(GREY, 1.2));
    d.line(p, bottom, Pen::new(GREY, 1.2));
    d.line(top, bottom, Pen::new(BLUE, 3.0));
    d.text(top + v(0.0, -14.0), "image plane", font(NOTE).colour(BLUE));
    let look = v(plane + 86.0, p.y);
    d.line(p, look, Pen::new(GREY, 1.0).dashed());
    d.arrow(p, v(p.x + 64.0, p.y), Pen::new(INK, 2.0));
    d.text(v(p.x + 128.0, p.y - 12.0), "forward", font(NOTE));
    d.dot(look, INK);
    d.text(look + v(0.0, 18.0), "`look_at`", font(NOTE));
    d.arc(p, 44.0, top - p, bottom - p, Pen::new(INK, 1.3));
    d.text(p + v(84.0, 22.0), "`fov_y`", font(NOTE));
    d.arrow2(
        v(plane + 14.0, p.y),
        v(plane + 14.0, top.y),
        Pen::new(GREY, 1.0),
    );
    d.text(
        v(plane + 20.0, 0.5 * (p.y + top.y)),
        "tan(`fov_y` / 2)",
        font(NOTE).start(),
    );
    d.arrow2(
        v(p.x, p.y + 104.0),
        v(plane, p.y + 104.0),
        Pen::new(GREY, 1.0),
    );
    d.text(v(0.5 * (p.x + plane), p.y + 118.0), "1", font(NOTE));
    // up as given (any direction not along forward) and up made perpendicular to it.
    let given = turn(v(0.0, -1.0), -24.0);
    d.arrow(p, p + given * 70.0, Pen::new(GREY, 1.6));
    d.text(
        p + given * 78.0 + v(6.0, -6.0),
        "`up` as given",
        font(NOTE).colour(GREY).start(),
    );
    d.arrow(p, p + v(0.0, -60.0), Pen::new(GREEN, 2.0));
    d.text(p + v(-4.0, -72.0), "up", font(NOTE).colour(GREEN));
    d.out_of_page(p, VERMILION);
    d.text(p + v(0.0, 22.0), "`position`", font(NOTE));
    d.text(
        v(170.0, 320.0),
        "right = forward × up: out of the page",
        font(NOTE).colour(VERMILION),
    );

    // Right: the image, as the camera sees it.
    let (w, h) = CAMERA_PIXELS;
    let cx = 498.0;
    d.text(v(cx, 22.0), "the image, seen from `position`", font(HEAD));
    let cell = 30.0;
    let (iw, ih) = (cell * f64::from(w), cell * f64::from(h));
    let origin = v(cx - 0.5 * iw, 178.0 - 0.5 * ih);
    d.polygon(
        &[
            origin,
            origin + v(cell, 0.0),
            origin + v(cell, cell),
            origin + v(0.0, cell),
        ],
        SKY,
        0.6,
    );
    for i in 0..=w {
        let x = origin.x + cell * f64::from(i);
        d.line(v(x, origin.y), v(x, origin.y + ih), Pen::new(FAINT, 1.0));
    }
    for j in 0..=h {
        let y = origin.y + cell * f64::from(j);
        d.line(v(origin.x, y), v(origin.x + iw, y), Pen::new(FAINT, 1.0));
    }
    d.polyline(
        &[
            origin,
            origin + v(iw, 0.0),
            origin + v(iw, ih),
            origin + v(0.0, ih),
            origin,
        ],
        Pen::new(BLUE, 3.0),
    );
    d.text(origin + v(0.5 * cell, 0.5 * cell), "0, 0", font(SMALL));
    d.arrow(
        origin + v(0.0, -14.0),
        origin + v(74.0, -14.0),
        Pen::new(INK, 1.6),
    );
    d.text(origin + v(86.0, -14.0), "*x*", font(LABEL));
    d.arrow(
        origin + v(-14.0, 0.0),
        origin + v(-14.0, 74.0),
        Pen::new(INK, 1.6),
    );
    d.text(origin + v(-14.0, 88.0), "*y*", font(LABEL));
    let centre = origin + v(0.5 * iw, 0.5 * ih);
    d.arrow(centre, centre + v(64.0, 0.0), Pen::new(VERMILION, 2.0));
    d.text(
        centre + v(66.0, 16.0),
        "right",
        font(NOTE).colour(VERMILION).start(),
    );
    d.arrow(centre, centre + v(0.0, -56.0), Pen::new(GREEN, 2.0));
    d.text(
        centre + v(-8.0, -50.0),
        "up",
        font(NOTE).colour(GREEN).end(),
    );
    d.circle(centre, 4.0, Some(INK), None);
    d.text(centre + v(-8.0, 16.0), "`look_at`", font(NOTE).end());
    let f = font(NOTE).colour(GREY);
    d.text(
        v(cx, origin.y + ih + 22.0),
        &format!("{w} × {h} pixels, row 0 at the top"),
        f,
    );
    d.text(
        v(cx, origin.y + ih + 44.0),
        &format!("2 tan(`fov_y` / 2) high, aspect {w} : {h}"),
        f,
    );
    d.text(
        v(cx, origin.y + ih + 66.0),
        "looking down +*z*, up +*y*: right is −*x*",
        f,
    );
    Ok(d.finish(
        "The camera's convention: a pinhole at position looking at look_at, up made perpendicular to the view, an image plane at unit distance 2 tan(fov_y / 2) high, and the image with pixel (0, 0) at the top left, x to the right and y down.",
        "Side view, in the plane of the view direction and up: rays leave position through an image plane at unit distance along forward (towards look_at), 2 tan(fov_y / 2) high, so that fov_y is the vertical field of view. The up given need not be perpendicular to the view; the camera uses its component perpendicular to forward, and right = forward × up points out of the page. Right: the image as the camera sees it, pixel (0, 0) at the top left, x growing to the right and y downwards, forward through its centre; a camera looking down +z with up +y has -x on its right. The drawing is checked against the library's camera.",
    ))
}
