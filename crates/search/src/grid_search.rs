//! Flat-array A*, Dijkstra and Theta* on a [`GridMap`], with scratch memory reused across
//! queries.

use std::time::Instant;

use envmap::GridMap;

use crate::SearchStats;
use crate::heap::{HeapKey, MinHeap, Upper};

const SQRT2: f64 = std::f64::consts::SQRT_2;
/// "No parent" in Theta*'s parent array, "no target" for a one-to-all search.
const NONE: u32 = u32::MAX;
/// Stamp bit of a closed cell in Theta*'s nodes; the rest of the stamp is the generation.
const CLOSED: u32 = 1 << 31;
/// Bits of the generation field at the top of a word (see [`GridSearch::base`]).
const GEN_BITS: u32 = 8;
/// The generation field of a word starts at this bit.
const GEN_SHIFT: u32 = 64 - GEN_BITS;
/// The g field of a word starts at this bit (below it: the parent move, 3 bits, and the
/// closed bit).
const G_SHIFT: u32 = 4;
/// The g field of a word, shifted down.
const G_MASK: u64 = (1 << (GEN_SHIFT - G_SHIFT)) - 1;

/// Which moves a grid search may make.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
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
    /// The expansion or time limit set by [`GridSearch::set_limit`] ran out first.
    #[error("search limit reached after {} expansions", stats.expansions)]
    LimitReached {
        /// Counters up to the stop.
        stats: SearchStats,
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
/// the inner loop needs no bounds tests for the map's edges, and one byte per cell with its
/// legal moves (corner rule applied). A* and Dijkstra then keep **one `u64` word per cell**
/// (no hash map): from the top, the query's generation (8 bits), g in fixed point (52 bits,
/// see "Costs" below), the move the cell was reached by (3 bits: the parent, for the path)
/// and a closed bit. Later queries have smaller generation fields, so a word of an earlier
/// query compares above every word of the current one and the arrays are reset in O(1)
/// between queries (refilled once in 254 queries); blocked cells hold 0. Whether a move
/// improves its cell is then one `u64` comparison.
///
/// The open list is a binary heap of packed keys (f, then h for ties toward the larger g,
/// then the cell; one `u64` on grids up to about 2^19 padded cells, else a `u128`) with
/// decrease-key: a slot per cell says where its key sits, so a cell whose g drops is moved
/// up in place instead of queued twice. A successor whose f equals the f of the cell being
/// expanded skips the heap and goes on a stack that is popped first: it would come out
/// next anyway, and this runs straight and diagonal stretches toward the goal depth-first.
/// The first successor that does go to the heap takes the place of the cell being
/// expanded at the root (one sift instead of a pop and a push). Theta* keeps its own nodes
/// (`f64` g, parent, stamp) and heap, allocated by its first query.
///
/// # Memory
///
/// Per cell of the padded `(width + 2) x (height + 2)` grid: 1 byte passable, 1 byte
/// legal-move mask, 8 bytes word, 4 bytes heap slot (`u32`): **14 bytes**
/// ([`BYTES_PER_CELL`](GridSearch::BYTES_PER_CELL)), allocated once in
/// [`new`](GridSearch::new) and reused; plus 8 or 16 bytes per open-list entry (the heap
/// keeps its capacity across queries too). The first Theta* query adds 16 bytes per cell.
///
/// # Costs and heuristics
///
/// Straight moves cost 1, diagonals sqrt 2 (cell units). A* uses the octile distance
/// (Manhattan when 4-connected), which is admissible and consistent, so its costs are
/// optimal; Dijkstra uses none. A* and Dijkstra add costs as fixed-point integers: 2^32
/// per straight move and the odd integer nearest to sqrt(2) 2^32 per diagonal (fewer
/// fraction bits from 2^19 padded cells on, so that g fits its 52 bits), so sums are
/// exact and the heuristic in the same units is exactly consistent. The open list orders
/// by f cut to the key's f field (a quantum of 2^-16 cells or finer below 2^22 cells).
/// The cost returned is `a + b * sqrt 2` in `f64` for the path's a straight moves and b
/// diagonals, recovered exactly from the integer. The integer order is the real order of
/// path lengths except between lengths closer than `b * 2^-33` cells (at 2^32), which needs
/// paths of tens of thousands of diagonals; even then the result is within that of the
/// optimum. Theta* sums `f64` Euclidean lengths.
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
    /// Per-cell state of A* and Dijkstra: one word each (see the type doc).
    words: Vec<u64>,
    /// Query counter of `words` (1 to `2^GEN_BITS - 2`).
    generation: u32,
    /// Per-cell state of Theta* (allocated by its first query).
    theta_nodes: Vec<Node>,
    /// Query counter of `theta_nodes`.
    theta_generation: u32,
    /// The fixed-point cost scale of this grid's size.
    fixed: Fixed,
    /// `u64::MAX / pw + 1`: divides a padded index by `pw` with one multiplication.
    magic: u64,
    /// Open list of A* and Dijkstra on grids whose keys fit 64 bits (see [`Fixed`]).
    heap: MinHeap<u64>,
    /// Open list of A* and Dijkstra on larger grids.
    wide_heap: MinHeap<Upper>,
    /// Open list of Theta* (ordered by the whole [`float_key`]).
    theta_heap: MinHeap<u128>,
    /// Cells whose f is not above the f of the cell being expanded: they come next anyway,
    /// so they skip the heap (see [`GridSearch::grid_search`]).
    stack: Vec<u32>,
    /// Where each cell's key sits in the A* / Dijkstra open list, if it is there (checked
    /// against the key before use, so stale values are harmless).
    slot: Vec<u32>,
    /// When a search gives up (none by default).
    limit: Limit,
}

/// An expansion cap and a deadline (see [`GridSearch::set_limit`]).
#[derive(Debug, Clone, Copy)]
struct Limit {
    max_expansions: u64,
    deadline: Option<Instant>,
}

impl Default for Limit {
    fn default() -> Self {
        Self {
            max_expansions: u64::MAX,
            deadline: None,
        }
    }
}

/// How many expansions pass between two readings of the clock: a few hundred
/// microseconds of search at most, so a deadline is kept to well under a millisecond
/// without a clock read per expansion.
const CLOCK_EVERY: u64 = 1024;

impl Limit {
    /// The expansion count at which to look again: the cap, or the next clock reading.
    fn next_check(&self, expansions: u64) -> u64 {
        if self.deadline.is_some() {
            (expansions + CLOCK_EVERY).min(self.max_expansions)
        } else {
            self.max_expansions
        }
    }

    /// Whether a search with `expansions` expansions must stop.
    fn spent(&self, expansions: u64) -> bool {
        expansions >= self.max_expansions || self.deadline.is_some_and(|d| Instant::now() >= d)
    }
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
        Self::new_until(map, options, None)
    }

    /// [`new`](GridSearch::new), giving up once `deadline` has passed: the preparation
    /// reads every cell (a few milliseconds per million cells), so a planner with a time
    /// limit builds its grid with this one, and the grid's deadline is also set as the
    /// search's limit ([`set_limit`](GridSearch::set_limit)).
    ///
    /// # Errors
    ///
    /// As [`new`](GridSearch::new), and [`GridSearchError::LimitReached`] (no expansion)
    /// when the deadline passes first.
    pub fn new_until(
        map: &GridMap,
        options: GridOptions,
        deadline: Option<Instant>,
    ) -> Result<Self, GridSearchError> {
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
            // Zeroed pages cost nothing until written; `update` writes every word.
            words: vec![0; n],
            generation: 0,
            theta_nodes: Vec::new(),
            theta_generation: 0,
            fixed: Fixed::new(pw, height + 2),
            magic: u64::MAX / pw as u64 + 1,
            heap: MinHeap::default(),
            wide_heap: MinHeap::default(),
            theta_heap: MinHeap::default(),
            stack: Vec::new(),
            slot: vec![0; n],
            limit: Limit {
                max_expansions: u64::MAX,
                deadline,
            },
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
        // The clock is read every 64 rows (a grid being built for a deadline).
        let deadline = self.limit.deadline;
        let late = |j: usize| j.is_multiple_of(64) && deadline.is_some_and(|d| Instant::now() >= d);
        let stop = Err(GridSearchError::LimitReached {
            stats: SearchStats::default(),
        });
        let blocked = map.blocked_from;
        for (j, row) in map.zones().chunks_exact(self.width).enumerate() {
            if late(j) {
                return stop;
            }
            let base = (j + 1) * self.pw + 1;
            for (cell, &zone) in self.passable[base..base + self.width].iter_mut().zip(row) {
                *cell = zone < blocked;
            }
        }
        let (pw, pass) = (self.pw, &self.passable);
        let eight = self.options.connectivity == Connectivity::Eight;
        let cut = self.options.corner_cutting;
        for j in 1..=self.height {
            if late(j) {
                return stop;
            }
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
        self.reset_words();
        Ok(())
    }

    /// Sets every word to "not reached": `u64::MAX` (above the words of every query) on
    /// passable cells, and 0 on blocked ones and the border (below every move's test, so
    /// no move into them improves anything).
    fn reset_words(&mut self) {
        for (word, &free) in self.words.iter_mut().zip(&self.passable) {
            *word = if free { u64::MAX } else { 0 };
        }
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

    /// Makes later searches (A*, Dijkstra, Theta*, cost-to-go) stop with
    /// [`GridSearchError::LimitReached`] after `max_expansions` expansions or once
    /// `deadline` has passed (the clock is read every 1024 expansions). `u64::MAX` and
    /// `None` (the default) never stop a search early.
    pub fn set_limit(&mut self, max_expansions: u64, deadline: Option<Instant>) {
        self.limit = Limit {
            max_expansions,
            deadline,
        };
    }

    /// Whether cell `(i, j)` is inside the map and passable.
    #[must_use]
    pub fn cell_passable(&self, i: usize, j: usize) -> bool {
        i < self.width && j < self.height && self.passable[self.index(i, j) as usize]
    }

    /// Scratch bytes held per padded cell by A* and Dijkstra (see the type doc).
    pub const BYTES_PER_CELL: usize = 1 + 1 + 8 + 4;

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
    /// line of sight, so the path goes straight between cell centres where it can. The
    /// diagonal moves never cut corners, whatever [`GridOptions::corner_cutting`] says.
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
        // Dijkstra without a target: runs until the reachable cells are exhausted.
        let stats = match self.grid_search(g0, NONE, false) {
            Err(GridSearchError::NoPath { stats }) => stats,
            _ => SearchStats::default(),
        };
        let (w, h) = (self.width, self.height);
        let mut cost = vec![f64::INFINITY; w * h];
        let mut next = vec![NONE; w * h];
        for j in 0..h {
            for i in 0..w {
                let p = self.index(i, j);
                if let Some(g) = self.g_of(p) {
                    cost[j * w + i] = self.fixed.to_cells(g);
                    if let Some(q) = self.parent(p) {
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
        let (x, y) = self.xy(p);
        (x as usize - 1, y as usize - 1)
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

    /// Starts an A* / Dijkstra query from `s`: bumps the generation (refilling the words
    /// only when its field wraps around, once in `2^GEN_BITS - 2` queries), empties the
    /// open list and opens `s` with g = 0. Returns the query's base word (its generation
    /// field; g = 0, open).
    fn begin(&mut self, s: u32, stats: &mut SearchStats) -> u64 {
        self.generation += 1;
        // The field of generation 2^GEN_BITS - 1 would be 0, the word of blocked cells.
        if self.generation >= (1 << GEN_BITS) - 1 {
            self.reset_words();
            self.generation = 1;
        }
        self.heap.clear();
        self.wide_heap.clear();
        self.stack.clear();
        let base = self.base();
        self.words[s as usize] = base;
        stats.pushes += 1;
        stats.reached = 1;
        base
    }

    /// The current query's base word: its generation field, g = 0, open. Later
    /// generations have smaller fields, so a word of an earlier query (or the initial
    /// `u64::MAX`) compares above every word of this one.
    fn base(&self) -> u64 {
        u64::from(!self.generation & ((1 << GEN_BITS) - 1)) << GEN_SHIFT
    }

    /// The g of padded cell `p` in the current A* / Dijkstra query (`None` if the query
    /// has not reached it).
    fn g_of(&self, p: u32) -> Option<u64> {
        let word = self.words[p as usize];
        (word >> GEN_SHIFT == self.base() >> GEN_SHIFT).then_some((word >> G_SHIFT) & G_MASK)
    }

    /// The cell that `p` was last reached from in the current A* / Dijkstra query (`None`
    /// at the start, the one cell with g = 0, and for cells not reached).
    fn parent(&self, p: u32) -> Option<u32> {
        self.parent_move(p).map(|(q, _, _)| q)
    }

    /// [`parent`](GridSearch::parent), with the move `(dx, dy)` from it to `p`.
    fn parent_move(&self, p: u32) -> Option<(u32, i32, i32)> {
        self.g_of(p).filter(|&g| g > 0)?;
        let (dx, dy, _) = DIRS[(self.words[p as usize] >> 1) as usize & 7];
        let q = (i64::from(p) - i64::from(dy) * self.pw as i64 - i64::from(dx)) as u32;
        Some((q, dx, dy))
    }

    /// Starts a Theta* query from `s` on its own nodes (allocated by the first query),
    /// with g = 0.
    fn begin_theta(&mut self, s: u32, stats: &mut SearchStats) {
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
    fn xy(&self, p: u32) -> (u32, u32) {
        let y = ((u128::from(p) * u128::from(self.magic)) >> 64) as u32;
        (p - y * self.pw as u32, y)
    }

    /// A* (`heuristic`) or Dijkstra from `s0` to `t0` (`NONE`: no target, run until the
    /// reachable cells are exhausted) on fixed-point integer costs.
    ///
    /// Open list: the [`MinHeap`] of [`GridKey`]s (smallest f first, ties toward larger g,
    /// i.e. smaller h; `u64` keys when [`Fixed::narrow`], else `u128`), with decrease-key
    /// through `slot`, plus a stack of cells whose f equals the f being expanded: they
    /// would come out of the heap next anyway (their g is final, the heuristic being
    /// consistent), so they skip it, and runs toward the goal go depth-first. Stale
    /// entries are skipped by the closed bit.
    fn grid_search(
        &mut self,
        s0: u32,
        t0: u32,
        heuristic: bool,
    ) -> Result<GridPath, GridSearchError> {
        if self.fixed.narrow {
            self.grid_search_with::<u64>(s0, t0, heuristic)
        } else {
            self.grid_search_with::<Upper>(s0, t0, heuristic)
        }
    }

    /// [`grid_search`](GridSearch::grid_search) with open-list keys of type `K`.
    fn grid_search_with<K: GridKey>(
        &mut self,
        s0: u32,
        t0: u32,
        heuristic: bool,
    ) -> Result<GridPath, GridSearchError> {
        let mut stats = SearchStats::default();
        let fx = self.fixed;
        let (unit, diag) = (fx.unit, fx.diag);
        let four = self.options.connectivity == Connectivity::Four;
        // h = hi * c_hi + lo * c_lo over the coordinate differences; zero for Dijkstra.
        let (c_hi, c_lo) = match (heuristic, four) {
            (false, _) => (0, 0),
            (true, true) => (unit, unit),
            (true, false) => (unit, diag - unit),
        };
        let (gx, gy) = if t0 == NONE { (0, 0) } else { self.xy(t0) };
        let h = move |x: u32, y: u32| {
            let dx = (i64::from(x) - i64::from(gx)).unsigned_abs();
            let dy = (i64::from(y) - i64::from(gy)).unsigned_abs();
            let (lo, hi) = if dx < dy { (dx, dy) } else { (dy, dx) };
            hi * c_hi + lo * c_lo
        };
        let (sx, sy) = self.xy(s0);
        let h0 = h(sx, sy);
        // `base | g << G_SHIFT | d << 1` is an open word of this query with cost g reached
        // by move d, `| 1` closes it.
        let base = self.begin(s0, &mut stats);
        K::heap(&mut self.heap, &mut self.wide_heap).push(K::pack(fx, fx.order(h0, h0), s0));
        let run = Run {
            t0,
            base,
            f0: h0 >> fx.f_shift,
            pw: self.pw,
            magic: self.magic,
            fx,
            h,
        };
        let Self {
            words,
            moves,
            heap,
            wide_heap,
            stack,
            slot,
            ..
        } = self;
        let heap = K::heap(heap, wide_heap);
        match expand(
            &run, words, moves, heap, stack, slot, &mut stats, self.limit,
        ) {
            Expanded::Target(g) => {
                let cost = fx.to_cells(g);
                Ok(self.trace_words(t0, cost, stats))
            }
            Expanded::Exhausted => Err(GridSearchError::NoPath { stats }),
            Expanded::Limit => Err(GridSearchError::LimitReached { stats }),
        }
    }

    /// The A* / Dijkstra / Theta* entry point.
    fn run(
        &mut self,
        map: Option<&GridMap>,
        start: (usize, usize),
        goal: (usize, usize),
        kind: Kind,
    ) -> Result<GridPath, GridSearchError> {
        let s0 = self.check(start, true)?;
        let t0 = self.check(goal, false)?;
        match (kind, map) {
            (Kind::Astar, _) => self.grid_search(s0, t0, true),
            (Kind::Dijkstra, _) | (Kind::ThetaStar, None) => self.grid_search(s0, t0, false),
            (Kind::ThetaStar, Some(map)) => self.theta_search(map, s0, t0),
        }
    }

    /// Theta*'s loop, on `f64` costs (stored as bits in `g`) and keys of `f64` bits.
    fn theta_search(
        &mut self,
        map: &GridMap,
        s0: u32,
        t0: u32,
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
            self.theta_expand(map, p, g, &mut stats, euclid);
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
        let open = self.theta_generation;
        let pp = self.theta_nodes[pu].parent;
        for &(q, c) in &moves[..k] {
            let qu = q as usize;
            let st = self.theta_nodes[qu].stamp;
            if st == open | CLOSED {
                continue;
            }
            let (mut ng, mut parent) = (g + c, p);
            if pp != NONE && self.line_of_sight(map, pp, q) {
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
    /// cells (corner touches included).
    fn line_of_sight(&self, map: &GridMap, a: u32, b: u32) -> bool {
        let (a, b) = (self.cell(a), self.cell(b));
        let (pa, pb) = (map.cell_center(a.0, a.1), map.cell_center(b.0, b.1));
        map.segment_cells(pa, pb, |i, j| self.cell_passable(i, j))
    }

    /// The path to `t` of a Theta* query, by parent links.
    fn trace(&self, t: u32, cost: f64, stats: SearchStats) -> GridPath {
        let mut cells = Vec::new();
        let mut p = t;
        while p != NONE {
            cells.push(self.cell(p));
            p = self.theta_nodes[p as usize].parent;
        }
        cells.reverse();
        GridPath { cells, cost, stats }
    }

    /// The path to `t` of an A* / Dijkstra query, by the parent moves in the words.
    fn trace_words(&self, t: u32, cost: f64, stats: SearchStats) -> GridPath {
        let (mut i, mut j) = self.cell(t);
        let mut cells = vec![(i, j)];
        let mut p = t;
        while let Some((q, dx, dy)) = self.parent_move(p) {
            i = i.wrapping_add_signed(-dx as isize);
            j = j.wrapping_add_signed(-dy as isize);
            cells.push((i, j));
            p = q;
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

/// The search state of one cell, valid in the current query only if `stamp` (without the
/// closed bit) is the current generation.
#[derive(Debug, Clone, Copy)]
struct Node {
    /// Cost so far: fixed point (see [`Fixed`]) for A* and Dijkstra, `f64` bits for Theta*.
    g: u64,
    /// The cell it was reached from ([`NONE`] for the start).
    parent: u32,
    /// Generation of the last query that reached it, plus the [`CLOSED`] bit.
    stamp: u32,
}

/// Theta*'s open-list key: one `u128` compared as an integer, smallest first. From the
/// top: the bits of `f` (non-negative `f64` bits sort as the numbers do), the complement of
/// `g` as `f32` bits (ties on `f` go to the larger `g`; `f32` is only a tie-breaker, the
/// order on `f` stays exact), and the cell index.
#[inline(always)]
fn float_key(f: f64, g: f64, p: u32) -> u128 {
    (u128::from(f.to_bits()) << 64) | (u128::from(!(g as f32).to_bits()) << 32) | u128::from(p)
}

/// The fixed inputs of [`expand`].
struct Run<H> {
    /// Target cell (`NONE`: none).
    t0: u32,
    /// The query's base word ([`GridSearch::base`]).
    base: u64,
    /// `f >> f_shift` of the start.
    f0: u64,
    pw: usize,
    magic: u64,
    fx: Fixed,
    /// Heuristic at padded coordinates.
    h: H,
}

/// How [`expand`] ended.
enum Expanded {
    /// The target was taken from the open list with this g.
    Target(u64),
    /// The open list ran out.
    Exhausted,
    /// The search's limit was reached first.
    Limit,
}

/// The loop of A* / Dijkstra (see [`GridSearch::grid_search`]) on the query's arrays,
/// passed apart so that nothing else can alias them: expands cells until the target is
/// taken from the open list (its g), the open list runs out, or the limit is reached.
#[inline]
#[expect(
    clippy::too_many_arguments,
    reason = "the arrays are passed apart, see above"
)]
fn expand<K: GridKey, H: Fn(u32, u32) -> u64>(
    run: &Run<H>,
    words: &mut [u64],
    moves: &[u8],
    heap: &mut MinHeap<K>,
    stack: &mut Vec<u32>,
    slot: &mut [u32],
    stats: &mut SearchStats,
    limit: Limit,
) -> Expanded {
    let mut check_at = limit.next_check(stats.expansions);
    let Run {
        t0,
        base,
        f0,
        pw,
        magic,
        fx,
        ref h,
    } = *run;
    let (unit, diag) = (fx.unit, fx.diag);
    // Every word above this one belongs to an earlier query.
    let last = base | ((1 << GEN_SHIFT) - 1);
    // The f of the cell being expanded, as the key holds it (`f >> f_shift`): every cell
    // on the stack has it.
    let mut f_cur = f0;
    // Keeps `slot` up to date as the heap moves keys.
    macro_rules! place {
        () => {
            &mut |k: K, i: usize| slot[k.cell(fx) as usize] = i as u32
        };
    }
    // The heap's root is the cell being expanded (taken but not yet removed): the first
    // successor that goes to the heap replaces it (one sift instead of a pop and a push).
    let mut taken = false;
    loop {
        let p = if let Some(p) = stack.pop() {
            p
        } else {
            if taken {
                heap.pop_placed(place!());
            }
            let Some(k) = heap.peek() else {
                break;
            };
            taken = true;
            f_cur = k.order(fx) >> fx.tie_bits;
            k.cell(fx)
        };
        let pu = p as usize;
        let word = words[pu];
        // Already closed: a stale entry. Queued cells are lowered in place, but a cell
        // whose lower f sends it to the stack leaves its heap entry behind (and, when f
        // values closer than the key's quantum were ordered wrongly, a closed cell can be
        // reopened and queued again).
        if word & 1 != 0 {
            continue;
        }
        words[pu] = word | 1;
        let g = (word >> G_SHIFT) & G_MASK;
        if p == t0 {
            return Expanded::Target(g);
        }
        if stats.expansions >= check_at {
            if limit.spent(stats.expansions) {
                return Expanded::Limit;
            }
            check_at = limit.next_check(stats.expansions);
        }
        stats.expansions += 1;
        let y = ((u128::from(p) * u128::from(magic)) >> 64) as u32;
        let x = p - y * pw as u32;
        let mask = moves[pu];
        // The 3 x 3 block around p as three rows of three words (south, middle, north),
        // so that the moves below index them with constants.
        let (below, rest) = words.split_at_mut(pu - 1);
        let (mid, above) = rest.split_at_mut(3);
        let (Some(south), Some(mid), Some(north)) = (
            below[pu - pw - 1..].first_chunk_mut::<3>(),
            mid.first_chunk_mut::<3>(),
            above[pw - 3..].first_chunk_mut::<3>(),
        ) else {
            // p is an inner cell of the padded grid: its 3 x 3 block exists.
            continue;
        };
        // One move: whether it is legal (all ones if not), word, bit, padded index, cost,
        // (dx, dy).
        macro_rules! relax {
            ($illegal:expr, $word:expr, $bit:expr, $q:expr, $cost:expr, $dx:expr, $dy:expr) => {{
                let word = &mut $word;
                let ng = g + $cost;
                // Relax a legal move unless q has a g from this query at least as
                // good (open, or closed: a closed cell's g is final, so never
                // worse). With the bits below g all set in `test`, one comparison
                // says it (a word of an earlier query is above every word of this
                // one, a blocked cell's word is 0, below every test), and an illegal
                // move's test is all ones, above every word. The word is read even
                // for an illegal move (it exists: the padded border), so that one
                // branch decides.
                let test = base | (ng << G_SHIFT) | ((1 << G_SHIFT) - 1) | $illegal;
                if test < *word {
                    stats.reached += u64::from(*word > last);
                    *word = (test & !((1 << G_SHIFT) - 1)) | ($bit << 1);
                    let q: u32 = $q;
                    let hq = h(x.wrapping_add_signed($dx), y.wrapping_add_signed($dy));
                    // The heuristic is consistent and the arithmetic exact, so
                    // f >= f_cur.
                    if (ng + hq) >> fx.f_shift <= f_cur {
                        stack.push(q);
                    } else {
                        let key = K::pack(fx, fx.order(ng + hq, hq), q);
                        // Already queued (its g dropped): lower its key in place. The
                        // taken root is on its way out, so it does not count.
                        // (`K::MAX` holds no cell: the border cell with the last index
                        // is never queued.)
                        let i = slot[q as usize] as usize;
                        let queued = (heap.at(i).cell(fx) == q) & ((i != 0) | !taken);
                        if queued {
                            heap.decrease_placed(i, key, place!());
                        } else if taken {
                            heap.replace_top_placed(key, place!());
                            taken = false;
                        } else {
                            heap.push_placed(key, place!());
                        }
                    }
                    stats.pushes += 1;
                }
            }};
        }
        let pw32 = pw as u32;
        // The order of `DIRS`: E, W, N, S, NE, NW, SE, SW.
        // A straight move is legal exactly when its cell is passable, which the blocked
        // word says; a diagonal also needs the corner rule, which the mask says.
        let illegal = |bit: u8| u64::from((mask >> bit) & 1 ^ 1).wrapping_neg();
        relax!(0, mid[2], 0, p + 1, unit, 1, 0);
        relax!(0, mid[0], 1, p - 1, unit, -1, 0);
        relax!(0, north[1], 2, p + pw32, unit, 0, 1);
        relax!(0, south[1], 3, p - pw32, unit, 0, -1);
        relax!(illegal(4), north[2], 4, p + pw32 + 1, diag, 1, 1);
        relax!(illegal(5), north[0], 5, p + pw32 - 1, diag, -1, 1);
        relax!(illegal(6), south[2], 6, p - pw32 + 1, diag, 1, -1);
        relax!(illegal(7), south[0], 7, p - pw32 - 1, diag, -1, -1);
    }
    Expanded::Exhausted
}

/// The open-list key of A* and Dijkstra: the order ([`Fixed::order`]: f, then the
/// tie-break on h) above the cell, in one `u64` on grids where both fit
/// ([`Fixed::narrow`]), else in the two halves of a `u128` ordered by its upper half.
trait GridKey: HeapKey {
    /// The key of cell `p` with order field `order`.
    fn pack(fx: Fixed, order: u64, p: u32) -> Self;
    /// The order field.
    fn order(self, fx: Fixed) -> u64;
    /// The cell.
    fn cell(self, fx: Fixed) -> u32;
    /// The open list of this key type.
    fn heap<'a>(
        narrow: &'a mut MinHeap<u64>,
        wide: &'a mut MinHeap<Upper>,
    ) -> &'a mut MinHeap<Self>;
}

impl GridKey for u64 {
    #[inline(always)]
    fn pack(fx: Fixed, order: u64, p: u32) -> Self {
        (order << fx.cell_bits) | u64::from(p)
    }
    #[inline(always)]
    fn order(self, fx: Fixed) -> u64 {
        self >> fx.cell_bits
    }
    #[inline(always)]
    fn cell(self, fx: Fixed) -> u32 {
        (self & ((1 << fx.cell_bits) - 1)) as u32
    }
    fn heap<'a>(narrow: &'a mut MinHeap<u64>, _: &'a mut MinHeap<Upper>) -> &'a mut MinHeap<Self> {
        narrow
    }
}

impl GridKey for Upper {
    #[inline(always)]
    fn pack(_: Fixed, order: u64, p: u32) -> Self {
        Upper((u128::from(order) << 64) | u128::from(p))
    }
    #[inline(always)]
    fn order(self, _: Fixed) -> u64 {
        (self.0 >> 64) as u64
    }
    #[inline(always)]
    fn cell(self, _: Fixed) -> u32 {
        self.0 as u32
    }
    fn heap<'a>(_: &'a mut MinHeap<u64>, wide: &'a mut MinHeap<Upper>) -> &'a mut MinHeap<Self> {
        wide
    }
}

/// Fixed-point costs of A* and Dijkstra: a straight move costs `unit = 2^k` and a diagonal
/// `diag`, the odd integer nearest to `sqrt(2) * 2^k` (relative error below `2^-k`), with
/// `k = 32` below 2^19 padded cells and smaller above so that g fits the 52 bits of its
/// field in a cell's word.
///
/// Sums are exact, so the octile heuristic in the same units is exactly consistent. A cost
/// `a * unit + b * diag` (a straight moves, b diagonals) determines `(a, b)` (diag is odd and
/// `b < 2^k`), so equal integer costs are equal real costs, and
/// [`to_cells`](Fixed::to_cells) returns `a + b * sqrt 2` exactly as `f64` sums it. Two
/// real path lengths closer than the approximation error (`b * 2^-k`) could be ordered
/// wrongly; for that, `|a' + b' sqrt 2|` must fall below `b 2^-k` for some integers of
/// that size, which needs `b` around `2^(k/2)` (65,536 diagonals at k = 32).
#[derive(Debug, Clone, Copy)]
struct Fixed {
    /// `k`.
    shift: u32,
    /// Cost of a straight move, `2^k`.
    unit: u64,
    /// Cost of a diagonal move.
    diag: u64,
    /// Inverse of `diag` modulo 2^64.
    inv_diag: u64,
    /// Right shift of f for the f field of the order.
    f_shift: u32,
    /// Right shift of h for the tie-break field of the order.
    h_shift: u32,
    /// Bits of the tie-break field.
    tie_bits: u32,
    /// Whether the open-list keys are `u64` (order above `cell_bits` bits of cell).
    narrow: bool,
    /// Bits of the cell in a `u64` key.
    cell_bits: u32,
}

impl Fixed {
    /// The scale for a padded grid of `pw x ph` cells.
    fn new(pw: usize, ph: usize) -> Self {
        let n = pw * ph;
        // Any path visits each cell at most once, so g < n * diag < n * 2^(k + 1) <=
        // 2^(bits(n) + k + 1), which must fit the word's g field, and
        // f = g + h < 2 n 2^(k + 1) <= 2^(bits(n) + k + 2) <= 2^64.
        let bits = usize::BITS - n.leading_zeros();
        let shift = (GEN_SHIFT - G_SHIFT - 1).saturating_sub(bits).min(32);
        let unit = 1u64 << shift;
        let diag = ((std::f64::consts::SQRT_2 * unit as f64).round() as u64) | 1;
        // Newton's iteration for the inverse of an odd number modulo 2^64.
        let mut inv_diag = diag;
        for _ in 0..6 {
            inv_diag = inv_diag.wrapping_mul(2u64.wrapping_sub(diag.wrapping_mul(inv_diag)));
        }
        // h <= (pw + ph) * diag < (pw + ph) * 2^(k + 1).
        let h_bits = usize::BITS - (pw + ph).leading_zeros() + shift + 1;
        // The f field quantum is 2^(bits(n) + 2 - f_bits) cells: a `u64` key is used when
        // f gets at least bits(n) + 18 bits (a quantum of 2^-16 cells or finer) besides
        // the cell and at least 8 bits of tie-break.
        let cell_bits = usize::BITS - (n - 1).leading_zeros();
        let spare = (64 - cell_bits).saturating_sub(bits + 18);
        let narrow = spare >= 8;
        let (f_bits, tie_bits) = if narrow {
            let tie_bits = spare.min(16);
            (64 - cell_bits - tie_bits, tie_bits)
        } else {
            (40, 24)
        };
        Self {
            shift,
            unit,
            diag,
            inv_diag,
            f_shift: (bits + shift + 2).saturating_sub(f_bits),
            h_shift: h_bits.saturating_sub(tie_bits),
            tie_bits,
            narrow,
            cell_bits,
        }
    }

    /// The order of a cell with f and h (fixed point) in the open list: the top bits of f,
    /// then the top `tie_bits` bits of h (ties on f go to the smaller h, that is, the
    /// larger g). With `u64` keys the cell's bits follow (so the order of equal fields is
    /// by cell); with `u128` keys the order is the upper half, and equal ones come out in
    /// any order.
    ///
    /// Truncating f merges only f values less than `2^f_shift` units apart: 2^-18 cells on
    /// the peers' 101 x 101 maze, 2^-22 on the MovingAI arena, at most 2^-16 wherever keys
    /// are `u64` (up to about 2^19 padded cells), and 2^-16 cells at 2^22 cells with
    /// `u128` keys. Distinct lengths `a + b sqrt 2` of paths with fewer than about 10^4
    /// diagonals lie further apart than that, so there the order is exact; otherwise a
    /// cell may come out before one whose f is smaller by less than the quantum (a closed
    /// cell that later gets a smaller g is reopened), and the cost is within the quantum
    /// of the optimum. Truncating h only coarsens the tie-break.
    #[inline(always)]
    fn order(self, f: u64, h: u64) -> u64 {
        // h < 2^(h_shift + tie_bits), so the tie field holds it.
        ((f >> self.f_shift) << self.tie_bits) | (h >> self.h_shift)
    }

    /// A fixed-point cost in cells: `a + b * sqrt 2` for `cost = a * unit + b * diag`.
    fn to_cells(self, cost: u64) -> f64 {
        let b = cost.wrapping_mul(self.inv_diag) & (self.unit - 1);
        let a = cost.wrapping_sub(b.wrapping_mul(self.diag)) >> self.shift;
        a as f64 + b as f64 * SQRT2
    }
}
