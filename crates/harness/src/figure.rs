//! Figures in the papers' conventions: white safe area, grey high-risk band, black
//! obstacles, blue rectangles, red path, the tree faint; and charts of metric
//! distributions.

use std::path::{Path, PathBuf};

use hyplan_core::{Point2, Tree};
use plotters::prelude::*;
use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Stroke, Transform};

use crate::{RunMetrics, World};

/// Side of the longer edge of a figure, pixels (small grids are scaled up to it).
const MIN_SIDE_PX: f64 = 600.0;

/// Draws the world with trees and a path into a PNG.
///
/// # Errors
///
/// [`FigureError`] naming the file when the picture cannot be allocated or written.
pub fn draw_world(
    world: &World,
    trees: &[Tree],
    path: &[Point2],
    out: &Path,
) -> Result<(), FigureError> {
    let map = &world.map;
    let (w, h) = (map.width(), map.height());
    // Pixels per cell: at least 1, more for small grids.
    let scale = (MIN_SIDE_PX / w.max(h) as f64).max(1.0).floor();
    let (pw, ph) = ((w as f64 * scale) as u32, (h as f64 * scale) as u32);
    let mut pixmap = Pixmap::new(pw, ph).ok_or_else(|| FigureError::TooLarge {
        path: out.to_path_buf(),
        width: pw,
        height: ph,
    })?;
    let data = pixmap.data_mut();
    for py in 0..ph as usize {
        let j = h - 1 - ((py as f64 / scale) as usize).min(h - 1);
        for px in 0..pw as usize {
            let i = ((px as f64 / scale) as usize).min(w - 1);
            let [r, g, b] = envmap::zone_colour(map.cell_zone(i, j));
            let k = 4 * (py * pw as usize + px);
            data[k..k + 4].copy_from_slice(&[r, g, b, 255]);
        }
    }
    // World -> pixel: cells are `scale` pixels, y flipped.
    let inv = scale / map.resolution();
    let o = map.origin();
    let to_px = |p: Point2| ((p.x - o.x) * inv, ph as f64 - (p.y - o.y) * inv);
    let line = |pixmap: &mut Pixmap,
                pts: &mut dyn Iterator<Item = (Point2, Point2)>,
                rgba: [u8; 4],
                width: f32| {
        let mut pb = PathBuilder::new();
        for (a, b) in pts {
            let (ax, ay) = to_px(a);
            let (bx, by) = to_px(b);
            pb.move_to(ax as f32, ay as f32);
            pb.line_to(bx as f32, by as f32);
        }
        if let Some(p) = pb.finish() {
            let mut paint = Paint::default();
            paint.set_color(Color::from_rgba8(rgba[0], rgba[1], rgba[2], rgba[3]));
            paint.anti_alias = true;
            let stroke = Stroke {
                width,
                ..Stroke::default()
            };
            pixmap.stroke_path(&p, &paint, &stroke, Transform::identity(), None);
        }
    };
    // Rectangles (cells, inclusive) outlined in blue.
    let mut pb = PathBuilder::new();
    for r in &world.rectangles {
        let x0 = r.i_min as f32 * scale as f32;
        let x1 = (r.i_max + 1) as f32 * scale as f32;
        let y0 = ph as f32 - (r.j_max + 1) as f32 * scale as f32;
        let y1 = ph as f32 - r.j_min as f32 * scale as f32;
        if let Some(rect) = tiny_skia::Rect::from_ltrb(x0, y0, x1, y1) {
            pb.push_rect(rect);
        }
    }
    if let Some(p) = pb.finish() {
        let mut paint = Paint::default();
        let [r, g, b] = envmap::RECTANGLE_COLOUR;
        paint.set_color_rgba8(r, g, b, 255);
        pixmap.stroke_path(
            &p,
            &paint,
            &Stroke {
                width: 2.0,
                ..Stroke::default()
            },
            Transform::identity(),
            None,
        );
    }
    for tree in trees {
        line(&mut pixmap, &mut tree.edges(), [60, 120, 200, 90], 1.0);
    }
    line(
        &mut pixmap,
        &mut path.windows(2).map(|s| (s[0], s[1])),
        [220, 20, 20, 255],
        3.0,
    );
    // Start (green) and goal region (red ring).
    let dot = |pixmap: &mut Pixmap, p: Point2, r: f32, rgba: [u8; 4], fill: bool| {
        let (x, y) = to_px(p);
        if let Some(c) = PathBuilder::from_circle(x as f32, y as f32, r.max(3.0)) {
            let mut paint = Paint::default();
            paint.set_color_rgba8(rgba[0], rgba[1], rgba[2], rgba[3]);
            paint.anti_alias = true;
            if fill {
                pixmap.fill_path(&c, &paint, FillRule::Winding, Transform::identity(), None);
            } else {
                pixmap.stroke_path(
                    &c,
                    &paint,
                    &Stroke {
                        width: 2.0,
                        ..Stroke::default()
                    },
                    Transform::identity(),
                    None,
                );
            }
        }
    };
    dot(
        &mut pixmap,
        world.query.start,
        5.0,
        [20, 160, 40, 255],
        true,
    );
    let g = world.query.goal;
    dot(
        &mut pixmap,
        g.center(),
        (g.radius() * inv) as f32,
        [220, 20, 20, 255],
        false,
    );
    pixmap.save_png(out).map_err(|e| FigureError::draw(out, &e))
}

/// A figure that could not be drawn or written.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    /// The picture is too large to allocate.
    #[error("{}: a {width} x {height} px picture cannot be allocated", path.display())]
    TooLarge {
        /// The file the figure was for.
        path: PathBuf,
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
    },
    /// Drawing or writing the file failed.
    #[error("{}: {message}", path.display())]
    Draw {
        /// The file.
        path: PathBuf,
        /// What the drawing library or the file system said.
        message: String,
    },
}

impl FigureError {
    fn draw(path: &Path, e: &dyn std::fmt::Display) -> Self {
        Self::Draw {
            path: path.to_path_buf(),
            message: e.to_string(),
        }
    }
}

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
    let labels: Vec<String> = planners.iter().map(|(l, _)| l.clone()).collect();
    for (panel, metric) in panels.iter().zip(metrics) {
        let series: Vec<(String, Quartiles)> = planners
            .iter()
            .filter_map(|(label, runs)| {
                let v: Vec<f64> = runs
                    .iter()
                    .filter_map(|r| r.get(metric))
                    .filter(|x| x.is_finite())
                    .collect();
                (!v.is_empty()).then(|| (label.clone(), Quartiles::new(&v)))
            })
            .collect();
        let (lo, hi) =
            series
                .iter()
                .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), (_, q)| {
                    let v = q.values();
                    (lo.min(v[0]), hi.max(v[4]))
                });
        if !lo.is_finite() {
            continue;
        }
        let pad = ((hi - lo) * 0.1).max(1e-6);
        let mut chart = ChartBuilder::on(panel)
            .caption(*metric, ("sans-serif", 14))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d(labels.as_slice().into_segmented(), (lo - pad)..(hi + pad))
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .light_line_style(WHITE)
            // The planner's label as written, not its Debug form with quotes.
            .x_label_formatter(&|v| match v {
                SegmentValue::Exact(l) | SegmentValue::CenterOf(l) => (*l).clone(),
                SegmentValue::Last => String::new(),
            })
            .draw()
            .map_err(|e| err(&e))?;
        chart
            .draw_series(series.iter().map(|(label, q)| {
                Boxplot::new_vertical(SegmentValue::CenterOf(label), q)
                    .width(24)
                    .style(BLUE)
            }))
            .map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))
}
