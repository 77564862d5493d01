//! Where the checkers draw pictures of a failure, and the one plot they draw by hand.
//! Chapters: *Checking a sampler* (the warp checker's images), *Importance sampling* (an
//! estimator's convergence), *Coursework* (the report card's `results/` folder).
//!
//! The folder is, in order: the one [`with_failure_dir`] set for the checks of this thread
//! (the report card: `results/EXERCISE/`), the one [`set_failure_dir`] set for the process
//! (`raylemma check sampler --failure-images DIR`), else `warp-failures/` in the working
//! directory, never a folder fixed when the binary was built (which may be read-only or
//! another user's).

use std::cell::RefCell;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::sync::OnceLock;

/// The folder set by [`set_failure_dir`].
static FAILURE_DIR: OnceLock<PathBuf> = OnceLock::new();

thread_local! {
    /// The folder [`with_failure_dir`] set for the checks running on this thread.
    static THREAD_DIR: RefCell<Option<PathBuf>> = const { RefCell::new(None) };
}

/// The folder the pictures of a failure go into (see the module's documentation).
pub fn failure_dir() -> PathBuf {
    THREAD_DIR
        .with(|d| d.borrow().clone())
        .or_else(|| FAILURE_DIR.get().cloned())
        .unwrap_or_else(|| PathBuf::from("warp-failures"))
}

/// Runs `f` with the pictures of this thread's checks going into `dir`, then restores the
/// folder.
pub fn with_failure_dir<T>(dir: PathBuf, f: impl FnOnce() -> T) -> T {
    let before = THREAD_DIR.with(|d| d.replace(Some(dir)));
    let out = f();
    THREAD_DIR.with(|d| *d.borrow_mut() = before);
    out
}

/// Sets the folder of the pictures for the rest of the process (the first call wins;
/// `false` if it was already set to another folder).
pub fn set_failure_dir(dir: PathBuf) -> bool {
    FAILURE_DIR.get_or_init(|| dir.clone()) == &dir
}

/// Writes `text` as `file` in [`failure_dir`] and returns its path, or `None` if it cannot
/// be written (a picture explains a failure; it is not the verdict).
pub fn write(file: &str, text: &str) -> Option<PathBuf> {
    let dir = failure_dir();
    std::fs::create_dir_all(&dir).ok()?;
    let path = dir.join(file);
    crate::output::write_file(&path, text.as_bytes()).ok()?;
    Some(path)
}

/// An SVG plot of `points` `(x, y)` on logarithmic axes, with a dashed line of slope
/// `slope` (on the log-log axes) through the first point: what the points should follow.
/// Points that are not finite and positive are left out. `labels` are the title, the `x`
/// axis, the `y` axis and the dashed line's legend.
pub fn loglog_svg(points: &[(f64, f64)], slope: f64, labels: [&str; 4]) -> String {
    let [title, x_label, y_label, line_label] = labels;
    let good: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|&(x, y)| x.is_finite() && y.is_finite() && x > 0.0 && y > 0.0)
        .collect();
    let (w, h, left, right, top, bottom) = (560.0, 360.0, 70.0, 20.0, 40.0, 50.0);
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
         font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n\
         <text x=\"{}\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">{}</text>\n",
        w / 2.0,
        escape(title)
    );
    let Some(&(x0, y0)) = good.first() else {
        svg.push_str("<text x=\"20\" y=\"60\">no finite positive point to plot</text>\n</svg>\n");
        return svg;
    };
    let line = |x: f64| y0 * (x / x0).powf(slope);
    let (lx, ly): (Vec<f64>, Vec<f64>) = good
        .iter()
        .flat_map(|&(x, y)| [(x.log10(), y.log10()), (x.log10(), line(x).log10())])
        .unzip();
    let span = |v: &[f64]| {
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min).floor();
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max).ceil();
        (lo, if hi > lo { hi } else { lo + 1.0 })
    };
    let ((xa, xb), (ya, yb)) = (span(&lx), span(&ly));
    let px = |x: f64| left + (x.log10() - xa) / (xb - xa) * (w - left - right);
    let py = |y: f64| h - bottom - (y.log10() - ya) / (yb - ya) * (h - top - bottom);
    let _ = writeln!(
        svg,
        "<rect x=\"{left}\" y=\"{top}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>",
        w - left - right,
        h - top - bottom
    );
    for d in xa as i32..=xb as i32 {
        let x = px(10f64.powi(d));
        let _ = writeln!(
            svg,
            "<line x1=\"{x:.1}\" y1=\"{}\" x2=\"{x:.1}\" y2=\"{top}\" stroke=\"#ddd\"/>\
             <text x=\"{x:.1}\" y=\"{}\" text-anchor=\"middle\">1e{d}</text>",
            h - bottom,
            h - bottom + 16.0
        );
    }
    for d in ya as i32..=yb as i32 {
        let y = py(10f64.powi(d));
        let _ = writeln!(
            svg,
            "<line x1=\"{left}\" y1=\"{y:.1}\" x2=\"{}\" y2=\"{y:.1}\" stroke=\"#ddd\"/>\
             <text x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">1e{d}</text>",
            w - right,
            left - 6.0,
            y + 4.0
        );
    }
    let (first, last) = (good[0].0, good[good.len() - 1].0);
    let _ = writeln!(
        svg,
        "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#0072b2\" \
         stroke-dasharray=\"6 4\"/>",
        px(first),
        py(line(first)),
        px(last),
        py(line(last))
    );
    let path: Vec<String> = good
        .iter()
        .map(|&(x, y)| format!("{:.1},{:.1}", px(x), py(y)))
        .collect();
    let _ = writeln!(
        svg,
        "<polyline points=\"{}\" fill=\"none\" stroke=\"#d55e00\" stroke-width=\"2\"/>",
        path.join(" ")
    );
    for &(x, y) in &good {
        let _ = writeln!(
            svg,
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3.5\" fill=\"#d55e00\"/>",
            px(x),
            py(y)
        );
    }
    let _ = writeln!(
        svg,
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n\
         <text x=\"16\" y=\"{}\" text-anchor=\"middle\" transform=\"rotate(-90 16 {})\">{}</text>\n\
         <text x=\"{}\" y=\"{}\" fill=\"#d55e00\">measured</text>\n\
         <text x=\"{}\" y=\"{}\" fill=\"#0072b2\">{}</text>\n</svg>",
        (left + w - right) / 2.0,
        h - 12.0,
        escape(x_label),
        (top + h - bottom) / 2.0,
        (top + h - bottom) / 2.0,
        escape(y_label),
        left + 10.0,
        top + 16.0,
        left + 10.0,
        top + 32.0,
        escape(line_label)
    );
    svg
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
