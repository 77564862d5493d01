//! The checks of `[render]` and `[camera]`, and of the emission wavelength strategy, which
//! needs the lights. Chapter: *Reference scenes and interop* (`chapters/renderer/scenes.md`).

use std::ops::Range;

use toml::Spanned;

use super::Checker;
use crate::data::DataError;
use crate::render::raw::{RawCamera, RawRender};
use crate::render::scene::{
    CameraSpec, DIRECT_STRATEGIES, DirectLight, Emitter, LIGHT_SAMPLINGS, LightSampling,
    RenderSettings, WAVELENGTH_STRATEGIES, Wavelength,
};
use crate::spectral::emission::{EmissionSampler, colour_proposal};
use crate::spectral::spectrum::Spectrum;
use crate::spectral::wavelength::WavelengthStrategy;
use crate::transport::shadow::Heuristic;

/// The largest accepted image side, in pixels.
const MAX_RESOLUTION: i64 = 16_384;

impl Checker<'_> {
    /// `[render]`: samples per pixel, seed, wavelength strategy (`"emission"` is resolved
    /// once the lights are known, [`Checker::emission_sampling`]), path-length controls.
    pub(super) fn render(&self, r: &Spanned<RawRender>) -> Result<RenderSettings, DataError> {
        let r = r.get_ref();
        let spp = self.non_negative_int(&r.spp, "spp (samples per pixel)", 1)?;
        let spp = u32::try_from(spp).or_else(|_| self.err(r.spp.span(), "spp is too large"))?;
        let seed = match &r.seed {
            Some(s) => self.non_negative_int(s, "seed", 0)?,
            None => 0,
        };
        let wavelengths = match &r.wavelengths {
            None => Wavelength::Strategy(WavelengthStrategy::HeroVisible),
            // Resolved once the lights are known.
            Some(w) if w.get_ref() == "emission" => {
                Wavelength::Strategy(WavelengthStrategy::HeroVisible)
            }
            Some(w) => Wavelength::Strategy(self.named(
                w,
                &WAVELENGTH_STRATEGIES,
                "wavelength strategy",
                ", emission",
            )?),
        };
        let depth =
            |x: &Option<Spanned<i64>>, what: &str, default: u32| -> Result<u32, DataError> {
                match x {
                    None => Ok(default),
                    Some(v) => {
                        let d = self.non_negative_int(v, what, 0)?;
                        u32::try_from(d)
                            .or_else(|_| self.err(v.span(), format!("{what} is too large")))
                    }
                }
            };
        let direct = match &r.direct {
            None => DirectLight::Mis(Heuristic::Power),
            Some(d) => self.named(d, &DIRECT_STRATEGIES, "direct-lighting strategy", "")?,
        };
        let light_sampling = match &r.light_sampling {
            None => LightSampling::Area,
            Some(d) => self.named(d, &LIGHT_SAMPLINGS, "light sampling", "")?,
        };
        Ok(RenderSettings {
            spp,
            light_sampling,
            seed,
            wavelengths,
            direct,
            roulette_depth: depth(&r.roulette_depth, "roulette_depth", 3)?,
            max_depth: depth(&r.max_depth, "max_depth", 1000)?,
        })
    }

    /// The value the table `names` gives the name `v`, or the scene error that names the
    /// key's `what` and lists the names (with `more`, names the caller accepts itself).
    fn named<T: Copy>(
        &self,
        v: &Spanned<String>,
        names: &[(&str, T)],
        what: &str,
        more: &str,
    ) -> Result<T, DataError> {
        match names.iter().find(|(n, _)| n == v.get_ref()) {
            Some((_, t)) => Ok(*t),
            None => {
                let list: Vec<&str> = names.iter().map(|(n, _)| *n).collect();
                self.err(
                    v.span(),
                    format!(
                        "unknown {what} {:?} (there are: {}{more})",
                        v.get_ref(),
                        list.join(", ")
                    ),
                )
            }
        }
    }

    /// `[camera]`: finite vectors, a view direction not along `up`, a field of view in
    /// `(0, 180)` degrees, a resolution in `1..=MAX_RESOLUTION`.
    pub(super) fn camera(&self, c: &Spanned<RawCamera>) -> Result<CameraSpec, DataError> {
        let c = c.get_ref();
        let position = self.vec3(&c.position, "camera position")?;
        let look_at = self.vec3(&c.look_at, "camera look_at")?;
        let up = self.vec3(&c.up, "camera up")?;
        let fov = self.finite(&c.fov_y, "fov_y")?;
        if !(fov > 0.0 && fov < 180.0) {
            return self.err(
                c.fov_y.span(),
                format!("fov_y is {fov} degrees; it must be in (0, 180)"),
            );
        }
        let forward = look_at - position;
        if forward.length() == 0.0 {
            return self.err(
                c.look_at.span(),
                "camera look_at is the camera position: no view direction",
            );
        }
        if forward.normalize().cross(up).length() < 1e-9 * up.length() || up.length() == 0.0 {
            return self.err(
                c.up.span(),
                "camera up is zero or parallel to the view direction",
            );
        }
        let [w, h] = *c.resolution.get_ref();
        if !(1..=MAX_RESOLUTION).contains(&w) || !(1..=MAX_RESOLUTION).contains(&h) {
            return self.err(
                c.resolution.span(),
                format!("resolution {w} x {h}: each side must be in 1..={MAX_RESOLUTION}"),
            );
        }
        Ok(CameraSpec {
            position,
            look_at,
            up,
            fov_y_deg: fov,
            width: w as u32,
            height: h as u32,
        })
    }

    /// The emission strategy: needs one light with a tabulated spectrum and no environment.
    pub(super) fn emission_sampling(
        &self,
        span: Range<usize>,
        lights: &[Emitter],
        environment: bool,
    ) -> Result<Wavelength, DataError> {
        let why = match (lights, environment) {
            (_, true) => "an environment also emits",
            ([one], false) => match &one.emission {
                Spectrum::Table(t) => {
                    return EmissionSampler::new(&colour_proposal(t))
                        .map(Wavelength::Emission)
                        .or_else(|e| self.err(span, format!("wavelengths = \"emission\": {e}")));
                }
                _ => "its light's spectrum is not a table (a file or a lamp)",
            },
            _ => "it needs exactly one light",
        };
        self.err(
            span,
            format!("wavelengths = \"emission\" cannot be used here: {why}"),
        )
    }
}
