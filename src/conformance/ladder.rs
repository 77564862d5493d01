//! The conformance ladder: scenes for checking another renderer one feature at a time,
//! each rung adding one thing to the one before (`scenes/conformance/`). Chapter:
//! *Reference scenes and interop* (`chapters/renderer/scenes.md`, *The conformance
//! ladder*).
//!
//! A renderer that agrees with the references up to some rung and not at it is wrong in
//! what that rung adds; the rungs' files say what each tests, which chapter derives it, and
//! what a failure there usually means. Each rung with paths longer than two segments is
//! also a depth ladder: at `max_depth` 1 (direct light) and its own depth, and rungs 5 to 8
//! at 1, 2, 3 and their own, so that the first depth that disagrees tells which bounce is
//! wrong.

/// One rung: its number, its file under `scenes/conformance/`, and the maximum depths its
/// references are made at (`None`: the scene's own).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rung {
    /// From 1, in the order a renderer should pass them.
    pub number: u32,
    /// `scenes/conformance/FILE`.
    pub file: &'static str,
    /// Whether a renderer needs to be spectral to express it (a thin film, dispersion).
    pub spectral_only: bool,
    /// The depths of its references.
    pub depths: &'static [Option<u32>],
}

/// The scene's own depth only: the direct-light rungs, whose scenes have no path longer
/// than two segments (a floor, one-sided lights that reflect nothing), so that every
/// larger depth renders the same image.
const OWN: &[Option<u32>] = &[None];
/// Direct light alone, then the scene's own depth.
const DIRECT_AND_OWN: &[Option<u32>] = &[Some(1), None];
/// The depth ladder: direct light, one and two indirect bounces, the scene's own depth.
const EVERY: &[Option<u32>] = &[Some(1), Some(2), Some(3), None];

/// The rungs, in order.
pub const LADDER: [Rung; 11] = [
    rung(1, "01-direct-quad.toml", false, OWN),
    rung(2, "02-direct-sphere.toml", false, OWN),
    rung(3, "03-two-lights.toml", false, OWN),
    rung(4, "04-one-bounce.toml", false, DIRECT_AND_OWN),
    rung(5, "05-box.toml", false, EVERY),
    rung(6, "06-mirror.toml", false, EVERY),
    rung(7, "07-glass.toml", false, EVERY),
    rung(8, "08-roulette.toml", false, EVERY),
    rung(9, "09-spectral-lamp.toml", false, DIRECT_AND_OWN),
    rung(10, "10-thin-film.toml", true, DIRECT_AND_OWN),
    rung(11, "11-dispersion.toml", true, DIRECT_AND_OWN),
];

const fn rung(
    number: u32,
    file: &'static str,
    spectral_only: bool,
    depths: &'static [Option<u32>],
) -> Rung {
    Rung {
        number,
        file,
        spectral_only,
        depths,
    }
}

/// The name of a rung's reference at `depth` under `figures/reference/conformance/`: the
/// scene's stem, with `-depthD` for a depth other than the scene's own.
pub fn reference_name(rung: &Rung, depth: Option<u32>) -> String {
    let stem = rung.file.trim_end_matches(".toml");
    depth.map_or(stem.to_string(), |d| format!("{stem}-depth{d}"))
}

/// What a rung's file says of it: its title and the `Tests:`, `Derived in:` and failure
/// lines of its header comment, each joined across its continuation lines.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Header {
    /// After `rung N: `.
    pub title: String,
    /// After `Tests: `.
    pub tests: String,
    /// After `Derived in: `.
    pub chapter: String,
    /// After `usually means: `.
    pub failure: String,
}

/// The header comment of a rung's scene file ([`Header`]); empty fields where a line is
/// missing.
pub fn header(text: &str) -> Header {
    const KEYS: [&str; 3] = ["Tests: ", "Derived in: ", "usually means: "];
    let mut title = String::new();
    let mut fields = [String::new(), String::new(), String::new()];
    let mut current: Option<usize> = None;
    for line in text.lines() {
        let Some(comment) = line.strip_prefix('#') else {
            break;
        };
        let comment = comment.trim();
        let keyed = KEYS
            .iter()
            .enumerate()
            .find_map(|(k, key)| comment.split_once(key).map(|(_, rest)| (k, rest)));
        if let Some((k, rest)) = keyed {
            fields[k] = rest.to_string();
            current = Some(k);
        } else if title.is_empty() {
            if let Some((_, t)) = comment.split_once(": ") {
                title = t.trim_end_matches('.').to_string();
            }
        } else if let Some(k) = current.filter(|_| !comment.starts_with("The ladder")) {
            fields[k].push(' ');
            fields[k].push_str(comment);
        } else {
            current = None;
        }
    }
    let [tests, chapter, failure] = fields;
    Header {
        title,
        tests,
        chapter,
        failure,
    }
}

/// A file of the suite as the library was built: its path under the project root, and its
/// bytes.
macro_rules! suite_file {
    ($path:literal) => {
        (
            $path,
            include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/", $path)) as &[u8],
        )
    };
}

/// The conformance suite built into the library, and so into every binary (40 files,
/// about 2 MB): the ladder's scene files, the data files they read, and the references of
/// every rung at every depth, as they were when it was built. `raylemma conformance`
/// writes it out and runs it unless given `--suite DIR`, so a copied binary carries its
/// suite. The test `the_built_in_suite_holds_every_rung_and_depth` holds it to the ladder
/// and to the tree.
pub const SUITE: &[(&str, &[u8])] = &[
    suite_file!("scenes/conformance/01-direct-quad.toml"),
    suite_file!("scenes/conformance/02-direct-sphere.toml"),
    suite_file!("scenes/conformance/03-two-lights.toml"),
    suite_file!("scenes/conformance/04-one-bounce.toml"),
    suite_file!("scenes/conformance/05-box.toml"),
    suite_file!("scenes/conformance/06-mirror.toml"),
    suite_file!("scenes/conformance/07-glass.toml"),
    suite_file!("scenes/conformance/08-roulette.toml"),
    suite_file!("scenes/conformance/09-spectral-lamp.toml"),
    suite_file!("scenes/conformance/10-thin-film.toml"),
    suite_file!("scenes/conformance/11-dispersion.toml"),
    suite_file!("data/cie_illuminant_D65.csv"),
    suite_file!("data/cornell_box_reflectance.csv"),
    suite_file!("figures/reference/conformance/01-direct-quad.exr"),
    suite_file!("figures/reference/conformance/02-direct-sphere.exr"),
    suite_file!("figures/reference/conformance/03-two-lights.exr"),
    suite_file!("figures/reference/conformance/04-one-bounce-depth1.exr"),
    suite_file!("figures/reference/conformance/04-one-bounce.exr"),
    suite_file!("figures/reference/conformance/05-box-depth1.exr"),
    suite_file!("figures/reference/conformance/05-box-depth2.exr"),
    suite_file!("figures/reference/conformance/05-box-depth3.exr"),
    suite_file!("figures/reference/conformance/05-box.exr"),
    suite_file!("figures/reference/conformance/06-mirror-depth1.exr"),
    suite_file!("figures/reference/conformance/06-mirror-depth2.exr"),
    suite_file!("figures/reference/conformance/06-mirror-depth3.exr"),
    suite_file!("figures/reference/conformance/06-mirror.exr"),
    suite_file!("figures/reference/conformance/07-glass-depth1.exr"),
    suite_file!("figures/reference/conformance/07-glass-depth2.exr"),
    suite_file!("figures/reference/conformance/07-glass-depth3.exr"),
    suite_file!("figures/reference/conformance/07-glass.exr"),
    suite_file!("figures/reference/conformance/08-roulette-depth1.exr"),
    suite_file!("figures/reference/conformance/08-roulette-depth2.exr"),
    suite_file!("figures/reference/conformance/08-roulette-depth3.exr"),
    suite_file!("figures/reference/conformance/08-roulette.exr"),
    suite_file!("figures/reference/conformance/09-spectral-lamp-depth1.exr"),
    suite_file!("figures/reference/conformance/09-spectral-lamp.exr"),
    suite_file!("figures/reference/conformance/10-thin-film-depth1.exr"),
    suite_file!("figures/reference/conformance/10-thin-film.exr"),
    suite_file!("figures/reference/conformance/11-dispersion-depth1.exr"),
    suite_file!("figures/reference/conformance/11-dispersion.exr"),
];
