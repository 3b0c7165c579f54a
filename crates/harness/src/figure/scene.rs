//! The world figure: zones, rectangles, trees, raw path, smoothed curve, start and goal.
//!
//! One composition ([`Scene::marks`]) decides what is drawn, in which colour and width;
//! the zone layer is always [`envmap::render_zones`] (seed 000's scheme,
//! [`envmap::zone_colour`]), drawn one pixel per cell and scaled up without smoothing, so a
//! zone has no seams between rows. The PNG and the SVG put the same marks on the same
//! pixel grid: the SVG embeds the zone picture as a PNG and draws the marks as vectors.

use std::path::Path;

use base64::Engine as _;
use envmap::{CellRect, GridMap};
use hyplan_core::{Point2, Query, Tree};
use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Stroke, Transform};

use super::FigureError;
use crate::World;

/// Side of the longer edge of a figure, pixels (small grids are scaled up to it).
const MIN_SIDE_PX: f64 = 600.0;

/// Colour of the first tree (from the start); a second tree (from the goal) is green.
pub const TREE_COLOURS: [[u8; 4]; 2] = [[60, 120, 200, 110], [60, 170, 80, 110]];
/// Colour of the raw path (red).
pub const PATH_COLOUR: [u8; 4] = [220, 20, 20, 255];
/// Colour of the smoothed curve (dark green).
pub const CURVE_COLOUR: [u8; 4] = [44, 160, 44, 255];
/// Colour of the start (filled) and of the goal region (ring).
pub const START_COLOUR: [u8; 4] = [20, 90, 220, 255];

/// What a world figure shows: plain data, borrowed from the caller.
///
/// ```
/// use envmap::GridMap;
/// use harness::Scene;
/// use hyplan_core::{Goal, Point2, Query};
/// let map = GridMap::from_ascii("
///     ....
///     .##.
///     ....
/// ")?;
/// let query = Query::new(Point2::new(0.5, 0.5), Goal::disc(Point2::new(3.5, 2.5), 0.3));
/// let path = [query.start, Point2::new(3.5, 0.5), Point2::new(3.5, 2.5)];
/// let svg = Scene::new(&map, &query).path(&path).to_svg()?;
/// assert!(svg.contains("data:image/png;base64,"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Scene<'a> {
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

/// One thing drawn on the figure, in pixels (y down).
#[derive(Clone, Debug, PartialEq)]
pub enum Mark {
    /// Separate line segments of one colour and width.
    Segments {
        /// The segments' end points.
        pairs: Vec<([f64; 2], [f64; 2])>,
        /// RGBA.
        colour: [u8; 4],
        /// Stroke width, pixels.
        width: f64,
    },
    /// An open polyline.
    Polyline {
        /// Its points.
        points: Vec<[f64; 2]>,
        /// RGBA.
        colour: [u8; 4],
        /// Stroke width, pixels.
        width: f64,
    },
    /// A circle, filled or outlined (2 px).
    Circle {
        /// Centre.
        center: [f64; 2],
        /// Radius, pixels.
        radius: f64,
        /// RGBA.
        colour: [u8; 4],
        /// Filled (`true`) or a ring.
        filled: bool,
    },
}

impl<'a> Scene<'a> {
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

    /// A scenario's world (map, rectangles, query).
    #[must_use]
    pub fn of_world(world: &'a World) -> Self {
        Self::new(&world.map, &world.query).rectangles(&world.rectangles)
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

    /// The marks drawn over the zone picture, bottom first: trees, raw path, curve,
    /// start, goal. Both outputs draw exactly these.
    #[must_use]
    pub fn marks(&self) -> Vec<Mark> {
        let (_, ph) = self.size_px();
        let inv = self.scale() / self.map.resolution();
        let o = self.map.origin();
        let px = |p: Point2| [(p.x - o.x) * inv, f64::from(ph) - (p.y - o.y) * inv];
        let mut marks = Vec::new();
        for (k, tree) in self.trees.iter().enumerate() {
            marks.push(Mark::Segments {
                pairs: tree.edges().map(|(a, b)| (px(a), px(b))).collect(),
                colour: TREE_COLOURS[k.min(1)],
                width: 1.0,
            });
        }
        for (line, colour, width) in [
            (self.path, PATH_COLOUR, 3.0),
            (self.curve, CURVE_COLOUR, 2.0),
        ] {
            if line.len() >= 2 {
                marks.push(Mark::Polyline {
                    points: line.iter().map(|&p| px(p)).collect(),
                    colour,
                    width,
                });
            }
        }
        marks.push(Mark::Circle {
            center: px(self.query.start),
            radius: 5.0,
            colour: START_COLOUR,
            filled: true,
        });
        let g = self.query.goal;
        marks.push(Mark::Circle {
            center: px(g.center()),
            radius: (g.radius() * inv).max(5.0),
            colour: START_COLOUR,
            filled: false,
        });
        marks
    }

    /// The zone layer: [`envmap::render_zones`] (one pixel per cell) scaled up to the
    /// figure's size by repeating pixels, so cells stay sharp squares in any viewer.
    fn zone_layer(&self, out: &Path) -> Result<Pixmap, FigureError> {
        let pic = envmap::render_zones(self.map, self.rectangles);
        let (pw, ph) = self.size_px();
        let mut pixmap = Pixmap::new(pw, ph).ok_or_else(|| FigureError::TooLarge {
            path: out.to_path_buf(),
            width: pw,
            height: ph,
        })?;
        let s = self.scale() as usize;
        let (w, pw) = (pic.width(), pw as usize);
        for (py, row) in pixmap.data_mut().chunks_exact_mut(4 * pw).enumerate() {
            let y = py / s;
            for (px, dst) in row.chunks_exact_mut(4).enumerate() {
                let src = pic.pixel((px / s).min(w - 1), y);
                dst.copy_from_slice(&[src[0], src[1], src[2], 255]);
            }
        }
        Ok(pixmap)
    }

    /// The figure as a PNG-encoded picture.
    ///
    /// # Errors
    ///
    /// [`FigureError`] (naming `out`, the file the bytes are for) when the picture cannot
    /// be allocated or encoded.
    pub fn png_bytes(&self, out: &Path) -> Result<Vec<u8>, FigureError> {
        let mut pixmap = self.zone_layer(out)?;
        for mark in self.marks() {
            draw_mark(&mut pixmap, &mark);
        }
        pixmap.encode_png().map_err(|e| FigureError::draw(out, &e))
    }

    /// Writes the figure as a PNG file.
    ///
    /// # Errors
    ///
    /// [`FigureError`] naming the file when the picture cannot be made or written.
    pub fn write_png(&self, out: &Path) -> Result<(), FigureError> {
        let bytes = self.png_bytes(out)?;
        std::fs::write(out, bytes).map_err(|e| FigureError::draw(out, &e))
    }

    /// The figure as an SVG document: the zone picture embedded (PNG, scaled without
    /// smoothing), the marks as vectors.
    ///
    /// # Errors
    ///
    /// [`FigureError`] when the zone picture cannot be allocated or encoded.
    pub fn to_svg(&self) -> Result<String, FigureError> {
        use svg::Document;
        use svg::node::element::{Circle, Image, Path as SvgPath, path::Data};
        let here = Path::new("<svg>");
        let zones = self.zone_layer(here)?;
        let png = zones
            .encode_png()
            .map_err(|e| FigureError::draw(here, &e))?;
        let (pw, ph) = self.size_px();
        let href = format!(
            "data:image/png;base64,{}",
            base64::engine::general_purpose::STANDARD.encode(png)
        );
        let mut doc = Document::new()
            .set("viewBox", (0, 0, pw, ph))
            .set("width", pw)
            .set("height", ph)
            .add(
                Image::new()
                    .set("width", pw)
                    .set("height", ph)
                    // Zoomed in, cells stay squares where the viewer honours it.
                    .set("image-rendering", "optimizeSpeed")
                    .set("href", href),
            );
        let rgb = |c: [u8; 4]| format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
        let alpha = |c: [u8; 4]| f64::from(c[3]) / 255.0;
        for mark in self.marks() {
            doc = match mark {
                Mark::Segments {
                    pairs,
                    colour,
                    width,
                } => {
                    let data = pairs.iter().fold(Data::new(), |d, (a, b)| {
                        d.move_to((a[0], a[1])).line_to((b[0], b[1]))
                    });
                    doc.add(
                        SvgPath::new()
                            .set("d", data)
                            .set("fill", "none")
                            .set("stroke", rgb(colour))
                            .set("stroke-opacity", alpha(colour))
                            .set("stroke-width", width),
                    )
                }
                Mark::Polyline {
                    points,
                    colour,
                    width,
                } => {
                    let data = points
                        .iter()
                        .skip(1)
                        .fold(Data::new().move_to((points[0][0], points[0][1])), |d, p| {
                            d.line_to((p[0], p[1]))
                        });
                    doc.add(
                        SvgPath::new()
                            .set("d", data)
                            .set("fill", "none")
                            .set("stroke", rgb(colour))
                            .set("stroke-opacity", alpha(colour))
                            .set("stroke-width", width)
                            .set("stroke-linejoin", "round"),
                    )
                }
                Mark::Circle {
                    center,
                    radius,
                    colour,
                    filled,
                } => {
                    let c = Circle::new()
                        .set("cx", center[0])
                        .set("cy", center[1])
                        .set("r", radius);
                    doc.add(if filled {
                        c.set("fill", rgb(colour))
                    } else {
                        c.set("fill", "none")
                            .set("stroke", rgb(colour))
                            .set("stroke-width", 2)
                    })
                }
            };
        }
        Ok(doc.to_string())
    }

    /// Writes the figure as an SVG file.
    ///
    /// # Errors
    ///
    /// [`FigureError`] naming the file when the picture cannot be made or written.
    pub fn write_svg(&self, out: &Path) -> Result<(), FigureError> {
        let text = self.to_svg().map_err(|e| e.for_file(out))?;
        std::fs::write(out, text).map_err(|e| FigureError::draw(out, &e))
    }
}

/// Puts one mark on a pixmap, anti-aliased.
fn draw_mark(pixmap: &mut Pixmap, mark: &Mark) {
    let paint_of = |c: [u8; 4]| {
        let mut paint = Paint::default();
        paint.set_color(Color::from_rgba8(c[0], c[1], c[2], c[3]));
        paint.anti_alias = true;
        paint
    };
    let stroke = |width: f64| Stroke {
        width: width as f32,
        ..Stroke::default()
    };
    let mut pb = PathBuilder::new();
    let (paint, how) = match mark {
        Mark::Segments {
            pairs,
            colour,
            width,
        } => {
            for (a, b) in pairs {
                pb.move_to(a[0] as f32, a[1] as f32);
                pb.line_to(b[0] as f32, b[1] as f32);
            }
            (paint_of(*colour), Some(stroke(*width)))
        }
        Mark::Polyline {
            points,
            colour,
            width,
        } => {
            pb.move_to(points[0][0] as f32, points[0][1] as f32);
            for p in &points[1..] {
                pb.line_to(p[0] as f32, p[1] as f32);
            }
            let mut s = stroke(*width);
            s.line_join = tiny_skia::LineJoin::Round;
            (paint_of(*colour), Some(s))
        }
        Mark::Circle {
            center,
            radius,
            colour,
            filled,
        } => {
            pb.push_circle(center[0] as f32, center[1] as f32, *radius as f32);
            (paint_of(*colour), (!filled).then(|| stroke(2.0)))
        }
    };
    let Some(path) = pb.finish() else { return };
    match how {
        Some(s) => pixmap.stroke_path(&path, &paint, &s, Transform::identity(), None),
        None => pixmap.fill_path(
            &path,
            &paint,
            FillRule::Winding,
            Transform::identity(),
            None,
        ),
    }
}

/// Draws a scenario's world with trees and a path into a PNG: [`Scene`] with the world's
/// rectangles.
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
    Scene::of_world(world)
        .trees(trees)
        .path(path)
        .write_png(out)
}
