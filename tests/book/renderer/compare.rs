//! Tests of `compare` with few candidates (chapter *Comparing images*): the statistics of variances estimated from few images, the reading of
//! plain EXRs as other renderers write them, and the refusal of images no comparison can
//! use.
//!
//! Statistical tests (4 of the suite's budget of 200), on synthetic images with normal
//! noise of known size (no rendering: the tests cost milliseconds): the pixel z's of 2, 4
//! and 16 candidates are standard normal and the verdict is *agree*; 4 candidates
//! with normal critical values (the planted twin) raise false alarms; a 3 % brighter
//! candidate is refused; on light that few samples reach, 4 candidates whose spread is
//! often 0 agree once floored by the reference's variance, and do not without the floor
//! (the planted twin), and the same light 25 % brighter is refused. Each at
//! `raylemma::stats::test_alpha()`, shared by Šidák.

use std::path::PathBuf;

use exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image as ExrImage, Layer, LayerAttributes,
    SmallVec, WritableImage, f16,
};
use glam::DVec3;
use raylemma::conformance::compare::{
    Estimate, block_chance, compare, equivalent_z, region_dof, test_level, upper_limit,
};
use raylemma::image::{ExrContents, Image};
use raylemma::rng::standard_normal;
use raylemma::rng::{self, Rng};
use raylemma::stats::two_sided_critical;
use raylemma::stats::{sidak, test_alpha};

/// Side of the synthetic images.
const SIDE: u32 = 128;

/// A synthetic scene: the exact value of every pixel and the standard deviation of one
/// image's pixel mean there (both varying over the image, as in a render).
struct Truth {
    mean: Vec<DVec3>,
    sd: Vec<DVec3>,
}

fn truth(rng: &mut Rng) -> Truth {
    let n = (SIDE * SIDE) as usize;
    let mut v = || {
        DVec3::new(
            rng::uniform(rng, 0.05, 1.0),
            rng::uniform(rng, 0.05, 1.0),
            0.3,
        )
    };
    let mean: Vec<DVec3> = (0..n).map(|_| v()).collect();
    let sd = mean.iter().map(|m| 0.05 * *m * (1.0 + m.x)).collect();
    Truth { mean, sd }
}

/// Three independent standard normal deviates, as one colour's noise.
fn normal3(rng: &mut Rng) -> DVec3 {
    DVec3::new(
        standard_normal(rng),
        standard_normal(rng),
        standard_normal(rng),
    )
}

/// One image of the scene scaled by `gain`: every pixel its exact value plus normal noise.
fn draw(t: &Truth, gain: f64, rng: &mut Rng) -> Vec<DVec3> {
    t.mean
        .iter()
        .zip(&t.sd)
        .map(|(m, s)| gain * *m + *s * normal3(rng))
        .collect()
}

/// A reference whose variance is known exactly (a 64th of one candidate image's), as a
/// render with very many samples per pixel.
fn reference(t: &Truth, rng: &mut Rng) -> Estimate {
    let quarter: Vec<DVec3> = t.sd.iter().map(|s| *s * *s / 64.0).collect();
    let mean = t
        .mean
        .iter()
        .zip(&quarter)
        .map(|(m, v)| *m + v.map(f64::sqrt) * normal3(rng))
        .collect();
    Estimate::from_variance(Image {
        width: SIDE,
        height: SIDE,
        mean,
        var: quarter,
        spp: None,
    })
}

fn candidates(t: &Truth, k: usize, gain: f64, rng: &mut Rng) -> Estimate {
    let images: Vec<Vec<DVec3>> = (0..k).map(|_| draw(t, gain, rng)).collect();
    let means: Vec<&[DVec3]> = images.iter().map(|m| &m[..]).collect();
    Estimate::from_spread(SIDE, SIDE, &means).unwrap()
}

/// The share of the `n` pixel-channel z's beyond 1.96, as a z-score against the 5 % of a
/// standard normal (binomial, normal approximation: `n p` is in the hundreds).
fn share_z(share: f64, n: usize) -> f64 {
    let n = n as f64;
    (share - 0.05) * n / (n * 0.05 * 0.95).sqrt()
}

#[test]
fn few_candidates_keep_the_false_alarm_rate_and_normal_critical_values_do_not() {
    let mut rng = rng::seeded(0x5eed_c0de);
    let t = truth(&mut rng);
    let r = reference(&t, &mut rng);
    // Nine claims: for each K, the pixels' share beyond 1.96, the blocks' z's and the verdict.
    let level = sidak(test_alpha(), 9);
    let critical = two_sided_critical(level);
    for k in [2, 4, 16] {
        let c = candidates(&t, k, 1.0, &mut rng);
        assert_eq!(c.dof, (k - 1) as f64);
        let cmp = compare(&r, &c, level).unwrap();
        // Pixels: conservative, so at most 5 % beyond 1.96 (one-sided).
        let z = share_z(cmp.share_beyond_95, cmp.pixel_tests);
        assert!(
            z <= critical,
            "K = {k}: |z| > 1.96 in {:.3} % of pixel-channels (z = {z:.2})",
            100.0 * cmp.share_beyond_95
        );
        // Blocks: their z's would be standard normal with the plug-in degrees of freedom,
        // and the guard only shrinks them (it is what makes a block with few candidates
        // safe, at the cost of power): their sum of squares is at most chi-squared with
        // one degree of freedom per block and channel (one-sided; with 2 and 4 candidates
        // the guard leaves them far below it, and only 16 can come near).
        let n = 3.0 * cmp.regions.len() as f64;
        let sum: f64 = cmp
            .regions
            .iter()
            .map(|b| b.zs.length_squared())
            .sum::<f64>();
        let chi = (sum - n) / (2.0 * n).sqrt();
        assert!(
            chi <= critical,
            "K = {k}: blocks' sum of z^2 {sum:.1} over {n} blocks (z = {chi:.2})"
        );
        assert!(cmp.agree(), "K = {k}:\n{}", cmp.report(["ref", "cand"]));
        // The planted twin: the same candidates with normal critical values.
        if k == 4 {
            let mut normal = c.clone();
            normal.dof = f64::INFINITY;
            let wrong = compare(&r, &normal, level).unwrap();
            assert!(
                wrong.share_beyond_95 > 0.08 && wrong.pixel_failure_count > 10 && !wrong.agree(),
                "normal critical values with 4 candidates raised no false alarm: {} pixels, {:.3} % beyond 1.96",
                wrong.pixel_failure_count,
                100.0 * wrong.share_beyond_95
            );
        }
    }
}

/// Exercise 1 of *Comparing images*: your critical `|z|` of one test, for two 256 x 256
/// images compared at `--alpha 0.01`.
const YOUR_CRITICAL_Z: Option<f64> = None;

#[test]
#[ignore = "exercise 1 of Comparing images: set YOUR_CRITICAL_Z, then run it"]
fn exercise_1_the_critical_z_of_a_256_by_256_comparison() {
    // Two images that agree exactly, with unit variances: the comparison's own critical value.
    const SIDE: u32 = 256;
    let image = Image {
        width: SIDE,
        height: SIDE,
        mean: vec![DVec3::ONE; (SIDE * SIDE) as usize],
        var: vec![DVec3::ONE; (SIDE * SIDE) as usize],
        spp: None,
    };
    let e = Estimate::from_variance(image);
    let c = compare(&e, &e, 0.01).unwrap();
    let yours = YOUR_CRITICAL_Z.expect("exercise 1 of Comparing images: set YOUR_CRITICAL_Z");
    // The message does not give the answer away: count the tests, then apply Šidák.
    assert!(
        (yours - c.z_critical).abs() <= 0.01,
        "your critical |z| {yours} is not within 0.01 of the one compare uses \
         (a test per pixel and channel, per block and channel, per channel of the image)"
    );
}

/// Four candidates 3 % brighter, floored as `compare --spp 64` floors them (the reference's
/// variance is a 64th of one candidate's, so it has 64 x 64 samples per pixel when each
/// candidate has 64), are refused by the whole image's mean. Not floored, they agree: the
/// guard against a pixel whose variance came out small leaves the region tests about 3
/// degrees of freedom, and no test sees 3 % (what `--spp` is for).
#[test]
fn four_candidates_three_percent_brighter_are_refused() {
    let mut rng = rng::seeded(0xb4_1647);
    let t = truth(&mut rng);
    let mut r = reference(&t, &mut rng);
    let bare = candidates(&t, 4, 1.03, &mut rng);
    let c = compare(&r, &bare, test_alpha()).unwrap();
    assert!(
        c.agree() && c.image.iter().all(|(_, dof, _)| *dof < 3.5),
        "{}",
        c.report(["ref", "cand"])
    );
    r.image.spp = Some(64 * 64);
    let mut floored = bare;
    assert!(floored.floor_from_reference(&r, 4 * 64));
    let c = compare(&r, &floored, test_alpha()).unwrap();
    assert!(!c.agree(), "{}", c.report(["ref", "cand"]));
    assert!(
        c.image.iter().all(|(z, _, _)| *z > c.z_critical),
        "the whole image's mean is not the test that fails (z > 0: the candidate brighter): {:?}",
        c.image
    );
    // And the report says by how much: 3 %, within the noise of four candidates.
    assert!(
        c.image
            .iter()
            .all(|(_, _, (rel, half))| (rel - 0.03).abs() < 0.01 && *half > 0.0),
        "relative differences: {:?}",
        c.image
    );
}

#[test]
fn the_spread_of_images_is_their_sample_variance_over_k() {
    // Three images of one pixel: 1, 2, 4 (R); mean 7/3, s^2 = 7/3, variance of the mean 7/9.
    let images = [
        [DVec3::new(1.0, 0.0, 5.0)],
        [DVec3::new(2.0, 0.0, 5.0)],
        [DVec3::new(4.0, 0.0, 5.0)],
    ];
    let means: Vec<&[DVec3]> = images.iter().map(|m| &m[..]).collect();
    let e = Estimate::from_spread(1, 1, &means).unwrap();
    assert!((e.image.mean[0].x - 7.0 / 3.0).abs() < 1e-15);
    assert!((e.image.var[0].x - 7.0 / 9.0).abs() < 1e-15);
    assert_eq!((e.image.var[0].y, e.image.var[0].z), (0.0, 0.0));
    assert_eq!(e.dof, 2.0);
    assert!(Estimate::from_spread(1, 1, &means[..1]).is_err());
    assert!(Estimate::from_spread(2, 1, &means).is_err());
}

#[test]
fn equivalent_z_matches_the_t_table_and_satterthwaite_the_hand_count() {
    // Published two-sided 5 % points: t_3 = 3.182446, t_15 = 2.131450, t_1 = 12.706205.
    for (t, dof) in [(3.182_446, 3.0), (2.131_450, 15.0), (12.706_205, 1.0)] {
        let z = equivalent_z(t, 1.0, dof);
        assert!((z - 1.959_964).abs() < 2e-5, "t = {t} with {dof}: z = {z}");
        assert!((equivalent_z(-t, 1.0, dof) + z).abs() < 1e-12);
    }
    // Far out, z keeps growing with t (no cap where a p-value computed as 1 - cdf would
    // round to 0 or 2^-53), so that the worst-pixel list keeps its order.
    for dof in [1.0, 3.0, 15.0, 1023.0] {
        let mut last = 0.0;
        for k in 0..60 {
            let t = 3.0 * 1.2_f64.powi(k);
            let z = equivalent_z(t, 1.0, dof);
            assert!(z > last, "dof {dof}: z({t}) = {z} after {last}");
            last = z;
        }
    }
    assert_eq!(equivalent_z(2.5, 1.0, f64::INFINITY), 2.5);
    assert_eq!(equivalent_z(0.0, 0.0, 3.0), 0.0);
    assert_eq!(equivalent_z(1.0, 0.0, 3.0), f64::INFINITY);
    // Two variances 1 and 1 with 3 and 3 degrees of freedom: Welch-Satterthwaite with
    // both parts unbiased, 2^2 / (1/5 + 1/5) - 2 = 8; with 3 and infinitely many,
    // 2^2 / (1/5) - 2 = 18; one alone, its own 3 (not 3 + 2). Unguarded (upper limits 1).
    let hand = [
        (vec![(1.0, 3.0, 1.0), (1.0, 3.0, 1.0)], 8.0),
        (vec![(1.0, 3.0, 1.0), (1.0, f64::INFINITY, 1.0)], 18.0),
        (vec![(1.0, 3.0, 1.0)], 3.0),
    ];
    for (terms, dof) in hand {
        let got = region_dof(terms.iter().copied());
        assert!((got - dof).abs() < 1e-12, "{terms:?}: {got}");
    }
    // In a comparison of one pixel the pixel test takes the smaller side's, 3; so does the
    // whole image's mean, all but: guarded, a term raised to its upper limit carries it.
    let one = |var: f64, spp: Option<u32>| {
        Estimate::from_variance(Image {
            width: 1,
            height: 1,
            mean: vec![DVec3::ZERO],
            var: vec![DVec3::splat(var)],
            spp,
        })
    };
    for other in [Some(4), None] {
        let c = compare(&one(1.0, Some(4)), &one(1.0, other), 0.01).unwrap();
        assert_eq!(c.pixel_dof, (3.0, 3.0));
        assert!((3.0..3.1).contains(&c.image[0].1), "{:?}", c.image);
    }
    // A side with no variance at all does not lower the degrees of freedom.
    let c = compare(&one(1.0, None), &one(0.0, Some(4)), 0.01).unwrap();
    assert_eq!(c.pixel_dof.0, f64::INFINITY);
    assert!(
        c.sources[0].contains("no spp attribute"),
        "{}",
        c.sources[0]
    );
}

// ---------------------------------------------------------------------------------------
// Files as other renderers write them.

pub fn tmp(name: &str) -> PathBuf {
    crate::support::scratch_file(&format!("compare-{name}"))
}

/// Writes a plain EXR with the channels `names` (in that order; EXR sorts them), each
/// `value(channel index, pixel index)`, as half floats if `half`.
pub fn write_plain(
    path: &std::path::Path,
    (w, h): (usize, usize),
    names: &[&str],
    half: bool,
    value: impl Fn(usize, usize) -> f32,
) {
    let list: SmallVec<[AnyChannel<FlatSamples>; 4]> = names
        .iter()
        .enumerate()
        .map(|(c, name)| {
            let v: Vec<f32> = (0..w * h).map(|i| value(c, i)).collect();
            let samples = if half {
                FlatSamples::F16(v.iter().map(|&x| f16::from_f32(x)).collect())
            } else {
                FlatSamples::F32(v)
            };
            AnyChannel::new(*name, samples)
        })
        .collect();
    let layer = Layer::new(
        (w, h),
        LayerAttributes::default(),
        Encoding::UNCOMPRESSED,
        AnyChannels::sort(list),
    );
    ExrImage::from_layer(layer).write().to_file(path).unwrap();
}

#[test]
fn plain_exrs_are_read_in_any_channel_order_half_or_float() {
    let path = tmp("plain-half.exr");
    // Alpha first, then B, G, R: what matters is the names.
    let rgb = |c: usize, i: usize| [0.0, 0.25, 0.5, 1.0][c] + i as f32;
    write_plain(&path, (3, 2), &["A", "B", "G", "R"], true, rgb);
    let c = ExrContents::read(&path).unwrap();
    assert_eq!(
        (c.width, c.height, c.var.is_none(), c.spp),
        (3, 2, true, None)
    );
    assert_eq!(c.mean[4], DVec3::new(5.0, 4.5, 4.25));
    let path = tmp("plain-float.exr");
    write_plain(&path, (3, 2), &["R", "G", "B"], false, |c, i| {
        0.1 * c as f32 + i as f32
    });
    let c = ExrContents::read(&path).unwrap();
    assert!((c.mean[5] - DVec3::new(5.0, 5.1, 5.2)).abs().max_element() < 1e-6);
    // raylemma's own files carry their samples per pixel.
    let image = Image {
        width: 2,
        height: 1,
        mean: vec![DVec3::ONE; 2],
        var: vec![DVec3::splat(0.5); 2],
        spp: Some(64),
    };
    let path = tmp("with-spp.exr");
    image.write_exr(&path).unwrap();
    let back = Image::read_exr(&path).unwrap();
    assert_eq!(back, image);
    assert_eq!(Estimate::from_variance(back).dof, 63.0);
}

#[test]
fn images_no_comparison_can_use_are_refused_by_name() {
    let good = |c: usize, _| [1.0, 0.5, 0.25, 0.01, 0.01, 0.01][c];
    let six = ["R", "G", "B", "var.R", "var.G", "var.B"];
    let problem = |name: &str, names: &[&str], value: &dyn Fn(usize, usize) -> f32| {
        let path = tmp(name);
        write_plain(&path, (4, 3), names, false, value);
        let e = ExrContents::read(&path).unwrap_err();
        assert!(e.to_string().contains(name), "{e}");
        e.problem
    };
    let p = problem("nan.exr", &six, &|c, i| {
        if (c, i) == (1, 6) {
            f32::NAN
        } else {
            good(c, i)
        }
    });
    assert!(p.contains("pixel (2, 1) channel G is NaN"), "{p}");
    let p = problem("inf.exr", &six, &|c, i| {
        if (c, i) == (0, 0) {
            f32::INFINITY
        } else {
            good(c, i)
        }
    });
    assert!(p.contains("pixel (0, 0) channel R is inf"), "{p}");
    let p = problem("negative.exr", &six, &|c, i| {
        if (c, i) == (5, 11) { -1e-3 } else { good(c, i) }
    });
    assert!(
        p.contains("pixel (3, 2) channel var.B") && p.contains(">= 0"),
        "{p}"
    );
    let p = problem("some-var.exr", &["R", "G", "B", "var.R"], &good);
    assert!(p.contains("only some of the variance channels"), "{p}");
    // X, Y, Z means with variance channels: the variances cannot be carried to sRGB.
    let xyz_var = ["X", "Y", "Z", "var.R", "var.G", "var.B"];
    let p = problem("xyz-var.exr", &xyz_var, &good);
    assert!(p.contains("the means are X, Y, Z"), "{p}");
    let p = problem("no-rgb.exr", &["Y"], &good);
    assert!(p.contains("no channel \"R\"") && p.contains("Y"), "{p}");
    // Truncated: the first half of a valid file.
    let whole = tmp("whole.exr");
    write_plain(&whole, (16, 16), &six, false, good);
    let bytes = std::fs::read(&whole).unwrap();
    let cut = tmp("truncated.exr");
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    let e = ExrContents::read(&cut).unwrap_err();
    assert!(e.problem.contains("truncated"), "{e}");
    // A PNG is named as one.
    let png = tmp("image.png");
    let bytes = raylemma::image::png::encode_png(1, 1, &[0, 0, 0]).unwrap();
    std::fs::write(&png, bytes).unwrap();
    let e = ExrContents::read(&png).unwrap_err();
    assert!(e.problem.contains("a PNG image"), "{e}");
    // A render of one sample per pixel has no variance.
    let one = Image {
        width: 1,
        height: 1,
        mean: vec![DVec3::ONE],
        var: vec![DVec3::NAN],
        spp: Some(1),
    };
    let path = tmp("one-spp.exr");
    one.write_exr(&path).unwrap();
    let e = ExrContents::read(&path).unwrap_err();
    assert!(e.problem.contains("at least 2 samples"), "{e}");
}

/// Four half-float candidates of a correct image whose noise (sd 2e-5) is below a half
/// float's spacing there (2.4e-4 to 4.9e-4): in most pixels the four round alike and their
/// spread is zero, so without the rounding's variance every such pixel's rounding error is
/// a "difference" of many sd (the planted twin: it must DIFFER); with it they AGREE, and the
/// same candidates 3 % brighter still DIFFER. Statistical: one test at the suite's level.
#[test]
fn half_float_candidates_whose_roundings_agree_are_not_a_difference() {
    use raylemma::conformance::compare::add_half_rounding;
    let mut rng = rng::seeded(2718);
    let exact = |i: usize| DVec3::new(0.2 + 0.003 * i as f64, 0.5, 0.25 + 0.001 * (i % 7) as f64);
    let noise = |rng: &mut Rng, sd: f64| sd * normal3(rng);
    let reference = Estimate::from_variance(Image {
        width: 16,
        height: 16,
        mean: (0..256).map(|i| exact(i) + noise(&mut rng, 1e-5)).collect(),
        var: vec![DVec3::splat(1e-10); 256],
        spp: Some(4096),
    });
    let mut candidates = |gain: f64, stem: &str| {
        let files: Vec<ExrContents> = (0..4)
            .map(|j| {
                let values: Vec<DVec3> = (0..256)
                    .map(|i| gain * exact(i) + noise(&mut rng, 2e-5))
                    .collect();
                let path = tmp(&format!("{stem}-{j}.exr"));
                write_plain(&path, (16, 16), &["R", "G", "B"], true, |c, i| {
                    values[i][c] as f32
                });
                ExrContents::read(&path).unwrap()
            })
            .collect();
        assert!(files.iter().all(|f| f.half));
        let means: Vec<&[DVec3]> = files.iter().map(|f| &f.mean[..]).collect();
        Estimate::from_spread(16, 16, &means).unwrap()
    };
    let alpha = test_alpha();
    let spread = candidates(1.0, "half-agree");
    let zero = spread
        .image
        .var
        .iter()
        .flat_map(|v| v.to_array())
        .filter(|&v| v == 0.0)
        .count();
    assert!(
        zero > 384,
        "only {zero} of 768 pixel-channels have zero spread"
    );
    let raw = compare(&reference, &spread, alpha).unwrap();
    assert!(!raw.agree(), "{}", raw.report(["ref", "half"]));
    let mut rounded = spread;
    add_half_rounding(&mut rounded, None);
    let c = compare(&reference, &rounded, alpha).unwrap();
    assert!(c.agree(), "{}", c.report(["ref", "half"]));
    assert!(
        rounded.source.contains("half floats' rounding"),
        "{}",
        rounded.source
    );
    let mut bright = candidates(1.03, "half-bright");
    add_half_rounding(&mut bright, None);
    assert!(!compare(&reference, &bright, alpha).unwrap().agree());
}

/// Half-float candidates written as X, Y, Z, as spectral films write them: the rounding
/// happens in X, Y and Z and reaches linear sRGB through the matrix. On saturated greens
/// (R and B near 0.01, while X, Y, Z are about 0.1 to 0.3, 0.2 to 0.6, 0.04 to 0.1), four candidates whose roundings
/// agree are off in R and B by many times the spacing of half floats near 0.01: with the
/// rounding taken at the sRGB values' spacing (the planted twin, `None`), they differ; taken
/// in X, Y, Z and carried through the matrix's squared entries, they agree, and the same
/// candidates 3 % brighter are refused. Each set floored by the reference, as `compare`
/// floors candidates whose samples per pixel it knows.
#[test]
fn half_float_xyz_candidates_round_in_xyz() {
    use raylemma::conformance::compare::add_half_rounding;
    use raylemma::spectral::cie::{linear_srgb_to_xyz, xyz_to_linear_srgb_matrix};
    let mut rng = rng::seeded(1618);
    // Values spread over many half-float spacings, so that the roundings of different pixels
    // are not alike (a block's mean takes its pixels' errors as independent).
    let exact = |i: usize| {
        DVec3::new(
            0.01 + 1e-4 * (i % 5) as f64,
            0.3 + 2e-3 * i as f64,
            0.01 + 1e-4 * (i % 3) as f64,
        )
    };
    let noise = |rng: &mut Rng, sd: f64| sd * normal3(rng);
    let reference = Estimate::from_variance(Image {
        width: 16,
        height: 16,
        mean: (0..256).map(|i| exact(i) + noise(&mut rng, 1e-7)).collect(),
        var: vec![DVec3::splat(1e-14); 256],
        spp: Some(4096),
    });
    let to_rgb = xyz_to_linear_srgb_matrix();
    let mut candidates = |gain: f64, stem: &str| {
        let files: Vec<ExrContents> = (0..4)
            .map(|j| {
                let values: Vec<DVec3> = (0..256)
                    .map(|i| linear_srgb_to_xyz(gain * exact(i) + noise(&mut rng, 1e-7)))
                    .collect();
                let path = tmp(&format!("{stem}-{j}.exr"));
                write_plain(&path, (16, 16), &["X", "Y", "Z"], true, |c, i| {
                    values[i][c] as f32
                });
                ExrContents::read(&path).unwrap().converted(to_rgb)
            })
            .collect();
        assert!(files.iter().all(|f| f.half && f.from_xyz));
        let means: Vec<&[DVec3]> = files.iter().map(|f| &f.mean[..]).collect();
        // Floored, as `compare --spp 64` floors them.
        let mut e = Estimate::from_spread(16, 16, &means).unwrap();
        assert!(e.floor_from_reference(&reference, 4 * 64));
        e
    };
    let alpha = test_alpha();
    let same = candidates(1.0, "half-xyz");
    let mut twin = same.clone();
    add_half_rounding(&mut twin, None);
    let c = compare(&reference, &twin, alpha).unwrap();
    assert!(
        !c.agree(),
        "{}",
        c.report(["ref", "half xyz, sRGB spacing"])
    );
    let mut rounded = same;
    add_half_rounding(&mut rounded, Some(to_rgb));
    let c = compare(&reference, &rounded, alpha).unwrap();
    assert!(c.agree(), "{}", c.report(["ref", "half xyz"]));
    let mut bright = candidates(1.03, "half-xyz-bright");
    add_half_rounding(&mut bright, Some(to_rgb));
    assert!(!compare(&reference, &bright, alpha).unwrap().agree());
}

/// A pixel of rare light: each sample is `1` with probability `p`, else `0`, as on a sliver
/// of floor that few paths reach. The mean of `n` samples (a binomial count over `n`) and
/// the variance of that mean, `s^2 / n` from the samples' own spread.
fn rare_pixel(p: f64, n: u32, gain: f64, rng: &mut Rng) -> (f64, f64) {
    let hits = (0..n).filter(|_| rng::uniform(rng, 0.0, 1.0) < p).count() as f64;
    let n = f64::from(n);
    let mean = hits / n;
    let var = if n > 1.0 {
        hits * (1.0 - mean) * (1.0 - mean) / (n - 1.0) + (n - hits) * mean * mean / (n - 1.0)
    } else {
        0.0
    } / n;
    (gain * mean, gain * gain * var)
}

/// An image of rare light, `SIDE_RARE` square, where each pixel's three channels are
/// reached with probability `p` rising from 0.5 % to 4 % across the image; `n` samples per
/// pixel.
fn rare_image(n: u32, gain: f64, rng: &mut Rng) -> Image {
    const SIDE_RARE: u32 = 32;
    let mut mean = Vec::new();
    let mut var = Vec::new();
    for i in 0..SIDE_RARE * SIDE_RARE {
        let p = 0.005 + 0.035 * f64::from(i % SIDE_RARE) / f64::from(SIDE_RARE - 1);
        let (mut m, mut v) = (DVec3::ZERO, DVec3::ZERO);
        for c in 0..3 {
            (m[c], v[c]) = rare_pixel(p, n, gain, rng);
        }
        mean.push(m);
        var.push(v);
    }
    Image {
        width: SIDE_RARE,
        height: SIDE_RARE,
        mean,
        var,
        spp: Some(n),
    }
}

/// The conformance card's case (chapter *Comparing images*, *A floor under the spread*):
/// four candidates of 64 samples of light that one sample in 25 to 200 reaches. Their
/// spread is often 0 where all four read 0; floored by the reference's per-sample variance
/// ([`Estimate::floor_from_reference`]) they agree with a reference of 4096 samples; without
/// the floor (the planted twin: the card before the floor) they do not; and the same light
/// 25 % brighter, floored, is refused.
#[test]
fn rare_light_agrees_once_floored_and_a_brighter_one_does_not() {
    let mut rng = rng::seeded(0x000f_1004);
    let reference = Estimate::from_variance(rare_image(4096, 1.0, &mut rng));
    let runs = |gain: f64, rng: &mut Rng| {
        let images: Vec<Image> = (0..4).map(|_| rare_image(64, gain, rng)).collect();
        let means: Vec<&[DVec3]> = images.iter().map(|i| &i.mean[..]).collect();
        Estimate::from_spread(32, 32, &means).unwrap()
    };
    let same = runs(1.0, &mut rng);
    let zero_spread = same
        .image
        .var
        .iter()
        .filter(|v| v.min_element() == 0.0)
        .count();
    assert!(
        zero_spread > 10,
        "only {zero_spread} pixels with a channel of no spread"
    );
    let bare = compare(&reference, &same, test_alpha()).unwrap();
    assert!(
        !bare.agree(),
        "without the floor, zero spread went unpunished:\n{}",
        bare.report(["ref", "cand"])
    );
    let mut floored = same.clone();
    assert!(floored.floor_from_reference(&reference, 4 * 64));
    let c = compare(&reference, &floored, test_alpha()).unwrap();
    assert!(c.agree(), "{}", c.report(["ref", "cand"]));
    let mut brighter = runs(1.25, &mut rng);
    assert!(brighter.floor_from_reference(&reference, 4 * 64));
    let c = compare(&reference, &brighter, test_alpha()).unwrap();
    assert!(
        !c.agree() && c.image.iter().all(|(z, _, _)| *z > 0.0),
        "{}",
        c.report(["ref", "cand"])
    );
    // What failed is said: the whole image's mean, brighter.
    let failed = c.failures();
    assert!(
        !failed.is_empty() && failed.text().contains("the whole image's mean"),
        "{}",
        failed.text()
    );
}

// ---------------------------------------------------------------------------------------
// A pixel that carries a block's variance.

/// The level of each test of a 32 x 32 comparison at `--alpha 0.01`.
fn level_32() -> f64 {
    test_level(32, 32, 0.01)
}

/// Where one pixel carries a block's variance (a caustic, a firefly) and the candidate's
/// variances are not floored, the plug-in Welch–Satterthwaite degrees of freedom are many
/// exactly when that pixel's estimate comes out small, which is when the block's `t` is
/// large: with 2, 4 or 16 candidates and a pixel of a thousand times the others' variance,
/// the block's test fails far more often than its level (the planted twin, by factors the
/// table of chapter *Comparing images* gives). Each term raised in turn to its upper
/// confidence limit at the test's level (`upper_limit`) holds the level; and where the
/// variance is spread, with 16 candidates, the guard costs no power. Computed
/// chances, not counted failures (`block_chance`); the one random part, the other pixels'
/// estimates, moves them by a few per cent, against margins of factors.
#[test]
fn a_pixel_that_carries_a_block_does_not_make_its_test_liberal() {
    let mut rng = rng::seeded(0x000b_10c5);
    let level = level_32();
    // The guard's limits are the chi-squared quantiles (scipy.stats.chi2.ppf(3.3e-6, nu)).
    for (nu, quantile) in [
        (1.0, 1.710_597_2e-11),
        (3.0, 5.360_146_327e-4),
        (15.0, 1.445_001_714),
        (1023.0, 831.888_930_6),
    ] {
        let u = upper_limit(nu, 3.3e-6);
        assert!(((u * quantile / nu) - 1.0).abs() < 1e-6, "nu {nu}: {u}");
    }
    for (nu, twin_at_least) in [(1, 100.0), (3, 30.0), (15, 2.0)] {
        let guarded = block_chance(nu, 1000.0, 0.0, true, level, &mut rng);
        let plug_in = block_chance(nu, 1000.0, 0.0, false, level, &mut rng);
        assert!(
            guarded <= level,
            "nu {nu}: the guarded block test fails with chance {guarded:.3e}, level {level:.3e}"
        );
        assert!(
            plug_in >= twin_at_least * level,
            "nu {nu}: the plug-in twin fails with chance {plug_in:.3e}, only {:.1} x the level",
            plug_in / level
        );
    }
    // Spread evenly over 256 pixels of 16 candidates: the false alarms at the level, and a
    // bias the exact-variance test finds half the time found as often.
    let bias = two_sided_critical(level);
    for guarded in [true, false] {
        let alarms = block_chance(15, 1.0, 0.0, guarded, level, &mut rng);
        let power = block_chance(15, 1.0, bias, guarded, level, &mut rng);
        assert!(
            alarms <= 1.2 * level && power >= 0.45,
            "guarded {guarded}: false alarms {:.2} x the level, power {power:.3}",
            alarms / level
        );
    }
}
