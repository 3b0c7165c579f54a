//! The figure of a plan: zones in seed 000's colours, obstacle rectangles, search trees,
//! raw path, smoothed curve, start and goal region.
//!
//! The zone layer is always [`envmap::render_zones`] (seed 000's scheme,
//! [`envmap::zone_colour`]), one cell a square of whole pixels, so a zone has no seams
//! between rows; the PNG and the SVG draw the same [`Scene`].

use std::path::Path;

use envmap::{CellRect, GridMap};
use hyplan_core::{Point2, Query, Tree};

use crate::{FigureError, GridImage, Mark, Rgba, Scene, Stroke};

/// Side of the longer edge of a figure, pixels (small grids are scaled up to it).
const MIN_SIDE_PX: f64 = 600.0;
/// Radius of the start marker (and the smallest goal ring), pixels.
const MARKER_PX: f64 = 5.0;

/// Colour of the first tree (from the start); a second tree (from the goal) is green.
pub const TREE_COLOURS: [Rgba; 2] = [[60, 120, 200, 110], [60, 170, 80, 110]];
/// Colour of the raw path (red).
pub const PATH_COLOUR: Rgba = [220, 20, 20, 255];
/// Colour of the smoothed curve (dark green).
pub const CURVE_COLOUR: Rgba = [44, 160, 44, 255];
/// Colour of the start (filled) and of the goal region (ring).
pub const START_COLOUR: Rgba = [20, 90, 220, 255];

/// What a plan's figure shows: plain data, borrowed from the caller.
///
/// ```
/// use envmap::GridMap;
/// use hyplan_core::{Goal, Point2, Query};
/// use viz::PlanFigure;
/// let map = GridMap::from_ascii("
///     ....
///     .##.
///     ....
/// ")?;
/// let query = Query::new(Point2::new(0.5, 0.5), Goal::disc(Point2::new(3.5, 2.5), 0.3));
/// let path = [query.start, Point2::new(3.5, 0.5), Point2::new(3.5, 2.5)];
/// let svg = PlanFigure::new(&map, &query).path(&path).to_svg()?;
/// assert!(svg.contains("data:image/png;base64,"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct PlanFigure<'a> {
    /// The three-zone map.
    pub map: &'a GridMap,
    /// Obstacle rectangles (cells) outlined in blue.
    pub rectangles: &'a [CellRect],
    /// Start and goal region.
    pub query: &'a Query,
    /// Search trees, drawn faint (at most two colours: from the start, from the goal).
    pub trees: &'a [Tree],
    /// The raw path, a polyline.
    pub path: &'a [Point2],
    /// The smoothed curve, a polyline (empty: none).
    pub curve: &'a [Point2],
}

impl<'a> PlanFigure<'a> {
    /// A figure of `map` and `query` alone; add the rest with the builder methods.
    #[must_use]
    pub const fn new(map: &'a GridMap, query: &'a Query) -> Self {
        Self {
            map,
            rectangles: &[],
            query,
            trees: &[],
            path: &[],
            curve: &[],
        }
    }

    /// With obstacle rectangles.
    #[must_use]
    pub const fn rectangles(mut self, rectangles: &'a [CellRect]) -> Self {
        self.rectangles = rectangles;
        self
    }

    /// With search trees.
    #[must_use]
    pub const fn trees(mut self, trees: &'a [Tree]) -> Self {
        self.trees = trees;
        self
    }

    /// With the raw path.
    #[must_use]
    pub const fn path(mut self, path: &'a [Point2]) -> Self {
        self.path = path;
        self
    }

    /// With the smoothed curve.
    #[must_use]
    pub const fn curve(mut self, curve: &'a [Point2]) -> Self {
        self.curve = curve;
        self
    }

    /// Pixels per cell: at least 1, more for small grids (the longer side near 600 px).
    #[must_use]
    pub fn scale(&self) -> f64 {
        let side = self.map.width().max(self.map.height()) as f64;
        (MIN_SIDE_PX / side).max(1.0).floor()
    }

    /// Figure size, pixels.
    #[must_use]
    pub fn size_px(&self) -> (u32, u32) {
        let s = self.scale();
        (
            (self.map.width() as f64 * s) as u32,
            (self.map.height() as f64 * s) as u32,
        )
    }

    /// The marks drawn over the zone layer, bottom first: trees, raw path, curve, start,
    /// goal (world coordinates; see [`Scene::to_px`] for pixels).
    #[must_use]
    pub fn marks(&self) -> Vec<Mark> {
        let marker = MARKER_PX * self.map.resolution() / self.scale();
        let mut marks = Vec::new();
        for (k, tree) in self.trees.iter().enumerate() {
            marks.push(Mark::Segments {
                pairs: tree.edges().collect(),
                stroke: Stroke::new(TREE_COLOURS[k.min(1)], 1.0),
            });
        }
        for (line, colour, width) in [
            (self.path, PATH_COLOUR, 3.0),
            (self.curve, CURVE_COLOUR, 2.0),
        ] {
            if line.len() >= 2 {
                marks.push(Mark::polyline(
                    line.to_vec(),
                    Stroke::new(colour, width).round(),
                ));
            }
        }
        marks.push(Mark::disc(self.query.start, marker, START_COLOUR));
        let g = self.query.goal;
        marks.push(Mark::ring(
            g.center(),
            g.radius().max(marker),
            Stroke::new(START_COLOUR, 2.0),
        ));
        marks
    }

    /// The figure as a scene: the zone layer, then [`PlanFigure::marks`].
    #[must_use]
    pub fn scene(&self) -> Scene {
        let (o, r) = (self.map.origin(), self.map.resolution());
        let max = Point2::new(
            o.x + self.map.width() as f64 * r,
            o.y + self.map.height() as f64 * r,
        );
        let mut scene = Scene::new(o, max, self.scale() / r);
        let zones = envmap::render_zones(self.map, self.rectangles);
        scene.push(Mark::Grid(GridImage::from_picture(&zones, o, r)));
        scene.marks.extend(self.marks());
        scene
    }

    /// The figure as a PNG-encoded picture.
    ///
    /// # Errors
    ///
    /// [`FigureError`] when the picture cannot be allocated or encoded.
    pub fn png_bytes(&self) -> Result<Vec<u8>, FigureError> {
        self.scene().png_bytes()
    }

    /// Writes the figure as a PNG file.
    ///
    /// # Errors
    ///
    /// [`FigureError`] naming the file when the picture cannot be made or written.
    pub fn write_png(&self, out: &Path) -> Result<(), FigureError> {
        self.scene().write_png(out)
    }

    /// The figure as an SVG document: the zone picture embedded (PNG, scaled without
    /// smoothing), the marks as vectors.
    ///
    /// # Errors
    ///
    /// [`FigureError`] when the zone picture cannot be encoded.
    pub fn to_svg(&self) -> Result<String, FigureError> {
        self.scene().to_svg()
    }

    /// Writes the figure as an SVG file.
    ///
    /// # Errors
    ///
    /// [`FigureError`] naming the file when the picture cannot be made or written.
    pub fn write_svg(&self, out: &Path) -> Result<(), FigureError> {
        self.scene().write_svg(out)
    }
}
