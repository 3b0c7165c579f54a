//! `Workspace` for `GridMap`: exact cell-level collision queries.

use hyplan_core::{Bounds, Point2, Workspace, Zone};

use crate::GridMap;

impl GridMap {
    /// Visits every cell whose closed square the closed segment `a`-`b` touches, corner
    /// touches included, until `visit` returns `false`; returns whether every visit
    /// returned `true`.
    ///
    /// The segment is swept along its major axis one column (or row) at a time, so the
    /// cost grows with the number of cells crossed, not with the map size. Cells outside
    /// the map are not visited; callers check the end points against the bounds.
    pub fn segment_cells(
        &self,
        a: Point2,
        b: Point2,
        mut visit: impl FnMut(usize, usize) -> bool,
    ) -> bool {
        let inv = 1.0 / self.resolution();
        let o = self.origin();
        let (ua, va) = ((a.x - o.x) * inv, (a.y - o.y) * inv);
        let (ub, vb) = ((b.x - o.x) * inv, (b.y - o.y) * inv);
        let (w, h) = (self.width(), self.height());
        if (ub - ua).abs() >= (vb - va).abs() {
            sweep(ua, va, ub, vb, w, h, &mut visit)
        } else {
            sweep(va, ua, vb, ub, h, w, |r, c| visit(c, r))
        }
    }

    /// Whether every cell the closed segment touches lets motion through, and both end
    /// points lie inside the map.
    ///
    /// Exact at the cell level: a segment that only grazes the corner of a blocked cell is
    /// blocked. This is stricter than OMPL's sampled motion checks, which can cut corners.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::Point2;
    /// let map = GridMap::from_ascii("
    ///     .#
    ///     ..
    /// ")?;
    /// // (0,0) -> (2,2) passes exactly through the corner of the blocked cell (1, 1).
    /// assert!(!map.segment_free_cells(Point2::new(0.0, 0.0), Point2::new(2.0, 2.0)));
    /// assert!(map.segment_free_cells(Point2::new(0.5, 0.5), Point2::new(1.5, 0.5)));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn segment_free_cells(&self, a: Point2, b: Point2) -> bool {
        let bounds = self.bounds();
        bounds.contains(a)
            && bounds.contains(b)
            && self.segment_cells(a, b, |i, j| self.cell_free(i, j))
    }

    /// The most dangerous zone among the cells whose closed squares contain `p`
    /// (`Forbidden` outside the map or for NaN).
    #[must_use]
    pub fn zone_at(&self, p: Point2) -> Zone {
        if !self.bounds().contains(p) {
            return Zone::Forbidden;
        }
        let mut zone = Zone::Free;
        self.segment_cells(p, p, |i, j| {
            zone = zone.max(self.cell_zone(i, j));
            true
        });
        zone
    }
}

/// Sweeps the closed segment (p0, q0)-(p1, q1) along the major axis p, with
/// |p1 - p0| >= |q1 - q0|, visiting (column, row) pairs of the closed unit cells it meets
/// within `[0, np) x [0, nq)`.
fn sweep(
    p0: f64,
    q0: f64,
    p1: f64,
    q1: f64,
    np: usize,
    nq: usize,
    mut visit: impl FnMut(usize, usize) -> bool,
) -> bool {
    let (lo, hi) = (p0.min(p1), p0.max(p1));
    if !(lo.is_finite() && hi.is_finite() && q0.is_finite() && q1.is_finite()) {
        return false;
    }
    let slope = if p1 == p0 { 0.0 } else { (q1 - q0) / (p1 - p0) };
    let q_at = |p: f64| if p1 == p0 { q0 } else { q0 + (p - p0) * slope };
    // Closed strip [c, c+1] meets [lo, hi] iff ceil(lo) - 1 <= c <= floor(hi).
    let c_first = clamp_index(lo.ceil() - 1.0, np);
    let c_last = clamp_index(hi.floor(), np);
    for c in c_first..=c_last {
        let s0 = lo.max(c as f64);
        let s1 = hi.min(c as f64 + 1.0);
        let (qa, qb) = (q_at(s0), q_at(s1));
        let (qlo, qhi) = (qa.min(qb), qa.max(qb));
        for r in clamp_index(qlo.ceil() - 1.0, nq)..=clamp_index(qhi.floor(), nq) {
            if !visit(c, r) {
                return false;
            }
        }
    }
    true
}

/// Clamps a (whole-number) float index to `[0, n - 1]`.
fn clamp_index(x: f64, n: usize) -> usize {
    if x < 0.0 {
        0
    } else if x >= n as f64 {
        n - 1
    } else {
        x as usize
    }
}

impl Workspace for GridMap {
    fn bounds(&self) -> Bounds {
        GridMap::bounds(self)
    }

    fn is_free(&self, p: Point2) -> bool {
        self.segment_free_cells(p, p)
    }

    fn segment_free(&self, a: Point2, b: Point2) -> bool {
        self.segment_free_cells(a, b)
    }

    fn zone(&self, p: Point2) -> Zone {
        self.zone_at(p)
    }

    fn clearance(&self, p: Point2) -> Option<f64> {
        Some(self.clearance_at(p))
    }

    fn disconnection(&self, query: &hyplan_core::Query) -> Option<hyplan_core::NoPathCause> {
        crate::connectivity::disconnection(self, query, crate::connectivity::Moves::Four)
    }

    fn as_any(&self) -> Option<&dyn std::any::Any> {
        Some(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cells(map: &GridMap, a: (f64, f64), b: (f64, f64)) -> Vec<(usize, usize)> {
        let mut v = Vec::new();
        map.segment_cells(Point2::new(a.0, a.1), Point2::new(b.0, b.1), |i, j| {
            v.push((i, j));
            true
        });
        v.sort_unstable();
        v
    }

    #[test]
    fn horizontal_through_centres_touches_one_row() {
        let map = GridMap::filled(5, 5, Zone::Free).unwrap();
        assert_eq!(
            cells(&map, (0.5, 2.5), (3.5, 2.5)),
            vec![(0, 2), (1, 2), (2, 2), (3, 2)]
        );
    }

    #[test]
    fn diagonal_through_corner_touches_the_four_cells() {
        let map = GridMap::filled(5, 5, Zone::Free).unwrap();
        assert_eq!(
            cells(&map, (0.5, 0.5), (1.5, 1.5)),
            vec![(0, 0), (0, 1), (1, 0), (1, 1)]
        );
    }

    #[test]
    fn segment_on_grid_line_touches_both_sides() {
        let map = GridMap::filled(4, 4, Zone::Free).unwrap();
        assert_eq!(
            cells(&map, (0.5, 2.0), (1.5, 2.0)),
            vec![(0, 1), (0, 2), (1, 1), (1, 2)]
        );
    }

    #[test]
    fn point_on_map_border_stays_inside() {
        let map = GridMap::filled(2, 2, Zone::Free).unwrap();
        assert_eq!(cells(&map, (2.0, 2.0), (2.0, 2.0)), vec![(1, 1)]);
        assert!(map.is_free(Point2::new(2.0, 2.0)));
        assert!(!map.is_free(Point2::new(2.0, 2.01)));
    }

    #[test]
    fn steep_segment_sweeps_rows() {
        let map = GridMap::filled(4, 8, Zone::Free).unwrap();
        assert_eq!(
            cells(&map, (0.5, 0.5), (1.5, 6.5)),
            vec![
                (0, 0),
                (0, 1),
                (0, 2),
                (0, 3),
                (1, 3),
                (1, 4),
                (1, 5),
                (1, 6)
            ]
        );
    }

    #[test]
    fn nan_is_never_free() {
        let map = GridMap::filled(2, 2, Zone::Free).unwrap();
        assert!(!map.is_free(Point2::new(f64::NAN, 1.0)));
        assert!(!map.segment_free(Point2::new(0.5, 0.5), Point2::new(f64::NAN, 1.0)));
    }
}
