//! Pieces the four planners share beyond `sampling`'s toolkit (the tree, the run frame,
//! steer, sampling, the counted collision checker, branches): the goal join, zone
//! queries, grid A* and path assembly.

use envmap::GridMap;
use hyplan_core::{Goal, Point2, Workspace, Zone};
use sampling::{CountingChecker, GrowTree};
use search::{Connectivity, GridOptions};

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

/// The raw path of a tree search: the branch from the root to `leaf`, then `end` (the
/// points after it to the goal), without consecutive duplicates.
pub(crate) fn branch_to_goal(
    tree: &GrowTree,
    leaf: usize,
    end: impl IntoIterator<Item = Point2>,
) -> Vec<Point2> {
    let mut path = tree.branch(leaf);
    path.extend(end);
    dedup(&mut path);
    path
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
        match GridMap::try_of_workspace(ws) {
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
            Self::Grid(map) => map.segment_in_safe_zone(a, b),
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
            Self::Grid(map) => map.risk_length(a, b),
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

#[cfg(test)]
mod tests {
    use super::*;

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
