//! Diagrams that explain: the geometry behind the book's derivations, drawn as line
//! drawings (issue 23), one idea per diagram, labelled in the notation of its chapter.
//!
//! They are SVG written element by element with the few primitives of this module (lines,
//! arrows, polylines, arcs, circles, translucent polygons, dashed lines, text with italic,
//! bold, subscripts and superscripts): plotters draws charts, not geometry. The style is the
//! charts' (`plot.rs`): the same font family, the Okabe-Ito colours, lines of 1 to 2 units,
//! dark text on a white card, which `assets/book/figures.css` sets off on the dark themes.
//! Each diagram is [`WIDTH`] units wide with a `viewBox`, so that it scales; its text is
//! 13.5 units at least (subscripts aside), and it carries its alt text as `<title>` and a
//! longer description as `<desc>`.
//!
//! Where a diagram shows a computed fact, it computes it with the library's own functions:
//! refracted and reflected directions (`optics::reflect`), the thin-film phasors
//! (`optics::thinfilm`), the colour-matching functions and the wavelength samplers
//! (`spectral`), the camera's pixel convention (`render::camera`), and it fails rather than
//! draw something the library disagrees with.

use std::f64::consts::PI;
use std::fmt::Write as _;

use glam::{DVec2, DVec3};
use num_complex::Complex64;

use super::{Output, Record, Settings};
use crate::plot::{BoxError, FAMILY};
use raylemma::optics::reflect::{reflect, refract};
use raylemma::optics::thinfilm::{self, Film};
use raylemma::render::camera::Camera;
use raylemma::render::scene::CameraSpec;
use raylemma::sampling::disc::disc_concentric;
use raylemma::spectral::wavelength::{self, N, Strategy};
use raylemma::spectral::{LAMBDA_MAX, LAMBDA_MIN, cie};

/// The outputs: one diagram each, in book order.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "diagram_malley.svg",
            what: "diagram: Malley's method, a disc lifted onto the hemisphere",
            make: malley,
        },
        Output {
            file: "diagram_fresnel_sp.svg",
            what: "diagram: s and p polarisation, and a beam's footprint",
            make: fresnel_sp,
        },
        Output {
            file: "diagram_thinfilm.svg",
            what: "diagram: the two rays of a thin film and the Airy sum as phasors",
            make: thinfilm_diagram,
        },
        Output {
            file: "diagram_solid_angle.svg",
            what: "diagram: a light's patch, its foreshortening and its solid angle",
            make: solid_angle,
        },
        Output {
            file: "diagram_hero_lanes.svg",
            what: "diagram: where each wavelength strategy puts its lanes",
            make: hero_lanes,
        },
        Output {
            file: "diagram_camera.svg",
            what: "diagram: the camera's convention",
            make: camera,
        },
        Output {
            file: "diagram_path.svg",
            what: "diagram: one path of the path tracer, its shadow rays and its last vertex",
            make: path,
        },
    ]
}

// ---------------------------------------------------------------------------------------
// Primitives.

type V = DVec2;

const fn v(x: f64, y: f64) -> V {
    DVec2::new(x, y)
}

/// Width of every diagram, in SVG units (CSS px at the book's natural size).
pub const WIDTH: f64 = 640.0;

/// Labels of points, vectors and angles.
const LABEL: f64 = 15.0;
/// Notes and formulas.
const NOTE: f64 = 14.0;
/// Panel headings.
const HEAD: f64 = 16.0;
/// Tick labels, the smallest text.
const SMALL: f64 = 13.5;
/// The family of names from the code and the scene files.
const MONO: &str = "DejaVu Sans Mono, Menlo, Consolas, monospace";
/// Subscripts and superscripts, as a fraction of their text's size.
const SCRIPT: f64 = 0.8;

/// Text, and the lines of what is drawn in black.
const INK: &str = "#000000";
/// Surfaces and construction lines: black at 0.7, as the charts' axes.
const GREY: &str = "#4D4D4D";
/// Guides: black at 0.35.
const FAINT: &str = "#A6A6A6";
/// The Okabe-Ito palette of `plot::PALETTE`, by name.
const BLUE: &str = "#0072B2";
const VERMILION: &str = "#D55E00";
const GREEN: &str = "#009E73";
const PURPLE: &str = "#CC79A7";
const ORANGE: &str = "#E69F00";
const SKY: &str = "#56B4E9";

/// A stroke: colour, width, dash pattern (empty: solid) and opacity.
#[derive(Clone, Copy, Debug)]
struct Pen {
    colour: &'static str,
    width: f64,
    dash: &'static str,
    opacity: f64,
}

impl Pen {
    const fn new(colour: &'static str, width: f64) -> Self {
        Pen {
            colour,
            width,
            dash: "",
            opacity: 1.0,
        }
    }

    const fn dashed(self) -> Self {
        Pen {
            dash: "7 5",
            ..self
        }
    }

    const fn dotted(self) -> Self {
        Pen {
            dash: "0.5 4.5",
            ..self
        }
    }

    const fn faded(self, opacity: f64) -> Self {
        Pen { opacity, ..self }
    }

    fn attributes(&self) -> String {
        let mut a = format!(
            " fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linecap=\"round\" stroke-linejoin=\"round\"",
            self.colour,
            num(self.width)
        );
        if !self.dash.is_empty() {
            let _ = write!(a, " stroke-dasharray=\"{}\"", self.dash);
        }
        if self.opacity < 1.0 {
            let _ = write!(a, " stroke-opacity=\"{}\"", num(self.opacity));
        }
        a
    }
}

/// Where a text's position is along its line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Anchor {
    Start,
    Middle,
    End,
}

/// How a text is drawn: size, anchor, colour, and a white halo that keeps it legible over
/// lines.
#[derive(Clone, Copy, Debug)]
struct Font {
    size: f64,
    anchor: Anchor,
    colour: &'static str,
    halo: bool,
}

const fn font(size: f64) -> Font {
    Font {
        size,
        anchor: Anchor::Middle,
        colour: INK,
        halo: true,
    }
}

impl Font {
    const fn start(self) -> Self {
        Font {
            anchor: Anchor::Start,
            ..self
        }
    }

    const fn end(self) -> Self {
        Font {
            anchor: Anchor::End,
            ..self
        }
    }

    const fn colour(self, colour: &'static str) -> Self {
        Font { colour, ..self }
    }
}

/// A number for an attribute: two decimals at most, no trailing zeros.
fn num(x: f64) -> String {
    let s = format!("{x:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

fn point(p: V) -> String {
    format!("{},{}", num(p.x), num(p.y))
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// One run of text in one style: italic, bold, and its script level (0 on the baseline,
/// 1 a subscript, -1 a superscript).
#[derive(Clone, Debug, PartialEq)]
struct Run {
    text: String,
    italic: bool,
    bold: bool,
    code: bool,
    script: i8,
}

/// The runs of a label written in a small markup: `*…*` italic, `~…~` bold, `` `…` ``
/// monospace (a name of the scene file or the code), `_x`, `_*x*`
/// or `_{…}` a subscript, `^x`, `^*x*` or `^{…}` a superscript, `\` takes the next
/// character literally. Unicode does the rest (θ, ω, λ, n₁, r̂).
fn runs(markup: &str) -> Vec<Run> {
    let mut out: Vec<Run> = Vec::new();
    let (mut italic, mut bold, mut code) = (false, false, false);
    let mut push = |c: char, italic: bool, bold: bool, code: bool, script: i8| match out.last_mut()
    {
        Some(r) if r.italic == italic && r.bold == bold && r.code == code && r.script == script => {
            r.text.push(c);
        }
        _ => out.push(Run {
            text: c.to_string(),
            italic,
            bold,
            code,
            script,
        }),
    };
    let mut chars = markup.chars();
    while let Some(c) = chars.next() {
        match c {
            '*' => italic = !italic,
            '~' => bold = !bold,
            '`' => code = !code,
            '\\' => {
                if let Some(n) = chars.next() {
                    push(n, italic, bold, code, 0);
                }
            }
            '_' | '^' if code => push(c, italic, bold, code, 0),
            '_' | '^' => {
                let script = if c == '_' { 1 } else { -1 };
                let mut group = String::new();
                match chars.next() {
                    Some('{') => {
                        for g in chars.by_ref() {
                            if g == '}' {
                                break;
                            }
                            group.push(g);
                        }
                    }
                    // `_*ω*`: an italic script of the letters up to the closing `*`.
                    Some('*') => {
                        group.push('*');
                        for g in chars.by_ref() {
                            group.push(g);
                            if g == '*' {
                                break;
                            }
                        }
                    }
                    Some(g) => group.push(g),
                    None => {}
                }
                for g in group.chars() {
                    match g {
                        '*' => italic = !italic,
                        '~' => bold = !bold,
                        _ => push(g, italic, bold, code, script),
                    }
                }
            }
            _ => push(c, italic, bold, code, 0),
        }
    }
    out
}

/// The baseline shift of a script level, in units of the text's size (SVG's y grows down).
fn shift(script: i8) -> f64 {
    match script {
        1 => 0.28,
        -1 => -0.42,
        _ => 0.0,
    }
}

/// An SVG diagram being drawn: [`WIDTH`] wide, `height` high, its elements in `body`.
struct Svg {
    height: f64,
    body: String,
}

impl Svg {
    fn new(height: f64) -> Self {
        Svg {
            height,
            body: String::new(),
        }
    }

    fn line(&mut self, a: V, b: V, pen: Pen) {
        let _ = writeln!(
            self.body,
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"{}/>",
            num(a.x),
            num(a.y),
            num(b.x),
            num(b.y),
            pen.attributes()
        );
    }

    fn polyline(&mut self, points: &[V], pen: Pen) {
        let p: Vec<String> = points.iter().map(|&p| point(p)).collect();
        let _ = writeln!(
            self.body,
            "<polyline points=\"{}\"{}/>",
            p.join(" "),
            pen.attributes()
        );
    }

    /// A filled polygon, no outline.
    fn polygon(&mut self, points: &[V], fill: &str, opacity: f64) {
        let p: Vec<String> = points.iter().map(|&p| point(p)).collect();
        let _ = writeln!(
            self.body,
            "<polygon points=\"{}\" fill=\"{fill}\" fill-opacity=\"{}\" stroke=\"none\"/>",
            p.join(" "),
            num(opacity)
        );
    }

    fn circle(&mut self, c: V, r: f64, fill: Option<&str>, pen: Option<Pen>) {
        let stroke = pen.map_or(" stroke=\"none\"".to_string(), |p| {
            p.attributes().replace(" fill=\"none\"", "")
        });
        let _ = writeln!(
            self.body,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"{stroke}/>",
            num(c.x),
            num(c.y),
            num(r),
            fill.unwrap_or("none")
        );
    }

    /// A point: a small filled disc.
    fn dot(&mut self, c: V, colour: &str) {
        self.circle(c, 3.5, Some(colour), None);
    }

    /// An arrowhead with its tip at `tip`, pointing along `dir`.
    fn head(&mut self, tip: V, dir: V, pen: Pen) {
        let d = dir.normalize();
        let n = v(-d.y, d.x);
        let (len, half) = (8.0 + 2.0 * pen.width, 3.0 + 1.0 * pen.width);
        let base = tip - d * len;
        let opacity = if pen.opacity < 1.0 {
            format!(" fill-opacity=\"{}\"", num(pen.opacity))
        } else {
            String::new()
        };
        let _ = writeln!(
            self.body,
            "<polygon points=\"{} {} {}\" fill=\"{}\"{opacity} stroke=\"none\"/>",
            point(tip),
            point(base + n * half),
            point(base - n * half),
            pen.colour
        );
    }

    /// A line from `a` to `b` with an arrowhead at `b`.
    fn arrow(&mut self, a: V, b: V, pen: Pen) {
        let d = (b - a).normalize();
        let len = 8.0 + 2.0 * pen.width;
        self.line(a, b - d * (0.7 * len), pen);
        self.head(b, d, pen);
    }

    /// A line from `a` to `b` with arrowheads at both ends: a dimension, or a field that
    /// oscillates.
    fn arrow2(&mut self, a: V, b: V, pen: Pen) {
        let d = (b - a).normalize();
        let len = 8.0 + 2.0 * pen.width;
        self.line(a + d * (0.7 * len), b - d * (0.7 * len), pen);
        self.head(b, d, pen);
        self.head(a, -d, pen);
    }

    /// A line from `a` to `b` with an arrowhead at the fraction `at` of the way: a ray.
    fn ray(&mut self, a: V, b: V, at: f64, pen: Pen) {
        self.line(a, b, pen);
        let len = 8.0 + 2.0 * pen.width;
        let d = (b - a).normalize();
        self.head(a.lerp(b, at) + d * (0.5 * len), d, pen);
    }

    /// The arc of radius `r` around `c` from the direction `from` to the direction `to`,
    /// the shorter way round.
    fn arc(&mut self, c: V, r: f64, from: V, to: V, pen: Pen) {
        let (a, b) = (from.normalize(), to.normalize());
        let cross = a.x * b.y - a.y * b.x;
        let (p, q) = (c + a * r, c + b * r);
        let _ = writeln!(
            self.body,
            "<path d=\"M{} A{} {} 0 0 {} {}\"{}/>",
            point(p),
            num(r),
            num(r),
            u8::from(cross > 0.0),
            point(q),
            pen.attributes()
        );
    }

    /// The square mark of a right angle at `c` between the directions `a` and `b`.
    fn right_angle(&mut self, c: V, a: V, b: V, pen: Pen) {
        let (a, b) = (a.normalize() * 9.0, b.normalize() * 9.0);
        self.polyline(&[c + a, c + a + b, c + b], pen);
    }

    /// The ⊙ of a field pointing out of the page.
    fn out_of_page(&mut self, c: V, colour: &'static str) {
        self.circle(c, 5.5, Some("#FFFFFF"), Some(Pen::new(colour, 1.6)));
        self.circle(c, 1.9, Some(colour), None);
    }

    /// A label in the markup of [`runs`], centred vertically on `at`.
    fn text(&mut self, at: V, markup: &str, f: Font) {
        let anchor = match f.anchor {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        };
        let halo = if f.halo {
            " stroke=\"#FFFFFF\" stroke-width=\"4\" stroke-linejoin=\"round\" paint-order=\"stroke\""
        } else {
            ""
        };
        let _ = write!(
            self.body,
            "<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"{anchor}\" fill=\"{}\" xml:space=\"preserve\"{halo}>",
            num(at.x),
            num(at.y + 0.35 * f.size),
            num(f.size),
            f.colour
        );
        let mut level = 0.0;
        for r in runs(markup) {
            let mut attrs = String::new();
            let target = shift(r.script) * f.size;
            if (target - level).abs() > 1e-9 {
                let _ = write!(attrs, " dy=\"{}\"", num(target - level));
                level = target;
            }
            if r.script != 0 {
                let _ = write!(attrs, " font-size=\"{}\"", num(SCRIPT * f.size));
            }
            if r.italic {
                attrs.push_str(" font-style=\"italic\"");
            }
            if r.bold {
                attrs.push_str(" font-weight=\"bold\"");
            }
            if r.code {
                let _ = write!(attrs, " font-family=\"{MONO}\"");
            }
            let text = escape(&r.text);
            if attrs.is_empty() {
                self.body.push_str(&text);
            } else {
                let _ = write!(self.body, "<tspan{attrs}>{text}</tspan>");
            }
        }
        self.body.push_str("</text>\n");
    }

    /// The SVG's bytes, with `title` (the alt text) and `desc`.
    fn finish(self, title: &str, desc: &str) -> Vec<u8> {
        let h = num(self.height);
        let w = num(WIDTH);
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" role=\"img\" font-family=\"{FAMILY}\">\n<title>{}</title>\n<desc>{}</desc>\n<rect x=\"0\" y=\"0\" width=\"{w}\" height=\"{h}\" fill=\"#FFFFFF\"/>\n{}</svg>\n",
            escape(title),
            escape(desc),
            self.body
        )
        .into_bytes()
    }
}

/// The unit vector at `deg` degrees counter-clockwise from +x as seen on the page (SVG's
/// y grows down).
fn dir(deg: f64) -> V {
    let a = deg.to_radians();
    v(a.cos(), -a.sin())
}

/// `d` turned by `deg` degrees counter-clockwise as seen on the page.
fn turn(d: V, deg: f64) -> V {
    let (s, c) = deg.to_radians().sin_cos();
    v(c * d.x + s * d.y, -s * d.x + c * d.y)
}

/// The unit vector half-way between the directions `a` and `b` (the shorter way round).
fn bisector(a: V, b: V) -> V {
    (a.normalize() + b.normalize()).normalize()
}

/// Where the lines `p + s d` and `q + t e` meet.
fn meet(p: V, d: V, q: V, e: V) -> V {
    let den = d.x * e.y - d.y * e.x;
    let s = ((q.x - p.x) * e.y - (q.y - p.y) * e.x) / den;
    p + d * s
}

/// A page vector as a 3-vector of the library (z = 0), and back.
fn to3(p: V) -> DVec3 {
    DVec3::new(p.x, p.y, 0.0)
}

fn to2(p: DVec3) -> V {
    v(p.x, p.y)
}

/// An error unless `ok`: a diagram that would disagree with the library is not drawn.
fn ensure(ok: bool, what: &str) -> Result<(), BoxError> {
    if ok {
        Ok(())
    } else {
        Err(format!("diagram disagrees with the library: {what}").into())
    }
}

// ---------------------------------------------------------------------------------------
// Shadow-ray pdfs: from area to solid angle.

fn solid_angle(_: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
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

// ---------------------------------------------------------------------------------------
// Cosine-weighted hemisphere: Malley's method.

fn malley(_: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
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
// ---------------------------------------------------------------------------------------
// Fresnel and Schlick: s and p, and the beam's footprint.

fn fresnel_sp(_: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    let (n1, n2) = (1.0, 1.5);
    let theta_i: f64 = 50.0;
    let mut d = Svg::new(430.0);
    // The directions, by the library (page coordinates, y down: the normal up is -y).
    let wi = dir(-90.0 + theta_i);
    let up = v(0.0, -1.0);
    let wr = to2(reflect(to3(wi), to3(up)));
    let wt = to2(refract(to3(wi), to3(up), n1, n2)
        .transmitted()
        .ok_or("no transmitted ray")?);
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
// ---------------------------------------------------------------------------------------
// Thin-film interference: the path difference, and the Airy sum as phasors.

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

fn thinfilm_diagram(_: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
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
        .ok_or("no ray in the film")?);
    let w_back = to2(reflect(to3(w2), to3(up)));
    let w_out = to2(refract(to3(w_back), to3(down), n2, n1)
        .transmitted()
        .ok_or("no ray out of the film")?);
    let w3 = to2(refract(to3(w2), to3(up), n2, n3)
        .transmitted()
        .ok_or("no ray into the substrate")?);
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
// ---------------------------------------------------------------------------------------
// Wavelength sampling: where each strategy puts its lanes.

/// The uniform number every row of the lanes diagram is drawn with.
const LANES_U: f64 = 0.3;

/// What each lane of a strategy is weighted by, in the chapter's notation.
fn lane_weights(s: Strategy) -> &'static str {
    match s {
        Strategy::Uniform => "one lane, *p* = 1/470",
        Strategy::Visible => "one lane, *p*(*λ*₀)",
        Strategy::HeroUniform => "each *p*_*j* = 1/470",
        Strategy::HeroVisible => "each *p*_*j* = *p*(*λ*_*j*)",
        Strategy::HeroBalance => "each *p*_*j* = Σ_*k* *p*(*λ*_*k*) / *N*",
        Strategy::SeedBand => "each *p*_*j* = 1/400, 5 nm apart",
    }
}

fn hero_lanes(_: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
    let rows = Strategy::ALL.len();
    let row_gap = 44.0;
    let first_row = 262.0;
    let mut d = Svg::new(first_row + row_gap * (rows as f64 - 1.0) + 62.0);
    let (x0, x1) = (40.0, 610.0);
    let x = |nm: f64| x0 + (nm - LAMBDA_MIN) / (LAMBDA_MAX - LAMBDA_MIN) * (x1 - x0);
    let (base, top) = (200.0, 44.0);
    let y = |value: f64| base - value / 1.8 * (base - top);

    // The colour-matching functions and the visible pdf, over 360-830 nm.
    let last_row = first_row + row_gap * (rows as f64 - 1.0);
    for nm in [400.0, 500.0, 600.0, 700.0, 800.0] {
        d.line(
            v(x(nm), top),
            v(x(nm), last_row + 10.0),
            Pen::new(INK, 1.0).faded(0.12),
        );
        d.line(v(x(nm), base), v(x(nm), base + 5.0), Pen::new(GREY, 1.0));
        let label = if nm == 800.0 {
            "800 nm".to_string()
        } else {
            format!("{nm}")
        };
        d.text(v(x(nm), base + 17.0), &label, font(SMALL).colour(GREY));
    }
    d.line(v(x0, base), v(x1, base), Pen::new(GREY, 1.0));
    let nms: Vec<f64> = (0..=470).map(|k| LAMBDA_MIN + f64::from(k)).collect();
    let peak = wavelength::visible_pdf(wavelength::VISIBLE_C) / 1.3;
    let pdf: Vec<V> = nms
        .iter()
        .map(|&nm| v(x(nm), y(wavelength::visible_pdf(nm) / peak)))
        .collect();
    d.polyline(&pdf, Pen::new(GREY, 1.5).dashed());
    let curves = [
        (0, VERMILION, "*x̄*", v(630.0, 1.04), Anchor::Start),
        (1, GREEN, "*ȳ*", v(528.0, 1.0), Anchor::End),
        (2, BLUE, "*z̄*", v(462.0, 1.74), Anchor::Start),
    ];
    for (k, colour, name, at, anchor) in curves {
        let pts: Vec<V> = nms.iter().map(|&nm| v(x(nm), y(cie::cmf(nm)[k]))).collect();
        d.polyline(&pts, Pen::new(colour, 2.0));
        let f = Font {
            anchor,
            ..font(LABEL).colour(colour)
        };
        d.text(v(x(at.x), y(at.y)), name, f);
    }
    d.text(
        v(x1, y(0.82)),
        "*p*(*λ*): the visible pdf, scaled",
        font(NOTE).colour(GREY).end(),
    );
    d.text(
        v(x0, 22.0),
        "the colour-matching functions",
        font(HEAD).start(),
    );

    // One row per strategy: the lanes of one sample.
    for (row, &s) in Strategy::ALL.iter().enumerate() {
        let yr = first_row + row_gap * row as f64;
        d.text(v(x0, yr - 15.0), s.name(), font(NOTE).start());
        d.text(
            v(x1, yr - 15.0),
            lane_weights(s),
            font(NOTE).colour(GREY).end(),
        );
        let (lo, hi) = if s == Strategy::SeedBand {
            let band = wavelength::SEED_BAND;
            (band.lo, band.hi + (N as f64 - 1.0) * band.spacing)
        } else {
            (LAMBDA_MIN, LAMBDA_MAX)
        };
        d.line(v(x(lo), yr), v(x(hi), yr), Pen::new(GREY, 1.5));
        for end in [lo, hi] {
            d.line(
                v(x(end), yr - 5.0),
                v(x(end), yr + 5.0),
                Pen::new(GREY, 1.5),
            );
        }
        let w = s.sample(LANES_U);
        for j in (1..N).rev() {
            if w.pdf[j] > 0.0 {
                d.circle(
                    v(x(w.lambda[j]), yr),
                    5.0,
                    Some("#FFFFFF"),
                    Some(Pen::new(BLUE, 2.0)),
                );
            }
        }
        d.circle(v(x(w.lambda[0]), yr), 5.5, Some(BLUE), None);
    }

    // The key.
    let yk = last_row + 40.0;
    d.circle(v(x0 + 6.0, yk), 5.5, Some(BLUE), None);
    d.text(v(x0 + 18.0, yk), "the hero *λ*₀", font(NOTE).start());
    d.circle(
        v(x0 + 128.0, yk),
        5.0,
        Some("#FFFFFF"),
        Some(Pen::new(BLUE, 2.0)),
    );
    d.text(v(x0 + 140.0, yk), "the other lanes", font(NOTE).start());
    d.text(
        v(x1, yk),
        &format!("*N* = {N}, one sample at *u* = {LANES_U} in every row"),
        font(NOTE).colour(GREY).end(),
    );
    Ok(d.finish(
        "The CIE colour-matching functions over 360–830 nm with the visible pdf, and below them, for each wavelength strategy, where the lanes of one sample fall: one uniform wavelength, one from the visible pdf, hero wavelengths uniform, rotated in sample space through the visible pdf, rotated in wavelength space (the balance heuristic over the rotations of the pdf), and the source notes' band.",
        "Top: the CIE 1931 colour-matching functions x̄, ȳ, z̄ and the visible-range pdf p(λ) (scaled to the height of ȳ), over the sampled range 360–830 nm. Below: the wavelengths of one path, drawn by the library's samplers at the same uniform number u = 0.3, one row per strategy, the hero lane filled and the others hollow, with the density each lane is weighted by. A single wavelength has one live lane; uniform hero lanes are equally spaced over the range; rotated in sample space through the visible pdf they crowd where the pdf is large; rotated in wavelength space the lanes are equally spaced in wavelength from a hero drawn from the pdf; the source notes' four lanes lie within 15 nm of each other, from a first lane drawn on 380–780 nm.",
    ))
}
// ---------------------------------------------------------------------------------------
// The reference renderer: the camera's convention.

/// The camera of the diagram: the renderer's own, for its convention.
const CAMERA_FOV_DEG: f64 = 50.0;
const CAMERA_PIXELS: (u32, u32) = (8, 6);

/// Checks the convention the diagram draws against the library's camera: pixel (0, 0) at
/// the top left, x to the right (`forward × up`), y down, the top edge at `fov_y / 2` above
/// the view direction.
fn check_camera() -> Result<(), BoxError> {
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

fn camera(_: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
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

// ---------------------------------------------------------------------------------------
// The reference renderer: one path.

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

fn path(_: &Settings, _: &mut Record) -> Result<Vec<u8>, BoxError> {
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

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::*;
    use crate::plot::PALETTE;

    #[test]
    fn the_named_colours_are_the_charts_palette() {
        let hex: Vec<String> = PALETTE
            .iter()
            .map(|c| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2))
            .collect();
        assert_eq!(hex, [BLUE, VERMILION, GREEN, PURPLE, ORANGE, SKY]);
    }

    #[test]
    fn markup_makes_italic_bold_code_and_script_runs() {
        let r = runs("*p*_*ω* = ~n̂~^{2*i*} `fov_y` max\\_depth");
        let parts: Vec<(&str, bool, bool, bool, i8)> = r
            .iter()
            .map(|r| (r.text.as_str(), r.italic, r.bold, r.code, r.script))
            .collect();
        assert_eq!(
            parts,
            [
                ("p", true, false, false, 0),
                ("ω", true, false, false, 1),
                (" = ", false, false, false, 0),
                ("n̂", false, true, false, 0),
                ("2", false, false, false, -1),
                ("i", true, false, false, -1),
                (" ", false, false, false, 0),
                ("fov_y", false, false, true, 0),
                (" max_depth", false, false, false, 0),
            ]
        );
    }

    #[test]
    fn every_diagram_is_a_scalable_svg_with_alt_text_and_legible_text() {
        let settings = Settings {
            quick: true,
            timings: false,
            root: PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../.."),
        };
        for o in outputs() {
            let mut record = Record::new(o.file);
            let svg = String::from_utf8((o.make)(&settings, &mut record).unwrap()).unwrap();
            let file = o.file;
            assert!(
                svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"640\""),
                "{file}"
            );
            assert!(svg.contains(" viewBox=\"0 0 640 "), "{file}");
            let between = |open: &str, close: &str| {
                let start = svg.find(open).map(|i| i + open.len())?;
                let end = svg[start..].find(close)?;
                Some(svg[start..start + end].to_string())
            };
            let title = between("<title>", "</title>").unwrap_or_default();
            let desc = between("<desc>", "</desc>").unwrap_or_default();
            assert!(title.len() > 60 && desc.len() > title.len(), "{file}");
            // Every text at least SMALL, every element closed, no number gone wrong.
            let sizes: Vec<f64> = svg
                .split("<text ")
                .skip(1)
                .map(|t| {
                    let s = &t[t.find("font-size=\"").unwrap() + 11..];
                    s[..s.find('"').unwrap()].parse().unwrap()
                })
                .collect();
            assert!(sizes.len() > 5, "{file}");
            assert!(sizes.iter().all(|&s| s >= SMALL), "{file}: {sizes:?}");
            assert_eq!(
                svg.matches("<text ").count(),
                svg.matches("</text>").count()
            );
            assert_eq!(
                svg.matches("<tspan").count(),
                svg.matches("</tspan>").count()
            );
            assert!(
                !svg.contains("NaN") && !svg.contains("inf\"") && !svg.contains("inf,"),
                "{file}"
            );
        }
    }

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
