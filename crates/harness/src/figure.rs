//! The harness's figures, drawn by `viz`: a scenario's world with a run's trees and path,
//! and box plots of run metrics. Everything else (the plan figure, box plots of plain
//! numbers, success bars) is `viz`'s, re-exported from the crate root.

use std::path::Path;

use hyplan_core::{Point2, Tree};

use crate::{RunMetrics, World};

/// The figure of a scenario's world (map, rectangles, query); add trees and paths with
/// its builder methods.
///
/// ```no_run
/// # fn f(world: &harness::World) -> Result<(), harness::FigureError> {
/// harness::world_figure(world).write_png(std::path::Path::new("world.png"))
/// # }
/// ```
#[must_use]
pub fn world_figure(world: &World) -> viz::PlanFigure<'_> {
    viz::PlanFigure::new(&world.map, &world.query).rectangles(&world.rectangles)
}

/// Draws a scenario's world with trees and a path into a PNG.
///
/// # Errors
///
/// [`viz::FigureError`] naming the file when the picture cannot be allocated or written.
pub fn draw_world(
    world: &World,
    trees: &[Tree],
    path: &[Point2],
    out: &Path,
) -> Result<(), viz::FigureError> {
    world_figure(world).trees(trees).path(path).write_png(out)
}

/// Draws box plots of some metrics, one panel per metric and one box per planner, into
/// an SVG file ([`viz::chart_boxes`] on the metrics' values).
///
/// # Errors
///
/// [`viz::FigureError`] naming the file when drawing or writing fails.
pub fn chart_metrics(
    title: &str,
    planners: &[(String, Vec<RunMetrics>)],
    metrics: &[&str],
    out: &Path,
) -> Result<(), viz::FigureError> {
    let panels: Vec<viz::Panel<'_>> = metrics
        .iter()
        .map(|&metric| {
            let series = planners
                .iter()
                .map(|(label, runs)| {
                    (
                        label.clone(),
                        runs.iter().filter_map(|r| r.get(metric)).collect(),
                    )
                })
                .collect();
            (metric, series)
        })
        .collect();
    viz::chart_boxes(title, &panels, out)
}
