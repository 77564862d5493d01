//! The checks of spectra: a number (a constant), the name of an entry of `[spectra]`, or
//! an inline table of one kind (`constant`, `file` with its `column`, `blackbody` with its
//! `peak`, `lamp`) with an optional `scale` or `luminance`; and the environment, made of
//! spectra. Chapter: *Reference scenes and interop* (`chapters/renderer/scenes.md`).

use std::collections::BTreeMap;
use std::ops::Range;

use glam::DVec3;
use toml::Spanned;

use super::Checker;
use crate::data::DataError;
use crate::render::raw::{RawEnvironment, RawSpectrum};
use crate::render::scene::Environment;
use crate::spectral::spectrum::{self, Spectrum, Table};
use crate::spectral::{cie, emission};

impl Checker<'_> {
    /// A spectrum: a number (constant), the name of an entry of `[spectra]`, or an inline
    /// table.
    pub(super) fn spectrum(
        &self,
        v: &Spanned<toml::Value>,
        named: &BTreeMap<String, Spectrum>,
        what: &str,
    ) -> Result<Spectrum, DataError> {
        let span = v.span();
        match v.get_ref() {
            toml::Value::Float(x) => self.constant(*x, span, what),
            toml::Value::Integer(x) => self.constant(*x as f64, span, what),
            toml::Value::String(name) => named.get(name).cloned().map_or_else(
                || {
                    let known: Vec<&str> = named.keys().map(String::as_str).collect();
                    self.err(
                        span,
                        format!(
                            "{what}: no spectrum called {name:?} in [spectra] (there are: {})",
                            if known.is_empty() {
                                "none".to_string()
                            } else {
                                known.join(", ")
                            }
                        ),
                    )
                },
                Ok,
            ),
            toml::Value::Table(_) => self.spectrum_table(v, what),
            other => self.err(
                span,
                format!(
                    "{what} must be a number, a spectrum's name or a table, not a {}",
                    other.type_str()
                ),
            ),
        }
    }

    fn constant(&self, x: f64, span: Range<usize>, what: &str) -> Result<Spectrum, DataError> {
        if x.is_finite() && x >= 0.0 {
            Ok(Spectrum::Constant(x))
        } else {
            self.err(
                span,
                format!("{what} is {x}; a spectrum's value must be finite and >= 0"),
            )
        }
    }

    /// An inline table: one kind, then `scale`, or `luminance` (the factor that gives the
    /// spectrum's CIE `Y`, [`cie::xyz`], that value).
    fn spectrum_table(&self, v: &Spanned<toml::Value>, what: &str) -> Result<Spectrum, DataError> {
        let span = v.span();
        let raw: RawSpectrum = v
            .get_ref()
            .clone()
            .try_into()
            .or_else(|e: toml::de::Error| {
                self.err(span.clone(), format!("{what}: {}", e.message()))
            })?;
        let Some(lum) = raw.luminance else {
            return self.spectrum_kind(&raw, span, what);
        };
        if raw.scale.is_some() {
            return self.err(
                span,
                format!("{what}: give `scale` or `luminance`, not both"),
            );
        }
        if !(lum.is_finite() && lum >= 0.0) {
            return self.err(
                span,
                format!("{what}: luminance {lum} must be finite and >= 0"),
            );
        }
        let s = self.spectrum_kind(&raw, span.clone(), what)?;
        let y = cie::xyz(|nm| s.eval(nm)).y;
        if y.is_nan() || y <= 0.0 {
            return self.err(
                span,
                format!(
                    "{what}: the spectrum is black in 360-830 nm; it has no luminance to scale"
                ),
            );
        }
        let k = lum / y;
        Ok(match s {
            Spectrum::Constant(c) => Spectrum::Constant(c * k),
            Spectrum::Table(t) => Spectrum::Table(t.scaled(k)),
            Spectrum::Blackbody { kelvin, peak } => Spectrum::Blackbody {
                kelvin,
                peak: peak * k,
            },
        })
    }

    fn spectrum_kind(
        &self,
        raw: &RawSpectrum,
        span: Range<usize>,
        what: &str,
    ) -> Result<Spectrum, DataError> {
        let kinds = [
            raw.constant.is_some(),
            raw.file.is_some(),
            raw.blackbody.is_some(),
            raw.lamp.is_some(),
        ];
        if kinds.iter().filter(|&&k| k).count() != 1 {
            return self.err(
                span,
                format!("{what}: give exactly one of `constant`, `file`, `blackbody`, `lamp`"),
            );
        }
        let scale = raw.scale.unwrap_or(1.0);
        if !(scale.is_finite() && scale >= 0.0) {
            return self.err(
                span,
                format!("{what}: scale {scale} must be finite and >= 0"),
            );
        }
        if raw.column.is_some() && raw.file.is_none() {
            return self.err(span, format!("{what}: `column` belongs with `file`"));
        }
        if raw.peak.is_some() && raw.blackbody.is_none() {
            return self.err(span, format!("{what}: `peak` belongs with `blackbody`"));
        }
        if let Some(c) = raw.constant {
            return self.constant(c * scale, span, what);
        }
        if let Some(kelvin) = raw.blackbody {
            let peak = raw.peak.unwrap_or(1.0) * scale;
            if !(kelvin.is_finite() && kelvin > 0.0) {
                return self.err(
                    span,
                    format!("{what}: blackbody temperature {kelvin} K must be > 0"),
                );
            }
            if !(peak.is_finite() && peak >= 0.0) {
                return self.err(span, format!("{what}: peak {peak} must be finite and >= 0"));
            }
            return Ok(Spectrum::Blackbody { kelvin, peak });
        }
        if let Some(name) = &raw.lamp {
            let lamps = emission::lamps();
            return match lamps.iter().find(|l| l.name == name || l.stem == name) {
                Some(l) => Ok(Spectrum::Table(l.spectrum.scaled(scale))),
                None => {
                    let names: Vec<&str> = lamps.iter().map(|l| l.name).collect();
                    self.err(
                        span,
                        format!("{what}: no lamp {name:?} (there are: {})", names.join(", ")),
                    )
                }
            };
        }
        let file = raw.file.as_deref().unwrap_or_default();
        let path = self.dir.join(file);
        if !path.is_file() {
            return self.err(
                span,
                format!("{what}: spectrum file {} does not exist", path.display()),
            );
        }
        let tables = spectrum::load_csv(&path)?;
        {
            let mut read = self.read.borrow_mut();
            if !read.contains(&path) {
                read.push(path.clone());
            }
        }
        let table: Table = match &raw.column {
            Some(c) => spectrum::column(&tables, c, &path.display().to_string())
                .or_else(|e| self.err(span.clone(), format!("{what}: {}", e.problem)))?,
            None => tables[0].1.clone(),
        };
        Ok(Spectrum::Table(table.scaled(scale)))
    }
}

impl Checker<'_> {
    /// `[environment]`: `emission` (the same spectrum from every direction), or `above`
    /// and `below` with an optional `axis` (default `[0, 1, 0]`): a gradient between them.
    pub(super) fn environment(
        &self,
        env: &Spanned<RawEnvironment>,
        named: &BTreeMap<String, Spectrum>,
    ) -> Result<Environment, DataError> {
        let e = env.get_ref();
        let gradient = [
            ("above", e.above.as_ref().map(Spanned::span)),
            ("below", e.below.as_ref().map(Spanned::span)),
            ("axis", e.axis.as_ref().map(Spanned::span)),
        ];
        if let Some(emission) = &e.emission {
            self.refuse_keys(
                &gradient,
                "[environment]",
                "constant environment (one with `emission`)",
            )?;
            return Ok(Environment::Constant(self.spectrum(
                emission,
                named,
                "environment emission",
            )?));
        }
        let above = self.required(&e.above, env.span(), "emission` or `above")?;
        let below = self.required(&e.below, env.span(), "below")?;
        let axis = match &e.axis {
            None => DVec3::Y,
            Some(a) => {
                let v = self.vec3(a, "environment axis")?;
                if v.length() == 0.0 {
                    return self.err(a.span(), "environment axis is the zero vector");
                }
                v.normalize()
            }
        };
        Ok(Environment::Gradient {
            axis,
            above: self.spectrum(above, named, "environment above")?,
            below: self.spectrum(below, named, "environment below")?,
        })
    }
}
