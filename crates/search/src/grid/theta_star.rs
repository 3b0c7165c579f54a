//! Theta*: any-angle paths between cell centres (line-of-sight parents).

use super::engine::*;
use super::*;

impl GridSearch {
    /// Any-angle path from `start` to `goal` by Theta* (Nash, Daniel, Koenig and Felner,
    /// 2007): A* on the grid moves, except that a cell's parent may be any earlier cell in
    /// line of sight, so the path goes straight between cell centres where it can. The
    /// diagonal moves never cut corners, whatever [`GridOptions::corner_cutting`] says.
    ///
    /// Line of sight between two cell centres means that every cell the closed segment
    /// touches (corners included, as [`GridMap::segment_cells`] sees it) is passable, so
    /// every segment of the path passes the map's exact `segment_free`. The heuristic is
    /// the Euclidean distance. Theta* is not guaranteed to find the shortest any-angle
    /// path, and nodes may be re-expanded when their cost drops.
    ///
    /// `map` is the map this search was built from; the line of sight is computed on this
    /// search's own passable cells, in cell coordinates.
    ///
    /// # Errors
    ///
    /// As [`astar`](GridSearch::astar).
    pub fn theta_star(
        &mut self,
        map: &GridMap,
        start: (usize, usize),
        goal: (usize, usize),
    ) -> Result<GridPath, GridSearchError> {
        self.run(Some(map), start, goal, Kind::ThetaStar)
    }

    /// Any-angle path from `start` to `goal` by Lazy Theta* (Nash, Koenig and Tovey,
    /// 2010): Theta* that assumes a new cell sees its predecessor's parent and checks that
    /// line of sight once, when the cell is expanded; where it fails, the cell's parent
    /// becomes its cheapest expanded grid neighbour. One line-of-sight test per expansion
    /// instead of one per neighbour, so it is several times faster on open maps; paths
    /// are as exact as [`theta_star`](GridSearch::theta_star)'s (every parent link is
    /// checked before it is used) and usually of about the same length.
    ///
    /// # Errors
    ///
    /// As [`astar`](GridSearch::astar).
    pub fn lazy_theta_star(
        &mut self,
        map: &GridMap,
        start: (usize, usize),
        goal: (usize, usize),
    ) -> Result<GridPath, GridSearchError> {
        self.run(Some(map), start, goal, Kind::LazyThetaStar)
    }

    /// Starts a Theta* query from `s` on its own nodes (allocated by the first query),
    /// with g = 0.
    pub(super) fn begin_theta(&mut self, s: u32, stats: &mut SearchStats) {
        if self.theta_nodes.len() != self.words.len() {
            let unset = Node {
                g: 0,
                parent: NONE,
                stamp: 0,
            };
            self.theta_nodes = vec![unset; self.words.len()];
            self.theta_generation = 0;
        }
        self.theta_generation += 1;
        if self.theta_generation >= CLOSED {
            for node in &mut self.theta_nodes {
                node.stamp = 0;
            }
            self.theta_generation = 1;
        }
        self.theta_heap.clear();
        self.theta_nodes[s as usize] = Node {
            g: 0f64.to_bits(),
            parent: NONE,
            stamp: self.theta_generation,
        };
        stats.pushes += 1;
        stats.reached = 1;
    }

    /// Padded coordinates `(x, y)` of a padded index (division by `pw` as a multiplication,
    /// exact for every `u32` index: Lemire, Kaser and Kurz 2019).
    #[inline(always)]
    pub(super) fn xy(&self, p: u32) -> (u32, u32) {
        let y = ((u128::from(p) * u128::from(self.magic)) >> 64) as u32;
        (p - y * self.pw as u32, y)
    }

    /// Theta*'s loop (Lazy Theta*'s with `lazy`), on `f64` costs (stored as bits in `g`)
    /// and keys of `f64` bits.
    pub(super) fn theta_search(
        &mut self,
        s0: u32,
        t0: u32,
        lazy: bool,
    ) -> Result<GridPath, GridSearchError> {
        let mut stats = SearchStats::default();
        let (gx, gy) = self.xy(t0);
        let euclid = move |x: u32, y: u32| {
            let dx = f64::from(x.abs_diff(gx));
            let dy = f64::from(y.abs_diff(gy));
            dx.hypot(dy)
        };
        let (sx, sy) = self.xy(s0);
        self.begin_theta(s0, &mut stats);
        self.theta_heap.push(float_key(euclid(sx, sy), 0.0, s0));
        let closed = self.theta_generation | CLOSED;
        let limit = self.limit;
        let mut check_at = limit.next_check(0);
        while let Some(k) = self.theta_heap.pop() {
            let p = k as u32;
            if self.theta_nodes[p as usize].stamp == closed {
                continue;
            }
            self.theta_nodes[p as usize].stamp = closed;
            if lazy {
                self.lazy_set_parent(p);
            }
            let g = f64::from_bits(self.theta_nodes[p as usize].g);
            if p == t0 {
                return Ok(self.trace(t0, g, stats));
            }
            if stats.expansions >= check_at {
                if limit.spent(stats.expansions) {
                    return Err(GridSearchError::LimitReached { stats });
                }
                check_at = limit.next_check(stats.expansions);
            }
            stats.expansions += 1;
            self.theta_expand(p, g, &mut stats, euclid, lazy);
        }
        Err(GridSearchError::NoPath { stats })
    }

    /// Lazy Theta*'s check when `p` is expanded: if `p` does not see the parent it was
    /// given, its parent becomes the expanded grid neighbour through which it is cheapest
    /// (one exists: the cell whose expansion reached `p`).
    fn lazy_set_parent(&mut self, p: u32) {
        let pp = self.theta_nodes[p as usize].parent;
        if pp == NONE || self.line_of_sight(pp, p) {
            return;
        }
        let closed = self.theta_generation | CLOSED;
        let (moves, k) = self.theta_moves(p);
        let mut best = (f64::INFINITY, NONE);
        for &(q, c) in &moves[..k] {
            let node = &self.theta_nodes[q as usize];
            if node.stamp == closed {
                let via = f64::from_bits(node.g) + c;
                if via < best.0 {
                    best = (via, q);
                }
            }
        }
        let node = &mut self.theta_nodes[p as usize];
        node.g = best.0.to_bits();
        node.parent = best.1;
    }

    /// The legal grid moves from `p` and their costs: the same as A*'s, except that a
    /// diagonal never cuts a corner (Theta*'s segments are checked exactly, so a diagonal
    /// must not touch a blocked corner).
    fn theta_moves(&self, p: u32) -> ([(u32, f64); 8], usize) {
        let pw = self.pw as u32;
        let pu = p as usize;
        let pass = &self.passable;
        let (e, w, n, s) = (
            pass[pu + 1],
            pass[pu - 1],
            pass[pu + self.pw],
            pass[pu - self.pw],
        );
        let mut moves = [(0u32, 0.0f64); 8];
        let mut k = 0;
        for (ok, q) in [(e, p + 1), (w, p - 1), (n, p + pw), (s, p - pw)] {
            if ok {
                moves[k] = (q, 1.0);
                k += 1;
            }
        }
        if self.options.connectivity == Connectivity::Eight {
            for (a, b, q) in [
                (n, e, p + pw + 1),
                (n, w, p + pw - 1),
                (s, e, p - pw + 1),
                (s, w, p - pw - 1),
            ] {
                if a && b && pass[q as usize] {
                    moves[k] = (q, SQRT2);
                    k += 1;
                }
            }
        }
        (moves, k)
    }

    /// Theta*'s expansion: for each legal grid move p -> q, take q's parent to be p's
    /// parent when it sees q (path 2 of the paper), else p (path 1). With `lazy`, p's
    /// parent is taken without the test, which q's own expansion makes
    /// ([`lazy_set_parent`](Self::lazy_set_parent)).
    pub(super) fn theta_expand(
        &mut self,
        p: u32,
        g: f64,
        stats: &mut SearchStats,
        h: impl Fn(u32, u32) -> f64,
        lazy: bool,
    ) {
        let (moves, k) = self.theta_moves(p);
        let pu = p as usize;
        let open = self.theta_generation;
        let pp = self.theta_nodes[pu].parent;
        for &(q, c) in &moves[..k] {
            let qu = q as usize;
            let st = self.theta_nodes[qu].stamp;
            if st == open | CLOSED {
                continue;
            }
            let (mut ng, mut parent) = (g + c, p);
            if pp != NONE && (lazy || self.line_of_sight(pp, q)) {
                let (a, b) = (self.cell(pp), self.cell(q));
                let d = (a.0 as f64 - b.0 as f64).hypot(a.1 as f64 - b.1 as f64);
                let via = f64::from_bits(self.theta_nodes[pp as usize].g) + d;
                if via <= ng {
                    ng = via;
                    parent = pp;
                }
            }
            if st == open && f64::from_bits(self.theta_nodes[qu].g) <= ng {
                continue;
            }
            stats.reached += u64::from(st != open);
            self.theta_nodes[qu].stamp = open;
            self.theta_nodes[qu].g = ng.to_bits();
            self.theta_nodes[qu].parent = parent;
            let (x, y) = self.xy(q);
            self.theta_heap.push(float_key(ng + h(x, y), ng, q));
            stats.pushes += 1;
        }
    }

    /// Whether the segment between the centres of cells `a` and `b` touches only passable
    /// cells (corner touches included): the cells [`GridMap::segment_cells`] visits,
    /// computed in integers. Between cell centres every crossing of a grid line is a
    /// multiple of `1 / (2 d)` (d the longer side of the segment's box), so the closed
    /// cells touched are found exactly without floating point (the property tests check
    /// the paths against the map's `segment_free`). The padded border is blocked, and
    /// a segment between centres never leaves the map, so no bounds test is needed.
    pub(super) fn line_of_sight(&self, a: u32, b: u32) -> bool {
        let ((ax, ay), (bx, by)) = (self.xy(a), self.xy(b));
        let (dx, dy) = (i64::from(bx) - i64::from(ax), i64::from(by) - i64::from(ay));
        let pw = self.pw as i64;
        // Sweep along the major axis u, in increasing u; v is the minor axis. `su`, `sv`:
        // index strides of one step along u and v.
        let (u0, v0, du, dv, su, sv) = if dx.abs() >= dy.abs() {
            if dx >= 0 {
                (i64::from(ax), i64::from(ay), dx, dy, 1, pw)
            } else {
                (i64::from(bx), i64::from(by), -dx, -dy, 1, pw)
            }
        } else if dy >= 0 {
            (i64::from(ay), i64::from(ax), dy, dx, pw, 1)
        } else {
            (i64::from(by), i64::from(bx), -dy, -dx, pw, 1)
        };
        if du == 0 {
            return self.passable[a as usize];
        }
        let pass = &self.passable;
        // In units of 1 / (2 du): the minor coordinate at doubled major coordinate t is
        // n(t) = (2 v0 + 1) du + (t - 2 u0 - 1) dv.
        let d = 2 * du;
        let n = |t: i64| (2 * v0 + 1) * du + (t - 2 * u0 - 1) * dv;
        for c in u0..=u0 + du {
            let t0 = (2 * c).max(2 * u0 + 1);
            let t1 = (2 * c + 2).min(2 * (u0 + du) + 1);
            let (na, nb) = (n(t0), n(t1));
            let (lo, hi) = (na.min(nb), na.max(nb));
            // Rows r with r <= v <= r + 1 for some v in [lo / d, hi / d].
            let r_first = lo.div_euclid(d) + i64::from(lo.rem_euclid(d) != 0) - 1;
            let r_last = hi.div_euclid(d);
            for r in r_first..=r_last {
                if !pass[(c * su + r * sv) as usize] {
                    return false;
                }
            }
        }
        true
    }
}
