//! A tiny exact grid world for the property tests: envmap's grid map, independent of
//! this crate.

use envmap::GridMap;
use hyplan_core::{Point2, Workspace, Zone};
use proptest::prelude::*;

/// A grid of unit cells, cell (i, j) covering [i, i + 1] x [j, j + 1], origin at (0, 0).
#[derive(Debug, Clone)]
pub struct Grid {
    map: GridMap,
}

impl Grid {
    /// A `w x h` grid with the cells `blocked[j * w + i]` blocked.
    pub fn new(w: usize, h: usize, blocked: &[bool]) -> Self {
        let zones = blocked
            .iter()
            .map(|&b| if b { Zone::Forbidden } else { Zone::Free })
            .collect();
        let map = GridMap::from_zones(w, h, 1.0, Point2::origin(), zones).unwrap();
        Self { map }
    }

    /// Whether cell (i, j) is blocked or outside the grid.
    pub fn is_blocked(&self, i: i64, j: i64) -> bool {
        i < 0 || j < 0 || !self.map.cell_free(i as usize, j as usize)
    }

    /// Whether `p` lies in a blocked cell (closed squares: boundaries count as blocked) or
    /// outside the grid.
    pub fn point_blocked(&self, p: Point2) -> bool {
        !self.map.is_free(p)
    }

    /// Exact: the closed segment misses every closed blocked square and stays inside the
    /// grid.
    pub fn segment_free(&self, a: Point2, b: Point2) -> bool {
        self.map.segment_free(a, b)
    }

    /// A wiggly free path between two free cell centres: a randomised depth-first search on
    /// the 4-connected free cells (so every segment joins two adjacent free cells).
    pub fn dfs_path(
        &self,
        start: (usize, usize),
        goal: (usize, usize),
        seed: u64,
    ) -> Option<Vec<Point2>> {
        let mut rng = seed | 1;
        let mut next = move || {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            rng
        };
        let (w, h) = (self.map.width(), self.map.height());
        let idx = |c: (usize, usize)| c.1 * w + c.0;
        if !self.map.cell_free(start.0, start.1) || !self.map.cell_free(goal.0, goal.1) {
            return None;
        }
        let mut seen = vec![false; w * h];
        let mut stack = vec![start];
        seen[idx(start)] = true;
        while let Some(&c) = stack.last() {
            if c == goal {
                return Some(
                    stack
                        .iter()
                        .map(|&(i, j)| Point2::new(i as f64 + 0.5, j as f64 + 0.5))
                        .collect(),
                );
            }
            let mut nb: Vec<(usize, usize)> = [(1i64, 0i64), (-1, 0), (0, 1), (0, -1)]
                .iter()
                .map(|&(dx, dy)| (c.0 as i64 + dx, c.1 as i64 + dy))
                .filter(|&(x, y)| !self.is_blocked(x, y))
                .map(|(x, y)| (x as usize, y as usize))
                .filter(|&n| !seen[idx(n)])
                .collect();
            if nb.is_empty() {
                stack.pop();
                continue;
            }
            let k = (next() % nb.len() as u64) as usize;
            let n = nb.swap_remove(k);
            seen[idx(n)] = true;
            stack.push(n);
        }
        None
    }
}

/// A random grid (about `density` blocked) with a free DFS path between two corners.
pub fn grid_and_path() -> impl Strategy<Value = (Grid, Vec<Point2>)> {
    (
        6usize..16,
        6usize..16,
        0.0f64..0.35,
        any::<u64>(),
        any::<u64>(),
    )
        .prop_filter_map(
            "no path between the corners",
            |(w, h, density, cells_seed, dfs_seed)| {
                let mut rng = cells_seed | 1;
                let mut blocked: Vec<bool> = (0..w * h)
                    .map(|_| {
                        rng ^= rng << 13;
                        rng ^= rng >> 7;
                        rng ^= rng << 17;
                        (rng % 10_000) as f64 / 10_000.0 < density
                    })
                    .collect();
                blocked[0] = false;
                blocked[w * h - 1] = false;
                let g = Grid::new(w, h, &blocked);
                let path = g.dfs_path((0, 0), (w - 1, h - 1), dfs_seed)?;
                Some((g, path))
            },
        )
}

#[test]
fn oracle_sanity() {
    let mut blocked = vec![false; 9];
    blocked[4] = true; // the centre cell [1, 2] x [1, 2]
    let g = Grid::new(3, 3, &blocked);
    assert!(g.segment_free(Point2::new(0.5, 0.5), Point2::new(2.5, 0.5)));
    assert!(!g.segment_free(Point2::new(0.5, 0.5), Point2::new(2.5, 2.5)));
    // Touching the corner (1, 1) counts as a collision.
    assert!(!g.segment_free(Point2::new(0.0, 2.0), Point2::new(2.0, 0.0)));
    assert!(g.segment_free(Point2::new(0.0, 1.9), Point2::new(0.9, 1.0)));
    assert!(g.point_blocked(Point2::new(1.0, 1.5)));
    assert!(!g.point_blocked(Point2::new(0.5, 1.5)));
}
