//! Obstacle shapes in world units and their rasterisation into a cell mask: the one
//! shape vocabulary of the workspace (a scenario's `Grid(obstacles: [...])` map, the
//! simulator's walls, boxes and pillars).
//!
//! ```
//! use envmap::{Shape, rasterize_shapes};
//! let disc = Shape::Circle { x: 5.0, y: 5.0, r: 2.0 };
//! let mask = rasterize_shapes(&[disc], 10, 10, 1.0, false);
//! assert!(mask.get(5, 5) && !mask.get(0, 0));
//! ```

use hyplan_core::Point2;
use nalgebra::Vector2;

use crate::Mask;

/// An obstacle shape in world units (a scenario's units).
///
/// `Rect`, `Circle` and `Polygon` are how grid scenarios draw; `Wall`, `Box` and `Disc`
/// how the simulator's worlds do (a rotated rectangle about its centre, a thick
/// segment, a disc by centre and radius). Every variant rasterises and outlines.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
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
    /// A straight wall from `from` to `to`, `thickness` wide (a rectangle around the
    /// centre line, reaching half the thickness past each end so that walls meeting at a
    /// corner close it).
    Wall {
        /// One end of the centre line.
        from: (f64, f64),
        /// The other end.
        to: (f64, f64),
        /// Width.
        thickness: f64,
    },
    /// A rectangle, `size` = (width, height), rotated by `angle_deg` about its centre.
    Box {
        /// Centre.
        center: (f64, f64),
        /// Width and height.
        size: (f64, f64),
        /// Rotation, degrees counter-clockwise (default 0).
        #[cfg_attr(feature = "serde", serde(default))]
        angle_deg: f64,
    },
    /// A round obstacle (a pillar, a bin) by centre and radius.
    Disc {
        /// Centre.
        center: (f64, f64),
        /// Radius.
        radius: f64,
    },
}

impl Shape {
    /// The centre and radius of a round shape (`Circle`, `Disc`); `None` for the others.
    ///
    /// ```
    /// use envmap::Shape;
    /// use hyplan_core::Point2;
    /// let pillar = Shape::Disc { center: (1.0, 2.0), radius: 0.5 };
    /// assert_eq!(pillar.disc(), Some((Point2::new(1.0, 2.0), 0.5)));
    /// ```
    #[must_use]
    pub fn disc(&self) -> Option<(Point2, f64)> {
        match *self {
            Self::Circle { x, y, r } => Some((Point2::new(x, y), r)),
            Self::Disc { center, radius } => Some((pt(center), radius)),
            _ => None,
        }
    }

    /// The outline as a closed polygon, vertices in order (`None` for a round shape).
    ///
    /// ```
    /// use envmap::Shape;
    /// let wall = Shape::Wall { from: (0.0, 0.0), to: (2.0, 0.0), thickness: 0.2 };
    /// let corners = wall.outline().unwrap();
    /// assert_eq!(corners.len(), 4);
    /// assert!((corners[0].x + 0.1).abs() < 1e-12 && (corners[0].y + 0.1).abs() < 1e-12);
    /// ```
    #[must_use]
    pub fn outline(&self) -> Option<Vec<Point2>> {
        match self {
            &Self::Rect { x, y, w, h } => Some(vec![
                Point2::new(x, y),
                Point2::new(x + w, y),
                Point2::new(x + w, y + h),
                Point2::new(x, y + h),
            ]),
            Self::Polygon { points } => Some(points.iter().copied().map(pt).collect()),
            Self::Circle { .. } | Self::Disc { .. } => None,
            &Self::Wall {
                from,
                to,
                thickness,
            } => {
                let (a, b) = (pt(from), pt(to));
                let d = b - a;
                let len = d.norm();
                let half = thickness / 2.0;
                let (n, t) = if len > 0.0 {
                    (Vector2::new(-d.y, d.x) / len * half, d / len * half)
                } else {
                    (Vector2::new(0.0, half), Vector2::new(half, 0.0))
                };
                Some(vec![a - t - n, b + t - n, b + t + n, a - t + n])
            }
            &Self::Box {
                center,
                size,
                angle_deg,
            } => {
                let c = pt(center);
                let (s, co) = angle_deg.to_radians().sin_cos();
                let (hw, hh) = (size.0 / 2.0, size.1 / 2.0);
                let corner =
                    |x: f64, y: f64| Point2::new(c.x + co * x - s * y, c.y + s * x + co * y);
                Some(vec![
                    corner(-hw, -hh),
                    corner(hw, -hh),
                    corner(hw, hh),
                    corner(-hw, hh),
                ])
            }
        }
    }
}

fn pt(p: (f64, f64)) -> Point2 {
    Point2::new(p.0, p.1)
}

/// Draws shapes into a `width` x `height` mask of cells `res` units wide: a cell is set
/// when a shape overlaps its interior ([`overlaps`]). Coordinates are y-up from the lower
/// left, or y-down from the top row when `y_down`.
#[must_use]
pub fn rasterize_shapes(
    shapes: &[Shape],
    width: usize,
    height: usize,
    res: f64,
    y_down: bool,
) -> Mask {
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
    if let &Shape::Rect { x, y, w, h } = shape {
        return x < x1 && x + w > x0 && y < y1 && y + h > y0;
    }
    if let Some((c, r)) = shape.disc() {
        let dx = c.x.clamp(x0, x1) - c.x;
        let dy = c.y.clamp(y0, y1) - c.y;
        return dx * dx + dy * dy < r * r;
    }
    let Some(outline) = shape.outline() else {
        return false;
    };
    polygon_overlaps(&outline, x0, y0, x1, y1)
}

/// Whether a polygon overlaps the open square `(x0, x1) x (y0, y1)`, through parry2d.
fn polygon_overlaps(points: &[Point2], x0: f64, y0: f64, x1: f64, y1: f64) -> bool {
    use parry2d::bounding_volume::Aabb;
    use parry2d::math::Point;
    use parry2d::shape::Segment;
    let pt = |p: (f64, f64)| Point::new(p.0 as f32, p.1 as f32);
    let poly: Vec<Point<f32>> = points.iter().map(|p| pt((p.x, p.y))).collect();
    let centre = pt(((x0 + x1) * 0.5, (y0 + y1) * 0.5));
    if parry2d::utils::point_in_poly2d(&centre, &poly) {
        return true;
    }
    // Shrink the square a little so that an edge lying on the cell's border does not
    // count as overlapping its interior.
    let e = (x1 - x0) * 1e-6;
    let aabb = Aabb::new(pt((x0 + e, y0 + e)), pt((x1 - e, y1 - e)));
    (0..poly.len()).any(|k| {
        let seg = Segment::new(poly[k], poly[(k + 1) % poly.len()]);
        parry2d::query::details::intersection_test_aabb_segment(&aabb, &seg)
    })
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
