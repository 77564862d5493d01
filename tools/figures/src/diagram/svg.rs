//! The SVG a diagram is written as, element by element: lines, arrows, polylines, arcs,
//! circles, translucent polygons and text, with its title and description.

use std::fmt::Write as _;

use super::geometry::{V, v};
use super::markup::{runs, shift};
use super::style::{Anchor, Font, MONO, Pen, SCRIPT, WIDTH};
use crate::plot::FAMILY;

/// A number for an attribute: two decimals at most, no trailing zeros.
pub(super) fn num(x: f64) -> String {
    let s = format!("{x:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

pub(super) fn point(p: V) -> String {
    format!("{},{}", num(p.x), num(p.y))
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// An SVG diagram being drawn: [`WIDTH`] wide, `height` high, its elements in `body`.
pub(super) struct Svg {
    pub(super) height: f64,
    pub(super) body: String,
}

impl Svg {
    pub(super) fn new(height: f64) -> Self {
        Svg {
            height,
            body: String::new(),
        }
    }

    pub(super) fn line(&mut self, a: V, b: V, pen: Pen) {
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

    pub(super) fn polyline(&mut self, points: &[V], pen: Pen) {
        let p: Vec<String> = points.iter().map(|&p| point(p)).collect();
        let _ = writeln!(
            self.body,
            "<polyline points=\"{}\"{}/>",
            p.join(" "),
            pen.attributes()
        );
    }

    /// A filled polygon, no outline.
    pub(super) fn polygon(&mut self, points: &[V], fill: &str, opacity: f64) {
        let p: Vec<String> = points.iter().map(|&p| point(p)).collect();
        let _ = writeln!(
            self.body,
            "<polygon points=\"{}\" fill=\"{fill}\" fill-opacity=\"{}\" stroke=\"none\"/>",
            p.join(" "),
            num(opacity)
        );
    }

    pub(super) fn circle(&mut self, c: V, r: f64, fill: Option<&str>, pen: Option<Pen>) {
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
    pub(super) fn dot(&mut self, c: V, colour: &str) {
        self.circle(c, 3.5, Some(colour), None);
    }

    /// An arrowhead with its tip at `tip`, pointing along `dir`.
    pub(super) fn head(&mut self, tip: V, dir: V, pen: Pen) {
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
    pub(super) fn arrow(&mut self, a: V, b: V, pen: Pen) {
        let d = (b - a).normalize();
        let len = 8.0 + 2.0 * pen.width;
        self.line(a, b - d * (0.7 * len), pen);
        self.head(b, d, pen);
    }

    /// A line from `a` to `b` with arrowheads at both ends: a dimension, or a field that
    /// oscillates.
    pub(super) fn arrow2(&mut self, a: V, b: V, pen: Pen) {
        let d = (b - a).normalize();
        let len = 8.0 + 2.0 * pen.width;
        self.line(a + d * (0.7 * len), b - d * (0.7 * len), pen);
        self.head(b, d, pen);
        self.head(a, -d, pen);
    }

    /// A line from `a` to `b` with an arrowhead at the fraction `at` of the way: a ray.
    pub(super) fn ray(&mut self, a: V, b: V, at: f64, pen: Pen) {
        self.line(a, b, pen);
        let len = 8.0 + 2.0 * pen.width;
        let d = (b - a).normalize();
        self.head(a.lerp(b, at) + d * (0.5 * len), d, pen);
    }

    /// The arc of radius `r` around `c` from the direction `from` to the direction `to`,
    /// the shorter way round.
    pub(super) fn arc(&mut self, c: V, r: f64, from: V, to: V, pen: Pen) {
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
    pub(super) fn right_angle(&mut self, c: V, a: V, b: V, pen: Pen) {
        let (a, b) = (a.normalize() * 9.0, b.normalize() * 9.0);
        self.polyline(&[c + a, c + a + b, c + b], pen);
    }

    /// The ⊙ of a field pointing out of the page.
    pub(super) fn out_of_page(&mut self, c: V, colour: &'static str) {
        self.circle(c, 5.5, Some("#FFFFFF"), Some(Pen::new(colour, 1.6)));
        self.circle(c, 1.9, Some(colour), None);
    }

    /// A label in the markup of [`runs`], centred vertically on `at`.
    pub(super) fn text(&mut self, at: V, markup: &str, f: Font) {
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
    pub(super) fn finish(self, title: &str, desc: &str) -> Vec<u8> {
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
