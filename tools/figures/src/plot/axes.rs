//! Axes: the tick labels' numbers, the chart builder with the book's axis areas, and the
//! grid and axes drawn by [`mesh!`].

use plotters::prelude::*;

use super::canvas::SvgArea;
use super::series::Scale;

/// Tick labels: plain numbers in a readable range, else scientific notation.
pub fn format_tick(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if (1e-2..1e4).contains(&a) {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.0e}")
    }
}

/// Tick labels on a linear axis: as [`format_tick`], but rounding noise around zero
/// (`-2e-16` for a tick meant to be 0) prints as `0`.
pub fn format_linear_tick(v: f64) -> String {
    if v.abs() < 1e-12 {
        "0".into()
    } else {
        format_tick(v)
    }
}

pub(super) fn tick(scale: Scale, v: f64) -> String {
    if scale == Scale::Linear {
        format_linear_tick(v)
    } else {
        format_tick(v)
    }
}

/// Space for the x axis's tick labels and title, and the y axis's.
const X_AXIS: u32 = 50;

const Y_AXIS: u32 = 80;

/// A chart builder on `area` with the book's axis areas and margins.
pub fn builder<'a, 'b>(area: &'a SvgArea<'b>) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
    let mut b = ChartBuilder::on(area);
    b.margin(10)
        .margin_right(16)
        .x_label_area_size(X_AXIS)
        .y_label_area_size(Y_AXIS);
    b
}

/// The book's grid and axes on `chart`: thin light grid lines, tick labels at [`TICK_PX`](super::TICK_PX),
/// axis titles at [`LABEL_PX`](super::LABEL_PX), as many ticks as fit the panel's width.
macro_rules! mesh {
    ($chart:expr, $x_label:expr, $y_label:expr, $xf:expr, $yf:expr) => {{
        let (w, _) = $chart.plotting_area().dim_in_pixel();
        $chart
            .configure_mesh()
            .x_desc($x_label)
            .y_desc($y_label)
            .x_labels(if w < 450 { 5 } else { 9 })
            .y_labels(6)
            .bold_line_style(BLACK.mix(0.12).stroke_width(1))
            .light_line_style(TRANSPARENT)
            .axis_style(BLACK.mix(0.7).stroke_width(1))
            .label_style($crate::plot::font($crate::plot::TICK_PX))
            .axis_desc_style($crate::plot::font($crate::plot::LABEL_PX))
            .x_label_formatter($xf)
            .y_label_formatter($yf)
            .draw()?;
    }};
}
pub(crate) use mesh;
