//! The conformance card without the binary (`raylemma::conformance::card`): its text for
//! people, its JSON and its JUnit XML, from rows made by hand, one of each verdict.

use std::path::PathBuf;

use raylemma::conformance::card::{self, Format, Row, RunFailure, Settings, Suite};
use raylemma::conformance::compare::Failures;
use raylemma::conformance::ladder::LADDER;

fn settings() -> Settings {
    Settings {
        renderer: "my-renderer {scene} {out} <&>".into(),
        format: Format::Mitsuba,
        runs: 4,
        spp: 64,
        seed: 2,
        alpha: 0.01,
    }
}

fn suite() -> Suite {
    Suite {
        dir: crate::support::root().to_path_buf(),
        source: "built into this binary".into(),
        hash: "0123456789abcdef".into(),
    }
}

fn row(rung: usize, depth: Option<u32>, verdict: &'static str, detail: &str) -> Row {
    Row {
        rung: LADDER[rung],
        depth,
        verdict,
        bias: None,
        detail: detail.into(),
        failures: None,
        run_failure: None,
        diagnosis: Vec::new(),
    }
}

/// One row of each verdict: rung 1 agrees, rung 2 differs, rung 4 failed to render,
/// rung 9 was skipped.
fn rows() -> Vec<Row> {
    let agree = Row {
        bias: Some([(0.001, 0.002), (-0.001, 0.002), (0.0, 0.002)]),
        ..row(
            0,
            None,
            "agree",
            "worst block at (1, 2) channel G: z = 1.0 (|z| > 4.00 fails)",
        )
    };
    let differ = Row {
        bias: Some([(0.05, 0.002), (0.05, 0.002), (0.05, 0.002)]),
        failures: Some(Failures {
            z_critical: 4.0,
            pixels: (3, Some((5, 6, 0, 7.5))),
            blocks: (0, None),
            image: vec![(0, 9.0)],
        }),
        diagnosis: vec!["too bright everywhere by 5 %".into()],
        ..row(1, None, "differ", "failed: 3 pixels")
    };
    // Written once: the tests that call this run in parallel, and one writing the file
    // while another reads it gave a torn log.
    static LOG: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    let log = LOG.get_or_init(|| {
        let log = crate::support::scratch_file("card-log.txt");
        std::fs::write(&log, "starting\n\nsegmentation fault\n").unwrap_or_else(|e| panic!("{e}"));
        log
    });
    let failure = RunFailure::new(
        "my-renderer a.xml out.exr",
        "run 1 (seed 5) ended with status 139".into(),
        log,
        &PathBuf::from("out.exr"),
    );
    let error = Row {
        run_failure: Some(failure),
        ..row(
            3,
            Some(1),
            "error",
            "the renderer failed: run 1 (seed 5) ended with status 139",
        )
    };
    let skipped = row(
        8,
        None,
        "skipped",
        "the Mitsuba export refuses it: a <thin film>",
    );
    vec![agree, differ, error, skipped]
}

#[test]
fn the_card_text_names_each_rung_the_first_failures_and_the_verdict() {
    let text = card::text(&rows(), &settings(), &suite());
    assert!(
        text.starts_with("conformance of `my-renderer {scene} {out} <&>` (Mitsuba scenes, 4 runs of 64 spp each, card seed 2; false alarms at most 1 % over the card)\nsuite 0123456789abcdef (built into this binary)\n"),
        "{text}"
    );
    for needle in [
        "  rung  1 01-direct-quad",
        "R +0.10 % ± 0.20 %",
        "  rung  2 02-direct-sphere",
        "depth 1",
        "the renderer FAILED on 1 of 4 comparisons",
        "command: my-renderer a.xml out.exr",
        "  | segmentation fault",
        "first differing: rung 2",
        "  what failed: 3 pixels",
        "    - too bright everywhere by 5 %",
        "a failure here usually means: ",
        "verdict: the renderer DIFFERS\n",
    ] {
        assert!(text.contains(needle), "{needle:?} not in\n{text}");
    }
    let agreeing = card::text(&rows()[..1], &settings(), &suite());
    assert!(
        agreeing.ends_with("verdict: every rung AGREES\n"),
        "{agreeing}"
    );
    let failed = card::text(&rows()[2..3], &settings(), &suite());
    assert!(
        failed.ends_with("verdict: the renderer FAILED to render (see above)\n"),
        "{failed}"
    );
}

#[test]
fn the_card_json_holds_every_row_and_the_first_failing_rung() {
    let json = card::json(&rows(), &settings(), &suite());
    assert!(json.ends_with("}\n"));
    let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(v["renderer"], "my-renderer {scene} {out} <&>");
    assert_eq!(
        (v["runs"].as_u64(), v["spp"].as_u64(), v["seed"].as_u64()),
        (Some(4), Some(64), Some(2))
    );
    assert_eq!(v["suite"]["hash"], "0123456789abcdef");
    assert_eq!(v["first_failing_rung"], 2);
    let rungs = v["rungs"].as_array().expect("rungs");
    assert_eq!(rungs.len(), 4);
    assert_eq!(rungs[0]["scene"], "scenes/conformance/01-direct-quad.toml");
    assert_eq!(rungs[0]["relative_difference"][0]["value"], 0.001);
    let failed = &rungs[1]["failed_tests"];
    assert_eq!(failed["pixels"]["count"], 3);
    assert_eq!(failed["pixels"]["worst"]["channel"], "R");
    assert_eq!(failed["whole_image"][0]["z"], 9.0);
    assert_eq!(rungs[1]["diagnosis"][0], "too bright everywhere by 5 %");
    assert_eq!(rungs[2]["depth"], 1);
    assert_eq!(
        rungs[2]["renderer_failure"]["log_tail"][1],
        "segmentation fault"
    );
    assert!(rungs[3]["relative_difference"].is_null());
    assert_eq!(rungs[3]["verdict"], "skipped");
}

#[test]
fn the_card_junit_has_one_case_per_row_escaped() {
    let xml = card::junit(&rows());
    assert!(
        xml.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"raylemma conformance\" tests=\"4\" failures=\"1\" errors=\"1\" skipped=\"1\">\n"),
        "{xml}"
    );
    assert!(xml.ends_with("</testsuite>\n"));
    assert_eq!(xml.matches("<testcase ").count(), 4);
    assert!(
        xml.contains("  <testcase name=\"rung 1 01-direct-quad own depth\"/>\n"),
        "{xml}"
    );
    assert!(
        xml.contains("<failure message=\"differs from the reference\">"),
        "{xml}"
    );
    assert!(xml.contains("<error message=\"the renderer failed: not a verdict on its physics\">"));
    assert!(xml.contains("name=\"rung 4 "), "{xml}");
    assert!(
        xml.contains("<skipped message=\" the Mitsuba export refuses it: a &lt;thin film&gt;\"/>"),
        "{xml}"
    );
    assert_eq!(
        card::xml_escape("a<b>&\"c\""),
        "a&lt;b&gt;&amp;&quot;c&quot;"
    );
}
