//! Flat-array A*, Dijkstra and Theta* on a [`GridMap`], with scratch memory reused across
//! queries.

use std::collections::BinaryHeap;

use envmap::GridMap;

use crate::SearchStats;
use crate::heap::Entry;

const SQRT2: f64 = std::f64::consts::SQRT_2;
/// "No parent" in the parent array.
const NONE: u32 = u32::MAX;

/// Which moves a grid search may make.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Connectivity {
    /// Up, down, left, right; cost 1 each.
    Four,
    /// The four straight moves (cost 1) and the four diagonals (cost sqrt 2).
    #[default]
    Eight,
}

/// Move rules of the grid searches.
///
/// Which cells are passable is the map's [`GridMap::blocked_from`]: by default only
/// `Forbidden` cells block; [`GridMap::avoiding_risk`] makes the high-risk band block too.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct GridOptions {
    /// 4- or 8-connected moves (default 8).
    pub connectivity: Connectivity,
    /// Whether a diagonal move may cut the corner of a blocked cell.
    ///
    /// `false` (the default, the MovingAI rule): a diagonal move needs both orthogonal
    /// neighbours it passes free, so the straight segment between the two cell centres
    /// never touches a blocked cell. `true`: one free orthogonal neighbour is enough (the
    /// move still never squeezes between two blocked cells that meet at a corner).
    pub corner_cutting: bool,
}

/// A path found on the grid: cells `(i, j)` (column, row from the bottom) from start to
/// goal, both included, and its cost in **cells** (multiply by the map's resolution for
/// world units).
#[derive(Debug, Clone, PartialEq)]
pub struct GridPath {
    /// Cells from the start to the goal, both included.
    pub cells: Vec<(usize, usize)>,
    /// Length in cell units: 1 per straight move, sqrt 2 per diagonal (Euclidean distance
    /// between cell centres for Theta*).
    pub cost: f64,
    /// Counters of the search.
    pub stats: SearchStats,
}

/// Why a grid search returned no path.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum GridSearchError {
    /// The start cell is outside the map.
    #[error("start cell ({i}, {j}) is outside the {width} x {height} map")]
    StartOutside {
        /// Column.
        i: usize,
        /// Row from the bottom.
        j: usize,
        /// Map columns.
        width: usize,
        /// Map rows.
        height: usize,
    },
    /// The goal cell is outside the map.
    #[error("goal cell ({i}, {j}) is outside the {width} x {height} map")]
    GoalOutside {
        /// Column.
        i: usize,
        /// Row from the bottom.
        j: usize,
        /// Map columns.
        width: usize,
        /// Map rows.
        height: usize,
    },
    /// The start cell is blocked.
    #[error("start cell ({i}, {j}) is blocked")]
    StartBlocked {
        /// Column.
        i: usize,
        /// Row from the bottom.
        j: usize,
    },
    /// The goal cell is blocked.
    #[error("goal cell ({i}, {j}) is blocked")]
    GoalBlocked {
        /// Column.
        i: usize,
        /// Row from the bottom.
        j: usize,
    },
    /// Every cell reachable from the start was expanded without meeting the goal.
    #[error("no path: the {} reachable cells were exhausted", stats.expansions)]
    NoPath {
        /// Counters of the search.
        stats: SearchStats,
    },
    /// The map is too large for 32-bit cell indices.
    #[error(
        "map of {width} x {height} cells is too large for the grid search (max 2^32 - 1 cells with the border)"
    )]
    MapTooLarge {
        /// Map columns.
        width: usize,
        /// Map rows.
        height: usize,
    },
}

/// Cost-to-go field of a one-to-all Dijkstra search toward a goal cell.
///
/// For every cell: the cost in cells of the cheapest path to the goal (`None` when the goal
/// cannot be reached) and the next cell along that path, so a robot can follow it from
/// wherever it is ([`path_from`](CostField::path_from)).
#[derive(Debug, Clone, PartialEq)]
pub struct CostField {
    width: usize,
    height: usize,
    goal: (usize, usize),
    cost: Vec<f64>,
    next: Vec<u32>,
    stats: SearchStats,
}

impl CostField {
    /// Map columns.
    #[must_use]
    pub const fn width(&self) -> usize {
        self.width
    }

    /// Map rows.
    #[must_use]
    pub const fn height(&self) -> usize {
        self.height
    }

    /// The goal cell the field leads to.
    #[must_use]
    pub const fn goal(&self) -> (usize, usize) {
        self.goal
    }

    /// Counters of the search that built the field.
    #[must_use]
    pub const fn stats(&self) -> SearchStats {
        self.stats
    }

    /// Cost in cells from `(i, j)` to the goal; `None` outside the map, on blocked cells and
    /// where the goal cannot be reached.
    #[must_use]
    pub fn cost(&self, i: usize, j: usize) -> Option<f64> {
        (i < self.width && j < self.height)
            .then(|| self.cost[j * self.width + i])
            .filter(|c| c.is_finite())
    }

    /// The next cell on a cheapest path from `(i, j)` to the goal (`None` at the goal and
    /// where [`cost`](CostField::cost) is `None`).
    #[must_use]
    pub fn next(&self, i: usize, j: usize) -> Option<(usize, usize)> {
        self.cost(i, j)?;
        let n = self.next[j * self.width + i];
        (n != NONE).then(|| (n as usize % self.width, n as usize / self.width))
    }

    /// The cells of a cheapest path from `(i, j)` to the goal, both included.
    #[must_use]
    pub fn path_from(&self, i: usize, j: usize) -> Option<Vec<(usize, usize)>> {
        self.cost(i, j)?;
        let mut cells = vec![(i, j)];
        let mut here = (i, j);
        while let Some(n) = self.next(here.0, here.1) {
            cells.push(n);
            here = n;
        }
        Some(cells)
    }

    /// Costs row-major from the bottom row (`f64::INFINITY` where unreachable).
    #[must_use]
    pub fn costs(&self) -> &[f64] {
        &self.cost
    }
}

/// Which search [`GridSearch::run`] performs.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Astar,
    Dijkstra,
    ThetaStar,
}

/// Flat-array grid searches on one [`GridMap`], with scratch memory reused across queries.
///
/// `GridSearch::new` copies which cells are passable (under the map's
/// [`blocked_from`](GridMap::blocked_from)) into an array padded with a blocked border, so
/// the inner loop needs no bounds checks. Each query then runs on flat per-cell arrays (no
/// hash map) with a binary heap whose ties go to the larger g. The arrays are reset in
/// O(1) between queries by a generation counter: a cell's g and parent count only when its
/// stamp equals the current generation.
///
/// # Memory
///
/// Per cell of the padded `(width + 2) x (height + 2)` grid: 1 byte passable, 8 bytes g
/// (`f64`), 4 bytes parent (`u32`), 4 bytes stamp (`u32`): **17 bytes**, allocated once
/// in [`new`](GridSearch::new) and reused; plus 24 bytes per open-list entry (the heap
/// keeps its capacity across queries too).
///
/// # Costs and heuristics
///
/// Straight moves cost 1, diagonals sqrt 2 (cell units). A* uses the octile distance
/// (Manhattan when 4-connected), which is admissible and consistent, so its costs are
/// optimal; Dijkstra uses none. Costs are summed in `f64` along the path.
///
/// # Example
///
/// ```
/// use envmap::GridMap;
/// use search::{GridOptions, GridSearch};
/// let map = GridMap::from_ascii("
///     ....
///     .##.
///     ....
/// ")?;
/// let mut search = GridSearch::new(&map, GridOptions::default())?;
/// let path = search.astar((0, 1), (3, 1))?;
/// assert_eq!(path.cells.first(), Some(&(0, 1)));
/// assert_eq!(path.cells.last(), Some(&(3, 1)));
/// // Around the wall: a diagonal may not cut the corner of a blocked cell.
/// assert_eq!(path.cost, 5.0);
/// // The same scratch serves the next query.
/// assert_eq!(search.dijkstra((0, 0), (3, 0))?.cost, 3.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct GridSearch {
    width: usize,
    height: usize,
    /// Padded width, `width + 2`.
    pw: usize,
    options: GridOptions,
    passable: Vec<bool>,
    g: Vec<f64>,
    parent: Vec<u32>,
    stamp: Vec<u32>,
    generation: u32,
    heap: BinaryHeap<Entry<u32>>,
}

impl GridSearch {
    /// Prepares searches on `map` with the move rules `options`.
    ///
    /// Later changes to the map are not seen: build a new `GridSearch` (or call
    /// [`update`](GridSearch::update)) after editing it.
    ///
    /// # Errors
    ///
    /// [`GridSearchError::MapTooLarge`] when the padded grid has `2^32 - 1` cells or more.
    pub fn new(map: &GridMap, options: GridOptions) -> Result<Self, GridSearchError> {
        let (width, height) = (map.width(), map.height());
        let pw = width + 2;
        let n = pw
            .checked_mul(height + 2)
            .filter(|&n| n < NONE as usize)
            .ok_or(GridSearchError::MapTooLarge { width, height })?;
        let mut search = Self {
            width,
            height,
            pw,
            options,
            passable: vec![false; n],
            g: vec![0.0; n],
            parent: vec![NONE; n],
            stamp: vec![0; n],
            generation: 0,
            heap: BinaryHeap::new(),
        };
        search.update(map)?;
        Ok(search)
    }

    /// Re-reads which cells are passable from `map` (same size as before).
    ///
    /// # Errors
    ///
    /// [`GridSearchError::MapTooLarge`] if `map` has another size than the one this
    /// search was built for (the error names the new size).
    pub fn update(&mut self, map: &GridMap) -> Result<(), GridSearchError> {
        if map.width() != self.width || map.height() != self.height {
            return Err(GridSearchError::MapTooLarge {
                width: map.width(),
                height: map.height(),
            });
        }
        let blocked = map.blocked_from;
        for (j, row) in map.zones().chunks_exact(self.width).enumerate() {
            let base = (j + 1) * self.pw + 1;
            for (cell, &zone) in self.passable[base..base + self.width].iter_mut().zip(row) {
                *cell = zone < blocked;
            }
        }
        Ok(())
    }

    /// Map columns.
    #[must_use]
    pub const fn width(&self) -> usize {
        self.width
    }

    /// Map rows.
    #[must_use]
    pub const fn height(&self) -> usize {
        self.height
    }

    /// The move rules.
    #[must_use]
    pub const fn options(&self) -> GridOptions {
        self.options
    }

    /// Whether cell `(i, j)` is inside the map and passable.
    #[must_use]
    pub fn cell_passable(&self, i: usize, j: usize) -> bool {
        i < self.width && j < self.height && self.passable[self.index(i, j) as usize]
    }

    /// Scratch bytes held per padded cell (see the type doc).
    pub const BYTES_PER_CELL: usize = 1 + 8 + 4 + 4;

    /// Optimal path from `start` to `goal` by A* with the octile (or Manhattan) heuristic.
    ///
    /// # Errors
    ///
    /// Start or goal outside the map or blocked; [`GridSearchError::NoPath`] after every
    /// cell reachable from the start was expanded.
    pub fn astar(
        &mut self,
        start: (usize, usize),
        goal: (usize, usize),
    ) -> Result<GridPath, GridSearchError> {
        self.run(None, start, goal, Kind::Astar)
    }

    /// Optimal path from `start` to `goal` by Dijkstra's algorithm (no heuristic).
    ///
    /// # Errors
    ///
    /// As [`astar`](GridSearch::astar).
    pub fn dijkstra(
        &mut self,
        start: (usize, usize),
        goal: (usize, usize),
    ) -> Result<GridPath, GridSearchError> {
        self.run(None, start, goal, Kind::Dijkstra)
    }

    /// Any-angle path from `start` to `goal` by Theta* (Nash, Daniel, Koenig and Felner,
    /// 2007): A* on the grid moves, except that a cell's parent may be any earlier cell in
    /// line of sight, so the path goes straight between cell centres where it can.
    ///
    /// Line of sight between two cell centres means that every cell the closed segment
    /// touches (corners included, as [`GridMap::segment_cells`] sees it) is passable, so
    /// every segment of the path passes the map's exact `segment_free`. The heuristic is
    /// the Euclidean distance. Theta* is not guaranteed to find the shortest any-angle
    /// path, and nodes may be re-expanded when their cost drops.
    ///
    /// `map` must be the map this search was built from (its frame is used for the line of
    /// sight; which cells are passable comes from this search).
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

    /// One-to-all Dijkstra from `goal`: the cost-to-go of every cell and the next cell
    /// toward the goal (moves are symmetric, so costs from the goal are costs to it).
    ///
    /// # Errors
    ///
    /// The goal outside the map or blocked.
    pub fn cost_to_go(&mut self, goal: (usize, usize)) -> Result<CostField, GridSearchError> {
        let g0 = self.check(goal, false)?;
        let generation = self.next_generation();
        let mut stats = SearchStats::default();
        self.g[g0 as usize] = 0.0;
        self.parent[g0 as usize] = NONE;
        self.stamp[g0 as usize] = generation;
        self.heap.clear();
        self.heap.push(Entry {
            f: 0.0,
            g: 0.0,
            item: g0,
        });
        stats.pushes += 1;
        while let Some(Entry { g, item: p, .. }) = self.heap.pop() {
            if g > self.g[p as usize] {
                continue;
            }
            stats.expansions += 1;
            self.relax_neighbours(p, g, generation, &mut stats, |_, _| 0.0);
        }
        let (w, h) = (self.width, self.height);
        let mut cost = vec![f64::INFINITY; w * h];
        let mut next = vec![NONE; w * h];
        for j in 0..h {
            for i in 0..w {
                let p = self.index(i, j) as usize;
                if self.stamp[p] == generation {
                    cost[j * w + i] = self.g[p];
                    let q = self.parent[p];
                    if q != NONE {
                        let (qi, qj) = self.cell(q);
                        next[j * w + i] = (qj * w + qi) as u32;
                    }
                }
            }
        }
        Ok(CostField {
            width: w,
            height: h,
            goal,
            cost,
            next,
            stats,
        })
    }

    /// Flat padded index of cell `(i, j)` (inside the map).
    #[inline]
    fn index(&self, i: usize, j: usize) -> u32 {
        ((j + 1) * self.pw + i + 1) as u32
    }

    /// Cell `(i, j)` of a flat padded index.
    #[inline]
    fn cell(&self, p: u32) -> (usize, usize) {
        let p = p as usize;
        (p % self.pw - 1, p / self.pw - 1)
    }

    /// Checks that a query cell is inside the map and passable; returns its index.
    fn check(&self, (i, j): (usize, usize), start: bool) -> Result<u32, GridSearchError> {
        let (width, height) = (self.width, self.height);
        if i >= width || j >= height {
            return Err(if start {
                GridSearchError::StartOutside {
                    i,
                    j,
                    width,
                    height,
                }
            } else {
                GridSearchError::GoalOutside {
                    i,
                    j,
                    width,
                    height,
                }
            });
        }
        let p = self.index(i, j);
        if !self.passable[p as usize] {
            return Err(if start {
                GridSearchError::StartBlocked { i, j }
            } else {
                GridSearchError::GoalBlocked { i, j }
            });
        }
        Ok(p)
    }

    /// Starts a new query: bumps the generation, clearing the stamps only on wrap-around.
    fn next_generation(&mut self) -> u32 {
        self.generation = self.generation.wrapping_add(1);
        if self.generation == 0 {
            self.stamp.fill(0);
            self.generation = 1;
        }
        self.generation
    }

    /// Generates the legal moves out of `p` and relaxes each neighbour with cost
    /// `g + move cost`, pushing it with `f = g' + h(q)`. Theta* has its own loop.
    #[inline(always)]
    fn relax_neighbours(
        &mut self,
        p: u32,
        g: f64,
        generation: u32,
        stats: &mut SearchStats,
        mut h: impl FnMut(&Self, u32) -> f64,
    ) {
        let pw = self.pw as u32;
        let pu = p as usize;
        let pass = &self.passable;
        let e = pass[pu + 1];
        let w = pass[pu - 1];
        let n = pass[pu + pw as usize];
        let s = pass[pu - pw as usize];
        let mut moves = [(0u32, 0.0f64); 8];
        let mut k = 0;
        for (ok, q) in [(e, p + 1), (w, p - 1), (n, p + pw), (s, p - pw)] {
            if ok {
                moves[k] = (q, 1.0);
                k += 1;
            }
        }
        if self.options.connectivity == Connectivity::Eight {
            let cut = self.options.corner_cutting;
            for (a, b, q) in [
                (n, e, p + pw + 1),
                (n, w, p + pw - 1),
                (s, e, p - pw + 1),
                (s, w, p - pw - 1),
            ] {
                let orth = if cut { a || b } else { a && b };
                if orth && pass[q as usize] {
                    moves[k] = (q, SQRT2);
                    k += 1;
                }
            }
        }
        for &(q, c) in &moves[..k] {
            let qu = q as usize;
            let ng = g + c;
            if self.stamp[qu] == generation && self.g[qu] <= ng {
                continue;
            }
            self.stamp[qu] = generation;
            self.g[qu] = ng;
            self.parent[qu] = p;
            let f = ng + h(self, q);
            self.heap.push(Entry { f, g: ng, item: q });
            stats.pushes += 1;
        }
    }

    /// The shared A* / Dijkstra / Theta* loop.
    fn run(
        &mut self,
        map: Option<&GridMap>,
        start: (usize, usize),
        goal: (usize, usize),
        kind: Kind,
    ) -> Result<GridPath, GridSearchError> {
        let s0 = self.check(start, true)?;
        let t0 = self.check(goal, false)?;
        let generation = self.next_generation();
        let mut stats = SearchStats::default();
        self.g[s0 as usize] = 0.0;
        self.parent[s0 as usize] = NONE;
        self.stamp[s0 as usize] = generation;
        self.heap.clear();
        let pw = self.pw as u32;
        let (gx, gy) = (t0 % pw, t0 / pw);
        let four = self.options.connectivity == Connectivity::Four;
        let octile = move |_: &Self, q: u32| {
            let dx = (q % pw).abs_diff(gx);
            let dy = (q / pw).abs_diff(gy);
            let (lo, hi) = if dx < dy { (dx, dy) } else { (dy, dx) };
            if four {
                f64::from(lo + hi)
            } else {
                f64::from(hi - lo) + SQRT2 * f64::from(lo)
            }
        };
        let euclid = move |q: u32| {
            let dx = f64::from((q % pw).abs_diff(gx));
            let dy = f64::from((q / pw).abs_diff(gy));
            dx.hypot(dy)
        };
        let h0 = match kind {
            Kind::Astar => octile(self, s0),
            Kind::Dijkstra => 0.0,
            Kind::ThetaStar => euclid(s0),
        };
        self.heap.push(Entry {
            f: h0,
            g: 0.0,
            item: s0,
        });
        stats.pushes += 1;
        while let Some(Entry { g, item: p, .. }) = self.heap.pop() {
            // Stale entry: the cell was pushed again with a lower g since.
            if g > self.g[p as usize] {
                continue;
            }
            if p == t0 {
                return Ok(self.trace(t0, g, stats));
            }
            stats.expansions += 1;
            match kind {
                Kind::Astar => self.relax_neighbours(p, g, generation, &mut stats, octile),
                Kind::Dijkstra => {
                    self.relax_neighbours(p, g, generation, &mut stats, |_, _| 0.0);
                }
                Kind::ThetaStar => {
                    // Map is always given for Theta* (see `theta_star`).
                    if let Some(map) = map {
                        self.theta_expand(map, p, g, generation, &mut stats, euclid);
                    }
                }
            }
        }
        Err(GridSearchError::NoPath { stats })
    }

    /// Theta*'s expansion: for each legal grid move p -> q, take q's parent to be p's
    /// parent when it sees q (path 2 of the paper), else p (path 1).
    fn theta_expand(
        &mut self,
        map: &GridMap,
        p: u32,
        g: f64,
        generation: u32,
        stats: &mut SearchStats,
        h: impl Fn(u32) -> f64,
    ) {
        // Collect the grid moves with the same rules as A*, without relaxing them.
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
            // Theta*'s segments are checked exactly, so a diagonal move must not touch a
            // blocked corner whatever `corner_cutting` says.
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
        let pp = self.parent[pu];
        for &(q, c) in &moves[..k] {
            let qu = q as usize;
            let (mut ng, mut parent) = (g + c, p);
            if pp != NONE && self.line_of_sight(map, pp, q) {
                let (a, b) = (self.cell(pp), self.cell(q));
                let d = (a.0 as f64 - b.0 as f64).hypot(a.1 as f64 - b.1 as f64);
                let via = self.g[pp as usize] + d;
                if via <= ng {
                    ng = via;
                    parent = pp;
                }
            }
            if self.stamp[qu] == generation && self.g[qu] <= ng {
                continue;
            }
            self.stamp[qu] = generation;
            self.g[qu] = ng;
            self.parent[qu] = parent;
            self.heap.push(Entry {
                f: ng + h(q),
                g: ng,
                item: q,
            });
            stats.pushes += 1;
        }
    }

    /// Whether the segment between the centres of cells `a` and `b` touches only passable
    /// cells (corner touches included).
    fn line_of_sight(&self, map: &GridMap, a: u32, b: u32) -> bool {
        let (a, b) = (self.cell(a), self.cell(b));
        let (pa, pb) = (map.cell_center(a.0, a.1), map.cell_center(b.0, b.1));
        map.segment_cells(pa, pb, |i, j| self.cell_passable(i, j))
    }

    /// The path to `t` by parent links.
    fn trace(&self, t: u32, cost: f64, stats: SearchStats) -> GridPath {
        let mut cells = Vec::new();
        let mut p = t;
        while p != NONE {
            cells.push(self.cell(p));
            p = self.parent[p as usize];
        }
        cells.reverse();
        GridPath { cells, cost, stats }
    }
}
