//! Pieces the four planners share beyond `sampling`'s toolkit (steer, uniform sampling,
//! the counted collision checker, step/budget validation, branches): the grid downcast,
//! the goal join, zone queries and path assembly.

use envmap::GridMap;
use hyplan_core::{Goal, PlanError, Point2, Workspace, Zone};
use sampling::CountingChecker;
use search::{Connectivity, GridOptions};

/// The grid map behind a workspace, or a typed error naming `workspace`.
pub(crate) fn as_grid<W: Workspace + ?Sized>(ws: &W) -> Result<&GridMap, PlanError> {
    ws.as_any()
        .and_then(|a| a.downcast_ref::<GridMap>())
        .ok_or(PlanError::InvalidParameter {
            name: "workspace",
            value: "not an envmap::GridMap".into(),
            reason: "this planner runs grid A* searches and needs a grid map",
        })
}

/// How a node that came within the planner's goal radius finishes the path.
///
/// Returns the goal centre when the last segment to it is free (the path then ends exactly
/// at the goal), `Some(None)` when the node itself already satisfies the query's goal (a
/// disc containing it), and `None` when the node cannot finish the path.
pub(crate) fn finish_at_goal<W: Workspace + ?Sized>(
    checker: &mut CountingChecker<'_, W>,
    goal: &Goal,
    node: Point2,
) -> Option<Option<Point2>> {
    let g = goal.center();
    if node == g {
        return Some(None);
    }
    if checker.segment_free(node, g) {
        Some(Some(g))
    } else if goal.contains(node) {
        Some(None)
    } else {
        None
    }
}

/// Finishes a path laid along grid cells: `out` runs from a continuous anchor, through
/// cell centres, to another continuous anchor, and `cells` are the A* cells it follows.
/// Where a joint to an anchor is not free, the anchor's own cell centre (`cells`' first
/// or last) is put in between; then consecutive duplicates are dropped and every segment
/// is checked. Returns the points after the first anchor, or `None` if a segment fails.
pub(crate) fn anchor_cell_path<W: Workspace + ?Sized>(
    map: &GridMap,
    checker: &mut CountingChecker<'_, W>,
    mut out: Vec<Point2>,
    cells: &[(usize, usize)],
) -> Option<Vec<Point2>> {
    let centre = |c: (usize, usize)| map.cell_center(c.0, c.1);
    if !checker.segment_free(out[0], out[1]) {
        out.insert(1, centre(cells[0]));
    }
    let n = out.len();
    if !checker.segment_free(out[n - 2], out[n - 1]) {
        out.insert(n - 1, centre(cells[cells.len() - 1]));
    }
    dedup(&mut out);
    out.windows(2)
        .all(|w| checker.segment_free(w[0], w[1]))
        .then(|| out.split_off(1))
}

/// Drops consecutive exact duplicates.
pub(crate) fn dedup(path: &mut Vec<Point2>) {
    path.dedup_by(|a, b| a == b);
}

/// Zone queries used by the safety cost of seed 003: exact on a grid map, sampled on any
/// other workspace.
pub(crate) enum ZoneView<'a, W: ?Sized> {
    /// Exact: cell by cell.
    Grid(&'a GridMap),
    /// Sampled along segments every `spacing` world units through [`Workspace::zone`].
    Sampled(&'a W, f64),
}

impl<'a, W: Workspace + ?Sized> ZoneView<'a, W> {
    /// The exact view for a grid map, else the sampled one with `spacing`.
    pub(crate) fn new(ws: &'a W, spacing: f64) -> Self {
        match ws.as_any().and_then(|a| a.downcast_ref::<GridMap>()) {
            Some(map) => Self::Grid(map),
            None => Self::Sampled(ws, spacing),
        }
    }

    /// The zone of a point.
    pub(crate) fn zone(&self, p: Point2) -> Zone {
        match self {
            Self::Grid(map) => map.zone_at(p),
            Self::Sampled(ws, _) => ws.zone(p),
        }
    }

    /// Whether the closed segment touches only `Free` cells (neither Risk nor Forbidden)
    /// and both ends are inside the bounds.
    pub(crate) fn safe_segment(&self, a: Point2, b: Point2) -> bool {
        match self {
            Self::Grid(map) => {
                let bounds = map.bounds();
                bounds.contains(a)
                    && bounds.contains(b)
                    && map.segment_cells(a, b, |i, j| map.cell_zone(i, j) == Zone::Free)
            }
            Self::Sampled(ws, spacing) => {
                if !ws.segment_free(a, b) {
                    return false;
                }
                let n = samples(a, b, *spacing);
                (0..=n).all(|k| ws.zone(a + (b - a) * (k as f64 / n as f64)) == Zone::Free)
            }
        }
    }

    /// Length of the segment inside the Risk zone, world units.
    pub(crate) fn risk_length(&self, a: Point2, b: Point2) -> f64 {
        match self {
            Self::Grid(map) => {
                let mut len = 0.0;
                map.segment_cells(a, b, |i, j| {
                    if map.cell_zone(i, j) == Zone::Risk {
                        len += clipped_length(map, i, j, a, b);
                    }
                    true
                });
                len.min((b - a).norm())
            }
            Self::Sampled(ws, spacing) => {
                let n = samples(a, b, *spacing);
                let piece = (b - a).norm() / n as f64;
                (0..n)
                    .filter(|&k| ws.zone(a + (b - a) * ((k as f64 + 0.5) / n as f64)) == Zone::Risk)
                    .count() as f64
                    * piece
            }
        }
    }
}

/// Number of pieces of at most `spacing` on segment `a`-`b` (at least 1).
fn samples(a: Point2, b: Point2, spacing: f64) -> usize {
    ((b - a).norm() / spacing).ceil().max(1.0) as usize
}

/// Length of segment `a`-`b` inside the closed square of cell `(i, j)` (Liang-Barsky).
fn clipped_length(map: &GridMap, i: usize, j: usize, a: Point2, b: Point2) -> f64 {
    let r = map.resolution();
    let o = map.origin();
    let (x0, y0) = (o.x + i as f64 * r, o.y + j as f64 * r);
    let (x1, y1) = (x0 + r, y0 + r);
    let d = b - a;
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-d.x, a.x - x0),
        (d.x, x1 - a.x),
        (-d.y, a.y - y0),
        (d.y, y1 - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return 0.0;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    if t1 > t0 { (t1 - t0) * d.norm() } else { 0.0 }
}

/// Distance from `p` to the nearest cell of `map` that blocks motion, if one lies within
/// `radius` (world units); `None` when none does. Exact point-to-square distances over
/// the cells of the disc's bounding box.
pub(crate) fn blocked_within(map: &GridMap, p: Point2, radius: f64) -> Option<f64> {
    let r = map.resolution();
    let o = map.origin();
    let (u, v) = ((p.x - o.x) / r, (p.y - o.y) / r);
    let k = radius / r;
    let i0 = (u - k).floor().max(0.0) as usize;
    let j0 = (v - k).floor().max(0.0) as usize;
    let i1 = ((u + k).floor().max(0.0) as usize).min(map.width().saturating_sub(1));
    let j1 = ((v + k).floor().max(0.0) as usize).min(map.height().saturating_sub(1));
    let mut best: Option<f64> = None;
    for j in j0..=j1 {
        for i in i0..=i1 {
            if map.cell_free(i, j) {
                continue;
            }
            let dx = (i as f64 - u).max(0.0).max(u - (i as f64 + 1.0));
            let dy = (j as f64 - v).max(0.0).max(v - (j as f64 + 1.0));
            let d = dx.hypot(dy) * r;
            if d < radius && best.is_none_or(|b| d < b) {
                best = Some(d);
            }
        }
    }
    best
}

/// Moves of an 8-connected grid: offset and cost; the first four are the straight ones.
const MOVES: [(isize, isize, f64); 8] = [
    (1, 0, 1.0),
    (-1, 0, 1.0),
    (0, 1, 1.0),
    (0, -1, 1.0),
    (1, 1, std::f64::consts::SQRT_2),
    (-1, 1, std::f64::consts::SQRT_2),
    (1, -1, std::f64::consts::SQRT_2),
    (-1, -1, std::f64::consts::SQRT_2),
];

/// Grid A* from cell `from` to cell `to` on the map's passable cells (its
/// `blocked_from`), with octile costs and the Euclidean heuristic (seed 002), that gives
/// up after
/// `max_visited` expanded nodes: the cells from `from` to `to`, or `None`; and the number
/// of nodes expanded.
///
/// Runs the generic [`search::astar`], whose memory grows with the nodes it touches, not
/// with the map: a bounded sub-search touches a few hundred cells, where a flat-array
/// `GridSearch` would first build 14 bytes per cell of the whole map. The success test runs
/// on every node taken from the open list before it is expanded: it stops at the goal, or once `max_visited` nodes have been expanded.
pub(crate) fn grid_astar(
    map: &GridMap,
    from: (usize, usize),
    to: (usize, usize),
    options: GridOptions,
    max_visited: usize,
) -> (Option<Vec<(usize, usize)>>, u64) {
    let passable = |i: isize, j: isize| i >= 0 && j >= 0 && map.cell_free(i as usize, j as usize);
    let moves = match options.connectivity {
        Connectivity::Four => &MOVES[..4],
        Connectivity::Eight => &MOVES[..],
    };
    let cut = options.corner_cutting;
    let mut popped = 0_usize;
    let found = search::astar(
        &from,
        |&(i, j)| {
            let (i, j) = (i as isize, j as isize);
            moves
                .iter()
                .filter(move |&&(di, dj, _)| {
                    if !passable(i + di, j + dj) {
                        return false;
                    }
                    if di == 0 || dj == 0 {
                        return true;
                    }
                    let (a, b) = (passable(i + di, j), passable(i, j + dj));
                    if cut { a || b } else { a && b }
                })
                .map(move |&(di, dj, c)| (((i + di) as usize, (j + dj) as usize), c))
                .collect::<Vec<_>>()
        },
        |&(i, j)| (i.abs_diff(to.0) as f64).hypot(j.abs_diff(to.1) as f64),
        |&n| {
            popped += 1;
            n == to || popped > max_visited
        },
    );
    match found {
        Ok(r) => {
            let ok = r.path.last() == Some(&to);
            (ok.then_some(r.path), r.stats.expansions)
        }
        Err(e) => (None, e.stats().expansions),
    }
}

/// `is_free` through a [`CountingChecker`], answered by one cell lookup when the
/// workspace is a [`GridMap`] and the point lies strictly inside one cell (the usual case
/// for a random sample), else by the workspace itself. Gives exactly `ws.is_free(p)` and
/// counts one check either way; it skips the general segment sweep that a point query
/// goes through in `GridMap::segment_free_cells`.
pub(crate) struct PointChecker<'a> {
    /// The grid, its bounds, origin, 1 / resolution, and width and height in cells.
    grid: Option<(&'a GridMap, hyplan_core::Bounds, Point2, f64, f64, f64)>,
}

impl<'a> PointChecker<'a> {
    /// The checker for `ws`: the direct lookup when it is a grid map.
    pub(crate) fn new<W: Workspace + ?Sized>(ws: &'a W) -> Self {
        // Cell indices go through `i32` (a cheaper conversion than to `usize`).
        let grid = ws
            .as_any()
            .and_then(|a| a.downcast_ref::<GridMap>())
            .filter(|map| map.width() < i32::MAX as usize && map.height() < i32::MAX as usize)
            .map(|map| {
                (
                    map,
                    map.bounds(),
                    map.origin(),
                    1.0 / map.resolution(),
                    map.width() as f64,
                    map.height() as f64,
                )
            });
        Self { grid }
    }

    /// Whether `p` is free, exactly as `checker.is_free(p)`, counted the same way: the
    /// direct lookup answers only for points more than 1e-6 cells from every cell edge.
    #[inline]
    pub(crate) fn is_free<W: Workspace + ?Sized>(
        &self,
        checker: &mut CountingChecker<'_, W>,
        p: Point2,
    ) -> bool {
        if let Some((map, bounds, o, inv, w, h)) = self.grid {
            // As `GridMap::segment_free_cells(p, p)`: inside the closed bounds, then the
            // cells whose closed squares contain p, in the same cell coordinates. A
            // coordinate that is not a whole number lies in one column (row) only.
            if !bounds.contains(p) {
                checker.checks += 1;
                return false;
            }
            let (u, v) = ((p.x - o.x) * inv, (p.y - o.y) * inv);
            if u >= 0.0 && v >= 0.0 && u < w && v < h {
                let (i, j) = (u as i32, v as i32);
                // Clear of the cell's edges by far more than the sweep's touch margin
                // (envmap::TOUCH_TOLERANCE) and the rounding of `* inv`; closer points
                // go through the sweep, which treats cells as closed.
                let inside =
                    |t: f64, k: i32| t - f64::from(k) > 1e-6 && f64::from(k) + 1.0 - t > 1e-6;
                if inside(u, i) && inside(v, j) {
                    checker.checks += 1;
                    return map.cell_free(i as usize, j as usize);
                }
            }
        }
        checker.is_free(p)
    }

    /// Whether the segment `a`-`b` is free, exactly as `checker.segment_free(a, b)` and
    /// counted as one check. On a grid map, when `b` lies well inside a blocked cell
    /// (each cell coordinate more than 1e-6 from a whole number, far beyond the sweep's
    /// rounding) the answer is `false` without the sweep: the sweep meets the cell of its
    /// end point `b` and stops at the first blocked cell it meets.
    #[inline]
    pub(crate) fn segment_free<W: Workspace + ?Sized>(
        &self,
        checker: &mut CountingChecker<'_, W>,
        a: Point2,
        b: Point2,
    ) -> bool {
        if let Some((map, bounds, o, inv, w, h)) = self.grid
            && bounds.contains(b)
        {
            let (u, v) = ((b.x - o.x) * inv, (b.y - o.y) * inv);
            if u >= 0.0 && v >= 0.0 && u < w && v < h {
                let (i, j) = (u as i32, v as i32);
                let inside =
                    |t: f64, k: i32| t - f64::from(k) > 1e-6 && f64::from(k) + 1.0 - t > 1e-6;
                if inside(u, i) && inside(v, j) && !map.cell_free(i as usize, j as usize) {
                    checker.checks += 1;
                    return false;
                }
            }
        }
        checker.segment_free(a, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipped_length_of_a_diagonal() {
        let map = GridMap::filled(4, 4, Zone::Free).unwrap();
        let (a, b) = (Point2::new(0.0, 0.0), Point2::new(2.0, 2.0));
        let l = clipped_length(&map, 0, 0, a, b);
        assert!((l - 2f64.sqrt()).abs() < 1e-12);
        assert_eq!(clipped_length(&map, 3, 0, a, b), 0.0);
    }

    #[test]
    fn risk_length_counts_risk_cells_only() {
        let map = GridMap::from_ascii("....\n.~~.\n....").unwrap();
        let view: ZoneView<'_, GridMap> = ZoneView::new(&map, 0.1);
        let l = view.risk_length(Point2::new(0.5, 1.5), Point2::new(3.5, 1.5));
        assert!((l - 2.0).abs() < 1e-12, "{l}");
        assert!(!view.safe_segment(Point2::new(0.5, 1.5), Point2::new(3.5, 1.5)));
        assert!(view.safe_segment(Point2::new(0.5, 0.5), Point2::new(3.5, 0.5)));
    }

    #[test]
    fn blocked_within_finds_the_nearest_cell() {
        let map = GridMap::from_ascii(".....\n....#\n.....").unwrap();
        let d = blocked_within(&map, Point2::new(2.5, 1.5), 5.0).unwrap();
        assert!((d - 1.5).abs() < 1e-12);
        assert!(blocked_within(&map, Point2::new(0.5, 1.5), 2.0).is_none());
    }

    #[test]
    fn grid_astar_gives_up_at_its_limit() {
        let map = GridMap::filled(60, 60, Zone::Free).unwrap();
        let opts = GridOptions::default();
        let (cells, visited) = grid_astar(&map, (0, 0), (50, 0), opts, 10);
        assert!(cells.is_none());
        assert_eq!(visited, 10);
        let (cells, visited) = grid_astar(&map, (0, 0), (50, 0), opts, 150);
        assert_eq!(cells.unwrap().len(), 51);
        assert_eq!(visited, 50);
    }

    #[test]
    fn grid_astar_does_not_cut_corners() {
        let map = GridMap::from_ascii("..\n#.").unwrap();
        // From (0, 1) to (1, 0): the diagonal would cut the corner of (0, 0).
        let (cells, _) = grid_astar(&map, (0, 1), (1, 0), GridOptions::default(), usize::MAX);
        assert_eq!(cells.unwrap(), vec![(0, 1), (1, 1), (1, 0)]);
    }
}
