//! The cells a segment crosses, in order (Amanatides and Woo 1987): the one cell
//! traversal of ray tracing and edge checks over a [`CellFrame`].

use hyplan_core::Point2;

use crate::CellFrame;

/// The cells from `a`'s to `b`'s, in the order the segment crosses them: each step enters
/// the next cell along x or along y, whichever boundary the segment meets first (along y
/// when both are met at once, so a segment through a corner visits one of the two side
/// cells). Cells are `(column, row)` and may lie outside the grid.
///
/// ```
/// use envmap::{CellFrame, CellWalk};
/// use hyplan_core::Point2;
/// let frame = CellFrame::new(Point2::origin(), 1.0, 4, 4);
/// let walk = CellWalk::new(&frame, Point2::new(0.5, 0.5), Point2::new(2.5, 1.5));
/// assert_eq!(walk.steps(), 3);
/// let cells: Vec<_> = walk.collect();
/// assert_eq!(cells, vec![(0, 0), (1, 0), (1, 1), (2, 1)]);
/// ```
#[derive(Debug, Clone)]
pub struct CellWalk {
    i: i64,
    j: i64,
    si: i64,
    sj: i64,
    t_x: f64,
    t_y: f64,
    t_dx: f64,
    t_dy: f64,
    end: (i64, i64),
    steps: u64,
    left: u64,
}

impl CellWalk {
    /// The walk from `a` to `b`, points in the world.
    #[must_use]
    #[inline]
    pub fn new(frame: &CellFrame, a: Point2, b: Point2) -> Self {
        Self::in_cells(frame.coords(a), frame.coords(b))
    }

    /// The walk between two points given in cell units ([`CellFrame::coords`]).
    #[must_use]
    #[inline]
    pub fn in_cells((ax, ay): (f64, f64), (bx, by): (f64, f64)) -> Self {
        let (i, j) = (ax.floor() as i64, ay.floor() as i64);
        let end = (bx.floor() as i64, by.floor() as i64);
        let (dx, dy) = (bx - ax, by - ay);
        let inv = |d: f64| {
            if d != 0.0 {
                (1.0 / d).abs()
            } else {
                f64::INFINITY
            }
        };
        let (t_dx, t_dy) = (inv(dx), inv(dy));
        let first = |a: f64, d: f64, t: f64| {
            if d > 0.0 {
                (a.floor() + 1.0 - a) * t
            } else if d < 0.0 {
                (a - a.floor()) * t
            } else {
                f64::INFINITY
            }
        };
        let steps = (end.0 - i).unsigned_abs() + (end.1 - j).unsigned_abs();
        Self {
            i,
            j,
            si: dx.signum() as i64,
            sj: dy.signum() as i64,
            t_x: first(ax, dx, t_dx),
            t_y: first(ay, dy, t_dy),
            t_dx,
            t_dy,
            end,
            steps,
            left: steps + 1,
        }
    }

    /// Cell moves from the first cell to the last (one less than the cells visited).
    #[must_use]
    #[inline]
    pub const fn steps(&self) -> u64 {
        self.steps
    }

    /// The cell the walk is in: the next one it yields (after all the cells, one step
    /// past the last).
    #[must_use]
    #[inline]
    pub const fn cell(&self) -> (i64, i64) {
        (self.i, self.j)
    }

    /// The cell holding the end point (where the walk ends, barring rounding).
    #[must_use]
    #[inline]
    pub const fn end_cell(&self) -> (i64, i64) {
        self.end
    }
}

impl Iterator for CellWalk {
    type Item = (i64, i64);

    #[inline]
    fn next(&mut self) -> Option<(i64, i64)> {
        if self.left == 0 {
            return None;
        }
        let cell = (self.i, self.j);
        self.left -= 1;
        // Written as selects: which axis steps next is a coin toss for the branch
        // predictor. The step after the last cell is harmless (see `cell`).
        let step_x = self.t_x < self.t_y;
        self.i += if step_x { self.si } else { 0 };
        self.j += if step_x { 0 } else { self.sj };
        self.t_x = if step_x {
            self.t_x + self.t_dx
        } else {
            self.t_x
        };
        self.t_y = if step_x {
            self.t_y
        } else {
            self.t_y + self.t_dy
        };
        Some(cell)
    }

    #[inline]
    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = usize::try_from(self.left).unwrap_or(usize::MAX);
        (n, Some(n))
    }
}
