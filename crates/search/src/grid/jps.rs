//! Jump point search on uniform-cost 8-connected grids without corner cutting, with the
//! straight jumps scanned 64 cells at a time over packed bit lines.
//!
//! Harabor and Grastien, "Online Graph Pruning for Pathfinding on Grid Maps" (AAAI 2011)
//! for the pruning and the jumps; "Improving Jump Point Search" (ICAPS 2014) for the
//! block-based scans, the pruning of intermediate (diagonal) jump points and the
//! no-corner-cutting rules used here.

use std::time::Instant;

use envmap::GridMap;

use super::bits::{BitGrid, Lines, PAD};
use super::{
    CLOSED, Connectivity, DIRS, Fixed, GridKey, GridOptions, GridPath, GridSearchError, Limit,
    NONE, directions,
};
use crate::SearchStats;
use crate::heap::{QuadHeap, Upper};

/// Why a [`JumpPointSearch`] cannot be prepared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum JpsError {
    /// The move rules are not the ones jump point search prunes: uniform costs on
    /// 8-connected moves without corner cutting (MovingAI's rules). Grid A* handles them.
    #[error(
        "jump point search does not apply to {rule}: it needs uniform-cost 8-connected moves \
         without corner cutting; use the `astar` planner"
    )]
    NotApplicable {
        /// The rule that rules it out (`4-connected moves`, `corner cutting`).
        rule: &'static str,
    },
    /// The map is too large, or the preparation's deadline passed
    /// ([`GridSearchError::MapTooLarge`], [`GridSearchError::LimitReached`]).
    #[error(transparent)]
    Grid(#[from] GridSearchError),
}

/// Jump point search (JPS): the optimal paths of [`GridSearch::astar`](super::GridSearch::astar)
/// on 8-connected grids without corner cutting, expanding only jump points.
///
/// A straight or diagonal run is not expanded cell by cell: from each expanded cell the
/// search jumps along the directions the pruning rules keep, to the next cell where an
/// optimal path may turn (a free cell beside the run whose neighbour behind it is blocked,
/// a "forced neighbour"), the goal, or a wall. A diagonal jump runs a straight jump along
/// each of its two components at every step, and what those find becomes a successor
/// directly (reached by the diagonal moves, then the straight ones), the diagonal cells
/// themselves not being generated (intermediate pruning). On open maps, rooms and mazes
/// this expands a small fraction of A*'s cells for the same cost; on random obstacles
/// (20-35 % blocked), where jump points are dense, it is about as fast as A*.
///
/// The search ends as soon as the goal is found: a goal reached by a jump from the
/// expanded cell (tried toward the goal first), or from the start by its octile path
/// (diagonal moves, then straight ones, all free), costs the least f left, so that path
/// is optimal; short queries on open maps then cost one expansion or none.
///
/// [`new`](JumpPointSearch::new) **prepares the map once**: which cells are free, packed
/// one bit per cell in rows and again in columns (the transpose), with a blocked border.
/// A straight jump then reads three 64-bit windows (its line and the two beside it) per 63
/// cells and finds the first wall or forced neighbour with one `trailing_zeros` (or
/// `leading_zeros` going back); along a diagonal jump, the straight jumps of one step
/// reuse the previous step's windows and read one new window each. Per-cell search state (g, parent and a query stamp in one
/// `u128`: 16 bytes per padded cell, allocated zeroed so untouched pages cost nothing) is
/// reset by bumping the query's generation, so a query costs what it touches, not the
/// map's size.
///
/// # Costs
///
/// As [`GridSearch`](super::GridSearch): 1 per straight move, sqrt 2 per diagonal, summed
/// in the same fixed point, so the cost returned equals A*'s exactly. The path lists every
/// cell from start to goal (the moves between jump points filled in); `stats.expansions`
/// counts the jump points expanded.
///
/// # Example
///
/// ```
/// use envmap::GridMap;
/// use search::{GridOptions, GridSearch, JumpPointSearch};
/// let map = GridMap::from_ascii("
///     ........
///     .######.
///     ........
/// ")?;
/// let mut jps = JumpPointSearch::new(&map, GridOptions::default())?;
/// let path = jps.search((0, 1), (7, 1))?;
/// let astar = GridSearch::new(&map, GridOptions::default())?.astar((0, 1), (7, 1))?;
/// assert_eq!(path.cost, astar.cost);
/// assert_eq!(path.cells.len(), astar.cells.len());
/// assert!(path.stats.expansions < astar.stats.expansions);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct JumpPointSearch {
    width: usize,
    height: usize,
    /// Padded width, `width + 2`.
    pw: usize,
    bits: BitGrid,
    /// Per-cell search state, one [`State`] each.
    states: Vec<u128>,
    /// Query counter (1 to `CLOSED - 1`).
    generation: u32,
    fixed: Fixed,
    /// Open list on grids whose keys fit 64 bits ([`Fixed::narrow`]; as A*'s: f, then h
    /// for ties toward the larger g, then the cell).
    heap: QuadHeap<u64>,
    /// Open list on larger grids.
    wide_heap: QuadHeap<Upper>,
    /// The successors of the jump point being expanded (kept for its capacity).
    found: Vec<(usize, usize)>,
    /// Jump points whose f equals the f being expanded (kept for its capacity).
    stack: Vec<u32>,
    limit: Limit,
}

hyplan_core::grid_size!(JumpPointSearch);

impl JumpPointSearch {
    /// Prepares jump point searches on `map` (which cells block: the map's
    /// [`blocked_from`](GridMap::blocked_from)). Later changes to the map are not seen.
    ///
    /// # Errors
    ///
    /// [`JpsError::NotApplicable`] unless `options` are 8-connected without corner cutting
    /// (the default); [`JpsError::Grid`] with [`GridSearchError::MapTooLarge`] when the
    /// padded grid has `2^32 - 1` cells or more.
    pub fn new(map: &GridMap, options: GridOptions) -> Result<Self, JpsError> {
        Self::new_until(map, options, None)
    }

    /// [`new`](JumpPointSearch::new), giving up once `deadline` has passed (the
    /// preparation reads every cell); the deadline is also set as the searches' limit.
    ///
    /// # Errors
    ///
    /// As [`new`](JumpPointSearch::new), and [`GridSearchError::LimitReached`] (no
    /// expansion) when the deadline passes first.
    pub fn new_until(
        map: &GridMap,
        options: GridOptions,
        deadline: Option<Instant>,
    ) -> Result<Self, JpsError> {
        Self::check_options(options)?;
        let (width, height) = (map.width(), map.height());
        let (pw, ph) = (width + 2, height + 2);
        let n = pw
            .checked_mul(ph)
            .filter(|&n| n < NONE as usize)
            .ok_or(GridSearchError::MapTooLarge { width, height })?;
        let mut bits = BitGrid::new(pw, ph);
        let blocked = map.blocked_from;
        for (j, row) in map.zones().chunks_exact(width.max(1)).enumerate() {
            if j.is_multiple_of(64) && deadline.is_some_and(|d| Instant::now() >= d) {
                return Err(GridSearchError::LimitReached {
                    stats: SearchStats::default(),
                }
                .into());
            }
            for (i, &zone) in row.iter().enumerate() {
                if zone < blocked {
                    bits.set_free(i + 1, j + 1);
                }
            }
        }
        let fixed = Fixed::new(pw, ph);
        Ok(Self {
            width,
            height,
            pw,
            bits,
            // Zeroed: the allocator hands out untouched pages.
            states: vec![0; n],
            generation: 0,
            fixed,
            heap: QuadHeap::default(),
            wide_heap: QuadHeap::default(),
            found: Vec::new(),
            stack: Vec::new(),
            limit: Limit {
                max_expansions: u64::MAX,
                deadline,
            },
        })
    }

    /// Re-reads which cells of `columns` x `rows` are passable from `map`, which
    /// differs from the map of [`new`](JumpPointSearch::new) (or the last update) only
    /// there, at a cost set by the window rather than the map. (A map with another
    /// `blocked_from` differs everywhere.)
    ///
    /// ```
    /// use envmap::GridMap;
    /// use search::{GridOptions, JumpPointSearch};
    /// let mut map = GridMap::from_ascii(".....\n.....\n.....").unwrap();
    /// let mut jps = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
    /// // A wall across the middle column leaves no way from left to right.
    /// for j in 0..3 {
    ///     map.zones_mut()[j * 5 + 2] = hyplan_core::Zone::Forbidden;
    /// }
    /// jps.update_window(&map, 2..3, 0..3).unwrap();
    /// assert!(jps.search((0, 1), (4, 1)).is_err());
    /// ```
    ///
    /// # Errors
    ///
    /// [`GridSearchError::SizeMismatch`] if `map` has another size than the one this
    /// search was built for.
    pub fn update_window(
        &mut self,
        map: &GridMap,
        columns: std::ops::Range<usize>,
        rows: std::ops::Range<usize>,
    ) -> Result<(), GridSearchError> {
        super::same_size((self.width, self.height), map)?;
        let columns = columns.start.min(self.width)..columns.end.min(self.width);
        let blocked = map.blocked_from;
        for j in rows.start.min(self.height)..rows.end.min(self.height) {
            let row = &map.zones()[j * self.width..(j + 1) * self.width];
            for i in columns.clone() {
                if row[i] < blocked {
                    self.bits.set_free(i + 1, j + 1);
                } else {
                    self.bits.set_blocked(i + 1, j + 1);
                }
            }
        }
        Ok(())
    }

    /// Whether jump point search applies to the move rules `options`.
    ///
    /// ```
    /// use search::{Connectivity, GridOptions, JpsError, JumpPointSearch};
    /// assert!(JumpPointSearch::check_options(GridOptions::default()).is_ok());
    /// let four = GridOptions { connectivity: Connectivity::Four, ..GridOptions::default() };
    /// let e = JumpPointSearch::check_options(four).unwrap_err();
    /// assert!(matches!(e, JpsError::NotApplicable { .. }));
    /// assert!(e.to_string().contains("astar"));
    /// ```
    ///
    /// # Errors
    ///
    /// [`JpsError::NotApplicable`] for 4-connected moves or corner cutting.
    pub fn check_options(options: GridOptions) -> Result<(), JpsError> {
        if options.connectivity == Connectivity::Four {
            return Err(JpsError::NotApplicable {
                rule: "4-connected moves",
            });
        }
        if options.corner_cutting {
            return Err(JpsError::NotApplicable {
                rule: "corner cutting",
            });
        }
        Ok(())
    }

    /// Makes later searches stop with [`GridSearchError::LimitReached`] after
    /// `max_expansions` jump points expanded or once `deadline` has passed (the clock is
    /// read every 1024 expansions). `u64::MAX` and `None` (the default) never stop early.
    pub fn set_limit(&mut self, max_expansions: u64, deadline: Option<Instant>) {
        self.limit = Limit {
            max_expansions,
            deadline,
        };
    }

    /// Whether cell `(i, j)` is inside the map and passable.
    #[must_use]
    pub fn cell_passable(&self, i: usize, j: usize) -> bool {
        i < self.width && j < self.height && self.bits.free(i + 1, j + 1)
    }

    /// Optimal path from `start` to `goal` (cells `(i, j)`, row from the bottom), with the
    /// cost [`GridSearch::astar`](super::GridSearch::astar) finds.
    ///
    /// # Errors
    ///
    /// Start or goal outside the map or blocked; [`GridSearchError::NoPath`] when every
    /// jump point reachable from the start was expanded; [`GridSearchError::LimitReached`]
    /// when the limit ([`set_limit`](JumpPointSearch::set_limit)) ran out first.
    pub fn search(
        &mut self,
        start: (usize, usize),
        goal: (usize, usize),
    ) -> Result<GridPath, GridSearchError> {
        let s = self.check(start, true)?;
        let t = self.check(goal, false)?;
        if self.fixed.narrow {
            self.search_with::<u64>(s, t)
        } else {
            self.search_with::<Upper>(s, t)
        }
    }

    /// [`search`](JumpPointSearch::search) between padded cells `s` and `t` with open-list
    /// keys of type `K`.
    fn search_with<K: GridKey>(
        &mut self,
        s: (usize, usize),
        t: (usize, usize),
    ) -> Result<GridPath, GridSearchError> {
        let mut stats = SearchStats::default();
        let generation = self.begin();
        let (fx, pw) = (self.fixed, self.pw);
        let h = |x: usize, y: usize| octile(fx, x.abs_diff(t.0), y.abs_diff(t.1));
        let key = |g: u64, hq: u64, p: usize| K::pack(fx, fx.order(g + hq, hq), p as u32);
        let (sp, tp) = (s.1 * pw + s.0, t.1 * pw + t.0);
        self.states[sp] = State::pack(0, NONE, generation);
        // The goal reached straight from the start, by diagonal moves then straight ones,
        // costs octile(s, t) = h(s), the least any path can: that path is optimal. (The
        // jumps would find it later, or a longer way round when a forced neighbour stops
        // them first.) Only from the start: at every jump point the test cost more than
        // it saved on mazes and random obstacles.
        if sp != tp && self.limit.max_expansions > 0 && self.bits.octile_path_free(s, t) {
            self.states[tp] = State::pack(h(s.0, s.1), sp as u32, generation | CLOSED);
            (stats.expansions, stats.pushes, stats.reached) = (1, 1, 2);
            return Ok(self.trace(sp, tp, stats));
        }
        let mut heap = std::mem::take(K::quad_heap(&mut self.heap, &mut self.wide_heap));
        heap.push(key(0, h(s.0, s.1), sp));
        stats.pushes = 1;
        stats.reached = 1;
        let mut check_at = self.limit.next_check(0);
        // Taken out for the loop (and put back after) so that it can borrow the rest.
        let mut found = std::mem::take(&mut self.found);
        // As A*'s loop ([`GridSearch::grid_search`](super::GridSearch)): successors whose
        // f equals the f being expanded would come out of the heap next anyway, so they
        // go on a stack; and the heap's root, the jump point being expanded, is taken but
        // left in place, so that the first successor to go to the heap replaces it.
        let mut stack = std::mem::take(&mut self.stack);
        stack.clear();
        let (mut taken, mut f_cur) = (false, 0);
        let outcome = loop {
            let p = if let Some(p) = stack.pop() {
                p as usize
            } else {
                if std::mem::take(&mut taken) {
                    heap.pop();
                }
                let Some(k) = heap.peek() else {
                    break Err(GridSearchError::NoPath { stats });
                };
                taken = true;
                f_cur = k.order(fx) >> fx.tie_bits;
                k.cell(fx) as usize
            };
            // Closed: a stale entry (the cell was pushed again with a lower g, and that
            // entry, whose f is lower, came out first).
            let state = self.states[p];
            if State::stamp(state) & CLOSED != 0 {
                continue;
            }
            self.states[p] = state | u128::from(CLOSED);
            if p == tp {
                break Ok(());
            }
            if stats.expansions >= check_at {
                if self.limit.spent(stats.expansions) {
                    break Err(GridSearchError::LimitReached { stats });
                }
                check_at = self.limit.next_check(stats.expansions);
            }
            stats.expansions += 1;
            let (x, y) = (p % pw, p / pw);
            let g = State::g(state);
            let parent = State::parent(state) as usize;
            let from = (parent != NONE as usize).then(|| (parent % pw, parent / pw));
            let kept = self.bits.directions((x, y), from);
            // All jumps first, then the successors' states: their loads (often cache
            // misses on large maps) then overlap instead of each waiting for its jump.
            found.clear();
            // The goal found by a jump from `p` is reached at g + octile(p, t) = f(p), the
            // least f left (the heuristic is consistent): that path is optimal and the
            // search ends there, without the other jumps. The directions toward the goal
            // go first, since those are where it is found.
            let toward = TOWARD[octant((x, y), t)];
            let mut goal_found = false;
            'jumps: for mask in [kept & toward, kept & !toward] {
                for d in directions(mask) {
                    let (dx, dy) = (DIRS[d].0 as isize, DIRS[d].1 as isize);
                    if dx == 0 || dy == 0 {
                        found.extend(self.bits.jump_straight((x, y), (dx, dy), t));
                    } else {
                        self.bits.jump_diagonal((x, y), (dx, dy), t, &mut found);
                    }
                    if found.last() == Some(&t) {
                        goal_found = true;
                        break 'jumps;
                    }
                }
            }
            if goal_found {
                let old = self.states[tp];
                stats.reached += u64::from(State::stamp(old) & !CLOSED != generation);
                stats.pushes += 1;
                let ng = g + octile(fx, t.0.abs_diff(x), t.1.abs_diff(y));
                self.states[tp] = State::pack(ng, p as u32, generation | CLOSED);
                break Ok(());
            }
            for &(qx, qy) in &found {
                let q = qy * pw + qx;
                // The successor is reached diagonally first, then straight: its octile
                // distance.
                let ng = g + octile(fx, qx.abs_diff(x), qy.abs_diff(y));
                let old = self.states[q];
                let seen = State::stamp(old) & !CLOSED == generation;
                // Not an improvement. A closed cell's g is final (the heuristic is
                // consistent on the jump graph: each edge costs the octile distance
                // between its ends) unless f values closer than the key's quantum came
                // out in the wrong order; then it is reopened, as A* does.
                if seen && State::g(old) <= ng {
                    continue;
                }
                stats.reached += u64::from(!seen);
                self.states[q] = State::pack(ng, p as u32, generation);
                let hq = h(qx, qy);
                if (ng + hq) >> fx.f_shift <= f_cur {
                    stack.push(q as u32);
                } else if std::mem::take(&mut taken) {
                    heap.replace_top(key(ng, hq, q));
                } else {
                    heap.push(key(ng, hq, q));
                }
                stats.pushes += 1;
            }
        };
        self.found = found;
        self.stack = stack;
        *K::quad_heap(&mut self.heap, &mut self.wide_heap) = heap;
        outcome.map(|()| self.trace(sp, tp, stats))
    }

    /// Checks that a query cell is inside the map and passable; returns its padded
    /// coordinates.
    fn check(
        &self,
        (i, j): (usize, usize),
        start: bool,
    ) -> Result<(usize, usize), GridSearchError> {
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
        if !self.bits.free(i + 1, j + 1) {
            return Err(if start {
                GridSearchError::StartBlocked { i, j }
            } else {
                GridSearchError::GoalBlocked { i, j }
            });
        }
        Ok((i + 1, j + 1))
    }

    /// Starts a query: a new generation (stamps are cleared only when the counter wraps,
    /// once in 2^31 - 1 queries) and an empty open list. Returns the generation.
    fn begin(&mut self) -> u32 {
        self.generation += 1;
        if self.generation >= CLOSED {
            self.states.fill(0);
            self.generation = 1;
        }
        self.heap.clear();
        self.wide_heap.clear();
        self.generation
    }

    /// The path to padded cell `t` by the parent links, with the cells between
    /// consecutive jump points (diagonal moves, then straight ones) filled in.
    #[inline(never)]
    fn trace(&self, s: usize, t: usize, stats: SearchStats) -> GridPath {
        let pw = self.pw;
        let xy = |p: usize| (p % pw, p / pw);
        let parent = |p: usize| State::parent(self.states[p]) as usize;
        // The number of moves first (the larger coordinate difference of each leg), for
        // the vector's size.
        let mut moves = 0;
        let mut p = t;
        while p != s {
            let ((x, y), (qx, qy)) = (xy(p), xy(parent(p)));
            moves += x.abs_diff(qx).max(y.abs_diff(qy));
            p = parent(p);
        }
        // From the goal back, each leg's straight moves, then its diagonal ones (a run of
        // one step repeated, without a test per cell), then the list turned around.
        let mut cells = Vec::with_capacity(moves + 1);
        let (mut x, mut y) = xy(t);
        p = t;
        while p != s {
            p = parent(p);
            let (qx, qy) = xy(p);
            let (ax, ay) = (x.abs_diff(qx), y.abs_diff(qy));
            let (sx, sy) = (qx.cmp(&x) as isize, qy.cmp(&y) as isize);
            let (straight, step) = if ax > ay {
                (ax - ay, (sx, 0))
            } else {
                (ay - ax, (0, sy))
            };
            for (n, (dx, dy)) in [(straight, step), (ax.min(ay), (sx, sy))] {
                for _ in 0..n {
                    cells.push((x - 1, y - 1));
                    (x, y) = (x.wrapping_add_signed(dx), y.wrapping_add_signed(dy));
                }
            }
        }
        cells.push((x - 1, y - 1));
        cells.reverse();
        GridPath {
            cells,
            cost: self.fixed.to_cells(State::g(self.states[t])),
            stats,
        }
    }
}

/// One cell's search state packed in a `u128`, so that a query touches one cache line per
/// cell and the array is allocated zeroed: from the top, g (fixed point, 64 bits), the
/// jump point it was reached from ([`NONE`] for the start; 32 bits), and the generation of
/// the last query that reached it with the [`CLOSED`] bit (32 bits). The state is valid
/// only where the generation is the current query's.
struct State;

impl State {
    #[inline]
    fn pack(g: u64, parent: u32, stamp: u32) -> u128 {
        (u128::from(g) << 64) | (u128::from(parent) << 32) | u128::from(stamp)
    }

    #[inline]
    fn g(state: u128) -> u64 {
        (state >> 64) as u64
    }

    #[inline]
    fn parent(state: u128) -> u32 {
        (state >> 32) as u32
    }

    #[inline]
    fn stamp(state: u128) -> u32 {
        state as u32
    }
}

/// The fixed-point octile distance over coordinate differences `dx`, `dy` (the length of
/// a straight or diagonal run exactly, as A* sums it).
#[inline]
fn octile(fx: Fixed, dx: usize, dy: usize) -> u64 {
    let (lo, hi) = if dx < dy { (dx, dy) } else { (dy, dx) };
    hi as u64 * fx.unit + lo as u64 * (fx.diag - fx.unit)
}

/// The cells a jump's window still knows past the jump's cell, as bits of a forward
/// window: bits 1 to 61 when carried (shifted up to twice since it was read, its top two
/// bits lost), bits 1 to 63 when just read. A backward window's are these reversed.
const CARRIED: u64 = (1 << 62) - 2;
const FRESH: u64 = !1;

/// Mirrors a forward window's bit set for a backward one.
#[inline(always)]
const fn oriented<const FWD: bool>(bits: u64) -> u64 {
    if FWD { bits } else { bits.reverse_bits() }
}

/// A jump window moved one cell along the jump.
#[inline(always)]
fn advance<const FWD: bool>(w: u64) -> u64 {
    if FWD { w >> 1 } else { w << 1 }
}

/// The first stop of a straight jump in windows of the line (`line`) and the lines beside
/// it (`side_b`, `side_a`) at the jump's cell, among the cells of `valid` (as forward
/// bits): how many cells ahead lies the first cell of the line that is blocked or has a
/// forced neighbour (a free side cell whose predecessor along the jump is blocked), and
/// whether that cell is free.
#[inline(always)]
fn first_stop<const FWD: bool>(
    side_b: u64,
    line: u64,
    side_a: u64,
    valid: u64,
) -> Option<(usize, bool)> {
    let behind = |w: u64| if FWD { w << 1 } else { w >> 1 };
    let forced = (side_a & !behind(side_a)) | (side_b & !behind(side_b));
    let stop = (forced | !line) & oriented::<FWD>(valid);
    (stop != 0).then(|| {
        let k = if FWD {
            stop.trailing_zeros()
        } else {
            stop.leading_zeros()
        } as usize;
        let bit = if FWD { k } else { 63 - k };
        (k, (line >> bit) & 1 != 0)
    })
}

/// What a straight jump from `from` found, its first stop being `k` cells ahead (`open`:
/// a free cell with a forced neighbour, else a wall): `target` if the jump passes it,
/// else the stop if open.
#[inline(always)]
fn outcome<const FWD: bool>(from: usize, (k, open): (usize, bool), target: usize) -> Option<usize> {
    let ahead = |c: usize, n: usize| if FWD { c + n } else { c - n };
    let at = ahead(from, k);
    // The last cell the jump reaches: the stop, or the one before the wall.
    let reach = if open { at } else { ahead(from, k - 1) };
    let passed = if FWD {
        target > from && target <= reach
    } else {
        target < from && target >= reach
    };
    if passed {
        return Some(target);
    }
    open.then_some(at)
}

/// A straight jump along line `l` of `lines` from cell `from`, toward higher positions
/// if `FWD`: the first cell after `from` that is `target` or has a forced neighbour on
/// line `l - 1` or `l + 1`, or `None` when a blocked cell comes first. Scans 63 cells a
/// window.
#[inline]
fn scan<const FWD: bool>(lines: &Lines, l: usize, from: usize, target: usize) -> Option<usize> {
    // The window's first bit (the line's cell c is bit PAD + c); the jump's current cell
    // is its bit 0 (bit 63 backward).
    let mut s = if FWD { PAD + from } else { PAD + from - 63 };
    loop {
        let (c, b, a) = lines.windows(l, s);
        if let Some((k, open)) = first_stop::<FWD>(b, c, a, FRESH) {
            // Cells from `from` to the stop.
            let k = if FWD {
                s + k - PAD - from
            } else {
                from - (s + 63 - k - PAD)
            };
            return outcome::<FWD>(from, (k, open), target);
        }
        // The blocked border stops a backward scan before s could go below 0.
        s = if FWD { s + 63 } else { s - 63 };
    }
}

/// A straight jump along line `l` of `lines` from cell `from` as [`scan`], given its
/// carried windows (the line behind, the jump's line, the line ahead) at `from`: the first
/// 61 cells from the windows, the rest by [`scan`].
#[inline(always)]
fn carried_scan<const FWD: bool>(
    lines: &Lines,
    l: usize,
    from: usize,
    (b, c, a): (u64, u64, u64),
    target: usize,
) -> Option<usize> {
    if let Some(stop) = first_stop::<FWD>(b, c, a, CARRIED) {
        return outcome::<FWD>(from, stop, target);
    }
    let last = if FWD { from + 61 } else { from - 61 };
    let passed = if FWD {
        target > from && target <= last
    } else {
        target < from && target >= last
    };
    if passed {
        Some(target)
    } else {
        scan::<FWD>(lines, l, last, target)
    }
}

impl BitGrid {
    /// The directions (bits in the order of [`DIRS`]) to jump along from jump point
    /// `(x, y)`, reached from jump point `from` (`None`: the start, every direction) by
    /// diagonal moves, then straight ones.
    ///
    /// A diagonal arrival keeps its two straight components and itself: without corner
    /// cutting a diagonal move has no forced neighbour. A straight arrival keeps itself,
    /// and each side whose cell is free while the cell behind it is blocked (the forced
    /// neighbour that stopped the jump): the side and the diagonal toward it.
    fn directions(&self, (x, y): (usize, usize), from: Option<(usize, usize)>) -> u8 {
        let Some((px, py)) = from else {
            return u8::MAX;
        };
        // The last move of the way from `from`: diagonal moves come first.
        let (sx, sy) = (x.cmp(&px) as isize, y.cmp(&py) as isize);
        let (ax, ay) = (x.abs_diff(px), y.abs_diff(py));
        let (dx, dy) = match ax.cmp(&ay) {
            std::cmp::Ordering::Equal => (sx, sy),
            std::cmp::Ordering::Greater => (sx, 0),
            std::cmp::Ordering::Less => (0, sy),
        };
        let mut kept = dir_bit(dx, dy);
        if dx != 0 && dy != 0 {
            return kept | dir_bit(dx, 0) | dir_bit(0, dy);
        }
        for side in [-1, 1] {
            // The side cell beside (x, y), and the one behind it, as seen along the move.
            let (beside, behind) = if dy == 0 {
                (
                    self.free(x, y.wrapping_add_signed(side)),
                    self.free(x.wrapping_add_signed(-dx), y.wrapping_add_signed(side)),
                )
            } else {
                (
                    self.free(x.wrapping_add_signed(side), y),
                    self.free(x.wrapping_add_signed(side), y.wrapping_add_signed(-dy)),
                )
            };
            if beside && !behind {
                kept |= if dy == 0 {
                    dir_bit(0, side) | dir_bit(dx, side)
                } else {
                    dir_bit(side, 0) | dir_bit(side, dy)
                };
            }
        }
        kept
    }

    /// Whether the way from `(x, y)` to `goal` by diagonal moves, then straight ones (the
    /// octile distance), is free (no corner cut).
    #[inline(never)]
    fn octile_path_free(&self, (mut x, mut y): (usize, usize), goal: (usize, usize)) -> bool {
        let (sx, sy) = (goal.0.cmp(&x) as isize, goal.1.cmp(&y) as isize);
        for _ in 0..x.abs_diff(goal.0).min(y.abs_diff(goal.1)) {
            let (nx, ny) = (x.wrapping_add_signed(sx), y.wrapping_add_signed(sy));
            if !(self.free(nx, y) && self.free(x, ny) && self.free(nx, ny)) {
                return false;
            }
            (x, y) = (nx, ny);
        }
        if x != goal.0 {
            self.rows.run_free(y, x.min(goal.0), x.max(goal.0))
        } else {
            self.cols.run_free(x, y.min(goal.1), y.max(goal.1))
        }
    }

    /// Jumps from `(x, y)` along the straight direction `(dx, dy)`: the first cell that
    /// is the goal or has a forced neighbour, or `None` at a wall.
    #[inline]
    fn jump_straight(
        &self,
        (x, y): (usize, usize),
        (dx, dy): (isize, isize),
        goal: (usize, usize),
    ) -> Option<(usize, usize)> {
        if dy == 0 {
            let target = if goal.1 == y { goal.0 } else { usize::MAX };
            let found = if dx > 0 {
                scan::<true>(&self.rows, y, x, target)
            } else {
                scan::<false>(&self.rows, y, x, target)
            };
            found.map(|x| (x, y))
        } else {
            let target = if goal.0 == x { goal.1 } else { usize::MAX };
            let found = if dy > 0 {
                scan::<true>(&self.cols, x, y, target)
            } else {
                scan::<false>(&self.cols, x, y, target)
            };
            found.map(|y| (x, y))
        }
    }

    /// Jumps from `(x, y)` along the diagonal `(dx, dy)` until the next diagonal move is
    /// illegal (a blocked cell or a cut corner) or the goal is reached, and adds to `out`
    /// what the straight jumps along both components find from each cell of the way (and
    /// the goal). The diagonal cells themselves are not generated ("intermediate
    /// pruning", Harabor and Grastien 2014): each successor is reached from `(x, y)` by
    /// diagonal moves, then straight ones.
    fn jump_diagonal(
        &self,
        start: (usize, usize),
        (dx, dy): (isize, isize),
        goal: (usize, usize),
        out: &mut Vec<(usize, usize)>,
    ) {
        match (dx > 0, dy > 0) {
            (true, true) => self.diagonal::<true, true>(start, goal, out),
            (true, false) => self.diagonal::<true, false>(start, goal, out),
            (false, true) => self.diagonal::<false, true>(start, goal, out),
            (false, false) => self.diagonal::<false, false>(start, goal, out),
        }
    }

    /// [`jump_diagonal`](BitGrid::jump_diagonal) toward increasing x if `EAST`, y if
    /// `NORTH`.
    ///
    /// Each step reads one new window for each straight jump: the line ahead. The windows
    /// of the jump's own line and of the line behind it are the previous step's, moved by
    /// the cell stepped (their far bits lost: [`CARRIED`]); they also hold the three cells
    /// of the next diagonal move.
    #[inline(always)]
    fn diagonal<const EAST: bool, const NORTH: bool>(
        &self,
        (mut x, mut y): (usize, usize),
        goal: (usize, usize),
        out: &mut Vec<(usize, usize)>,
    ) {
        let step = |c: usize, up: bool| if up { c + 1 } else { c - 1 };
        // The first move checked on the rows alone: on mazes and dense obstacles most
        // diagonal jumps end there, before the columns are read.
        let (nx, ny) = (step(x, EAST), step(y, NORTH));
        if !(self.free(nx, y) && self.free(x, ny) && self.free(nx, ny)) {
            return;
        }
        let (rows, cols) = (&self.rows, &self.cols);
        // The next cell's bit in a window at the jump's cell.
        let (next_x, next_y) = (oriented::<EAST>(2), oriented::<NORTH>(2));
        // Row windows on the jump's row and the one ahead (the one behind comes with the
        // first move); column windows the same.
        let (mut ro, mut ra) = (rows.window_at::<EAST>(y, x), rows.window_at::<EAST>(ny, x));
        let (mut co, mut ca) = (
            cols.window_at::<NORTH>(x, y),
            cols.window_at::<NORTH>(nx, y),
        );
        loop {
            // The move's two sides and the cell it reaches.
            if ro & ra & next_x == 0 || co & next_y == 0 {
                return;
            }
            (x, y) = (step(x, EAST), step(y, NORTH));
            if (x, y) == goal {
                out.push(goal);
                return;
            }
            let (rb, cb) = (advance::<EAST>(ro), advance::<NORTH>(co));
            (ro, ra) = (
                advance::<EAST>(ra),
                rows.window_at::<EAST>(step(y, NORTH), x),
            );
            (co, ca) = (
                advance::<NORTH>(ca),
                cols.window_at::<NORTH>(step(x, EAST), y),
            );
            // Along the row, then along the column (nothing after the goal is needed:
            // the search ends once it is found).
            let target = if goal.1 == y { goal.0 } else { usize::MAX };
            if let Some(qx) = carried_scan::<EAST>(rows, y, x, (rb, ro, ra), target) {
                out.push((qx, y));
                if (qx, y) == goal {
                    return;
                }
            }
            let target = if goal.0 == x { goal.1 } else { usize::MAX };
            if let Some(qy) = carried_scan::<NORTH>(cols, x, y, (cb, co, ca), target) {
                out.push((x, qy));
                if (x, qy) == goal {
                    return;
                }
            }
        }
    }
}

/// Index into [`TOWARD`] of the goal's side of `(x, y)`: `3 (sx + 1) + sy + 1` for the
/// signs `sx`, `sy` of the coordinate differences.
#[inline]
fn octant((x, y): (usize, usize), goal: (usize, usize)) -> usize {
    3 * (goal.0.cmp(&x) as isize + 1) as usize + (goal.1.cmp(&y) as isize + 1) as usize
}

/// For each [`octant`], the directions (bits in [`DIRS`]' order) whose components both
/// point toward the goal or are zero.
const TOWARD: [u8; 9] = {
    let mut table = [0; 9];
    let mut k = 0;
    while k < 9 {
        let (sx, sy) = (k as i32 / 3 - 1, k as i32 % 3 - 1);
        let mut d = 0;
        while d < 8 {
            let (dx, dy) = (DIRS[d].0, DIRS[d].1);
            if (dx == 0 || dx == sx) && (dy == 0 || dy == sy) {
                table[k] |= 1 << d;
            }
            d += 1;
        }
        k += 1;
    }
    table
};

/// The bit of direction `(dx, dy)` in [`DIRS`]' order (E, W, N, S, NE, NW, SE, SW).
#[inline]
fn dir_bit(dx: isize, dy: isize) -> u8 {
    let d = match (dx, dy) {
        (1, 0) => 0,
        (-1, 0) => 1,
        (0, 1) => 2,
        (0, -1) => 3,
        (1, 1) => 4,
        (-1, 1) => 5,
        (1, -1) => 6,
        _ => 7,
    };
    1 << d
}
