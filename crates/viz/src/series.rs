//! Time series, SVG (plotters): stacked panels sharing the time axis, such as v(t) and
//! omega(t) of a run, or coverage(t) of an exploration, with event times marked.

use plotters::prelude::*;

use crate::{FigureError, Rgba};

/// One panel: a quantity over time.
#[derive(Clone, Debug, PartialEq)]
pub struct TimePanel {
    /// The quantity with its unit, e.g. `"v (m/s)"`.
    pub label: String,
    /// `(t, value)` samples, t in seconds, increasing.
    pub points: Vec<(f64, f64)>,
    /// The line's colour.
    pub colour: Rgba,
    /// Times of events, drawn as vertical lines across the panel.
    pub events: Vec<f64>,
    /// The value axis (`None`: the samples' range with 0, padded a tenth).
    pub range: Option<(f64, f64)>,
}

/// Colour of the event lines (orange).
pub const EVENT_COLOUR: Rgba = [0xee, 0x88, 0x00, 255];

/// Panels stacked top to bottom, sharing the time axis from 0 to `t_end` seconds, as an
/// SVG document `width` pixels wide and `panel_height` pixels per panel (plus 20).
///
/// ```
/// use viz::{TimePanel, time_series_svg};
/// let v = TimePanel {
///     label: "v (m/s)".into(),
///     points: vec![(0.0, 0.0), (1.0, 0.2), (2.0, 0.2)],
///     colour: [0, 102, 204, 255],
///     events: vec![1.5],
///     range: None,
/// };
/// let svg = time_series_svg(&[v], 2.0, 800, 220)?;
/// assert!(svg.contains("v (m/s)"));
/// # Ok::<(), viz::FigureError>(())
/// ```
///
/// # Errors
///
/// [`FigureError::Draw`] with the chart library's message.
pub fn time_series_svg(
    panels: &[TimePanel],
    t_end: f64,
    width: u32,
    panel_height: u32,
) -> Result<String, FigureError> {
    let err = |e: &dyn std::fmt::Display| FigureError::draw(e);
    let t_end = if t_end > 0.0 { t_end } else { 1.0 };
    let height = panel_height * panels.len().max(1) as u32 + 20;
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, (width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let areas = root
            .margin(10, 10, 0, 0)
            .split_evenly((panels.len().max(1), 1));
        for (area, panel) in areas.iter().zip(panels) {
            let (lo, hi) = panel.range.unwrap_or_else(|| value_range(&panel.points));
            let mut chart = ChartBuilder::on(area)
                .margin(5)
                .x_label_area_size(30)
                .y_label_area_size(60)
                .build_cartesian_2d(0.0..t_end, lo..hi)
                .map_err(|e| err(&e))?;
            chart
                .configure_mesh()
                .light_line_style(WHITE)
                .x_desc("t (s)")
                .y_desc(panel.label.as_str())
                .draw()
                .map_err(|e| err(&e))?;
            let grey = RGBColor(0xcc, 0xcc, 0xcc);
            chart
                .draw_series(LineSeries::new([(0.0, 0.0), (t_end, 0.0)], grey))
                .map_err(|e| err(&e))?;
            let event = colour(EVENT_COLOUR);
            for &t in &panel.events {
                chart
                    .draw_series(LineSeries::new([(t, lo), (t, hi)], event))
                    .map_err(|e| err(&e))?;
            }
            chart
                .draw_series(LineSeries::new(
                    panel.points.iter().copied(),
                    colour(panel.colour).stroke_width(2),
                ))
                .map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    Ok(text)
}

fn colour(c: Rgba) -> RGBAColor {
    RGBAColor(c[0], c[1], c[2], f64::from(c[3]) / 255.0)
}

/// The samples' range with 0, padded a tenth (at least 0.1 when flat).
fn value_range(points: &[(f64, f64)]) -> (f64, f64) {
    let (lo, hi) = points.iter().fold((0.0_f64, 0.0_f64), |(lo, hi), &(_, v)| {
        (lo.min(v), hi.max(v))
    });
    let pad = ((hi - lo) * 0.1).max(0.1);
    (lo - pad, hi + pad)
}
