//! Theta*: any-angle paths between cell centres (line-of-sight parents).

use super::bits::{BitGrid, Lines, SLIDE};
use super::engine::*;
use super::*;

/// Lines of sight whose shorter side spans at most this many cells are read from the bit
/// lines, one run of cells per line crossed; longer ones cross the open stretches of the
/// stride table first.
const RUNS_UP_TO: u32 = 64;

/// The bits Theta*'s lines of sight read: the passable cells' bit lines, and the same
/// lines [`SLIDE`] at a time from each line ([`Lines::slides`]), so that a segment crossing
/// eight free lines reads one run instead of eight.
#[derive(Debug, Clone)]
pub(super) struct SightBits {
    grid: BitGrid,
    row_slides: Lines,
    col_slides: Lines,
}

impl SightBits {
    fn new(grid: BitGrid) -> Self {
        Self {
            row_slides: grid.rows.slides(),
            col_slides: grid.cols.slides(),
            grid,
        }
    }
}

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
        self.run(Some(map), start, goal, Kind::LazyThetaStar(1.0))
    }

    /// Lazy Theta* with Optimizations (Nash, Koenig and Tovey 2010): Lazy Theta* whose
    /// heuristic is `weight` times the straight-line distance to the goal, as weighted A*.
    /// With `weight > 1` it expands fewer cells and may find longer paths (usually by far
    /// less than the factor: a cell it skips can still be cut across by its neighbours'
    /// parent links); `weight = 1` is [`lazy_theta_star`](Self::lazy_theta_star). A weight
    /// below 1 or not finite counts as 1.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use search::{GridOptions, GridSearch};
    /// let map = GridMap::from_ascii("
    ///     ..........
    ///     ...####...
    ///     ..........
    /// ")?;
    /// let mut search = GridSearch::new(&map, GridOptions::default())?;
    /// let plain = search.lazy_theta_star(&map, (0, 1), (9, 1))?;
    /// let weighted = search.lazy_theta_star_weighted(&map, (0, 1), (9, 1), 1.2)?;
    /// assert!(weighted.stats.expansions <= plain.stats.expansions);
    /// assert!(weighted.cost <= 1.2 * plain.cost);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    ///
    /// As [`astar`](GridSearch::astar).
    pub fn lazy_theta_star_weighted(
        &mut self,
        map: &GridMap,
        start: (usize, usize),
        goal: (usize, usize),
        weight: f64,
    ) -> Result<GridPath, GridSearchError> {
        let weight = if weight.is_finite() {
            weight.max(1.0)
        } else {
            1.0
        };
        self.run(Some(map), start, goal, Kind::LazyThetaStar(weight))
    }

    /// Makes now what Theta*'s and Lazy Theta*'s first query would make: the passable
    /// cells as bit lines (rows and columns, and their slides) that the lines of sight
    /// read, `map`'s stride table (kept with the map: [`GridMap::blocked_strides`]) and
    /// the searches' per-cell state (16 bytes a cell, written here when it is allocated
    /// here). After it, their first query costs what it expands, as later ones do,
    /// instead of a pass over the map. Calling it is optional (a query makes what is
    /// missing), and calling it again costs nothing.
    /// [`update`](GridSearch::update) and [`update_window`](GridSearch::update_window)
    /// drop the bit lines, so call it again after them. `map` is the map this search was
    /// built from.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use search::{GridOptions, GridSearch};
    /// let map = GridMap::from_ascii("
    ///     ..........
    ///     ...####...
    ///     ..........
    /// ")?;
    /// let mut search = GridSearch::new(&map, GridOptions::default())?;
    /// search.prepare_lines_of_sight(&map);
    /// let path = search.lazy_theta_star(&map, (0, 1), (9, 1))?;
    /// assert_eq!(path.cells.first(), Some(&(0, 1)));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn prepare_lines_of_sight(&mut self, map: &GridMap) {
        if map.width() == self.width && map.height() == self.height {
            let _ = map.blocked_strides();
        }
        if self.theta_bits.is_none() {
            self.theta_bits = Some(SightBits::new(self.bit_grid()));
        }
        if self.theta_state() {
            // Written once here, so that a query does not wait on the system for the
            // first touch of each page of them (the allocation is zeroed but not yet
            // mapped): 16 bytes a cell.
            self.theta_stamps.fill(0);
            self.theta_parents.fill(0);
            self.theta_g.fill(0);
        }
    }

    /// Theta*'s per-cell state, allocated once per search; whether it was allocated now.
    fn theta_state(&mut self) -> bool {
        let new = self.theta_stamps.len() != self.words.len();
        if new {
            // Zeroed, so the allocator hands out untouched pages: a first query on a large
            // map does not write every cell's state (8 ms on 2,000 x 2,000 cells).
            self.theta_stamps = vec![0; self.words.len()];
            self.theta_parents = vec![0; self.words.len()];
            self.theta_g = vec![0; self.words.len()];
            self.theta_generation = 0;
        }
        new
    }

    /// Starts a Theta* query from `s` on its own nodes (allocated by the first query),
    /// with g = 0.
    pub(super) fn begin_theta(&mut self, s: u32, stats: &mut SearchStats) {
        let _ = self.theta_state();
        self.theta_generation += 1;
        if self.theta_generation >= CLOSED {
            self.theta_stamps.fill(0);
            self.theta_generation = 1;
        }
        self.theta_heap.clear();
        self.theta_g[s as usize] = 0f64.to_bits();
        self.theta_parents[s as usize] = NONE;
        self.theta_stamps[s as usize] = self.theta_generation;
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

    /// Theta*'s loop (Lazy Theta*'s with `lazy`; the heuristic `weight` times the
    /// straight-line distance), on `f64` costs (stored as bits in `g`)
    /// and keys of `f32` bits ([`float_key`]).
    pub(super) fn theta_search(
        &mut self,
        s0: u32,
        t0: u32,
        lazy: bool,
        sight: &[u8],
        weight: f64,
    ) -> Result<GridPath, GridSearchError> {
        let mut stats = SearchStats::default();
        let (gx, gy) = self.xy(t0);
        let euclid = move |x: u32, y: u32| {
            let dx = f64::from(x.abs_diff(gx));
            let dy = f64::from(y.abs_diff(gy));
            weight * (dx * dx + dy * dy).sqrt()
        };
        let (sx, sy) = self.xy(s0);
        self.begin_theta(s0, &mut stats);
        if self.theta_bits.is_none() {
            self.theta_bits = Some(SightBits::new(self.bit_grid()));
        }
        self.theta_heap.push(float_key(euclid(sx, sy), s0));
        let closed = self.theta_generation | CLOSED;
        let limit = self.limit;
        let mut check_at = limit.next_check(0);
        // The heap's root is the cell being expanded, taken but left in place: the first
        // cell it pushes replaces it (one sift instead of a pop and a push; the keys are
        // distinct, so the cells come out in the same order).
        let mut taken = false;
        loop {
            if taken {
                self.theta_heap.pop();
            }
            let Some(k) = self.theta_heap.peek() else {
                break;
            };
            taken = true;
            let p = k as u32;
            if self.theta_stamps[p as usize] == closed {
                continue;
            }
            self.theta_stamps[p as usize] = closed;
            // The neighbours' stamps, read before the line of sight so that their loads
            // overlap it (it writes none of them), and which of them are closed.
            let mask = self.theta_moves(p);
            let mut stamps = [0; 8];
            let mut shut = 0u8;
            for (d, &(dx, dy, _)) in DIRS.iter().enumerate() {
                stamps[d] = self.theta_stamps[self.moved(p, (dx, dy)) as usize];
                shut |= u8::from(stamps[d] == closed) << d;
            }
            if lazy {
                self.lazy_set_parent(p, mask & shut, sight);
            }
            let g = f64::from_bits(self.theta_g[p as usize]);
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
            self.theta_expand(
                (p, g),
                (mask & !shut, stamps),
                &mut stats,
                (euclid, sight),
                lazy,
                &mut taken,
            );
        }
        Err(GridSearchError::NoPath { stats })
    }

    /// Lazy Theta*'s check when `p` is expanded: if `p` does not see the parent it was
    /// given, its parent becomes the expanded grid neighbour through which it is cheapest
    /// (one exists: the cell whose expansion reached `p`). `shut`: the legal moves from
    /// `p` to expanded cells, one bit per direction of [`DIRS`].
    fn lazy_set_parent(&mut self, p: u32, shut: u8, sight: &[u8]) {
        let pp = self.theta_parents[p as usize];
        if pp == NONE || self.line_of_sight(pp, p, sight) {
            return;
        }
        let mut best = (f64::INFINITY, NONE);
        for d in directions(shut) {
            let (dx, dy, c) = DIRS[d];
            let q = self.moved(p, (dx, dy));
            let via = f64::from_bits(self.theta_g[q as usize]) + c;
            if via < best.0 {
                best = (via, q);
            }
        }
        self.theta_g[p as usize] = best.0.to_bits();
        self.theta_parents[p as usize] = best.1;
    }

    /// The legal grid moves from `p`, one bit per direction of [`DIRS`]: the same as
    /// A*'s, except that a diagonal never cuts a corner (Theta*'s segments are checked
    /// exactly, so a diagonal must not touch a blocked corner).
    #[inline(always)]
    fn theta_moves(&self, p: u32) -> u8 {
        let pu = p as usize;
        if !self.options.corner_cutting {
            // The search's own moves follow the same rule (and its border is blocked).
            return self.moves[pu];
        }
        let pass = &self.passable;
        let (e, w, n, s) = (
            pass[pu + 1],
            pass[pu - 1],
            pass[pu + self.pw],
            pass[pu - self.pw],
        );
        let mut mask = u8::from(e) | u8::from(w) << 1 | u8::from(n) << 2 | u8::from(s) << 3;
        if self.options.connectivity == Connectivity::Eight {
            let pw = self.pw;
            for (d, (a, b, q)) in [
                (n, e, pu + pw + 1),
                (n, w, pu + pw - 1),
                (s, e, pu - pw + 1),
                (s, w, pu - pw - 1),
            ]
            .into_iter()
            .enumerate()
            {
                mask |= u8::from(a && b && pass[q]) << (4 + d);
            }
        }
        mask
    }

    /// The cell one move `(dx, dy)` from padded index `p`.
    #[inline(always)]
    fn moved(&self, p: u32, (dx, dy): (i32, i32)) -> u32 {
        (i64::from(p) + i64::from(dy) * self.pw as i64 + i64::from(dx)) as u32
    }

    /// Theta*'s expansion: for each legal grid move p -> q, take q's parent to be p's
    /// parent when it sees q (path 2 of the paper), else p (path 1). With `lazy`, p's
    /// parent is taken without the test, which q's own expansion makes
    /// ([`lazy_set_parent`](Self::lazy_set_parent)). `g`: p's cost; `live`: its legal
    /// moves to cells not yet expanded, one bit per direction of [`DIRS`] (walked as set
    /// bits: a test per direction was a branch taken at random); `stamps`: its neighbours'
    /// stamps, one per direction (read by the caller). `taken`: the heap's root is `p`'s
    /// own entry, which the first push replaces.
    pub(super) fn theta_expand(
        &mut self,
        (p, g): (u32, f64),
        (live, stamps): (u8, [u32; 8]),
        stats: &mut SearchStats,
        (h, sight): (impl Fn(u32, u32) -> f64, &[u8]),
        lazy: bool,
        taken: &mut bool,
    ) {
        let pu = p as usize;
        let open = self.theta_generation;
        let pp = self.theta_parents[pu];
        let (px, py) = self.xy(p);
        // The parent's place and cost, read once for the eight moves.
        let (ppx, ppy, gpp) = if pp == NONE {
            (0.0, 0.0, 0.0)
        } else {
            let (x, y) = self.xy(pp);
            (
                f64::from(x),
                f64::from(y),
                f64::from_bits(self.theta_g[pp as usize]),
            )
        };
        // The cost through the parent, for the moves that get that far only: most of the
        // eight lead to closed cells or are not legal, and their roots cost more than the
        // loop's wait on the few taken.
        let (pxf, pyf) = (f64::from(px), f64::from(py));
        let through = |d: usize| {
            let (ex, ey) = (
                ppx - (pxf + f64::from(DIRS[d].0)),
                ppy - (pyf + f64::from(DIRS[d].1)),
            );
            gpp + (ex * ex + ey * ey).sqrt()
        };
        for d in directions(live) {
            let (dx, dy, c) = DIRS[d];
            let q = self.moved(p, (dx, dy));
            let (qx, qy) = (px.wrapping_add_signed(dx), py.wrapping_add_signed(dy));
            let qu = q as usize;
            let st = stamps[d];
            // Lazy: q would get p's parent at the cost it already has through it.
            if lazy && st == open && pp != NONE && self.theta_parents[qu] == pp {
                continue;
            }
            let (mut ng, mut parent) = (g + c, p);
            if pp != NONE && (lazy || self.line_of_sight(pp, q, sight)) {
                let via = through(d);
                if via <= ng {
                    ng = via;
                    parent = pp;
                }
            }
            if st == open && f64::from_bits(self.theta_g[qu]) <= ng {
                continue;
            }
            stats.reached += u64::from(st != open);
            self.theta_stamps[qu] = open;
            self.theta_g[qu] = ng.to_bits();
            self.theta_parents[qu] = parent;
            let key = float_key(ng + h(qx, qy), q);
            if std::mem::take(taken) {
                self.theta_heap.replace_top(key);
            } else {
                self.theta_heap.push(key);
            }
            stats.pushes += 1;
        }
    }

    /// The stride table Theta*'s lines of sight take from `map` (the map's own, made
    /// once and cached with it: [`GridMap::blocked_strides`]), or none (every line swept
    /// cell by cell) for a map of another size than this search's. A search with a
    /// deadline takes the table only if the map has it already: making it costs time
    /// that grows with the map (60 ms on 2,000 x 2,000 cells), outside the search's
    /// checks of its limit. The lines of sight are the same without it, only slower.
    pub(super) fn sight<'m>(&self, map: &'m GridMap) -> &'m [u8] {
        let table = if self.limit.deadline.is_some() {
            map.made_blocked_strides()
        } else {
            map.blocked_strides()
        };
        match table {
            Some(t) if map.width() == self.width && map.height() == self.height => t,
            _ => &[],
        }
    }

    /// Whether the segment between the centres of cells `a` and `b` touches only passable
    /// cells (corner touches included): the cells [`GridMap::segment_cells`] visits.
    ///
    /// The open stretches at both ends are crossed in strides of the sight table (no
    /// cell there can touch a blocked square, [`envmap::DistanceField::strides`]); the
    /// columns left between are swept exactly in integers. Between cell centres every
    /// crossing of a grid line is a multiple of `1 / (2 d)` (d the longer side of the
    /// segment's box), so the closed cells touched are found without floating point (the
    /// property tests check the paths against the map's `segment_free`). The padded
    /// border is blocked, and a segment between centres never leaves the map, so no
    /// bounds test is needed.
    pub(super) fn line_of_sight(&self, a: u32, b: u32, sight: &[u8]) -> bool {
        let ((ax, ay), (bx, by)) = (self.xy(a), self.xy(b));
        if let Some(bits) = &self.theta_bits
            && ax.abs_diff(bx).min(ay.abs_diff(by)) <= RUNS_UP_TO
        {
            return runs_free(bits, (ax, ay), (bx, by));
        }
        let (dx, dy) = (i64::from(bx) - i64::from(ax), i64::from(by) - i64::from(ay));
        if dx == 0 && dy == 0 {
            return self.passable[a as usize];
        }
        // How far the ends' open stretches reach, in cells along the segment.
        let len = ((dx * dx + dy * dy) as f64).sqrt();
        let (ex, ey) = (dx as f64 / len, dy as f64 / len);
        let from_a = self.open_stretch(sight, (ax, ay), (ex, ey), len);
        if from_a >= len {
            return true;
        }
        let from_b = self.open_stretch(sight, (bx, by), (-ex, -ey), len - from_a);
        if from_a + from_b >= len {
            return true;
        }
        let pw = self.pw as i64;
        // Sweep along the major axis u, in increasing u, from the start cell s; v is the
        // minor axis, mirrored about s's row when the segment goes down it, so that v
        // grows too. `su`, `sv`: index strides of one step along u and v. `(open_lo,
        // open_hi)`: how far the stretches reach along u from each end.
        let (du, dv, su, sv, s, open_lo, open_hi) = if dx.abs() >= dy.abs() {
            let f = dx.unsigned_abs() as f64 / len;
            if dx >= 0 {
                (dx, dy, 1, pw, a, from_a * f, from_b * f)
            } else {
                (-dx, -dy, 1, pw, b, from_b * f, from_a * f)
            }
        } else {
            let f = dy.unsigned_abs() as f64 / len;
            if dy >= 0 {
                (dy, dx, pw, 1, a, from_a * f, from_b * f)
            } else {
                (-dy, -dx, pw, 1, b, from_b * f, from_a * f)
            }
        };
        let (dv, sv) = if dv < 0 { (-dv, -sv) } else { (dv, sv) };
        // Columns k = 0..=du from s's column. The segment runs from u = 0.5 to du + 0.5
        // (in column units from s's column's left edge); column k is known free when its
        // stretch [k, k + 1] lies inside an open stretch. One column of margin each side.
        // Both floors' arguments are positive (`open_hi` is at most `du`), where the
        // truncation of `as` is the floor, without a call to libm's `floor` (the
        // baseline x86-64 target has no rounding instruction).
        let k_first = (((0.5 + open_lo) as i64) - 2).max(0);
        let k_last = (((du as f64 + 0.5 - open_hi) as i64) + 1).min(du);
        // In units of 1 / (2 du), the minor coordinate from s's row's lower edge at the
        // left edge of column k (k >= 1) is y = du + (2k - 1) dv; at the start, du. Each
        // column adds 2 dv (dv at the first and the last, which are half columns), at most
        // one row, so rows are tracked by a quotient and a remainder without dividing.
        let d = 2 * du;
        let y = if k_first == 0 {
            du
        } else {
            du + (2 * k_first - 1) * dv
        };
        let (mut q, mut rem) = (y / d, y % d);
        let pass = &self.passable;
        let mut col = i64::from(s) + k_first * su;
        for k in k_first..=k_last {
            // Rows m with m <= y <= m + 1 for some y of the column's stretch.
            let first = q + i64::from(rem != 0) - 1;
            rem += if k == 0 || k == du { dv } else { 2 * dv };
            if rem >= d {
                rem -= d;
                q += 1;
            }
            for m in first..=q {
                if !pass[(col + m * sv) as usize] {
                    return false;
                }
            }
            col += su;
        }
        true
    }

    /// The passable cells as bit lines.
    fn bit_grid(&self) -> BitGrid {
        let ph = self.passable.len() / self.pw;
        let mut bits = BitGrid::new(self.pw, ph);
        for (p, _) in self.passable.iter().enumerate().filter(|(_, free)| **free) {
            bits.set_free(p % self.pw, p / self.pw);
        }
        bits
    }

    /// How far, in cells along the unit direction `e`, the segment from the centre of
    /// padded cell `c` is known to touch no blocked square ([`envmap::open_stretch`] on
    /// the map's `sight` table; empty: not known at all).
    #[inline]
    fn open_stretch(&self, sight: &[u8], (cx, cy): (u32, u32), e: (f64, f64), len: f64) -> f64 {
        if sight.is_empty() {
            return 0.0;
        }
        // Unpadded coordinates: the padding is never touched by a segment between
        // centres, and points of the segment lie at least half a cell inside the map.
        let centre = (f64::from(cx) - 0.5, f64::from(cy) - 0.5);
        envmap::open_stretch(sight, (self.width, self.height), centre, e, len)
    }
}

/// Whether the closed segment between the centres of padded cells `a` and `b` touches
/// only free cells: along the lines of the segment's longer side (rows when it is at
/// least as wide as tall, else columns), the cells it touches in each line it crosses
/// form one run, read from the bit lines.
fn runs_free(sight: &SightBits, (ax, ay): (u32, u32), (bx, by): (u32, u32)) -> bool {
    if ax.abs_diff(bx) >= ay.abs_diff(by) {
        runs_along(&sight.grid.rows, &sight.row_slides, (ax, ay), (bx, by))
    } else {
        runs_along(&sight.grid.cols, &sight.col_slides, (ay, ax), (by, bx))
    }
}

/// [`runs_free`] on `lines` for a segment from `(au, av)` to `(bu, bv)` (cell centres;
/// `u` along the lines, `v` the line), at most one line crossed per cell along `u`.
///
/// In cells from `au`'s left edge (mirrored so that the segment goes toward larger `u`)
/// and units of `1 / (2 dv)`, the segment crosses the line boundary `v = m` at the integer
/// `dv + (2 (m - av) - 1) du`, each boundary `2 du` after the one before. Line `m` holds the
/// part between its two boundaries (or the ends), and the cells whose closed span `[k, k +
/// 1]` meets that part's span `[lo, hi]` are `ceil(lo) - 1` to `floor(hi)`: the floors are
/// kept as a quotient and a remainder, so no line costs a division.
///
/// The runs of [`SLIDE`] successive lines lie within one span of cells, from the first
/// line's start to the last line's end: if their slide (of `slides`) is free there, so are
/// they, in one read; if not, they are read line by line. Short segments take their runs
/// from a table instead ([`SHORT_RUNS`]).
fn runs_along(lines: &Lines, slides: &Lines, (au, av): (u32, u32), (bu, bv): (u32, u32)) -> bool {
    let ((au, av), (bu, bv)) = if av <= bv {
        ((au, av), (bu, bv))
    } else {
        ((bu, bv), (au, av))
    };
    if av == bv {
        return lines.run_free(av as usize, au.min(bu) as usize, au.max(bu) as usize);
    }
    let (dv, du) = (u64::from(bv - av), u64::from(au.abs_diff(bu)));
    if du < SHORT_DU as u64 && dv < SHORT_DV as u64 {
        // A short segment: its runs from the table, one window each, no walk; from two
        // slides when it crosses at least [`SLIDE`] lines, if they are free.
        let (au, forward) = (au as usize, bu >= au);
        let (dv, (av, bv)) = (dv as usize, (av as usize, bv as usize));
        let runs = &SHORT_RUNS[du as usize][dv];
        // Lines `first..=last`'s cells.
        let span = |first: usize, last: usize| {
            let k = (usize::from(runs[first].0), usize::from(runs[last].1));
            toward(au, forward, k)
        };
        if dv >= SLIDE {
            let (lo, hi) = span(0, SLIDE - 1);
            let (tail_lo, tail_hi) = span(dv + 1 - SLIDE, dv);
            if slides.run_free(av, lo, hi) && slides.run_free(bv + 1 - SLIDE, tail_lo, tail_hi) {
                return true;
            }
        }
        return runs[..=dv].iter().zip(av..).all(|(&(lo, hi), m)| {
            let (lo, hi) = toward(au, forward, (usize::from(lo), usize::from(hi)));
            lines.window_free(m, lo, hi)
        });
    }
    runs_walked(lines, slides, (au, av), (bu, bv))
}

/// The cells `k.0 ..= k.1` counted from `au` toward the other end of a segment (`forward`:
/// toward larger cells), lowest first.
#[inline(always)]
fn toward(au: usize, forward: bool, (k_lo, k_hi): (usize, usize)) -> (usize, usize) {
    if forward {
        (au + k_lo, au + k_hi)
    } else {
        (au - k_hi, au - k_lo)
    }
}

/// Segments shorter than this many cells along the lines take their runs from
/// [`SHORT_RUNS`] (a run is then at most 64 cells: one window).
const SHORT_DU: usize = 64;

/// ... and crossing fewer than this many lines.
const SHORT_DV: usize = 16;

/// The runs of the short segments, as [`Crossings`] finds them: for a segment `du` cells
/// along the lines and `dv` lines across (`1 <= dv <= du`), the first and last cell of
/// line `i` from the first end (`0 <= i <= dv`), counted toward the other end. They
/// depend on nothing else, and a walk costs a branch per line that the table does not
/// (32 KB; with 8 lines, not 16, Lazy Theta* took 4-8 % longer on the rooms, streets and
/// wide mazes).
static SHORT_RUNS: [[[(u8, u8); SHORT_DV]; SHORT_DV]; SHORT_DU] = short_runs();

const fn short_runs() -> [[[(u8, u8); SHORT_DV]; SHORT_DV]; SHORT_DU] {
    let mut table = [[[(0, 0); SHORT_DV]; SHORT_DV]; SHORT_DU];
    let mut du = 1;
    while du < SHORT_DU {
        let mut dv = 1;
        while dv < SHORT_DV && dv <= du {
            let mut walk = Crossings::new((0, du as u32), du as u64, dv as u64);
            let mut i = 0;
            while i < dv {
                table[du][dv][i] = (walk.k_lo as u8, walk.q as u8);
                walk.advance();
                i += 1;
            }
            // The last line's part ends at the centre of the other end's cell.
            table[du][dv][dv] = (walk.k_lo as u8, du as u8);
            dv += 1;
        }
        du += 1;
    }
    table
}

/// The part of a segment in each line it crosses, line after line, for [`runs_along`]:
/// the first cell `k_lo` and the boundary above the line as a quotient `q` (its last
/// cell) and a remainder `r`, in units of `1 / (2 dv)`.
struct Crossings {
    /// The first end's cell along the lines, and whether the segment goes toward larger
    /// cells from it (`k` counts cells from `au` that way).
    au: usize,
    forward: bool,
    k_lo: u64,
    q: u64,
    r: u64,
    /// One line's step of the boundary, `2 du` as quotient and remainder.
    step: (u64, u64),
    /// `2 dv`.
    d: u64,
}

impl Crossings {
    /// The first line's: its part starts at the centre, 1/2 (cells from 0), and its
    /// upper boundary is at `dv + du`.
    #[inline(always)]
    const fn new((au, bu): (u32, u32), du: u64, dv: u64) -> Self {
        let d = 2 * dv;
        Self {
            au: au as usize,
            forward: bu >= au,
            k_lo: 0,
            q: (dv + du) / d,
            r: (dv + du) % d,
            step: ((2 * du) / d, (2 * du) % d),
            d,
        }
    }

    /// The line's cells from this part's first to `k_hi` (counted from `au`), lowest
    /// first.
    #[inline(always)]
    fn cells(&self, k_hi: u64) -> (usize, usize) {
        toward(self.au, self.forward, (self.k_lo as usize, k_hi as usize))
    }

    /// Whether the parts of lines `from .. to` are free, read line by line (the walk at
    /// line `from`; it ends at line `to`, or at the first line blocked).
    #[inline(always)]
    fn lines_free(&mut self, lines: &Lines, from: u32, to: u32) -> bool {
        for m in from..to {
            let (lo, hi) = self.cells(self.q);
            if !lines.run_free(m as usize, lo, hi) {
                return false;
            }
            self.advance();
        }
        true
    }

    /// On to the next line, whose part starts where the last one's ended.
    #[inline(always)]
    const fn advance(&mut self) {
        self.k_lo = self.q + (self.r != 0) as u64 - 1;
        self.q += self.step.0;
        self.r += self.step.1;
        if self.r >= self.d {
            self.r -= self.d;
            self.q += 1;
        }
    }
}

/// [`runs_along`] for a segment outside [`SHORT_RUNS`] (`av < bv`): its runs walked line
/// by line ([`Crossings`]), [`SLIDE`] lines at a time where their slide is free over their
/// span.
fn runs_walked(lines: &Lines, slides: &Lines, (au, av): (u32, u32), (bu, bv): (u32, u32)) -> bool {
    let (dv, du) = (u64::from(bv - av), u64::from(au.abs_diff(bu)));
    let mut walk = Crossings::new((au, bu), du, dv);
    // `SLIDE - 1` steps at once: from a slide's first line's upper boundary to its last's.
    let slide_steps = (SLIDE - 1) as u64 * (2 * du);
    let (last_q, last_r) = (slide_steps / walk.d, slide_steps % walk.d);
    let mut m = av;
    // Whole slides of lines before the last line.
    while m + (SLIDE as u32 - 1) < bv {
        // The slide's last line's upper boundary.
        let (mut bq, mut br) = (walk.q + last_q, walk.r + last_r);
        if br >= walk.d {
            br -= walk.d;
            bq += 1;
        }
        let (lo, hi) = walk.cells(bq);
        if slides.run_free(m as usize, lo, hi) {
            // As if at the slide's last line: on to the line after it.
            (walk.q, walk.r) = (bq, br);
            walk.advance();
            m += SLIDE as u32;
            continue;
        }
        // Blocked somewhere in the span: the slide's lines one by one.
        if !walk.lines_free(lines, m, m + SLIDE as u32) {
            return false;
        }
        m += SLIDE as u32;
    }
    // The lines left, the last one's part ending at the centre of `bu`'s cell: within the
    // slide that ends with the last line, if there is one (it starts at or before `m`).
    let (lo, hi) = walk.cells(du);
    if let Some(first) = (bv as usize).checked_sub(SLIDE - 1)
        && slides.run_free(first, lo, hi)
    {
        return true;
    }
    if !walk.lines_free(lines, m, bv) {
        return false;
    }
    let (lo, hi) = walk.cells(du);
    lines.run_free(bv as usize, lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A cell `(i, j)`.
    type Cell = (usize, usize);

    /// A random map, 2-80 cells a side, 0-40 % blocked or a few cells in open space
    /// (where the strides run up to the obstacles), and pairs of cells.
    fn maps() -> impl Strategy<Value = (GridMap, Vec<(Cell, Cell)>)> {
        let density = prop_oneof![0.0f64..0.4, 0.0f64..0.004];
        (2usize..80, 2usize..80, density).prop_flat_map(|(w, h, density)| {
            (
                proptest::collection::vec(prop::bool::weighted(density), w * h),
                proptest::collection::vec(((0..w, 0..h), (0..w, 0..h)), 1..200),
            )
                .prop_map(move |(blocked, pairs)| (test_map(w, h, blocked), pairs))
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]

        /// The line of sight is the map's exact edge check between the two centres,
        /// both ways: not only never through a blocked cell, but never refused where
        /// the segment is free.
        #[test]
        fn line_of_sight_is_segment_free_between_centres((map, pairs) in maps()) {
            let mut search = GridSearch::new(&map, GridOptions::default()).unwrap();
            let sight = search.sight(&map);
            prop_assert!(!sight.is_empty());
            let bits = SightBits::new(search.bit_grid());
            for (a, b) in pairs {
                let (pa, pb) = (search.index(a.0, a.1), search.index(b.0, b.1));
                let expected = map.segment_free_cells(
                    map.cell_center(a.0, a.1),
                    map.cell_center(b.0, b.1),
                );
                // The stride table and the sweep, then the bit lines' runs too.
                search.theta_bits = None;
                prop_assert_eq!(search.line_of_sight(pa, pb, sight), expected, "{:?} -> {:?}", a, b);
                prop_assert_eq!(search.line_of_sight(pb, pa, sight), expected, "{:?} -> {:?}", b, a);
                search.theta_bits = Some(bits.clone());
                prop_assert_eq!(search.line_of_sight(pa, pb, sight), expected, "{:?} -> {:?}", a, b);
                prop_assert_eq!(search.line_of_sight(pb, pa, sight), expected, "{:?} -> {:?}", b, a);
                let (ca, cb) = (search.xy(pa), search.xy(pb));
                prop_assert_eq!(runs_free(&bits, ca, cb), expected, "{:?} -> {:?}", a, b);
            }
        }
    }
}
