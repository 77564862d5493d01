//! A candidate renderer's EXR files read and compared with a reference, as `raylemma
//! compare` and the conformance card do: the reference carries its variance channels (a
//! raylemma render); the candidate is one image with variance channels, or several
//! independent plain images of the scene (different seeds), whose spread gives its
//! variance; half floats add their rounding, X, Y, Z channels are converted to linear
//! sRGB, identical candidates are refused. Chapter: *Comparing images*
//! (`chapters/renderer/compare.md`).

use std::path::{Path, PathBuf};

use super::compare::{self, Estimate};
use super::diagnose;
use crate::image::{ExrContents, Image, ImageError};
use crate::spectral::cie::xyz_to_linear_srgb_matrix;

/// The reference: it must carry its variance.
pub fn reference(path: &Path) -> Result<Estimate, ImageError> {
    let contents = ExrContents::read(path)?.converted(xyz_to_linear_srgb_matrix());
    let channels = contents.channels.join(", ");
    let (half, from_xyz) = (contents.half, contents.from_xyz);
    match contents.into_image() {
        Some(image) => Ok(rounded(Estimate::from_variance(image), half, from_xyz)),
        None => Err(ImageError::Mismatch(format!(
            "{}: the reference has no variance channels var.R, var.G, var.B (it has {channels}); \
             the reference must be a render with its variance, such as `raylemma render` writes \
             or figures/reference/NAME.exr",
            path.display()
        ))),
    }
}

// ANCHOR: candidate
/// The candidate: one image with its variance channels, or the spread of two or more;
/// its variances floored by the reference's ([`Estimate::floor_from_reference`]) when its
/// samples per pixel are known (each image's `spp` attribute, else `spp`).
pub fn candidate(
    paths: &[PathBuf],
    reference: &Estimate,
    spp: Option<u32>,
) -> Result<(Estimate, String, bool), ImageError> {
    let size = (reference.image.width, reference.image.height);
    let (mut estimate, name, from_xyz, samples) = read_candidate(paths, size, spp)?;
    let floored = samples.is_some_and(|n| estimate.floor_from_reference(reference, n));
    if !floored {
        estimate.source +=
            "; not floored by the reference's variance (its samples per pixel unknown: pass --spp)";
    }
    Ok((estimate, name, from_xyz))
}

/// The candidate as read, and its samples per pixel in all when every image's is known.
fn read_candidate(
    paths: &[PathBuf],
    size: (u32, u32),
    spp: Option<u32>,
) -> Result<(Estimate, String, bool, Option<u64>), ImageError> {
    let mut files = Vec::new();
    for path in paths {
        let c = ExrContents::read(path)?.converted(xyz_to_linear_srgb_matrix());
        if (c.width, c.height) != size {
            return Err(ImageError::Mismatch(format!(
                "{}: {}x{}, but the reference is {}x{}",
                path.display(),
                c.width,
                c.height,
                size.0,
                size.1
            )));
        }
        files.push(c);
    }
    if let [one] = &files[..] {
        let path = paths[0].display();
        let name = path.to_string();
        return match one.clone().into_image() {
            Some(image) => Ok((
                xyz_noted(
                    rounded(Estimate::from_variance(image), one.half, one.from_xyz),
                    one.from_xyz,
                ),
                name,
                one.from_xyz,
                one.spp.map(u64::from),
            )),
            None => Err(ImageError::Mismatch(format!(
                "{path} is a plain image without variance channels, and it is the only candidate: \
                 one image cannot say how noisy it is. Render the scene several times with \
                 different seeds (for example 16 renders of a sixteenth of the samples each) and \
                 pass them all: raylemma compare REF.exr render-1.exr render-2.exr ...; or write \
                 the variance of each pixel's mean as channels var.R, var.G, var.B"
            ))),
        };
    }
    let means: Vec<&[glam::DVec3]> = files.iter().map(|c| &c.mean[..]).collect();
    refuse_identical(paths, &means)?;
    let mut estimate = Estimate::from_spread(size.0, size.1, &means)?;
    if files.iter().any(|c| c.var.is_some()) {
        estimate.source += "; their own variance channels are not used";
    }
    let from_xyz = files.iter().any(|c| c.from_xyz);
    let half = files.iter().any(|c| c.half);
    let estimate = xyz_noted(rounded(estimate, half, from_xyz), from_xyz);
    let name = format!(
        "{} candidates ({} ... {})",
        paths.len(),
        paths[0].display(),
        paths[paths.len() - 1].display()
    );
    let samples = files
        .iter()
        .map(|c| c.spp.or(spp).map(u64::from))
        .sum::<Option<u64>>();
    Ok((estimate, name, from_xyz, samples))
}
// ANCHOR_END: candidate

/// `estimate` with the rounding of half-float means added to its variances
/// ([`compare::add_half_rounding`]) if `half`, in the file's X, Y, Z if `from_xyz`.
fn rounded(mut estimate: Estimate, half: bool, from_xyz: bool) -> Estimate {
    if half {
        let to_rgb = from_xyz.then(xyz_to_linear_srgb_matrix);
        compare::add_half_rounding(&mut estimate, to_rgb);
    }
    estimate
}

/// `estimate` with a note, if `from_xyz`, that its means were converted from CIE XYZ.
fn xyz_noted(mut estimate: Estimate, from_xyz: bool) -> Estimate {
    if from_xyz {
        estimate.source += "; its channels X, Y, Z (CIE XYZ) converted to linear sRGB";
    }
    estimate
}

/// Candidates rendered with the same seed (a renderer's default, often) are the same
/// image: their spread is zero, and every pixel that differs from the reference at all
/// would fail. Two identical candidates are refused, naming them.
fn refuse_identical(paths: &[PathBuf], means: &[&[glam::DVec3]]) -> Result<(), ImageError> {
    // Black images are the same whatever the seed: they have no noise to hide, and a
    // black candidate is compared (and differs from any reference that is not black).
    if means
        .iter()
        .all(|m| m.iter().all(|&p| p == glam::DVec3::ZERO))
    {
        return Ok(());
    }
    let same: Vec<usize> = (1..means.len()).filter(|&j| means[j] == means[0]).collect();
    if same.len() + 1 == means.len() {
        return Err(ImageError::Mismatch(format!(
            "these {} images are identical ({} ... {}): their spread says nothing of their noise. \
             Render each with a different seed (Mitsuba: `mi.render(scene, seed=k)` or \
             `<integer name=\"seed\" value=\"k\"/>` in the sampler; raylemma: --seed k)",
            means.len(),
            paths[0].display(),
            paths[paths.len() - 1].display()
        )));
    }
    for i in 0..means.len() {
        if let Some(j) = (i + 1..means.len()).find(|&j| means[i] == means[j]) {
            return Err(ImageError::Mismatch(format!(
                "{} and {} are the same image: render each candidate with a different seed",
                paths[i].display(),
                paths[j].display()
            )));
        }
    }
    Ok(())
}

/// `Ok(true)`: agree, `Ok(false)`: differ; an error is returned for bad input (exit
/// status 2).
///
/// # Errors
/// `alpha` not in (0, 1), or as [`reference()`], [`candidate()`], [`compare::compare`] and
/// the writing of the difference image.
pub fn compare_files(
    reference_path: &Path,
    candidates: &[PathBuf],
    alpha: f64,
    spp: Option<u32>,
    diff: Option<&Path>,
) -> Result<bool, ImageError> {
    if !(alpha > 0.0 && alpha < 1.0) {
        return Err(ImageError::Parameter(format!(
            "--alpha {} must be in (0, 1)",
            alpha
        )));
    }
    let reference = reference(reference_path)?;
    let (candidate, name, from_xyz) = candidate(candidates, &reference, spp)?;
    let c = compare::compare(&reference, &candidate, alpha)?;
    let names = [reference_path.display().to_string(), name];
    print!("{}", c.report([&names[0], &names[1]]));
    if !c.agree()
        && let Some(hint) = diagnose::xyz_swapped(&reference.image, &candidate.image, from_xyz)
    {
        println!("hint: {hint}");
    }
    if let Some(path) = diff {
        let Image { width, height, .. } = reference.image;
        crate::image::png::write_png(path, width, height, &compare::difference_rgb8(&c))?;
        println!("difference image: {}", path.display());
    }
    Ok(c.agree())
}
