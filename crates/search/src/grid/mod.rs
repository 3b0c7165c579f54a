//! Flat-array A*, Dijkstra and Theta* on a [`GridMap`], with scratch memory reused across
//! queries.
//!
//! - this file: the move rules ([`GridOptions`], [`Connectivity`]), results and errors,
//!   and [`GridSearch`] (the scratch grid, its preparation from a map, limits);
//! - `astar`: [`GridSearch::astar`]; `dijkstra`: [`GridSearch::dijkstra`];
//!   `theta_star`: [`GridSearch::theta_star`] and its line-of-sight expansion;
//! - `cost_field`: [`GridSearch::cost_to_go`] and [`CostField`];
//! - `jps`: [`JumpPointSearch`], jump point search over packed bit rows;
//! - `engine`: the packed A*/Dijkstra engine the first three share (one word per cell,
//!   the heap keys, the expansion loop).

use std::time::Instant;

use envmap::GridMap;

use crate::SearchStats;
use crate::heap::{HeapKey, MinHeap, QuadHeap, Upper};

mod astar;
mod bits;
mod connected;
mod cost_field;
mod dijkstra;
mod engine;
mod jps;
mod theta_star;

pub use cost_field::CostField;
use engine::*;
pub use jps::{JpsError, JumpPointSearch};

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

/// Which search [`GridSearch::run`] performs.
#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Astar,
    Dijkstra,
    ThetaStar,
    /// With the heuristic's weight (1: Lazy Theta* itself).
    LazyThetaStar(f64),
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
/// keeps its capacity across queries too). The first Theta* query adds 16 bytes per cell,
/// the first [`connected`](GridSearch::connected) query 3 bits (the passable cells and
/// each side's reached cells, a bit each).
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
    /// Theta*'s per-cell stamps: the generation of the last query that reached the cell,
    /// plus the [`CLOSED`] bit; a cell's parent and g are valid in the current query only
    /// where its stamp (without the bit) is the current generation. Kept apart from the
    /// parents and costs, so that the eight neighbours' stamps an expansion reads first
    /// take 4 bytes a cell. (All three allocated by Theta*'s first query.)
    theta_stamps: Vec<u32>,
    /// Theta*'s parent of each cell ([`NONE`] for the start).
    theta_parents: Vec<u32>,
    /// Theta*'s cost so far of each cell, `f64` bits.
    theta_g: Vec<u64>,
    /// Query counter of `theta_stamps`.
    theta_generation: u32,
    /// The passable cells as bit lines and their slides, which Theta*'s lines of sight read
    /// (built by its first query after the passable cells were last read).
    theta_bits: Option<theta_star::SightBits>,
    /// The fixed-point cost scale of this grid's size.
    fixed: Fixed,
    /// `u64::MAX / pw + 1`: divides a padded index by `pw` with one multiplication.
    magic: u64,
    /// Open list of A* and Dijkstra on grids whose keys fit 64 bits (see [`Fixed`]).
    heap: MinHeap<u64>,
    /// Open list of A* and Dijkstra on larger grids.
    wide_heap: MinHeap<Upper>,
    /// Dijkstra's open list.
    buckets: Buckets,
    /// Open list of Theta* (ordered by the whole [`float_key`]).
    theta_heap: QuadHeap<u64>,
    /// Cells whose f is not above the f of the cell being expanded: they come next anyway,
    /// so they skip the heap (see [`GridSearch::grid_search`]).
    stack: Vec<u32>,
    /// Where each cell's key sits in the A* / Dijkstra open list, if it is there (checked
    /// against the key before use, so stale values are harmless).
    slot: Vec<u32>,
    /// When a search gives up (none by default).
    limit: Limit,
    /// Scratch of [`connected`](GridSearch::connected) (allocated by its first query).
    reach: connected::Reach,
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

hyplan_core::grid_size!(GridSearch);

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
            theta_stamps: Vec::new(),
            theta_parents: Vec::new(),
            theta_g: Vec::new(),
            theta_generation: 0,
            theta_bits: None,
            fixed: Fixed::new(pw, height + 2),
            magic: u64::MAX / pw as u64 + 1,
            heap: MinHeap::default(),
            wide_heap: MinHeap::default(),
            buckets: Buckets::default(),
            theta_heap: QuadHeap::default(),
            stack: Vec::new(),
            slot: vec![0; n],
            limit: Limit {
                max_expansions: u64::MAX,
                deadline,
            },
            reach: connected::Reach::default(),
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
        self.refresh(map, 0..map.width(), 0..map.height())?;
        self.reset_words();
        Ok(())
    }

    /// [`update`](GridSearch::update) for a map that differs from the one of the last
    /// update (or [`new`](GridSearch::new)) only in the cells of `columns` x `rows`, at a
    /// cost set by the window rather than the map; the same later searches as `update`.
    /// (A map with another `blocked_from` differs everywhere.)
    ///
    /// ```
    /// use envmap::GridMap;
    /// use search::{GridOptions, GridSearch};
    /// let mut map = GridMap::from_ascii(".....\n.....\n.....").unwrap();
    /// let mut search = GridSearch::new(&map, GridOptions::default()).unwrap();
    /// // A wall across the middle column leaves no way from left to right.
    /// for j in 0..3 {
    ///     map.zones_mut()[j * 5 + 2] = hyplan_core::Zone::Forbidden;
    /// }
    /// search.update_window(&map, 2..3, 0..3).unwrap();
    /// assert!(search.astar((0, 1), (4, 1)).is_err());
    /// ```
    ///
    /// # Errors
    ///
    /// As [`update`](GridSearch::update).
    pub fn update_window(
        &mut self,
        map: &GridMap,
        columns: std::ops::Range<usize>,
        rows: std::ops::Range<usize>,
    ) -> Result<(), GridSearchError> {
        let columns = columns.start.min(self.width)..columns.end.min(self.width);
        let rows = rows.start.min(self.height)..rows.end.min(self.height);
        self.refresh(map, columns.clone(), rows.clone())?;
        // Words of cells whose passability may have changed; the others keep their
        // (older-generation) words, which later queries read as "not reached".
        for j in rows {
            let base = (j + 1) * self.pw + 1;
            for p in base + columns.start..base + columns.end {
                self.words[p] = if self.passable[p] { u64::MAX } else { 0 };
            }
        }
        Ok(())
    }

    /// Re-reads the passable cells of `columns` x `rows` (inside the grid) and the moves
    /// of those cells and of their neighbours.
    fn refresh(
        &mut self,
        map: &GridMap,
        columns: std::ops::Range<usize>,
        rows: std::ops::Range<usize>,
    ) -> Result<(), GridSearchError> {
        same_size((self.width, self.height), map)?;
        if columns.is_empty() || rows.is_empty() {
            return Ok(());
        }
        self.theta_bits = None;
        // The clock is read every 64 rows (a grid being built for a deadline).
        let deadline = self.limit.deadline;
        let late = |j: usize| j.is_multiple_of(64) && deadline.is_some_and(|d| Instant::now() >= d);
        let stop = Err(GridSearchError::LimitReached {
            stats: SearchStats::default(),
        });
        let blocked = map.blocked_from;
        let zones = map.zones();
        for j in rows.clone() {
            if late(j) {
                return stop;
            }
            let row = &zones[j * self.width + columns.start..j * self.width + columns.end];
            let base = (j + 1) * self.pw + 1 + columns.start;
            for (cell, &zone) in self.passable[base..base + row.len()].iter_mut().zip(row) {
                *cell = zone < blocked;
            }
            // Written here once (any value is a valid hint), so that a query does not wait
            // on the system for the first touch of each of its pages: on a 4096 x 4096 map
            // that was most of a short query's first run.
            self.slot[base..base + row.len()].fill(0);
            self.reach.refresh(
                &self.passable,
                self.pw,
                columns.start + 1..columns.end + 1,
                j + 1..j + 2,
            );
        }
        let (pw, pass) = (self.pw, &self.passable);
        let eight = self.options.connectivity == Connectivity::Eight;
        let cut = self.options.corner_cutting;
        // Padded coordinates: the window's cells are 1 + their own, and their neighbours'
        // moves change with them.
        let (i_lo, i_hi) = (columns.start.max(1), (columns.end + 1).min(self.width));
        let (j_lo, j_hi) = (rows.start.max(1), (rows.end + 1).min(self.height));
        for j in j_lo..=j_hi {
            if late(j) {
                return stop;
            }
            for i in i_lo..=i_hi {
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

    /// Sets every word to "not reached": `u64::MAX` (above the words of every query) on
    /// passable cells, and 0 on blocked ones and the border (below every move's test, so
    /// no move into them improves anything).
    fn reset_words(&mut self) {
        for (word, &free) in self.words.iter_mut().zip(&self.passable) {
            *word = if free { u64::MAX } else { 0 };
        }
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

    /// The path to `t` of a Theta* query, by parent links.
    fn trace(&self, t: u32, cost: f64, stats: SearchStats) -> GridPath {
        let mut cells = Vec::new();
        let mut p = t;
        while p != NONE {
            cells.push(self.cell(p));
            p = self.theta_parents[p as usize];
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

/// [`GridSearchError::SizeMismatch`] unless `map` is `width x height` cells (a search
/// brought up to date with another map than the one it was built for).
pub(super) fn same_size(
    (width, height): (usize, usize),
    map: &GridMap,
) -> Result<(), GridSearchError> {
    if map.width() == width && map.height() == height {
        Ok(())
    } else {
        Err(GridSearchError::SizeMismatch {
            width,
            height,
            got_width: map.width(),
            got_height: map.height(),
        })
    }
}

/// A test map of `w x h` unit cells, blocked where `blocked` says (row-major from the
/// bottom row).
#[cfg(test)]
fn test_map(w: usize, h: usize, blocked: impl IntoIterator<Item = bool>) -> GridMap {
    use hyplan_core::{Point2, Zone};
    let zones = blocked
        .into_iter()
        .map(|b| if b { Zone::Forbidden } else { Zone::Free })
        .collect();
    GridMap::from_zones(w, h, 1.0, Point2::origin(), zones).unwrap()
}
