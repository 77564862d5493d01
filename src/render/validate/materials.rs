//! The checks of `[materials]`: each type's keys and values (a reflectance in `[0, 1]`, an
//! index of refraction `> 0` or a known Sellmeier fit, a film's thickness and the heights
//! over which it varies). Chapter: *Reference scenes and
//! interop* (`chapters/renderer/scenes.md`).

use std::collections::BTreeMap;

use toml::Spanned;

use super::Checker;
use crate::data::DataError;
use crate::optics::dispersion;
use crate::render::raw::RawMaterial;
use crate::render::scene::{Ior, Material, Thickness};
use crate::spectral::spectrum::Spectrum;

impl Checker<'_> {
    pub(super) fn material(
        &self,
        name: &str,
        m: &Spanned<RawMaterial>,
        spectra: &BTreeMap<String, Spectrum>,
    ) -> Result<Material, DataError> {
        let span = m.span();
        let m = m.get_ref();
        let what = format!("material {name:?}");
        let allowed: &[&str] = match m.kind.get_ref().as_str() {
            "lambert" => &["reflectance"],
            "mirror" => &[],
            "dielectric" => &["ior", "sellmeier"],
            "thin-film" => &["ior", "thickness_nm", "y_range"],
            other => {
                return self.err(
                    m.kind.span(),
                    format!("{what}: unknown material type {other:?} (there are: lambert, mirror, dielectric, thin-film)"),
                );
            }
        };
        let given = [
            ("reflectance", m.reflectance.as_ref().map(Spanned::span)),
            ("ior", m.ior.as_ref().map(Spanned::span)),
            ("sellmeier", m.sellmeier.as_ref().map(Spanned::span)),
            ("thickness_nm", m.thickness_nm.as_ref().map(Spanned::span)),
            ("y_range", m.y_range.as_ref().map(Spanned::span)),
        ];
        self.refuse_keys(
            given.iter().filter(|(key, _)| !allowed.contains(key)),
            &what,
            &format!("{} material", m.kind.get_ref()),
        )?;
        let ior = |x: &Spanned<f64>| -> Result<f64, DataError> {
            let n = self.finite(x, &format!("{what}: ior"))?;
            if n > 0.0 {
                Ok(n)
            } else {
                self.err(x.span(), format!("{what}: ior is {n}; it must be > 0"))
            }
        };
        match m.kind.get_ref().as_str() {
            "lambert" => {
                let r = self.required(&m.reflectance, span, "reflectance")?;
                let reflectance = self.spectrum(r, spectra, &format!("{what}: reflectance"))?;
                if let Some(bad) = reflectance_above_one(&reflectance) {
                    return self.err(
                        r.span(),
                        format!("{what}: reflectance is {bad} somewhere; a Lambertian surface needs values in [0, 1]"),
                    );
                }
                Ok(Material::Lambert { reflectance })
            }
            "mirror" => Ok(Material::Mirror),
            "dielectric" => match (&m.ior, &m.sellmeier) {
                (Some(n), None) => Ok(Material::Dielectric {
                    ior: Ior::Constant(ior(n)?),
                }),
                (None, Some(s)) => match dispersion::catalogue().get(s.get_ref()) {
                    Some(fit) => Ok(Material::Dielectric {
                        ior: Ior::Sellmeier(fit),
                    }),
                    None => {
                        let names: Vec<&str> = dispersion::catalogue()
                            .materials
                            .iter()
                            .map(|m| m.name.as_str())
                            .collect();
                        self.err(
                            s.span(),
                            format!(
                                "{what}: no Sellmeier fit {:?} (there are: {})",
                                s.get_ref(),
                                names.join(", ")
                            ),
                        )
                    }
                },
                _ => self.err(
                    span,
                    format!("{what}: a dielectric needs exactly one of `ior` and `sellmeier`"),
                ),
            },
            _ => {
                let n = ior(self.required(&m.ior, span.clone(), "ior")?)?;
                let t = self.required(&m.thickness_nm, span, "thickness_nm")?;
                let thickness = self.thickness(t, m.y_range.as_ref(), &what)?;
                Ok(Material::ThinFilm { ior: n, thickness })
            }
        }
    }

    fn thickness(
        &self,
        t: &Spanned<toml::Value>,
        y_range: Option<&Spanned<[f64; 2]>>,
        what: &str,
    ) -> Result<Thickness, DataError> {
        let num = |v: &toml::Value| match v {
            toml::Value::Float(x) => Some(*x),
            toml::Value::Integer(x) => Some(*x as f64),
            _ => None,
        };
        let (bottom, top) = match t.get_ref() {
            toml::Value::Array(a) if a.len() == 2 => match (num(&a[0]), num(&a[1])) {
                (Some(b), Some(t)) => (b, t),
                _ => return self.err(t.span(), format!("{what}: thickness_nm must hold numbers")),
            },
            v => match num(v) {
                Some(x) => (x, x),
                None => {
                    return self.err(
                        t.span(),
                        format!("{what}: thickness_nm must be a number or [bottom, top]"),
                    );
                }
            },
        };
        for d in [bottom, top] {
            if !(d.is_finite() && d >= 0.0) {
                return self.err(
                    t.span(),
                    format!("{what}: thickness {d} nm must be finite and >= 0"),
                );
            }
        }
        let y = match y_range {
            Some(r) => {
                let [a, b] = *r.get_ref();
                if !(a.is_finite() && b.is_finite() && a < b) {
                    return self.err(
                        r.span(),
                        format!("{what}: y_range [{a}, {b}] must be finite and increasing"),
                    );
                }
                [a, b]
            }
            None if bottom == top => [0.0, 0.0],
            None => {
                return self.err(
                    t.span(),
                    format!("{what}: a varying thickness needs `y_range`"),
                );
            }
        };
        Ok(Thickness {
            bottom_nm: bottom,
            top_nm: top,
            y,
        })
    }
}

/// The largest value of a spectrum above 1, if any (a table's knots, a constant, a
/// blackbody's peak).
fn reflectance_above_one(s: &Spectrum) -> Option<f64> {
    let max = match s {
        Spectrum::Constant(c) => *c,
        Spectrum::Table(t) => t.values().iter().copied().fold(0.0, f64::max),
        Spectrum::Blackbody { peak, .. } => *peak,
    };
    (max > 1.0).then_some(max)
}
