//! Obstacle shapes in world units and their rasterisation into a cell mask: what a
//! scenario file's `Grid(obstacles: [...])` map is drawn from.
//!
//! ```
//! use envmap::shapes::{Shape, rasterize};
//! let disc = Shape::Circle { x: 5.0, y: 5.0, r: 2.0 };
//! let mask = rasterize(&[disc], 10, 10, 1.0, false);
//! assert!(mask.get(5, 5) && !mask.get(0, 0));
//! ```

use crate::Mask;

/// An obstacle shape in world units (a scenario's units).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Shape {
    /// Axis-aligned rectangle from its corner `(x, y)` with width `w` and height `h`.
    Rect {
        /// Corner x.
        x: f64,
        /// Corner y (lower-left, or top-left when the grid is `y_down`).
        y: f64,
        /// Width.
        w: f64,
        /// Height.
        h: f64,
    },
    /// Simple polygon (convex or not) through its vertices, in order.
    Polygon {
        /// Vertices `(x, y)`.
        points: Vec<(f64, f64)>,
    },
    /// Disc with centre `(x, y)` and radius `r`.
    Circle {
        /// Centre x.
        x: f64,
        /// Centre y.
        y: f64,
        /// Radius.
        r: f64,
    },
}

/// Draws shapes into a `width` x `height` mask of cells `res` units wide: a cell is set
/// when a shape overlaps its interior ([`overlaps`]). Coordinates are y-up from the lower
/// left, or y-down from the top row when `y_down`.
#[must_use]
pub fn rasterize(shapes: &[Shape], width: usize, height: usize, res: f64, y_down: bool) -> Mask {
    let mut mask = Mask::new(width, height);
    let top = height as f64 * res;
    for shape in shapes {
        for j in 0..height {
            for i in 0..width {
                // The cell square in world coordinates.
                let (x0, x1) = (i as f64 * res, (i + 1) as f64 * res);
                let (mut y0, mut y1) = (j as f64 * res, (j + 1) as f64 * res);
                if y_down {
                    (y0, y1) = (top - y1, top - y0);
                }
                if overlaps(shape, x0, y0, x1, y1) {
                    mask.set(i, j, true);
                }
            }
        }
    }
    mask
}

/// Whether a shape overlaps the open square `(x0, x1) x (y0, y1)` (touching its border
/// does not count): exact for rectangles and discs, and for polygons through parry2d.
pub fn overlaps(shape: &Shape, x0: f64, y0: f64, x1: f64, y1: f64) -> bool {
    match shape {
        &Shape::Rect { x, y, w, h } => x < x1 && x + w > x0 && y < y1 && y + h > y0,
        &Shape::Circle { x, y, r } => {
            let dx = x.clamp(x0, x1) - x;
            let dy = y.clamp(y0, y1) - y;
            dx * dx + dy * dy < r * r
        }
        Shape::Polygon { points } => {
            use parry2d::bounding_volume::Aabb;
            use parry2d::math::Point;
            use parry2d::shape::Segment;
            let pt = |p: (f64, f64)| Point::new(p.0 as f32, p.1 as f32);
            let poly: Vec<Point<f32>> = points.iter().map(|&p| pt(p)).collect();
            let centre = pt(((x0 + x1) * 0.5, (y0 + y1) * 0.5));
            if parry2d::utils::point_in_poly2d(&centre, &poly) {
                return true;
            }
            // Shrink the square a little so that an edge lying on the cell's border does
            // not count as overlapping its interior.
            let e = (x1 - x0) * 1e-6;
            let aabb = Aabb::new(pt((x0 + e, y0 + e)), pt((x1 - e, y1 - e)));
            (0..poly.len()).any(|k| {
                let seg = Segment::new(poly[k], poly[(k + 1) % poly.len()]);
                parry2d::query::details::intersection_test_aabb_segment(&aabb, &seg)
            })
        }
    }
}

/// Dilation by a square of radius `r` cells (the 8-neighbourhood for r = 1).
#[must_use]
pub fn dilate_square(mask: &Mask, r: usize) -> Mask {
    let (w, h) = (mask.width(), mask.height());
    let mut out = Mask::new(w, h);
    for j in 0..h {
        for i in 0..w {
            if mask.get(i, j) {
                for jj in j.saturating_sub(r)..=(j + r).min(h - 1) {
                    for ii in i.saturating_sub(r)..=(i + r).min(w - 1) {
                        out.set(ii, jj, true);
                    }
                }
            }
        }
    }
    out
}
