//! Diagrams that explain: the geometry behind the book's derivations, drawn as line
//! drawings (issue 23), one idea per diagram, labelled in the notation of its chapter.
//!
//! They are SVG written element by element with the few primitives of the modules below (lines,
//! arrows, polylines, arcs, circles, translucent polygons, dashed lines, text with italic,
//! bold, subscripts and superscripts): plotters draws charts, not geometry. The style is the
//! charts' (`plot.rs`): the same font family, the Okabe-Ito colours, lines of 1 to 2 units,
//! dark text on a white card, which `assets/book/figures.css` sets off on the dark themes.
//! Each diagram is [`WIDTH`](style::WIDTH) units wide with a `viewBox`, so that it scales; its text is
//! 13.5 units at least (subscripts aside), and it carries its alt text as `<title>` and a
//! longer description as `<desc>`.
//!
//! Where a diagram shows a computed fact, it computes it with the library's own functions:
//! refracted and reflected directions (`optics::reflect`), the thin-film phasors
//! (`optics::thinfilm`), the colour-matching functions and the wavelength samplers
//! (`spectral`), the camera's pixel convention (`render::camera`), and it fails rather than
//! draw something the library disagrees with.
//!
//! The primitives: [`style`] (text sizes, colours, pens and fonts), [`markup`] (the labels'
//! italic, bold and scripts), [`svg`] (the elements and the finished file) and [`geometry`]
//! (vectors and angles on the page). Then one module per diagram, named for its output
//! (`diagram_<name>.svg`), each citing its chapter.

mod geometry;
mod markup;
mod style;
mod svg;

mod camera;
mod fresnel_sp;
mod hero_lanes;
mod malley;
mod path;
mod solid_angle;
mod thinfilm;

use anyhow::anyhow;

use super::Output;

/// The outputs: one diagram each, in book order.
pub fn outputs() -> Vec<Output> {
    vec![
        Output {
            file: "diagram_malley.svg",
            what: "diagram: Malley's method, a disc lifted onto the hemisphere",
            make: malley::malley,
        },
        Output {
            file: "diagram_fresnel_sp.svg",
            what: "diagram: s and p polarisation, and a beam's footprint",
            make: fresnel_sp::fresnel_sp,
        },
        Output {
            file: "diagram_thinfilm.svg",
            what: "diagram: the two rays of a thin film and the Airy sum as phasors",
            make: thinfilm::thinfilm_diagram,
        },
        Output {
            file: "diagram_solid_angle.svg",
            what: "diagram: a light's patch, its foreshortening and its solid angle",
            make: solid_angle::solid_angle,
        },
        Output {
            file: "diagram_hero_lanes.svg",
            what: "diagram: where each wavelength strategy puts its lanes",
            make: hero_lanes::hero_lanes,
        },
        Output {
            file: "diagram_camera.svg",
            what: "diagram: the camera's convention",
            make: camera::camera,
        },
        Output {
            file: "diagram_path.svg",
            what: "diagram: one path of the path tracer, its shadow rays and its last vertex",
            make: path::path,
        },
    ]
}

/// An error unless `ok`: a diagram that would disagree with the library is not drawn.
fn ensure(ok: bool, what: &str) -> anyhow::Result<()> {
    if ok {
        Ok(())
    } else {
        Err(anyhow!("diagram disagrees with the library: {what}"))
    }
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::style::SMALL;
    use super::*;
    use crate::{Record, Settings};

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
}
