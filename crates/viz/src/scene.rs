//! The scene model: what a figure shows, in world coordinates, bottom first. One scene
//! is drawn to SVG ([`Scene::to_svg`]) and to PNG ([`Scene::png_bytes`]) with the same
//! marks on the same pixel grid; a sequence of scenes is an animated PNG
//! ([`apng_scenes`](crate::apng_scenes)); moving marks also animate the SVG (SMIL).

use std::path::Path;

use hyplan_core::Point2;

use crate::error::write_file;
use crate::{FigureError, GridImage, Rgba};

/// How a line is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    /// RGBA (alpha below 255: see-through).
    pub colour: Rgba,
    /// Width, pixels.
    pub width: f64,
    /// Dashes: drawn and gap lengths, pixels (`None`: solid).
    pub dash: Option<[f64; 2]>,
    /// Round joins between a polyline's pieces (otherwise mitred).
    pub round: bool,
}

impl Stroke {
    /// A solid line of `colour`, `width` pixels wide.
    #[must_use]
    pub const fn new(colour: Rgba, width: f64) -> Self {
        Self {
            colour,
            width,
            dash: None,
            round: false,
        }
    }

    /// Dashed: `on` pixels drawn, `off` pixels left.
    #[must_use]
    pub const fn dashed(mut self, on: f64, off: f64) -> Self {
        self.dash = Some([on, off]);
        self
    }

    /// With round joins.
    #[must_use]
    pub const fn round(mut self) -> Self {
        self.round = true;
        self
    }
}

/// One thing drawn in a scene, in world coordinates (y up); widths in pixels.
#[derive(Clone, Debug, PartialEq)]
pub enum Mark {
    /// A map layer: coloured cells, scaled without smoothing.
    Grid(GridImage),
    /// Separate line segments of one stroke (a tree's edges).
    Segments {
        /// The segments' end points.
        pairs: Vec<(Point2, Point2)>,
        /// How they are drawn.
        stroke: Stroke,
    },
    /// An open polyline (a path, a robot track, a person's walk).
    Polyline {
        /// Its points.
        points: Vec<Point2>,
        /// How it is drawn.
        stroke: Stroke,
        /// A tooltip (SVG `<title>`), e.g. "person 0".
        title: Option<String>,
    },
    /// A disc or a ring (a person, the robot, a frontier point, a start or goal).
    Disc {
        /// Centre.
        center: Point2,
        /// Radius, world units.
        radius: f64,
        /// Fill (`None`: a ring).
        fill: Option<Rgba>,
        /// Outline (`None`: none).
        stroke: Option<Stroke>,
    },
    /// A mark that moves: `frames[k]` is where it is at `times[k]` (seconds, increasing).
    /// The SVG plays it (SMIL, for discs and single segments); a still picture shows the
    /// first frame; [`Scene::at_frame`] picks one.
    Moving {
        /// Key times, seconds from the start.
        times: Vec<f64>,
        /// The mark at each key time: discs, or segments of one pair, all of one kind.
        frames: Vec<Mark>,
    },
}

impl Mark {
    /// A filled disc.
    #[must_use]
    pub const fn disc(center: Point2, radius: f64, fill: Rgba) -> Self {
        Self::Disc {
            center,
            radius,
            fill: Some(fill),
            stroke: None,
        }
    }

    /// A ring (a circle outline).
    #[must_use]
    pub const fn ring(center: Point2, radius: f64, stroke: Stroke) -> Self {
        Self::Disc {
            center,
            radius,
            fill: None,
            stroke: Some(stroke),
        }
    }

    /// A polyline without a tooltip.
    #[must_use]
    pub const fn polyline(points: Vec<Point2>, stroke: Stroke) -> Self {
        Self::Polyline {
            points,
            stroke,
            title: None,
        }
    }
}

/// A figure: a world rectangle seen at some pixels per world unit, an optional background
/// and marks drawn bottom first.
///
/// ```
/// use hyplan_core::Point2;
/// use viz::{Mark, Scene, Stroke};
/// let mut scene = Scene::new(Point2::new(0.0, 0.0), Point2::new(4.0, 2.0), 50.0);
/// scene.push(Mark::polyline(
///     vec![Point2::new(0.5, 0.5), Point2::new(3.5, 1.5)],
///     Stroke::new([220, 20, 20, 255], 3.0),
/// ));
/// scene.push(Mark::disc(Point2::new(0.5, 0.5), 0.1, [20, 90, 220, 255]));
/// assert_eq!(scene.size_px(), (200, 100));
/// let svg = scene.to_svg()?;
/// assert!(svg.contains("#dc1414") && svg.contains("<circle"));
/// let png = scene.png_bytes()?;
/// assert_eq!(&png[1..4], b"PNG");
/// # Ok::<(), viz::FigureError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    min: Point2,
    max: Point2,
    px_per_unit: f64,
    /// Filled under everything (`None`: transparent in the PNG, nothing in the SVG).
    pub background: Option<Rgba>,
    /// The marks, bottom first.
    pub marks: Vec<Mark>,
}

impl Scene {
    /// An empty scene of the world rectangle `min`..`max`, `px_per_unit` pixels per world
    /// unit.
    #[must_use]
    pub const fn new(min: Point2, max: Point2, px_per_unit: f64) -> Self {
        Self {
            min,
            max,
            px_per_unit,
            background: None,
            marks: Vec::new(),
        }
    }

    /// With a background colour.
    #[must_use]
    pub const fn with_background(mut self, colour: Rgba) -> Self {
        self.background = Some(colour);
        self
    }

    /// Adds a mark on top.
    pub fn push(&mut self, mark: Mark) {
        self.marks.push(mark);
    }

    /// Pixels per world unit.
    #[must_use]
    pub const fn px_per_unit(&self) -> f64 {
        self.px_per_unit
    }

    /// The figure's size, pixels (the world rectangle scaled, rounded).
    #[must_use]
    pub fn size_px(&self) -> (u32, u32) {
        let s = self.px_per_unit;
        (
            ((self.max.x - self.min.x) * s).round().max(0.0) as u32,
            ((self.max.y - self.min.y) * s).round().max(0.0) as u32,
        )
    }

    /// A world point in pixels, y down from the top-left corner.
    #[must_use]
    pub fn to_px(&self, p: Point2) -> [f64; 2] {
        let s = self.px_per_unit;
        [(p.x - self.min.x) * s, (self.max.y - p.y) * s]
    }

    /// The scene at key frame `k` of its moving marks: each [`Mark::Moving`] replaced by
    /// its frame `k` (the last when it has fewer).
    #[must_use]
    pub fn at_frame(&self, k: usize) -> Self {
        let marks = self
            .marks
            .iter()
            .filter_map(|m| match m {
                Mark::Moving { frames, .. } => frames.get(k).or(frames.last()).cloned(),
                other => Some(other.clone()),
            })
            .collect();
        Self {
            marks,
            ..self.clone()
        }
    }

    /// The scene as an SVG document, in pixels: map layers embedded as PNG pictures
    /// (scaled without smoothing), everything else as vectors.
    ///
    /// # Errors
    ///
    /// [`FigureError`] when a map layer cannot be encoded.
    pub fn to_svg(&self) -> Result<String, FigureError> {
        crate::svg::write(self)
    }

    /// Writes the SVG document to `path`.
    ///
    /// # Errors
    ///
    /// [`FigureError`] naming the file when the figure cannot be made or written.
    pub fn write_svg(&self, path: &Path) -> Result<(), FigureError> {
        let text = self.to_svg().map_err(|e| e.for_file(path))?;
        write_file(path, text)
    }

    /// The scene drawn anti-aliased as a PNG (moving marks at their first frame).
    ///
    /// # Errors
    ///
    /// [`FigureError::TooLarge`] when the picture cannot be allocated, [`FigureError::Draw`]
    /// when it cannot be encoded.
    pub fn png_bytes(&self) -> Result<Vec<u8>, FigureError> {
        self.render()?
            .pixmap
            .encode_png()
            .map_err(|e| FigureError::draw(&e))
    }

    /// Writes the PNG to `path`.
    ///
    /// # Errors
    ///
    /// [`FigureError`] naming the file when the figure cannot be made or written.
    pub fn write_png(&self, path: &Path) -> Result<(), FigureError> {
        let bytes = self.png_bytes().map_err(|e| e.for_file(path))?;
        write_file(path, bytes)
    }

    pub(crate) fn render(&self) -> Result<crate::raster::Raster, FigureError> {
        crate::raster::render(self)
    }
}
