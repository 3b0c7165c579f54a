//! Charts of metric distributions, SVG (plotters): box plots with whiskers at the
//! extremes, one box per planner, and success-rate bars.

use std::path::Path;

use plotters::coord::Shift;
use plotters::data::Quartiles;
use plotters::prelude::*;

use super::FigureError;
use crate::RunMetrics;

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// Draws box plots of some metrics, one panel per metric and one box per planner, into
/// an SVG file.
///
/// # Errors
///
/// [`FigureError`] naming the file when drawing or writing fails.
pub fn chart_metrics(
    title: &str,
    planners: &[(String, Vec<RunMetrics>)],
    metrics: &[&str],
    out: &Path,
) -> Result<(), FigureError> {
    let err = |e: &dyn std::fmt::Display| FigureError::draw(out, e);
    let width = 320 * metrics.len().max(1) as u32;
    let root = SVGBackend::new(out, (width, 360)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let root = root
        .titled(title, ("sans-serif", 16))
        .map_err(|e| err(&e))?;
    let panels = root.split_evenly((1, metrics.len().max(1)));
    for (panel, metric) in panels.iter().zip(metrics) {
        let series: Vec<(String, Vec<f64>)> = planners
            .iter()
            .map(|(label, runs)| {
                (
                    label.clone(),
                    runs.iter().filter_map(|r| r.get(metric)).collect(),
                )
            })
            .collect();
        box_panel(panel, metric, None, &series, 14).map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))
}

/// Draws box plots of one measure, one box per planner, Planner Arena's default view of
/// a real property, into an SVG file.
///
/// # Errors
///
/// [`FigureError`] naming the file when drawing or writing fails.
pub fn chart_box(
    title: &str,
    measure: &str,
    series: &[(String, Vec<f64>)],
    out: &Path,
) -> Result<(), FigureError> {
    let err = |e: &dyn std::fmt::Display| FigureError::draw(out, e);
    let labels: Vec<String> = series.iter().map(|(l, _)| l.clone()).collect();
    let root = SVGBackend::new(out, chart_size(&labels)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    box_panel(&root, title, Some(measure), series, 16).map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))
}

/// One panel of box plots (whiskers at the extremes); non-finite values (failed runs'
/// lengths) are left out, and a panel with no finite value is left blank.
fn box_panel(
    area: &Area<'_>,
    caption: &str,
    y_desc: Option<&str>,
    series: &[(String, Vec<f64>)],
    caption_size: u32,
) -> Result<(), String> {
    let labels: Vec<String> = series.iter().map(|(l, _)| l.clone()).collect();
    let boxes: Vec<(&String, Quartiles)> = series
        .iter()
        .filter_map(|(label, v)| {
            let v: Vec<f64> = v.iter().copied().filter(|x| x.is_finite()).collect();
            (!v.is_empty()).then(|| (label, Quartiles::new(&v)))
        })
        .collect();
    let (lo, hi) = boxes
        .iter()
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), (_, q)| {
            let v = q.values();
            (lo.min(v[0]), hi.max(v[4]))
        });
    if !lo.is_finite() {
        return Ok(());
    }
    let pad = ((hi - lo) * 0.1).max(1e-6);
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", caption_size))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(labels.as_slice().into_segmented(), (lo - pad)..(hi + pad))
        .map_err(|e| e.to_string())?;
    let mut mesh = chart.configure_mesh();
    mesh.light_line_style(WHITE)
        .x_label_formatter(&segment_label);
    if let Some(desc) = y_desc {
        mesh.y_desc(desc);
    }
    mesh.draw().map_err(|e| e.to_string())?;
    chart
        .draw_series(boxes.iter().map(|(label, q)| {
            Boxplot::new_vertical(SegmentValue::CenterOf(*label), q)
                .width(24)
                .style(BLUE)
        }))
        .map_err(|e| e.to_string())?;
    Ok(())
}

/// Draws the success rate of each planner as a bar chart (percent), Planner Arena's view
/// of the `solved` property, into an SVG file.
///
/// # Errors
///
/// [`FigureError`] naming the file when drawing or writing fails.
pub fn chart_success(title: &str, rates: &[(String, f64)], out: &Path) -> Result<(), FigureError> {
    let err = |e: &dyn std::fmt::Display| FigureError::draw(out, e);
    let labels: Vec<String> = rates.iter().map(|(l, _)| l.clone()).collect();
    let root = SVGBackend::new(out, chart_size(&labels)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 16))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(labels.as_slice().into_segmented(), 0.0..105.0_f64)
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .light_line_style(WHITE)
        .x_label_formatter(&segment_label)
        .y_desc("solved (%)")
        .draw()
        .map_err(|e| err(&e))?;
    chart
        .draw_series(
            labels
                .iter()
                .zip(rates)
                .enumerate()
                .map(|(i, (label, (_, rate)))| {
                    // A bar spans its label's segment, up to the next label's (the last, to the end).
                    let next = labels
                        .get(i + 1)
                        .map_or(SegmentValue::Last, SegmentValue::Exact);
                    let mut bar = Rectangle::new(
                        [(SegmentValue::Exact(label), 0.0), (next, 100.0 * rate)],
                        BLUE.mix(0.6).filled(),
                    );
                    bar.set_margin(0, 0, 20, 20);
                    bar
                }),
        )
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))
}

/// Wide enough for every label written level under its box (about 7 px a character).
fn chart_size(labels: &[String]) -> (u32, u32) {
    let slots: u32 = labels
        .iter()
        .map(|l| (7 * l.len() as u32 + 20).max(110))
        .sum();
    ((slots + 90).max(420), 380)
}

/// The planner's label as written, not its Debug form with quotes.
fn segment_label(v: &SegmentValue<&String>) -> String {
    match v {
        SegmentValue::Exact(s) | SegmentValue::CenterOf(s) => (*s).clone(),
        SegmentValue::Last => String::new(),
    }
}
