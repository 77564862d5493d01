//! What a chart shows: [`Panel`]s of [`Series`], each drawn as a [`Mark`], on linear or log
//! axes ([`Scale`]), with a legend placed where [`Legend`] says; and the ranges axes get
//! from their data.

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mark {
    /// A line through the points, in the series' dash pattern: curves.
    Line,
    /// A marker at each point: a few measurements.
    Points,
    /// A line and a marker at each point: a few measurements in order.
    LinePoints,
    /// Bars: the points are the corners of a step outline (see [`Series::bars`]), filled
    /// down to the bottom of the panel.
    Bars,
    /// A small dot at each point: a scatter plot of many points.
    Dots,
}

/// One named series of a panel. A point that cannot be drawn (not finite, or not positive
/// on a log axis) breaks a line: a `NaN` point separates the pieces of one series.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend label; an empty label is left out of the legend.
    pub label: String,
    /// Points `(x, y)`.
    pub points: Vec<(f64, f64)>,
    /// How it is drawn.
    pub mark: Mark,
}

impl Series {
    pub(super) fn new(label: impl Into<String>, points: Vec<(f64, f64)>, mark: Mark) -> Self {
        Series {
            label: label.into(),
            points,
            mark,
        }
    }

    /// A curve: a line, no markers.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Mark::Line)
    }

    /// Measured points: markers only.
    pub fn points(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Mark::Points)
    }

    /// A few measured points in order: a line and markers.
    pub fn measured(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Mark::LinePoints)
    }

    /// A histogram: bar `i` spans `edges[i]..edges[i + 1]` with height `heights[i]`.
    pub fn bars(label: impl Into<String>, edges: &[f64], heights: &[f64]) -> Self {
        Self::new(label, steps(edges, heights), Mark::Bars)
    }

    /// A scatter plot.
    pub fn dots(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Mark::Dots)
    }
}

/// The outline of a histogram: for each bar its two top corners.
pub fn steps(edges: &[f64], heights: &[f64]) -> Vec<(f64, f64)> {
    edges
        .windows(2)
        .zip(heights)
        .flat_map(|(e, &h)| [(e[0], h), (e[1], h)])
        .collect()
}

/// Axis scale.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    /// Linear.
    Linear,
    /// Base-10 logarithmic.
    Log,
}

/// Where a panel's legend goes when it is not the emptiest corner of the panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Legend {
    /// Top right.
    UpperRight,
    /// Bottom right.
    LowerRight,
    /// Top left.
    UpperLeft,
    /// Bottom left.
    LowerLeft,
    /// Below the panel, outside it (the panel's cell grows to hold it).
    Below,
}

/// One panel of a chart.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Title above the panel (wrapped onto two lines when it is too long for one).
    pub title: String,
    /// X axis label.
    pub x_label: String,
    /// Y axis label.
    pub y_label: String,
    /// X scale.
    pub x_scale: Scale,
    /// Y scale.
    pub y_scale: Scale,
    /// The series.
    pub series: Vec<Series>,
    /// A fixed x range instead of one fitted to the data.
    pub x_range: Option<(f64, f64)>,
    /// A fixed y range instead of one fitted to the data (a fitted linear range starts at
    /// 0: give one for curves whose variation is a few percent of their value).
    pub y_range: Option<(f64, f64)>,
    /// A fixed legend position instead of the emptiest corner.
    pub legend: Option<Legend>,
}

impl Panel {
    /// A panel with linear axes fitted to the data.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
        series: Vec<Series>,
    ) -> Self {
        Panel {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series,
            x_range: None,
            y_range: None,
            legend: None,
        }
    }

    /// A logarithmic x axis.
    pub fn log_x(mut self) -> Self {
        self.x_scale = Scale::Log;
        self
    }

    /// A logarithmic y axis.
    pub fn log_y(mut self) -> Self {
        self.y_scale = Scale::Log;
        self
    }

    /// A fixed x range.
    pub fn x_range(mut self, range: (f64, f64)) -> Self {
        self.x_range = Some(range);
        self
    }

    /// A fixed y range.
    pub fn y_range(mut self, range: (f64, f64)) -> Self {
        self.y_range = Some(range);
        self
    }

    /// A fixed legend position.
    pub fn legend(mut self, at: Legend) -> Self {
        self.legend = Some(at);
        self
    }

    pub(super) fn usable(&self, p: (f64, f64)) -> bool {
        p.0.is_finite()
            && p.1.is_finite()
            && (self.x_scale == Scale::Linear || p.0 > 0.0)
            && (self.y_scale == Scale::Linear || p.1 > 0.0)
    }

    /// The legend's entries: label and series index, empty labels left out.
    pub(super) fn keys(&self) -> Vec<Key> {
        self.series
            .iter()
            .enumerate()
            .filter(|(_, s)| !s.label.is_empty())
            .map(|(k, s)| Key {
                label: s.label.clone(),
                index: k,
                mark: s.mark,
            })
            .collect()
    }
}

/// One legend entry.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Key {
    pub(super) label: String,
    pub(super) index: usize,
    pub(super) mark: Mark,
}

pub(super) fn range(values: impl Iterator<Item = f64>, scale: Scale) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !lo.is_finite() {
        return (if scale == Scale::Log { 1e-1 } else { 0.0 }, 1.0);
    }
    match scale {
        Scale::Log => {
            let (lo, hi) = (lo.log10().floor(), hi.log10().ceil());
            (
                10f64.powf(lo),
                10f64.powf(if hi > lo { hi } else { lo + 1.0 }),
            )
        }
        Scale::Linear => {
            let pad = if hi > lo { 0.05 * (hi - lo) } else { 1.0 };
            (lo.min(0.0) - if lo < 0.0 { pad } else { 0.0 }, hi + pad)
        }
    }
}
