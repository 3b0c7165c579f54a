//! Charts of distributions, SVG (plotters): box plots with whiskers at the extremes, one
//! box per label, and bars.

use std::path::Path;

use plotters::coord::Shift;
use plotters::data::Quartiles;
use plotters::prelude::*;

use crate::FigureError;
use crate::error::write_file;

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// Labelled samples: one box (or bar) per label.
pub type Series = [(String, Vec<f64>)];

/// One panel of [`chart_boxes`]: its caption and its labelled samples.
pub type Panel<'a> = (&'a str, Vec<(String, Vec<f64>)>);

fn err(e: &dyn std::fmt::Display) -> FigureError {
    FigureError::draw(e)
}

/// Draws side-by-side panels of box plots, one panel per `(caption, series)` and one box
/// per label, under `title`, into an SVG file.
///
/// ```
/// let dir = std::env::temp_dir().join("viz-doc-boxes.svg");
/// let series = vec![("a".to_string(), vec![1.0, 2.0, 3.0]), ("b".to_string(), vec![2.0, 4.0])];
/// viz::chart_boxes("runs", &[("length", series)], &dir)?;
/// assert!(std::fs::read_to_string(&dir)?.contains("<svg"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`FigureError`] naming the file when drawing or writing fails.
pub fn chart_boxes(title: &str, panels: &[Panel<'_>], out: &Path) -> Result<(), FigureError> {
    let text = boxes_svg(title, panels).map_err(|e| e.for_file(out))?;
    write_file(out, text)
}

fn boxes_svg(title: &str, panels: &[Panel<'_>]) -> Result<String, FigureError> {
    let mut text = String::new();
    {
        let width = 320 * panels.len().max(1) as u32;
        let root = SVGBackend::with_string(&mut text, (width, 360)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let root = root
            .titled(title, ("sans-serif", 16))
            .map_err(|e| err(&e))?;
        let areas = root.split_evenly((1, panels.len().max(1)));
        for (area, (caption, series)) in areas.iter().zip(panels) {
            box_panel(area, caption, None, series, 14)?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    Ok(text)
}

/// Draws box plots of one measure, one box per label, Planner Arena's default view of a
/// real property, into an SVG file.
///
/// # Errors
///
/// [`FigureError`] naming the file when drawing or writing fails.
pub fn chart_box(
    title: &str,
    measure: &str,
    series: &Series,
    out: &Path,
) -> Result<(), FigureError> {
    let text = box_svg(title, measure, series).map_err(|e| e.for_file(out))?;
    write_file(out, text)
}

fn box_svg(title: &str, measure: &str, series: &Series) -> Result<String, FigureError> {
    let labels: Vec<String> = series.iter().map(|(l, _)| l.clone()).collect();
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, chart_size(&labels)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        box_panel(&root, title, Some(measure), series, 16)?;
        root.present().map_err(|e| err(&e))?;
    }
    Ok(text)
}

/// One panel of box plots (whiskers at the extremes); non-finite values (failed runs'
/// lengths) are left out, and a panel with no finite value is left blank.
fn box_panel(
    area: &Area<'_>,
    caption: &str,
    y_desc: Option<&str>,
    series: &Series,
    caption_size: u32,
) -> Result<(), FigureError> {
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
        .map_err(|e| err(&e))?;
    let mut mesh = chart.configure_mesh();
    mesh.light_line_style(WHITE)
        .x_label_formatter(&segment_label);
    if let Some(desc) = y_desc {
        mesh.y_desc(desc);
    }
    mesh.draw().map_err(|e| err(&e))?;
    chart
        .draw_series(boxes.iter().map(|(label, q)| {
            Boxplot::new_vertical(SegmentValue::CenterOf(*label), q)
                .width(24)
                .style(BLUE)
        }))
        .map_err(|e| err(&e))?;
    Ok(())
}

/// Draws the success rate (a fraction) of each label as a bar chart in percent, Planner
/// Arena's view of the `solved` property, into an SVG file.
///
/// # Errors
///
/// [`FigureError`] naming the file when drawing or writing fails.
pub fn chart_success(title: &str, rates: &[(String, f64)], out: &Path) -> Result<(), FigureError> {
    let percent: Vec<(String, f64)> = rates.iter().map(|(l, r)| (l.clone(), 100.0 * r)).collect();
    chart_bars(title, "solved (%)", &percent, 105.0, out)
}

/// Draws one bar per label, from 0 to its value, on an axis from 0 to `y_max`, into an SVG
/// file.
///
/// # Errors
///
/// [`FigureError`] naming the file when drawing or writing fails.
pub fn chart_bars(
    title: &str,
    y_desc: &str,
    bars: &[(String, f64)],
    y_max: f64,
    out: &Path,
) -> Result<(), FigureError> {
    let text = bars_svg(title, y_desc, bars, y_max).map_err(|e| e.for_file(out))?;
    write_file(out, text)
}

fn bars_svg(
    title: &str,
    y_desc: &str,
    bars: &[(String, f64)],
    y_max: f64,
) -> Result<String, FigureError> {
    let labels: Vec<String> = bars.iter().map(|(l, _)| l.clone()).collect();
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, chart_size(&labels)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(labels.as_slice().into_segmented(), 0.0..y_max)
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            .x_label_formatter(&segment_label)
            .y_desc(y_desc)
            .draw()
            .map_err(|e| err(&e))?;
        chart
            .draw_series(
                labels
                    .iter()
                    .zip(bars)
                    .enumerate()
                    .map(|(i, (label, (_, value)))| {
                        // A bar spans its label's segment, up to the next label's (the last, to the end).
                        let next = labels
                            .get(i + 1)
                            .map_or(SegmentValue::Last, SegmentValue::Exact);
                        let mut bar = Rectangle::new(
                            [(SegmentValue::Exact(label), 0.0), (next, *value)],
                            BLUE.mix(0.6).filled(),
                        );
                        bar.set_margin(0, 0, 20, 20);
                        bar
                    }),
            )
            .map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    Ok(text)
}

/// Wide enough for every label written level under its box (about 7 px a character).
fn chart_size(labels: &[String]) -> (u32, u32) {
    let slots: u32 = labels
        .iter()
        .map(|l| (7 * l.len() as u32 + 20).max(110))
        .sum();
    ((slots + 90).max(420), 380)
}

/// The label as written, not its Debug form with quotes.
fn segment_label(v: &SegmentValue<&String>) -> String {
    match v {
        SegmentValue::Exact(s) | SegmentValue::CenterOf(s) => (*s).clone(),
        SegmentValue::Last => String::new(),
    }
}
