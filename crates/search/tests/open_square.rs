//! A workspace that is not a grid map, for the grid planners' refusal of it and the other
//! planners' acceptance: shared by `search`'s and `hybrid`'s tests, which include this file.

use hyplan_core::{Bounds, Point2, Workspace};

/// An empty square from the origin to `(side, side)`, world units.
pub struct OpenSquare(pub f64);

impl Workspace for OpenSquare {
    fn bounds(&self) -> Bounds {
        Bounds::new(Point2::new(0.0, 0.0), Point2::new(self.0, self.0))
    }
    fn is_free(&self, p: Point2) -> bool {
        self.bounds().contains(p)
    }
    fn segment_free(&self, a: Point2, b: Point2) -> bool {
        self.is_free(a) && self.is_free(b)
    }
}
