//! The baseline: classic nearest-frontier exploration (Yamauchi 1997). Frontier cells are
//! free cells of the built map with an unknown 4-neighbour; they are grouped into
//! 8-connected clusters; the robot goes to the cluster whose closest cell is the fewest
//! costmap steps away, through cells its centre may occupy (free or unknown, outside the
//! inscribed radius).
//!
//! Choices: distances are breadth-first steps on the 8-connected costmap grid (every step
//! counts one cell, diagonal or not): enough to rank clusters, no heavier than the map;
//! clusters of fewer than `min_cells` cells are ignored (laser speckle).

use envmap::{
    Connectivity, INSCRIBED_INFLATED_OBSTACLE, Mask, clusters, nearest_passable, steps_from,
};
use hyplan_core::Point2;

use crate::costmap::Costmap;
use crate::mapping::{FREE, OccupancyGrid, UNKNOWN};

/// Free cells with an unknown 4-neighbour, row-major order.
#[must_use]
pub fn frontier_cells(map: &OccupancyGrid) -> Vec<(usize, usize)> {
    let (w, h) = (map.width(), map.height());
    let v = map.ros_values();
    // Whole-row passes (no per-cell branches): whether a cell has an unknown 4-neighbour.
    let unknown: Vec<u8> = v.iter().map(|&x| u8::from(x == UNKNOWN)).collect();
    let mut near = vec![0u8; w * h];
    for (row, unk) in near.chunks_exact_mut(w).zip(unknown.chunks_exact(w)) {
        for (n, &u) in row[1..].iter_mut().zip(&unk[..w - 1]) {
            *n |= u;
        }
        for (n, &u) in row[..w - 1].iter_mut().zip(&unk[1..]) {
            *n |= u;
        }
    }
    for (n, &u) in near[w..].iter_mut().zip(&unknown[..w * (h - 1)]) {
        *n |= u;
    }
    for (n, &u) in near[..w * (h - 1)].iter_mut().zip(&unknown[w..]) {
        *n |= u;
    }
    v.iter()
        .zip(&near)
        .enumerate()
        .filter(|&(_, (&x, &n))| x == FREE && n != 0)
        .map(|(k, _)| (k % w, k / w))
        .collect()
}

/// The frontier cells of `map` in 8-connected clusters (each in discovery order, clusters
/// ordered by their first cell).
#[must_use]
pub fn frontier_clusters(map: &OccupancyGrid) -> Vec<Vec<(usize, usize)>> {
    let cells = frontier_cells(map);
    let mut is_frontier = Mask::new(map.width(), map.height());
    for &(i, j) in &cells {
        is_frontier.set(i, j, true);
    }
    clusters(&is_frontier, cells, Connectivity::Eight)
}

/// Breadth-first steps from `from` over the costmap cells below the inscribed cost
/// (`u32::MAX` where unreachable); the start cell is always entered, or, when it is at
/// the inscribed cost or above, the nearest cell below it within the planner's start
/// slack (else a robot whose centre is a little too near an obstacle on the costmap
/// would find every cell unreachable).
#[must_use]
pub fn costmap_steps(costmap: &Costmap, from: Point2) -> Vec<u32> {
    let (w, h) = (costmap.map.width(), costmap.map.height());
    let Some(cell) = costmap.map.world_to_cell(from) else {
        return vec![u32::MAX; w * h];
    };
    let open = costmap
        .costs
        .iter()
        .map(|&c| c < INSCRIBED_INFLATED_OBSTACLE)
        .collect();
    let open = Mask::from_cells(w, h, open).expect("a cost per cell");
    let rings = crate::planner::start_rings(costmap.map.resolution());
    let start = nearest_passable((w, h), cell, rings, |i, j| open.get(i, j)).unwrap_or(cell);
    steps_from(&open, start, Connectivity::Eight)
}

/// The travel to `target` on `costmap`, m: over the reachable cells within `radius` of
/// it, the least of [`costmap_steps`]' `steps` times the cell side plus the straight line
/// on to the target; `None` when no reachable cell is that near.
///
/// ```
/// use hyplan_core::{Bounds, Point2};
/// use sim::{CostmapBuilder, CostmapParams, StaticWorld, costmap_steps, travel};
/// let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(4.0, 4.0));
/// let builder = CostmapBuilder::new(bounds, &StaticWorld::default(), CostmapParams::default(), 0.18);
/// let costmap = builder.build(None, &[]);
/// let steps = costmap_steps(&costmap, Point2::new(1.0, 1.0));
/// let t = travel(&costmap, &steps, Point2::new(3.0, 1.0), 0.5).unwrap();
/// assert!((t - 2.0).abs() < 0.1);
/// ```
#[must_use]
pub fn travel(costmap: &Costmap, steps: &[u32], target: Point2, radius: f64) -> Option<f64> {
    let map = &costmap.map;
    let frame = map.frame();
    let res = map.resolution();
    let mut best: Option<f64> = None;
    for j in frame.rows(target.y - radius, target.y + radius) {
        for i in frame.columns(target.x - radius, target.x + radius) {
            let s = steps[j * frame.width + i];
            let d = (map.cell_center(i, j) - target).norm();
            if s == u32::MAX || d > radius {
                continue;
            }
            let t = f64::from(s) * res + d;
            if best.is_none_or(|b| t < b) {
                best = Some(t);
            }
        }
    }
    best
}

/// The goal of nearest-frontier exploration: the centre of the reachable frontier cell
/// closest to `robot` (in costmap steps) among clusters of at least `min_cells` cells,
/// skipping cells for which `skip` holds (blacklisted goals); `None` when there is none.
#[must_use]
pub fn nearest_frontier(
    map: &OccupancyGrid,
    costmap: &Costmap,
    robot: Point2,
    min_cells: usize,
    skip: impl Fn(Point2) -> bool,
) -> Option<Point2> {
    let steps = costmap_steps(costmap, robot);
    let frame = costmap.map.frame();
    let mut best: Option<(u32, Point2)> = None;
    for cluster in frontier_clusters(map) {
        if cluster.len() < min_cells {
            continue;
        }
        for (i, j) in cluster {
            let p = map.cell_center(i, j);
            let Some(d) = frame.index_of(p).map(|k| steps[k]) else {
                continue;
            };
            if d != u32::MAX && best.is_none_or(|(bd, _)| d < bd) && !skip(p) {
                best = Some((d, p));
            }
        }
    }
    best.map(|(_, p)| p)
}
