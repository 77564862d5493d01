//! The elements plotters draws for the series: a polyline whose dashes run on across its
//! points ([`Styled`]) and a marker of a series' shape ([`Marker`]).

use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters_backend::{BackendCoord, DrawingErrorKind};

use super::look::{LINE_WIDTH, Shape};

/// A polyline in a dash pattern (empty: solid). Dashes run on across the points, so a
/// dense curve is dashed like a straight line.
pub struct Styled<Coord> {
    pub(super) points: Vec<Coord>,
    pub(super) colour: RGBColor,
    pub(super) dash: &'static [f64],
}

impl<Coord> Styled<Coord> {
    pub(super) fn line(points: Vec<Coord>, colour: RGBColor, dash: &'static [f64]) -> Self {
        Styled {
            points,
            colour,
            dash,
        }
    }
}

impl<'a, Coord> PointCollection<'a, Coord> for &'a Styled<Coord> {
    type Point = &'a Coord;
    type IntoIter = &'a [Coord];
    fn point_iter(self) -> &'a [Coord] {
        &self.points
    }
}

impl<Coord, DB: DrawingBackend> Drawable<DB> for Styled<Coord> {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        points: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let style = self.colour.stroke_width(LINE_WIDTH);
        let mut points: Vec<BackendCoord> = points.collect();
        points.dedup();
        if self.dash.is_empty() {
            return backend.draw_path(points, &style);
        }
        let f = |p: BackendCoord| (f64::from(p.0), f64::from(p.1));
        let round = |(x, y): (f64, f64)| (x.round() as i32, y.round() as i32);
        // `k`: the pattern's current entry (even: on); `left`: what remains of it.
        let (mut k, mut left) = (0, self.dash[0]);
        let mut dash = vec![points[0]];
        for w in points.windows(2) {
            let (mut a, b) = (f(w[0]), f(w[1]));
            let mut seg = (b.0 - a.0).hypot(b.1 - a.1);
            while seg > left {
                let t = left / seg;
                a = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
                seg -= left;
                if k % 2 == 0 {
                    dash.push(round(a));
                    backend.draw_path(std::mem::take(&mut dash), &style)?;
                } else {
                    dash = vec![round(a)];
                }
                k = (k + 1) % self.dash.len();
                left = self.dash[k];
            }
            left -= seg;
            if k % 2 == 0 {
                dash.push(w[1]);
            }
        }
        if k % 2 == 0 && dash.len() > 1 {
            backend.draw_path(dash, &style)?;
        }
        Ok(())
    }
}

/// A marker of one of the six shapes, `size` units from its centre to its edge.
pub struct Marker<Coord> {
    pub(super) at: Coord,
    pub(super) shape: Shape,
    pub(super) colour: RGBColor,
    pub(super) size: i32,
}

impl<Coord> Marker<Coord> {
    pub(super) fn new(at: Coord, shape: Shape, colour: RGBColor, size: i32) -> Self {
        Marker {
            at,
            shape,
            colour,
            size,
        }
    }
}

impl<'a, Coord> PointCollection<'a, Coord> for &'a Marker<Coord> {
    type Point = &'a Coord;
    type IntoIter = std::iter::Once<&'a Coord>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<Coord, DB: DrawingBackend> Drawable<DB> for Marker<Coord> {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        mut points: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let Some((x, y)) = points.next() else {
            return Ok(());
        };
        let (s, fill, line) = (self.size, self.colour.filled(), self.colour.stroke_width(2));
        match self.shape {
            Shape::Circle => backend.draw_circle((x, y), s as u32, &fill, true),
            Shape::Ring => backend.draw_circle((x, y), s as u32, &line, false),
            Shape::Square => backend.draw_rect((x - s, y - s), (x + s, y + s), &fill, true),
            Shape::Triangle => backend.fill_polygon(
                [(x, y - s - 1), (x + s + 1, y + s), (x - s - 1, y + s)],
                &fill,
            ),
            Shape::Diamond => backend.fill_polygon(
                [
                    (x, y - s - 1),
                    (x + s + 1, y),
                    (x, y + s + 1),
                    (x - s - 1, y),
                ],
                &fill,
            ),
            Shape::Cross => {
                backend.draw_line((x - s, y - s), (x + s, y + s), &line)?;
                backend.draw_line((x - s, y + s), (x + s, y - s), &line)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::look::{DASHES, PALETTE};
    use crate::plot::svg;

    #[test]
    fn dashes_run_on_across_points() {
        // A dashed line along x from 0 to 40 drawn through points 1 apart has the dashes of
        // the same line through its two ends: on 0-10, 15-25, 30-40.
        let mut lines = Vec::new();
        for points in [vec![(0, 0), (40, 0)], (0..=40).map(|x| (x, 0)).collect()] {
            let svg = String::from_utf8(
                svg(50, 10, |root, _| {
                    root.draw(&Styled::line(points, PALETTE[0], DASHES[1]))?;
                    Ok(())
                })
                .unwrap(),
            )
            .unwrap();
            let ends: Vec<String> = svg
                .split("points=\"")
                .skip(1)
                .map(|s| {
                    let p: Vec<&str> = s[..s.find('"').unwrap()].split_whitespace().collect();
                    format!("{}-{}", p[0], p[p.len() - 1])
                })
                .collect();
            lines.push(ends);
        }
        assert_eq!(lines[0], ["0,0-10,0", "15,0-25,0", "30,0-40,0"]);
        assert_eq!(lines[0], lines[1]);
    }
}
