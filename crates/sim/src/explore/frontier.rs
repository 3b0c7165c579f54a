//! The baseline: classic nearest-frontier exploration (Yamauchi 1997). Frontier cells are
//! free cells of the built map with an unknown 4-neighbour; they are grouped into
//! 8-connected clusters; the robot goes to the cluster whose closest cell is the fewest
//! costmap steps away, through cells its centre may occupy (free or unknown, outside the
//! inscribed radius).
//!
//! Choices: distances are breadth-first steps on the 8-connected costmap grid (every step
//! counts one cell, diagonal or not): enough to rank clusters, no heavier than the map;
//! clusters of fewer than `min_cells` cells are ignored (laser speckle).

use envmap::INSCRIBED_INFLATED_OBSTACLE;
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
    let w = map.width();
    let mut is_frontier = vec![false; w * map.height()];
    for &(i, j) in &cells {
        is_frontier[j * w + i] = true;
    }
    let mut seen = vec![false; is_frontier.len()];
    let mut clusters = Vec::new();
    for &(i, j) in &cells {
        if seen[j * w + i] {
            continue;
        }
        seen[j * w + i] = true;
        let mut cluster = vec![(i, j)];
        let mut k = 0;
        while k < cluster.len() {
            let (ci, cj) = cluster[k];
            k += 1;
            for dj in -1i64..=1 {
                for di in -1i64..=1 {
                    let (a, b) = (ci as i64 + di, cj as i64 + dj);
                    if a < 0 || b < 0 || a as usize >= w || b as usize >= map.height() {
                        continue;
                    }
                    let n = b as usize * w + a as usize;
                    if is_frontier[n] && !seen[n] {
                        seen[n] = true;
                        cluster.push((a as usize, b as usize));
                    }
                }
            }
        }
        clusters.push(cluster);
    }
    clusters
}

/// Breadth-first steps from `from` over the costmap cells below the inscribed cost
/// (`u32::MAX` where unreachable); the start cell is always entered, or, when it is at
/// the inscribed cost or above, the nearest cell below it within 5 cells (the planner's
/// rule).
#[must_use]
pub fn costmap_steps(costmap: &Costmap, from: Point2) -> Vec<u32> {
    let (w, h) = (costmap.map.width(), costmap.map.height());
    let b = costmap.map.bounds();
    let res = costmap.map.resolution();
    let mut dist = vec![u32::MAX; w * h];
    let u = ((from.x - b.min.x) / res).floor();
    let v = ((from.y - b.min.y) / res).floor();
    if !(u >= 0.0 && v >= 0.0 && (u as usize) < w && (v as usize) < h) {
        return dist;
    }
    let (u, v) = (u as usize, v as usize);
    let passable = |i: usize, j: usize| costmap.costs[j * w + i] < INSCRIBED_INFLATED_OBSTACLE;
    // As the planner does: a robot on an inscribed cell (its centre a little too near an
    // obstacle on the coarse costmap) starts from the nearest passable cell within 5
    // cells, else every cell would look unreachable.
    let mut start = v * w + u;
    if !passable(u, v) {
        let ring = (1..=5i64).find_map(|r| {
            let mut best: Option<(i64, usize)> = None;
            for dj in -r..=r {
                for di in -r..=r {
                    let (i, j) = (u as i64 + di, v as i64 + dj);
                    if di.abs().max(dj.abs()) != r
                        || i < 0
                        || j < 0
                        || i as usize >= w
                        || j as usize >= h
                        || !passable(i as usize, j as usize)
                    {
                        continue;
                    }
                    let d = di * di + dj * dj;
                    if best.is_none_or(|b| d < b.0) {
                        best = Some((d, j as usize * w + i as usize));
                    }
                }
            }
            best.map(|(_, c)| c)
        });
        if let Some(c) = ring {
            start = c;
        }
    }
    dist[start] = 0;
    // Breadth-first distances do not depend on the order neighbours are visited in: a
    // plain vector is the queue, and cells off the border skip the bounds tests.
    let open: Vec<bool> = costmap
        .costs
        .iter()
        .map(|&c| c < INSCRIBED_INFLATED_OBSTACLE)
        .collect();
    let offsets = [
        -(w as isize) - 1,
        -(w as isize),
        -(w as isize) + 1,
        -1,
        1,
        w as isize - 1,
        w as isize,
        w as isize + 1,
    ];
    let mut queue = vec![start];
    let mut head = 0;
    while head < queue.len() {
        let c = queue[head];
        head += 1;
        let next = dist[c] + 1;
        let (ci, cj) = (c % w, c / w);
        if ci > 0 && cj > 0 && ci + 1 < w && cj + 1 < h {
            for o in offsets {
                let n = c.wrapping_add_signed(o);
                if dist[n] == u32::MAX && open[n] {
                    dist[n] = next;
                    queue.push(n);
                }
            }
        } else {
            for dj in -1i64..=1 {
                for di in -1i64..=1 {
                    let (a, bb) = (ci as i64 + di, cj as i64 + dj);
                    if a < 0 || bb < 0 || a as usize >= w || bb as usize >= h {
                        continue;
                    }
                    let n = bb as usize * w + a as usize;
                    if dist[n] == u32::MAX && open[n] {
                        dist[n] = next;
                        queue.push(n);
                    }
                }
            }
        }
    }
    dist
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
    let b = costmap.map.bounds();
    let cres = costmap.map.resolution();
    let cw = costmap.map.width();
    let mut best: Option<(u32, Point2)> = None;
    for cluster in frontier_clusters(map) {
        if cluster.len() < min_cells {
            continue;
        }
        for (i, j) in cluster {
            let p = map.cell_center(i, j);
            let u = ((p.x - b.min.x) / cres) as usize;
            let v = ((p.y - b.min.y) / cres) as usize;
            let Some(&d) = steps.get(v * cw + u) else {
                continue;
            };
            if d != u32::MAX && best.is_none_or(|(bd, _)| d < bd) && !skip(p) {
                best = Some((d, p));
            }
        }
    }
    best.map(|(_, p)| p)
}
