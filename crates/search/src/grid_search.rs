//! Flat-array A*, Dijkstra and Theta* on a [`GridMap`], with scratch memory reused across
//! queries.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use envmap::GridMap;

use crate::SearchStats;

const SQRT2: f64 = std::f64::consts::SQRT_2;
/// "No parent" in the parent array.
const NONE: u32 = u32::MAX;
/// Stamp bit of a closed cell; the rest of the stamp is the generation.
const CLOSED: u32 = 1 << 31;

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
    /// [`GridSearch::update`] was given a map of another size than the search was built for.
    #[error("map is {got_width} x {got_height} cells, the search was built for {width} x {height}")]
    SizeMismatch {
        /// Columns the search was built for.
        width: usize,
        /// Rows the search was built for.
        height: usize,
        /// Columns of the map given.
        got_width: usize,
        /// Rows of the map given.
        got_height: usize,
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
/// hash map) with a binary heap of packed `u128` keys whose ties go to the larger g, and a
/// closed bit in the stamp (stale heap entries are skipped). A successor whose f is not
/// above the f of the cell being expanded (up to a rounding allowance of 4 ulps) skips the
/// heap and goes on a stack that is popped first: it would come out next anyway, and this
/// runs straight and diagonal stretches toward the goal depth-first. The arrays are reset in
/// O(1) between queries by a generation counter: a cell's g and parent count only when its
/// stamp carries the current generation.
///
/// # Memory
///
/// Per cell of the padded `(width + 2) x (height + 2)` grid: 1 byte passable, 1 byte
/// legal-move mask, 8 bytes g (`f64`), 4 bytes parent (`u32`), 4 bytes stamp (`u32`):
/// **18 bytes**, allocated once
/// in [`new`](GridSearch::new) and reused; plus 16 bytes per open-list entry (the heap
/// keeps its capacity across queries too).
///
/// # Costs and heuristics
///
/// Straight moves cost 1, diagonals sqrt 2 (cell units). A* uses the octile distance
/// (Manhattan when 4-connected), which is admissible and consistent, so its costs are
/// optimal; Dijkstra uses none. Costs are summed in `f64` along the path. The stack's
/// rounding allowance can reorder cells whose f differ by a few ulps, so "optimal" means
/// exact up to about 1e-12 relative (tests compare with Dijkstra to 1e-9).
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
    /// Legal moves out of each cell, one bit per direction of [`DIRS`].
    moves: Vec<u8>,
    /// Padded-index offset of each direction of [`DIRS`].
    offsets: [u32; 8],
    g: Vec<f64>,
    parent: Vec<u32>,
    stamp: Vec<u32>,
    generation: u32,
    heap: BinaryHeap<Reverse<u128>>,
    /// Cells whose f is not above the f of the cell being expanded: they come next anyway,
    /// so they skip the heap (see [`GridSearch::pop`]).
    stack: Vec<u32>,
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
            moves: vec![0; n],
            offsets: DIRS.map(|(dx, dy, _)| (dy as isize * pw as isize + dx as isize) as u32),
            g: vec![0.0; n],
            parent: vec![NONE; n],
            stamp: vec![0; n],
            generation: 0,
            heap: BinaryHeap::new(),
            stack: Vec::new(),
        };
        search.update(map)?;
        Ok(search)
    }

    /// Re-reads which cells are passable from `map` (same size as before).
    ///
    /// # Errors
    ///
    /// [`GridSearchError::SizeMismatch`] if `map` has another size than the one this
    /// search was built for.
    pub fn update(&mut self, map: &GridMap) -> Result<(), GridSearchError> {
        if map.width() != self.width || map.height() != self.height {
            return Err(GridSearchError::SizeMismatch {
                width: self.width,
                height: self.height,
                got_width: map.width(),
                got_height: map.height(),
            });
        }
        let blocked = map.blocked_from;
        for (j, row) in map.zones().chunks_exact(self.width).enumerate() {
            let base = (j + 1) * self.pw + 1;
            for (cell, &zone) in self.passable[base..base + self.width].iter_mut().zip(row) {
                *cell = zone < blocked;
            }
        }
        let (pw, pass) = (self.pw, &self.passable);
        let eight = self.options.connectivity == Connectivity::Eight;
        let cut = self.options.corner_cutting;
        for j in 1..=self.height {
            for i in 1..=self.width {
                let p = j * pw + i;
                let free = |dx: i32, dy: i32| {
                    pass[(p as isize + dy as isize * pw as isize + dx as isize) as usize]
                };
                let mut mask = 0u8;
                if pass[p] {
                    for (d, &(dx, dy, _)) in DIRS.iter().enumerate() {
                        let legal = if dx == 0 || dy == 0 {
                            free(dx, dy)
                        } else if !eight {
                            false
                        } else {
                            let (a, b) = (free(dx, 0), free(0, dy));
                            free(dx, dy) && if cut { a || b } else { a && b }
                        };
                        mask |= u8::from(legal) << d;
                    }
                }
                self.moves[p] = mask;
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
    pub const BYTES_PER_CELL: usize = 1 + 1 + 8 + 4 + 4;

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
        let mut stats = SearchStats::default();
        self.begin(g0, 0.0, &mut stats);
        while let Some(p) = self.pop() {
            stats.expansions += 1;
            let g = self.g[p as usize];
            // Dijkstra: f = g, and every move costs > 0, so nothing goes on the stack.
            self.relax_neighbours(p, g, g, &mut stats, |_, _| 0.0);
        }
        let (w, h) = (self.width, self.height);
        let mut cost = vec![f64::INFINITY; w * h];
        let mut next = vec![NONE; w * h];
        for j in 0..h {
            for i in 0..w {
                let p = self.index(i, j) as usize;
                if self.stamp[p] & !CLOSED == self.generation {
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

    /// Starts a query from `s` with heuristic `h0`: bumps the generation (clearing the
    /// stamps only on wrap-around), empties the heap and pushes `s`.
    fn begin(&mut self, s: u32, h0: f64, stats: &mut SearchStats) {
        self.generation += 1;
        if self.generation >= CLOSED {
            self.stamp.fill(0);
            self.generation = 1;
        }
        self.heap.clear();
        self.stack.clear();
        let s = s as usize;
        self.g[s] = 0.0;
        self.parent[s] = NONE;
        self.stamp[s] = self.generation;
        self.heap.push(Reverse(key(h0, 0.0, s as u32)));
        stats.pushes += 1;
        stats.reached = 1;
    }

    /// Pops the open cell with the smallest f (ties: larger g), skipping stale entries of
    /// cells already closed, and closes it.
    #[inline(always)]
    fn pop(&mut self) -> Option<u32> {
        let closed = self.generation | CLOSED;
        while let Some(p) = self
            .stack
            .pop()
            .or_else(|| self.heap.pop().map(|Reverse(k)| k as u32))
        {
            // A cell can sit in the heap several times (each time its g dropped). With a
            // consistent heuristic the first pop carries its final g; the later ones are
            // stale and skipped.
            if self.stamp[p as usize] != closed {
                self.stamp[p as usize] = closed;
                return Some(p);
            }
        }
        None
    }

    /// Relaxes the legal moves out of `p` (its bit mask of [`DIRS`]) with cost
    /// `g + move cost`. A neighbour whose `f = g' + h(x, y)` (padded coordinates) is not
    /// above `f_here` goes on the stack, the others on the heap.
    #[inline(always)]
    fn relax_neighbours(
        &mut self,
        p: u32,
        g: f64,
        f_here: f64,
        stats: &mut SearchStats,
        h: impl Fn(u32, u32) -> f64,
    ) {
        let pw = self.pw as u32;
        let (x, y) = (p % pw, p / pw);
        let open = self.generation;
        let mut mask = self.moves[p as usize];
        while mask != 0 {
            let d = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            let (dx, dy, c) = DIRS[d];
            let q = p.wrapping_add(self.offsets[d]);
            let qu = q as usize;
            let ng = g + c;
            let st = self.stamp[qu];
            if st == open | CLOSED || (st == open && self.g[qu] <= ng) {
                continue;
            }
            stats.reached += u64::from(st != open);
            self.stamp[qu] = open;
            self.g[qu] = ng;
            self.parent[qu] = p;
            let f = ng + h(x.wrapping_add_signed(dx), y.wrapping_add_signed(dy));
            // `f_here` plus a rounding allowance: moves that keep f constant in exact
            // arithmetic (straight or diagonal toward the goal) can come out one ulp above.
            if f <= f_here * (1.0 + 4.0 * f64::EPSILON) {
                self.stack.push(q);
            } else {
                self.heap.push(Reverse(key(f, ng, q)));
            }
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
        let mut stats = SearchStats::default();
        let pw = self.pw as u32;
        let (gx, gy) = (t0 % pw, t0 / pw);
        let four = self.options.connectivity == Connectivity::Four;
        let octile = move |x: u32, y: u32| {
            let dx = x.abs_diff(gx);
            let dy = y.abs_diff(gy);
            let (lo, hi) = if dx < dy { (dx, dy) } else { (dy, dx) };
            if four {
                f64::from(lo + hi)
            } else {
                f64::from(hi - lo) + SQRT2 * f64::from(lo)
            }
        };
        let euclid = move |x: u32, y: u32| {
            let dx = f64::from(x.abs_diff(gx));
            let dy = f64::from(y.abs_diff(gy));
            dx.hypot(dy)
        };
        let (sx, sy) = (s0 % pw, s0 / pw);
        let h0 = match kind {
            Kind::Astar => octile(sx, sy),
            Kind::Dijkstra => 0.0,
            Kind::ThetaStar => euclid(sx, sy),
        };
        self.begin(s0, h0, &mut stats);
        while let Some(p) = self.pop() {
            let g = self.g[p as usize];
            if p == t0 {
                return Ok(self.trace(t0, g, stats));
            }
            stats.expansions += 1;
            match kind {
                Kind::Astar => {
                    let (x, y) = (p % pw, p / pw);
                    self.relax_neighbours(p, g, g + octile(x, y), &mut stats, octile);
                }
                Kind::Dijkstra => self.relax_neighbours(p, g, g, &mut stats, |_, _| 0.0),
                Kind::ThetaStar => {
                    // The map is always given for Theta* (see `theta_star`).
                    if let Some(map) = map {
                        self.theta_expand(map, p, g, &mut stats, euclid);
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
        stats: &mut SearchStats,
        h: impl Fn(u32, u32) -> f64,
    ) {
        // The grid moves, with the same rules as A* but never cutting corners: Theta*'s
        // segments are checked exactly, so a diagonal must not touch a blocked corner.
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
        let open = self.generation;
        let pp = self.parent[pu];
        for &(q, c) in &moves[..k] {
            let qu = q as usize;
            let st = self.stamp[qu];
            if st == open | CLOSED {
                continue;
            }
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
            if st == open && self.g[qu] <= ng {
                continue;
            }
            stats.reached += u64::from(st != open);
            self.stamp[qu] = open;
            self.g[qu] = ng;
            self.parent[qu] = parent;
            self.heap.push(Reverse(key(ng + h(q % pw, q / pw), ng, q)));
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

/// The eight moves `(dx, dy, cost)`: E, W, N, S, then the diagonals NE, NW, SE, SW.
const DIRS: [(i32, i32, f64); 8] = [
    (1, 0, 1.0),
    (-1, 0, 1.0),
    (0, 1, 1.0),
    (0, -1, 1.0),
    (1, 1, SQRT2),
    (-1, 1, SQRT2),
    (1, -1, SQRT2),
    (-1, -1, SQRT2),
];

/// The open-list key of a cell: one `u128` compared as an integer, smallest first (the heap
/// holds it in [`Reverse`]). From the top: the bits of `f` (non-negative `f64` bits sort as
/// the numbers do), the complement of `g` as `f32` bits (ties on `f` go to the larger `g`;
/// `f32` is only a tie-breaker, the order on `f` stays exact), and the cell index.
#[inline(always)]
fn key(f: f64, g: f64, p: u32) -> u128 {
    (u128::from(f.to_bits()) << 64) | (u128::from(!(g as f32).to_bits()) << 32) | u128::from(p)
}
