//! Where a grid's cells lie in the world: the one conversion between metres and cells.

use std::ops::Range;

use hyplan_core::{Bounds, Point2};

/// A grid's place in the world: its lower-left corner, the side of its square cells and
/// its size in cells. Cell `(i, j)` is column `i` from the left, row `j` from the bottom,
/// and covers `[origin + i res, origin + (i + 1) res)` on x (likewise on y).
///
/// ```
/// use envmap::CellFrame;
/// use hyplan_core::Point2;
/// let frame = CellFrame::new(Point2::new(-1.0, 0.0), 0.5, 4, 2);
/// assert_eq!(frame.cell_of(Point2::new(0.2, 0.7)), Some((2, 1)));
/// assert_eq!(frame.cell_center(2, 1), Point2::new(0.25, 0.75));
/// assert_eq!(frame.cell_of(Point2::new(1.0, 0.2)), None); // past the right side
/// assert_eq!(frame.columns(-0.6, 0.1), 0..3);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CellFrame {
    /// Lower-left corner of cell `(0, 0)`.
    pub origin: Point2,
    /// Side of a cell, world units.
    pub resolution: f64,
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
}

impl CellFrame {
    /// A frame of `width x height` cells of side `resolution` from `origin`.
    #[must_use]
    pub const fn new(origin: Point2, resolution: f64, width: usize, height: usize) -> Self {
        Self {
            origin,
            resolution,
            width,
            height,
        }
    }

    /// The frame of cells of side `resolution` covering `bounds` from its lower-left
    /// corner (at least one cell a side; the last row and column may reach past it).
    ///
    /// ```
    /// use envmap::CellFrame;
    /// use hyplan_core::{Bounds, Point2};
    /// let f = CellFrame::covering(Bounds::new(Point2::origin(), Point2::new(1.0, 0.3)), 0.25);
    /// assert_eq!((f.width, f.height), (4, 2));
    /// ```
    #[must_use]
    pub fn covering(bounds: Bounds, resolution: f64) -> Self {
        Self {
            origin: bounds.min,
            resolution,
            width: (bounds.width() / resolution).ceil().max(1.0) as usize,
            height: (bounds.height() / resolution).ceil().max(1.0) as usize,
        }
    }

    /// Number of cells.
    #[must_use]
    #[inline]
    pub const fn cells(&self) -> usize {
        self.width * self.height
    }

    /// `p` in cell units from the origin (cell `(i, j)` spans `[i, i + 1) x [j, j + 1)`).
    #[must_use]
    #[inline]
    pub fn coords(&self, p: Point2) -> (f64, f64) {
        (
            (p.x - self.origin.x) / self.resolution,
            (p.y - self.origin.y) / self.resolution,
        )
    }

    /// The cell holding `p`, `None` outside the grid.
    #[must_use]
    #[inline]
    pub fn cell_of(&self, p: Point2) -> Option<(usize, usize)> {
        let (u, v) = self.coords(p);
        // Bounded as floats, then truncated: for `u >= 0` the truncation is below a whole
        // `width` exactly when `u` is, so these are the cells `(u as usize) < width` gave,
        // without a saturating conversion to unsigned (a dozen instructions) per test.
        let inside = (u >= 0.0) & (v >= 0.0) & (u < self.width as f64) & (v < self.height as f64);
        inside.then_some((u as i64 as usize, v as i64 as usize))
    }

    /// The row-major index (rows from the bottom) of the cell holding `p`.
    #[must_use]
    #[inline]
    pub fn index_of(&self, p: Point2) -> Option<usize> {
        self.cell_of(p).map(|(i, j)| j * self.width + i)
    }

    /// The world position of the centre of cell `(i, j)`.
    #[must_use]
    #[inline]
    pub fn cell_center(&self, i: usize, j: usize) -> Point2 {
        let res = self.resolution;
        Point2::new(
            self.origin.x + (i as f64 + 0.5) * res,
            self.origin.y + (j as f64 + 0.5) * res,
        )
    }

    /// The columns of the cells that `[lo, hi]` (x, world units) touches, clamped to the
    /// grid (empty when it misses).
    #[must_use]
    #[inline]
    pub fn columns(&self, lo: f64, hi: f64) -> Range<usize> {
        span(lo, hi, self.origin.x, self.resolution, self.width)
    }

    /// The rows of the cells that `[lo, hi]` (y, world units) touches, clamped to the grid.
    #[must_use]
    #[inline]
    pub fn rows(&self, lo: f64, hi: f64) -> Range<usize> {
        span(lo, hi, self.origin.y, self.resolution, self.height)
    }
}

/// The cells `[lo, hi]` touches along one axis of `n` cells of side `res` from `o`.
#[inline]
fn span(lo: f64, hi: f64, o: f64, res: f64, n: usize) -> Range<usize> {
    let a = ((lo - o) / res).floor().max(0.0) as usize;
    let b = (((hi - o) / res).floor().max(-1.0) + 1.0).min(n as f64) as usize;
    a..b.max(a)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The cell of `p` by floors: `(floor(u), floor(v))` when both are within the grid.
    fn floored(frame: &CellFrame, p: Point2) -> Option<(usize, usize)> {
        let (u, v) = frame.coords(p);
        let (i, j) = (u.floor(), v.floor());
        (i >= 0.0 && j >= 0.0 && i < frame.width as f64 && j < frame.height as f64)
            .then_some((i as usize, j as usize))
    }

    proptest! {
        /// Points anywhere, on cell edges and on the grid's own edges included (whole and
        /// half cells from the origin, and a hair either side).
        #[test]
        fn cell_of_is_the_floor_within_the_grid(
            (w, h) in (1usize..40, 1usize..40),
            res in prop_oneof![Just(0.05), Just(0.5), Just(1.0), 0.01f64..2.0],
            (ox, oy) in (-5.0f64..5.0, -5.0f64..5.0),
            (a, b) in (-4i32..180, -4i32..180),
            nudge in prop_oneof![Just(0.0), Just(-1e-12), Just(1e-12), -0.5f64..0.5],
        ) {
            let frame = CellFrame::new(Point2::new(ox, oy), res, w, h);
            let p = Point2::new(
                ox + (f64::from(a) / 4.0 + nudge) * res,
                oy + (f64::from(b) / 4.0 - nudge) * res,
            );
            prop_assert_eq!(frame.cell_of(p), floored(&frame, p));
        }
    }

    #[test]
    fn cell_of_rejects_what_is_not_a_number_or_far_away() {
        let frame = CellFrame::new(Point2::origin(), 0.5, 4, 2);
        for p in [
            Point2::new(f64::NAN, 0.2),
            Point2::new(0.2, f64::INFINITY),
            Point2::new(-0.0, 1e300),
            Point2::new(-1e-300, 0.2),
        ] {
            assert_eq!(frame.cell_of(p), None, "{p:?}");
        }
        assert_eq!(frame.cell_of(Point2::new(-0.0, -0.0)), Some((0, 0)));
    }
}
