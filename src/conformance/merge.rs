//! Pooling independent renders of one scene into one, exactly: the reference that one
//! machine would take days to render is rendered as many jobs with different seeds, on
//! as many machines, and merged. Chapter: *Reference scenes and interop*
//! (`chapters/renderer/scenes.md`, *References beyond one machine*).
//!
//! A render's pixel is the mean `m` of its `n` samples with the variance of that mean
//! `v = s² / n`, so it carries the whole Welford summary `(n, m, M₂ = v n (n - 1))`. The
//! summaries of independent renders combine exactly (Chan, Golub and LeVeque:
//! [`crate::stats::welford::combine`]): with `δ = m_b - m_a` and `n = n_a + n_b`,
//!
//! ```text
//! m = m_a + δ n_b / n,   M₂ = M₂a + M₂b + δ² n_a n_b / n,
//! ```
//!
//! the mean and sum of squared deviations of all `n` samples together, the same numbers
//! (to rounding) that one render of `n` samples with those samples would have.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use glam::DVec3;

use crate::image::{Image, ImageError};
use crate::render::files::Sidecar;
use crate::stats::welford::combine;

/// One render to pool: its image (with its variances) and its sidecar.
#[derive(Clone, Debug)]
pub struct Part {
    /// The EXR file, for messages.
    pub path: PathBuf,
    /// The means and their variances.
    pub image: Image,
    /// What the render was (read from the `.json` beside the EXR).
    pub sidecar: Sidecar,
}

/// Reads the render `exr` and its sidecar, the `.json` of the same name beside it.
///
/// # Errors
/// The EXR ([`ImageError::File`]) or the sidecar ([`ImageError::Sidecar`]) cannot be
/// read, or they disagree on the samples per pixel ([`ImageError::Mismatch`]).
pub fn read_part(exr: &Path) -> Result<Part, ImageError> {
    let image = Image::read_exr(exr)?;
    let json = exr.with_extension("json");
    let sidecar = Sidecar::read(&json).map_err(ImageError::Sidecar)?;
    if image.spp.is_some_and(|n| n != sidecar.spp) {
        return Err(ImageError::Mismatch(format!(
            "{}: {} samples per pixel in the image, {} in {}",
            exr.display(),
            image.spp.unwrap_or(0),
            sidecar.spp,
            json.display()
        )));
    }
    Ok(Part {
        path: exr.to_path_buf(),
        image,
        sidecar,
    })
}

/// The pixels of renders of `n_i` samples each pooled exactly (the module's formulas):
/// `parts` are `(image, n_i)` of one size, each `n_i >= 2`.
pub fn pool(parts: &[(&Image, u32)]) -> Image {
    let Some(&(first, _)) = parts.first() else {
        return Image {
            width: 0,
            height: 0,
            mean: Vec::new(),
            var: Vec::new(),
            spp: Some(0),
        };
    };
    fn summaries<'a>(
        &(image, n): &(&'a Image, u32),
    ) -> impl Iterator<Item = (u64, DVec3, DVec3)> + 'a {
        let f = f64::from(n);
        image
            .mean
            .iter()
            .zip(&image.var)
            .map(move |(&m, &v)| (u64::from(n), m, v * (f * (f - 1.0))))
    }
    let mut pooled: Vec<(u64, DVec3, DVec3)> = summaries(&(first, parts[0].1)).collect();
    for part in &parts[1..] {
        for (p, s) in pooled.iter_mut().zip(summaries(part)) {
            *p = combine(*p, s);
        }
    }
    let total = pooled.first().map_or(0, |p| p.0);
    let f = total as f64;
    Image {
        width: first.width,
        height: first.height,
        mean: pooled.iter().map(|p| p.1).collect(),
        var: pooled.iter().map(|p| p.2 / (f * (f - 1.0))).collect(),
        spp: u32::try_from(total).ok(),
    }
}

/// Pools `parts` into one render and its sidecar: the scene, its hash, the wavelengths
/// and the build of the first, the sum of samples per pixel and of seconds, every seed.
///
/// # Errors
/// Fewer than two parts; parts of different scenes (their hash: the file with its
/// settings), wavelength strategies, sizes or builds (the `raylemma` executable's hash,
/// when both recorded it); two parts with a seed in common (their samples would be the
/// same samples, counted twice); a part of fewer than 2 samples per pixel (no variance);
/// more than `u32::MAX` samples per pixel in all. Each message names the files
/// ([`ImageError::Mismatch`]).
pub fn merge(parts: &[Part]) -> Result<(Image, Sidecar), ImageError> {
    let [first, rest @ ..] = parts else {
        return Err(ImageError::Mismatch("nothing to merge".into()));
    };
    if rest.is_empty() {
        return Err(ImageError::Mismatch(format!(
            "{}: one render; merge pools two or more renders of one scene made with different seeds",
            first.path.display()
        )));
    }
    let (a, name) = (&first.sidecar, first.path.display());
    let mut seen: HashMap<u64, &Path> = HashMap::new();
    for part in parts {
        let (b, other) = (&part.sidecar, part.path.display());
        let differ = |what: &str, x: &dyn std::fmt::Display, y: &dyn std::fmt::Display| {
            ImageError::Mismatch(format!(
                "{name} and {other} are renders of different {what} ({x} and {y}): only renders of one scene with one renderer pool"
            ))
        };
        if b.scene_hash != a.scene_hash {
            return Err(differ(
                "scenes or settings (the scene file's hash)",
                &format!("{} {:016x}", a.scene, a.scene_hash),
                &format!("{} {:016x}", b.scene, b.scene_hash),
            ));
        }
        if b.wavelengths != a.wavelengths {
            return Err(differ(
                "wavelength strategies",
                &a.wavelengths,
                &b.wavelengths,
            ));
        }
        let size = |p: &Part| format!("{}x{}", p.image.width, p.image.height);
        if size(part) != size(first) {
            return Err(differ("sizes", &size(first), &size(part)));
        }
        if let (Some(x), Some(y)) = (&a.build, &b.build)
            && x != y
        {
            return Err(differ("builds of raylemma (the executable's hash)", x, y));
        }
        if b.spp < 2 {
            return Err(ImageError::Mismatch(format!(
                "{other}: {} sample per pixel has no variance; render each part with at least 2",
                b.spp
            )));
        }
        for seed in b.all_seeds() {
            if let Some(earlier) = seen.insert(seed, &part.path) {
                return Err(ImageError::Mismatch(format!(
                    "{} and {other} were both rendered with seed {seed}: their samples are the same \
                     samples, and would be counted twice; render each part with its own --seed",
                    earlier.display()
                )));
            }
        }
    }
    let total: u64 = parts.iter().map(|p| u64::from(p.sidecar.spp)).sum();
    let spp = u32::try_from(total).map_err(|_| {
        ImageError::Mismatch(format!(
            "{total} samples per pixel in all: more than a render can record"
        ))
    })?;
    let counts: Vec<(&Image, u32)> = parts.iter().map(|p| (&p.image, p.sidecar.spp)).collect();
    let image = pool(&counts);
    let mut seeds: Vec<u64> = parts.iter().flat_map(|p| p.sidecar.all_seeds()).collect();
    seeds.sort_unstable();
    let sidecar = Sidecar {
        scene: a.scene.clone(),
        scene_hash: a.scene_hash,
        spp,
        seed: seeds[0],
        wavelengths: a.wavelengths.clone(),
        seconds: parts.iter().map(|p| p.sidecar.seconds).sum(),
        threads: parts.iter().map(|p| p.sidecar.threads).max().unwrap_or(1),
        made_from: None,
        build: a.build.clone(),
        seeds,
    };
    Ok((image, sidecar))
}
