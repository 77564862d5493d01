//! Merging renders: means and variances pooled exactly, and what does not pool refused
//! from the command line.

use super::*;

/// `merge` pools exactly: three renders' summaries of 2, 5 and 9 samples a pixel, pooled,
/// are the mean and the variance of the mean of all 16 samples, counted afresh.
#[test]
fn merge_pools_means_and_variances_exactly() {
    use glam::DVec3;
    use raylemma::conformance::merge::pool;
    use raylemma::image::Image;
    use raylemma::stats::welford::Welford;
    let mut rng = rng::seeded(31);
    let counts = [2u32, 5, 9];
    let samples: Vec<Vec<Vec<DVec3>>> = counts
        .iter()
        .map(|&n| {
            (0..6)
                .map(|p| {
                    (0..n)
                        .map(|_| {
                            let mut u = || rng::uniform(&mut rng, 0.0, 1.0);
                            DVec3::new(u(), 10.0 * u(), 1e-3 * p as f64 + u() * u())
                        })
                        .collect()
                })
                .collect()
        })
        .collect();
    let summary = |pixels: &[Vec<DVec3>]| {
        let w: Vec<Welford<DVec3>> = pixels
            .iter()
            .map(|s| {
                let mut w = Welford::default();
                s.iter().for_each(|&x| w.push(x));
                w
            })
            .collect();
        Image {
            width: 3,
            height: 2,
            mean: w.iter().map(Welford::mean).collect(),
            var: w.iter().map(Welford::var_of_mean).collect(),
            spp: Some(w[0].count() as u32),
        }
    };
    let parts: Vec<Image> = samples.iter().map(|s| summary(s)).collect();
    let all: Vec<Vec<DVec3>> = (0..6)
        .map(|p| samples.iter().flat_map(|s| s[p].iter().copied()).collect())
        .collect();
    let expected = summary(&all);
    let pooled = pool(&[(&parts[0], 2), (&parts[1], 5), (&parts[2], 9)]);
    assert_eq!(pooled.spp, Some(16));
    for (p, e) in [(&pooled.mean, &expected.mean), (&pooled.var, &expected.var)] {
        for (a, b) in p.iter().zip(e.iter()) {
            let rel = ((*a - *b) / *b).abs().max_element();
            assert!(rel < 1e-13, "{a} against {b}: {rel:e}");
        }
    }
}

/// `raylemma merge` from the command line: two renders with seeds 1 and 2 pool into one of
/// their summed samples that records both seeds; the same seed twice, renders of another
/// scene, a render without its sidecar, one render alone and a name that is not .exr are
/// refused with exit status 2 and the files named, and nothing is written.
#[test]
fn merge_from_the_command_line_refuses_what_does_not_pool() {
    let dir = out_dir("merge");
    let scene = dir.join("tiny.toml");
    std::fs::write(&scene, GOOD).unwrap();
    let render = |scene: &Path, seed: &str, sub: &str| {
        let out = raylemma()
            .arg("render")
            .arg(scene)
            .args(["--spp", "4", "--seed", seed, "--out"])
            .arg(dir.join(sub))
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        dir.join(sub).join(format!(
            "{}.exr",
            scene.file_stem().unwrap().to_string_lossy()
        ))
    };
    let (a, b, a_again) = (
        render(&scene, "1", "a"),
        render(&scene, "2", "b"),
        render(&scene, "1", "c"),
    );
    let merge = |parts: &[&Path], out: &Path| {
        raylemma()
            .arg("merge")
            .args(parts)
            .arg("--out")
            .arg(out)
            .output()
            .unwrap()
    };
    let merged = dir.join("m").join("tiny-8.exr");
    let out = merge(&[&a, &b], &merged);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json = std::fs::read_to_string(merged.with_extension("json")).unwrap();
    assert!(
        json.contains("\"spp\": 8") && json.contains("\"seeds\": [\n    1,\n    2\n  ]"),
        "{json}"
    );
    assert!(json.contains("\"build\""), "{json}");
    let other = dir.join("other.toml");
    std::fs::write(&other, GOOD.replace("seed = 1", "seed = 1\nmax_depth = 2")).unwrap();
    let other = render(&other, "3", "d");
    let no_sidecar = dir.join("e.exr");
    std::fs::copy(&a, &no_sidecar).unwrap();
    let refused = dir.join("refused.exr");
    for (parts, words) in [
        (
            vec![&a, &a_again],
            vec!["a/tiny.exr", "c/tiny.exr", "seed 1", "counted twice"],
        ),
        (vec![&a, &other], vec!["different scenes", "other.exr"]),
        (vec![&a, &no_sidecar], vec!["e.json", "sidecar"]),
        (vec![&a], vec!["one render"]),
    ] {
        let parts: Vec<&Path> = parts.iter().map(|p| p.as_path()).collect();
        let out = merge(&parts, &refused);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(!err.contains("panicked"), "{err}");
        for w in words {
            assert!(err.contains(w), "{w:?} not in {err}");
        }
        assert!(!refused.exists(), "{err}");
    }
    let out = merge(&[&a, &b], &dir.join("m.png"));
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("must end in .exr"));
}
