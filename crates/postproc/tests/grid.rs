//! A tiny exact grid world for the property tests, independent of the crate.

use hyplan_core::Point2;
use proptest::prelude::*;

/// A grid of unit cells, cell (i, j) covering [i, i + 1] x [j, j + 1]; `blocked` row-major.
#[derive(Debug, Clone)]
pub struct Grid {
    pub w: usize,
    pub h: usize,
    pub blocked: Vec<bool>,
}

impl Grid {
    pub fn is_blocked(&self, i: i64, j: i64) -> bool {
        if i < 0 || j < 0 || i >= self.w as i64 || j >= self.h as i64 {
            return true;
        }
        self.blocked[j as usize * self.w + i as usize]
    }

    /// Whether `p` lies in a blocked cell (closed squares: boundaries count as blocked) or
    /// outside the grid.
    pub fn point_blocked(&self, p: Point2) -> bool {
        let (fx, fy) = (p.x.floor() as i64, p.y.floor() as i64);
        // On a boundary the point touches the cells on both sides.
        let xs: Vec<i64> = if p.x == p.x.floor() {
            vec![fx - 1, fx]
        } else {
            vec![fx]
        };
        let ys: Vec<i64> = if p.y == p.y.floor() {
            vec![fy - 1, fy]
        } else {
            vec![fy]
        };
        xs.iter()
            .any(|&i| ys.iter().any(|&j| self.is_blocked(i, j)))
    }

    /// Exact: the closed segment misses every closed blocked square and stays inside the
    /// grid (Liang-Barsky clipping against each blocked cell of the bounding box).
    pub fn segment_free(&self, a: Point2, b: Point2) -> bool {
        let inside =
            |p: Point2| p.x >= 0.0 && p.y >= 0.0 && p.x <= self.w as f64 && p.y <= self.h as f64;
        if !(inside(a) && inside(b)) {
            return false;
        }
        let (x0, x1) = (
            a.x.min(b.x).floor() as i64 - 1,
            a.x.max(b.x).floor() as i64 + 1,
        );
        let (y0, y1) = (
            a.y.min(b.y).floor() as i64 - 1,
            a.y.max(b.y).floor() as i64 + 1,
        );
        for j in y0..=y1 {
            for i in x0..=x1 {
                if i < 0 || j < 0 || i >= self.w as i64 || j >= self.h as i64 {
                    continue;
                }
                if self.is_blocked(i, j) && hits_box(a, b, i as f64, j as f64) {
                    return false;
                }
            }
        }
        true
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
        let idx = |c: (usize, usize)| c.1 * self.w + c.0;
        if self.blocked[idx(start)] || self.blocked[idx(goal)] {
            return None;
        }
        let mut seen = vec![false; self.w * self.h];
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

/// Whether the closed segment a-b meets the closed unit square at (i, j).
fn hits_box(a: Point2, b: Point2, i: f64, j: f64) -> bool {
    let d = b - a;
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-d.x, a.x - i),
        (d.x, i + 1.0 - a.x),
        (-d.y, a.y - j),
        (d.y, j + 1.0 - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    t0 <= t1
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
                let blocked = (0..w * h)
                    .map(|_| {
                        rng ^= rng << 13;
                        rng ^= rng >> 7;
                        rng ^= rng << 17;
                        (rng % 10_000) as f64 / 10_000.0 < density
                    })
                    .collect();
                let mut g = Grid { w, h, blocked };
                g.blocked[0] = false;
                g.blocked[w * h - 1] = false;
                let path = g.dfs_path((0, 0), (w - 1, h - 1), dfs_seed)?;
                Some((g, path))
            },
        )
}

#[test]
fn oracle_sanity() {
    let mut g = Grid {
        w: 3,
        h: 3,
        blocked: vec![false; 9],
    };
    g.blocked[4] = true; // the centre cell [1, 2] x [1, 2]
    assert!(g.segment_free(Point2::new(0.5, 0.5), Point2::new(2.5, 0.5)));
    assert!(!g.segment_free(Point2::new(0.5, 0.5), Point2::new(2.5, 2.5)));
    // Touching the corner (1, 1) counts as a collision.
    assert!(!g.segment_free(Point2::new(0.0, 2.0), Point2::new(2.0, 0.0)));
    assert!(g.segment_free(Point2::new(0.0, 1.9), Point2::new(0.9, 1.0)));
    assert!(g.point_blocked(Point2::new(1.0, 1.5)));
    assert!(!g.point_blocked(Point2::new(0.5, 1.5)));
}
