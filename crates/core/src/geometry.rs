//! Points and boxes in world coordinates.

/// A point in world coordinates (x right, y up), in the workspace's units.
pub type Point2 = nalgebra::Point2<f64>;

/// An axis-aligned box `[min.x, max.x] x [min.y, max.y]` in world units.
///
/// ```
/// use hyplan_core::{Bounds, Point2};
/// let b = Bounds::new(Point2::new(0.0, 0.0), Point2::new(4.0, 2.0));
/// assert!(b.contains(Point2::new(4.0, 1.0)));
/// assert_eq!(b.width(), 4.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Bounds {
    /// Lower-left corner.
    pub min: Point2,
    /// Upper-right corner.
    pub max: Point2,
}

impl Bounds {
    /// A box from its lower-left and upper-right corners.
    #[must_use]
    pub const fn new(min: Point2, max: Point2) -> Self {
        Self { min, max }
    }

    /// Extent along x, in world units.
    #[must_use]
    pub fn width(&self) -> f64 {
        self.max.x - self.min.x
    }

    /// Extent along y, in world units.
    #[must_use]
    pub fn height(&self) -> f64 {
        self.max.y - self.min.y
    }

    /// Length of the diagonal, in world units.
    #[must_use]
    pub fn diagonal(&self) -> f64 {
        self.width().hypot(self.height())
    }

    /// Whether `p` lies in the closed box. NaN coordinates are outside.
    #[must_use]
    pub fn contains(&self, p: Point2) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
    }
}

/// The Euclidean length of a polyline, in world units (0 for fewer than two points).
///
/// ```
/// use hyplan_core::{Point2, path_length};
/// let p = [Point2::new(0.0, 0.0), Point2::new(3.0, 4.0), Point2::new(3.0, 5.0)];
/// assert_eq!(path_length(&p), 6.0);
/// ```
#[must_use]
pub fn path_length(path: &[Point2]) -> f64 {
    path.windows(2)
        .map(|w| nalgebra::distance(&w[0], &w[1]))
        .sum()
}
