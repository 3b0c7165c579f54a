//! A scenario's map: loaded from a picture or a map file, drawn from a room's furniture,
//! or rasterised from a grid's shapes, within a cell limit.

use std::path::Path;

use envmap::{CellRect, GridMap, LoadOptions, Pipeline};
use hyplan_core::Point2;

use crate::Shape;
use crate::scenario::{MapSpec, Scenario, ScenarioError};

/// The map of `spec` (files relative to `dir`, errors naming `path`), whether its cells
/// are numbered from the top (`y_down`), and its rectangles when the spec asks for them.
pub(crate) fn build_map(
    spec: &MapSpec,
    dir: &Path,
    path: &Path,
    max_cells: usize,
) -> Result<(GridMap, bool, Vec<CellRect>), ScenarioError> {
    let map_err = |e: &dyn std::fmt::Display| Scenario::invalid(path, "map", "", &e.to_string());
    // A map file above the limit: the file's size, named as the scenario's field.
    let load_err = |file: &str, e: envmap::MapError| match e {
        envmap::MapError::TooLarge {
            width,
            height,
            limit,
            ..
        } => ScenarioError::TooLarge {
            path: path.to_path_buf(),
            field: "map.path".into(),
            value: file.to_string(),
            width,
            height,
            limit,
        },
        e => map_err(&e),
    };
    // A drawn map above the limit, before a pixel or cell is allocated.
    let check_size = |width: usize, height: usize| {
        if width.checked_mul(height).is_none_or(|n| n > max_cells) {
            Err(ScenarioError::TooLarge {
                path: path.to_path_buf(),
                field: "map.width x map.height".into(),
                value: format!("{width} x {height}"),
                width,
                height,
                limit: max_cells,
            })
        } else {
            Ok(())
        }
    };
    let built = match spec {
        MapSpec::Picture {
            path: file,
            threshold,
            rectangles,
            safety_radius_px,
            resolution,
        } => {
            let opts = LoadOptions {
                threshold: *threshold,
                rectangles: *rectangles,
                safety_radius: Some(*safety_radius_px),
                max_cells,
                ..LoadOptions::default()
            };
            let loaded = envmap::load_map(&dir.join(file), &opts).map_err(|e| load_err(file, e))?;
            let rects = if *rectangles {
                loaded.components.iter().map(|c| c.rect).collect()
            } else {
                Vec::new()
            };
            let map = loaded
                .map
                .with_frame(*resolution, Point2::origin())
                .map_err(|e| map_err(&e))?;
            (map, true, rects)
        }
        MapSpec::Room {
            width,
            height,
            furniture,
            threshold,
            rectangles,
            safety_radius_px,
            resolution,
        } => {
            check_size(*width, *height)?;
            let picture = crate::draw_room(*width, *height, furniture);
            let pipeline = Pipeline {
                threshold: *threshold,
                invert: false,
                rectangles: *rectangles,
                safety_radius: *safety_radius_px,
            };
            let out = pipeline.run(&picture).map_err(|e| map_err(&e))?;
            let map = out
                .map
                .with_frame(*resolution, Point2::origin())
                .map_err(|e| map_err(&e))?;
            let rects = if *rectangles {
                out.rectangles
            } else {
                Vec::new()
            };
            (map, true, rects)
        }
        MapSpec::Grid {
            width,
            height,
            resolution,
            obstacles,
            safety_radius_cells,
            padding_cells,
            y_down,
        } => {
            check_size(*width, *height)?;
            let raster = Raster {
                width: *width,
                height: *height,
                resolution: *resolution,
                padding_cells: *padding_cells,
                y_down: *y_down,
            };
            let map = raster
                .draw(obstacles, *safety_radius_cells)
                .map_err(|e| map_err(&e))?;
            (map, *y_down, Vec::new())
        }
        MapSpec::File {
            path: file,
            safety_radius,
        } => {
            let opts = LoadOptions {
                safety_radius: *safety_radius,
                max_cells,
                ..LoadOptions::default()
            };
            let loaded = envmap::load_map(&dir.join(file), &opts).map_err(|e| load_err(file, e))?;
            let y_down = matches!(loaded.frame, envmap::InputFrame::Cells { .. });
            (loaded.map, y_down, Vec::new())
        }
    };
    Ok(built)
}

/// How shapes are drawn into a grid.
struct Raster {
    width: usize,
    height: usize,
    resolution: f64,
    padding_cells: usize,
    y_down: bool,
}

impl Raster {
    /// Draws shapes into a grid: a cell is forbidden when a shape overlaps its interior
    /// (exact tests from parry2d), then dilated by the padding, then the safety band is
    /// added by the seed-000 pipeline's zone step.
    fn draw(
        &self,
        obstacles: &[Shape],
        safety_radius_cells: f64,
    ) -> Result<GridMap, envmap::MapError> {
        let (width, height, res) = (self.width, self.height, self.resolution);
        if width == 0 || height == 0 || !(res.is_finite() && res > 0.0) {
            return Err(envmap::MapError::InvalidParameter {
                name: "map",
                value: format!("{width} x {height} cells at {res}"),
                reason: "sides must be >= 1 and the resolution finite and > 0".into(),
            });
        }
        let mut mask = envmap::rasterize_shapes(obstacles, width, height, res, self.y_down);
        if self.padding_cells > 0 {
            mask = envmap::dilate_square(&mask, self.padding_cells);
        }
        let pipeline = Pipeline {
            safety_radius: safety_radius_cells,
            ..Pipeline::default()
        };
        let out = pipeline.run_mask(mask, &[])?;
        out.map
            .with_frame(res, Point2::origin())
            .map_err(|e| envmap::MapError::InvalidParameter {
                name: "resolution",
                value: res.to_string(),
                reason: e.to_string(),
            })
    }
}
