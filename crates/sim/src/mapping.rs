//! The occupancy grid the robot builds from its scans.
//!
//! Rule (our choice, documented in `docs/papers/004-dynamic-obstacles.md`): clamped
//! log-odds, as OctoMap does. Every cell a beam crosses before its hit gets `l_miss`, the
//! hit cell gets `l_hit`, and the sum is clamped to `[l_min, l_max]`. A cell never crossed
//! by a beam is unknown (ROS -1); a crossed cell is occupied (100) when its log-odds is
//! above 0 (probability above 0.5), else free (0). gmapping's hit / visit counting was the
//! paper's likely rule; we clamp because counting never forgets: a cell where a person
//! stood for a minute would stay occupied long after they left. With the defaults, a
//! cell at `l_max` is free again after `ceil(l_max / -l_miss) = 9` later beams pass
//! through it, so people leave no permanent marks.

use envmap::{CellFrame, CellWalk, GridMap};
use hyplan_core::{Bounds, Point2, Zone};
use serde::{Deserialize, Serialize};

use crate::laser::Scan;

/// Mapping parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Mapping {
    /// Cell side, m (gmapping's `delta`, 0.05).
    pub resolution: f64,
    /// Log-odds added to a hit cell.
    pub l_hit: f64,
    /// Log-odds added to a crossed cell (negative).
    pub l_miss: f64,
    /// Lower clamp.
    pub l_min: f64,
    /// Upper clamp.
    pub l_max: f64,
    /// Beams are used up to this range, m (gmapping's `maxUrange`; 4 m, the tutorial's
    /// clearing range); a longer beam or one with no return clears up to it.
    pub max_range: f64,
    /// Seconds between map updates (gmapping updates on motion or time; 1 s here).
    pub period: f64,
}

impl Default for Mapping {
    fn default() -> Self {
        Self {
            resolution: 0.05,
            l_hit: 0.85,
            l_miss: -0.4,
            l_min: -2.0,
            l_max: 3.5,
            max_range: 4.0,
            period: 1.0,
        }
    }
}

/// ROS value of an unknown cell.
pub const UNKNOWN: i8 = -1;
/// ROS value of a free cell.
pub const FREE: i8 = 0;
/// ROS value of an occupied cell.
pub const OCCUPIED: i8 = 100;

/// An occupancy grid in the ROS frame (origin at the lower-left corner, rows from the
/// bottom), updated from scans.
#[derive(Debug, Clone)]
pub struct OccupancyGrid {
    /// Parameters.
    pub params: Mapping,
    width: usize,
    height: usize,
    origin: Point2,
    /// Log-odds per cell; `-0.0` marks a cell no beam has crossed yet. A crossed cell
    /// can never hold `-0.0` (`l_hit > 0 > l_miss`, and a sum is `-0.0` only when both
    /// terms are), and `-0.0 + x = x`, so the first update needs no special case and the
    /// walk touches one array.
    logodds: Vec<f32>,
    /// Updates so far (see [`OccupancyGrid::version`]).
    version: u64,
    /// Per block of `BLOCK` x `BLOCK` cells, the version of the last update that may have
    /// changed one of its cells: lets callers keep what they computed from a part of the
    /// map the robot has not seen again ([`OccupancyGrid::unchanged_near`]).
    touched: Vec<u64>,
    /// Which grid this is, for callers that keep what they computed from a version of it.
    id: GridId,
}

/// An [`OccupancyGrid`]'s identity: drawn anew for every grid, a clone included (a clone
/// may then be updated apart from the original, so its versions say nothing of it).
#[derive(Debug, PartialEq, Eq)]
struct GridId(u64);

impl GridId {
    fn new() -> Self {
        static NEXT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
        Self(NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed))
    }
}

impl Clone for GridId {
    fn clone(&self) -> Self {
        Self::new()
    }
}

/// Side of a change-tracking block, cells.
const BLOCK: usize = 16;

hyplan_core::grid_size!(OccupancyGrid);

impl OccupancyGrid {
    /// An all-unknown grid covering `bounds`.
    #[must_use]
    pub fn new(bounds: Bounds, params: Mapping) -> Self {
        let width = (bounds.width() / params.resolution).ceil().max(1.0) as usize;
        let height = (bounds.height() / params.resolution).ceil().max(1.0) as usize;
        Self {
            params,
            width,
            height,
            origin: bounds.min,
            logodds: vec![-0.0; width * height],
            version: 0,
            touched: vec![0; width.div_ceil(BLOCK) * height.div_ceil(BLOCK)],
            id: GridId::new(),
        }
    }

    /// This grid's identity, unique among the grids of the process (a clone has its
    /// own): with [`version`](Self::version), what a caller's copy of the grid's content
    /// was taken from.
    ///
    /// ```
    /// use hyplan_core::{Bounds, Point2};
    /// use sim::{Mapping, OccupancyGrid};
    /// let map = OccupancyGrid::new(Bounds::new(Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)), Mapping::default());
    /// assert_ne!(map.id(), map.clone().id());
    /// ```
    #[must_use]
    pub fn id(&self) -> u64 {
        self.id.0
    }

    /// How many updates the grid has had ([`integrate`](Self::integrate),
    /// [`mark_footprint_free`](Self::mark_footprint_free), [`set_value`](Self::set_value)):
    /// a stamp for [`unchanged_near`](Self::unchanged_near).
    #[must_use]
    pub const fn version(&self) -> u64 {
        self.version
    }

    /// Whether no cell overlapping the square of half-side `reach` around `p` can have
    /// changed after version `since`. Tracked per block of 16 x 16 cells, so a `false`
    /// may be a cell nearby: what a caller computed from that square at version `since`
    /// still holds when this is `true`.
    #[must_use]
    pub fn unchanged_near(&self, p: Point2, reach: f64, since: u64) -> bool {
        since >= self.version
            || self
                .blocks(p, reach)
                .all(|r| self.touched[r].iter().all(|&v| v <= since))
    }

    /// A new version, stamped on the blocks the square of half-side `reach` around `p`
    /// overlaps: every cell the caller is about to change lies in that square.
    fn touch(&mut self, p: Point2, reach: f64) {
        self.version += 1;
        for r in self.blocks(p, reach) {
            self.touched[r].fill(self.version);
        }
    }

    /// The blocks the square of half-side `reach` around `p` overlaps, as one range of
    /// `touched` per row of blocks (none when the square misses the grid).
    fn blocks(
        &self,
        p: Point2,
        reach: f64,
    ) -> impl Iterator<Item = std::ops::Range<usize>> + use<> {
        let (cols, rows) = self.window(p, reach);
        let bw = self.width.div_ceil(BLOCK);
        let (c0, c1) = (cols.start / BLOCK, cols.end.div_ceil(BLOCK));
        let block_rows = if cols.is_empty() || rows.is_empty() {
            0..0
        } else {
            rows.start / BLOCK..rows.end.div_ceil(BLOCK)
        };
        block_rows.map(move |bj| bj * bw + c0..bj * bw + c1)
    }

    /// Lower-left corner, m.
    #[must_use]
    pub const fn origin(&self) -> Point2 {
        self.origin
    }

    /// The ROS value of cell `(i, j)`: -1, 0 or 100.
    #[must_use]
    pub fn value(&self, i: usize, j: usize) -> i8 {
        ros_value(self.logodds[j * self.width + i])
    }

    /// The occupied cells (column, row), row-major from the bottom row: those whose
    /// [`value`](Self::value) is [`OCCUPIED`], without classifying the others.
    pub fn occupied_cells(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        let w = self.width;
        // Most cells are not occupied: a block of them is passed over with one test that
        // compiles to vector compares (no early exit), and only blocks holding an occupied
        // cell are walked cell by cell. A costmap rebuild reads every cell of the map.
        const BLOCK: usize = 64;
        self.logodds
            .chunks(BLOCK)
            .enumerate()
            .filter(|(_, block)| block.iter().fold(false, |any, &l| any | (l > 0.0)))
            .flat_map(move |(b, block)| {
                block
                    .iter()
                    .enumerate()
                    .filter(|(_, l)| **l > 0.0)
                    .map(move |(k, _)| {
                        let c = b * BLOCK + k;
                        (c % w, c / w)
                    })
            })
    }

    /// Every cell's ROS value, row-major from the bottom row.
    #[must_use]
    pub fn ros_values(&self) -> Vec<i8> {
        self.logodds.iter().map(|&l| ros_value(l)).collect()
    }

    /// The unknown cells and the free ones ([`UNKNOWN`] and [`FREE`] of
    /// [`ros_values`](Self::ros_values)) as rows of bits: cell `(i, j)` is bit `i % 64` of
    /// word `j * width.div_ceil(64) + i / 64`; the bits past a row's end are clear. For
    /// tests of whole rows, 64 cells at a time.
    pub(crate) fn unknown_and_free_bits(&self) -> (Vec<u64>, Vec<u64>) {
        let words = self.width.div_ceil(64);
        let (mut unknown, mut free) = (vec![0; words * self.height], vec![0; words * self.height]);
        for (j, row) in self.logodds.chunks_exact(self.width.max(1)).enumerate() {
            // A byte a cell first (`ros_value` has no branch: vector compares), then
            // eight bytes to a bit each.
            for (x, cells) in row.chunks(64).enumerate() {
                let (mut u, mut f) = ([0u8; 64], [0u8; 64]);
                for ((u, f), &l) in u.iter_mut().zip(&mut f).zip(cells) {
                    let v = ros_value(l);
                    *u = u8::from(v == UNKNOWN);
                    *f = u8::from(v == FREE);
                }
                unknown[j * words + x] = pack_bytes(&u);
                free[j * words + x] = pack_bytes(&f);
            }
        }
        (unknown, free)
    }

    /// Brings `values`, the [`OccupancyGrid::ros_values`] of [`version`](Self::version)
    /// `since` (or empty), up to date in place: whether any changed. Only the blocks of
    /// 16 x 16 cells an update touched after `since` are read, for a recorder that
    /// publishes the map at every update that changed it.
    ///
    /// ```
    /// use hyplan_core::{Bounds, Point2};
    /// use sim::{Mapping, OccupancyGrid};
    /// let p = Point2::new;
    /// let mut map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(2.0, 2.0)), Mapping::default());
    /// let mut values = Vec::new();
    /// assert!(map.update_ros_values(&mut values, 0));
    /// let since = map.version();
    /// map.mark_footprint_free(p(1.0, 1.0), 0.3);
    /// assert!(map.update_ros_values(&mut values, since));
    /// assert_eq!(values, map.ros_values());
    /// assert!(!map.update_ros_values(&mut values, map.version()));
    /// ```
    pub fn update_ros_values(&self, values: &mut Vec<i8>, since: u64) -> bool {
        if values.len() != self.logodds.len() {
            *values = self.ros_values();
            return true;
        }
        let w = self.width;
        let mut changed = false;
        for (cols, rows) in self.changed_blocks(since) {
            for j in rows {
                let row = j * w + cols.start..j * w + cols.end;
                // Branch-free per cell: the compiler vectorises it.
                for (v, &l) in values[row.clone()].iter_mut().zip(&self.logodds[row]) {
                    let new = ros_value(l);
                    changed |= *v != new;
                    *v = new;
                }
            }
        }
        changed
    }

    /// The cells (columns, rows) of each block of 16 x 16 that an update after version
    /// `since` may have changed: every cell that changed lies in one of them.
    pub(crate) fn changed_blocks(
        &self,
        since: u64,
    ) -> impl Iterator<Item = (std::ops::Range<usize>, std::ops::Range<usize>)> + '_ {
        let (w, h) = (self.width, self.height);
        let bw = w.div_ceil(BLOCK);
        self.touched
            .iter()
            .enumerate()
            .filter(move |(_, v)| **v > since)
            .map(move |(b, _)| {
                let (i0, j0) = ((b % bw) * BLOCK, (b / bw) * BLOCK);
                (i0..(i0 + BLOCK).min(w), j0..(j0 + BLOCK).min(h))
            })
    }

    /// Whether cell `(i, j)` is occupied: its [`value`](Self::value) is [`OCCUPIED`], as
    /// [`occupied_cells`](Self::occupied_cells) lists them.
    #[must_use]
    pub fn is_occupied(&self, i: usize, j: usize) -> bool {
        ros_value(self.logodds[j * self.width + i]) == OCCUPIED
    }

    /// Where the cells lie in the world.
    #[must_use]
    pub const fn frame(&self) -> CellFrame {
        CellFrame::new(self.origin, self.params.resolution, self.width, self.height)
    }

    /// The world position of the centre of cell `(i, j)`.
    #[must_use]
    pub fn cell_center(&self, i: usize, j: usize) -> Point2 {
        self.frame().cell_center(i, j)
    }

    /// The columns and rows of the cells a square of half-side `reach` around `center`
    /// overlaps, clamped to the grid.
    fn window(
        &self,
        center: Point2,
        reach: f64,
    ) -> (std::ops::Range<usize>, std::ops::Range<usize>) {
        let d = nalgebra::Vector2::new(reach, reach);
        self.window_of(Bounds::new(center - d, center + d))
    }

    /// The columns and rows of the cells `area` overlaps, clamped to the grid.
    fn window_of(&self, area: Bounds) -> (std::ops::Range<usize>, std::ops::Range<usize>) {
        let res = self.params.resolution;
        let o = self.origin;
        let lo = |c: f64, o: f64| ((c - o) / res).floor().max(0.0) as usize;
        let hi = |c: f64, o: f64, n: usize| (((c - o) / res).ceil().max(0.0) as usize).min(n);
        (
            lo(area.min.x, o.x)..hi(area.max.x, o.x, self.width),
            lo(area.min.y, o.y)..hi(area.max.y, o.y, self.height),
        )
    }

    /// The cell holding `p`, if inside.
    #[must_use]
    pub fn cell_of(&self, p: Point2) -> Option<(usize, usize)> {
        self.frame().cell_of(p)
    }

    /// Updates the grid from one scan.
    pub fn integrate(&mut self, scan: &Scan) {
        let max = self.params.max_range;
        // Every beam is traced at most `max` from the scanner; a cell of margin for the
        // rounding of the ends.
        self.touch(scan.origin, max + 2.0 * self.params.resolution);
        for k in 0..scan.ranges.len() {
            let r = scan.ranges[k];
            if r == f64::NEG_INFINITY {
                // Too close to measure: the beam says nothing about the cells beyond.
                continue;
            }
            let (hit, len) = if r.is_finite() && r <= max {
                (true, r)
            } else {
                (false, max)
            };
            let end = scan.origin + scan.directions[k] * len;
            self.trace(scan.origin, end, hit);
        }
    }

    /// Walks the cells from `a` to `b` (Amanatides-Woo): misses before the last cell, a
    /// hit (or a miss) in the last.
    fn trace(&mut self, a: Point2, b: Point2, hit: bool) {
        let mut walk = CellWalk::new(&self.frame(), a, b);
        let (w, h) = (self.width as i64, self.height as i64);
        let (miss, lo) = (self.params.l_miss as f32, self.params.l_min as f32);
        // Both ends inside (the usual case): no bounds test per cell. Misses only lower a
        // cell's log-odds, so only the lower clamp applies.
        let inside = |(i, j): (i64, i64)| i >= 0 && j >= 0 && i < w && j < h;
        let checked = !(inside(walk.cell()) && inside(walk.end_cell()));
        let steps = usize::try_from(walk.steps()).unwrap_or(usize::MAX);
        for (i, j) in walk.by_ref().take(steps) {
            if !checked || inside((i, j)) {
                let l = &mut self.logodds[(j * w + i) as usize];
                // `max` without its NaN handling (no log-odds is NaN; `lo` < 0 is no tie
                // between zeros): on the critical path of every traced cell.
                let x = *l + miss;
                *l = if x < lo { lo } else { x };
            }
        }
        let (i, j) = walk.cell();
        let last = if hit {
            self.params.l_hit
        } else {
            self.params.l_miss
        };
        self.update(i, j, last);
    }

    fn update(&mut self, i: i64, j: i64, dl: f64) {
        if i < 0 || j < 0 || i as usize >= self.width || j as usize >= self.height {
            return;
        }
        let k = j as usize * self.width + i as usize;
        let l = f64::from(self.logodds[k]) + dl;
        self.logodds[k] = l.clamp(self.params.l_min, self.params.l_max) as f32;
    }

    /// The grid as a [`GridMap`]: free -> `Free`, occupied -> `Forbidden`, unknown ->
    /// `Risk` (the occupied cells are the obstacles of a map made by exploring; unknown
    /// cells are neither).
    #[must_use]
    pub fn to_grid_map(&self) -> GridMap {
        let zones = self
            .ros_values()
            .into_iter()
            .map(|v| match v {
                FREE => Zone::Free,
                OCCUPIED => Zone::Forbidden,
                _ => Zone::Risk,
            })
            .collect();
        GridMap::from_zones(
            self.width,
            self.height,
            self.params.resolution,
            self.origin,
            zones,
        )
        .expect("the grid's own size and frame are valid")
    }

    /// Every cell as free, occupied or unknown, row-major from the bottom row.
    #[must_use]
    pub fn occupancy(&self) -> Vec<envmap::Occupancy> {
        self.logodds
            .iter()
            .map(|&l| match ros_value(l) {
                FREE => envmap::Occupancy::Free,
                OCCUPIED => envmap::Occupancy::Occupied,
                _ => envmap::Occupancy::Unknown,
            })
            .collect()
    }

    /// How many cells are `[free, occupied, unknown]`.
    #[must_use]
    pub fn counts(&self) -> [usize; 3] {
        let mut n = [0; 3];
        for &l in &self.logodds {
            n[match ros_value(l) {
                FREE => 0,
                OCCUPIED => 1,
                _ => 2,
            }] += 1;
        }
        n
    }

    /// Writes the grid as map_saver writes a map (YAML + PGM beside it, through
    /// [`envmap::write_ros_occupancy`]): free 254, occupied 0, unknown 205,
    /// `mode: trinary`, so ROS tools read the unknown cells as unknown.
    ///
    /// # Errors
    ///
    /// The writer's [`envmap::MapError`].
    pub fn write_ros(&self, yaml_path: &std::path::Path) -> Result<(), envmap::MapError> {
        envmap::write_ros_occupancy(
            &self.occupancy(),
            self.width,
            self.height,
            self.params.resolution,
            self.origin,
            yaml_path,
        )
    }

    /// How many cells are free among those `mask` selects (row-major from the bottom row,
    /// one flag per cell; a shorter mask selects fewer cells).
    #[must_use]
    pub fn count_free(&self, mask: &[bool]) -> usize {
        free_cells(&self.logodds, mask)
    }

    /// [`Self::count_free`] over the cells of the square of half-side `reach` around
    /// `center` (clamped to the grid) only. An update that touches nothing outside that
    /// square changes the whole count by exactly the change of this one, so the
    /// coverage of a growing map costs a window per scan instead of the whole grid.
    #[must_use]
    pub fn count_free_near(&self, mask: &[bool], center: Point2, reach: f64) -> usize {
        let (cols, rows) = self.window(center, reach);
        self.count_free_window(mask, cols, rows)
    }

    /// [`Self::count_free`] over the cells `area` overlaps (clamped to the grid) only: as
    /// [`Self::count_free_near`], for an update whose cells fit a box that is not a
    /// square around a point ([`Scan::traced_bounds`]).
    #[must_use]
    pub fn count_free_in(&self, mask: &[bool], area: Bounds) -> usize {
        let (cols, rows) = self.window_of(area);
        self.count_free_window(mask, cols, rows)
    }

    fn count_free_window(
        &self,
        mask: &[bool],
        cols: std::ops::Range<usize>,
        rows: std::ops::Range<usize>,
    ) -> usize {
        let mut n = 0;
        for j in rows {
            let row = j * self.width;
            let (a, b) = (row + cols.start, (row + cols.end).max(row + cols.start));
            if a >= mask.len() {
                break;
            }
            n += free_cells(&self.logodds[a..b], &mask[a..b.min(mask.len())]);
        }
        n
    }

    /// The distance from `p` to the nearest centre of an occupied cell among the cells
    /// `(ci +- reach, cj +- reach)` (`INFINITY` if none); rows are read as slices and
    /// only occupied cells cost a distance.
    #[must_use]
    pub fn nearest_occupied_centre(
        &self,
        p: Point2,
        (ci, cj): (usize, usize),
        reach: usize,
    ) -> f64 {
        let (i0, i1) = (ci.saturating_sub(reach), (ci + reach + 1).min(self.width));
        let mut best = f64::INFINITY;
        for j in cj.saturating_sub(reach)..(cj + reach + 1).min(self.height) {
            let row = &self.logodds[j * self.width..(j + 1) * self.width];
            for (i, &l) in row.iter().enumerate().take(i1).skip(i0) {
                if l > 0.0 {
                    best = best.min((self.cell_center(i, j) - p).norm());
                }
            }
        }
        best
    }

    /// How many unknown cells have their centre within `radius` of `p`.
    #[must_use]
    pub fn count_unknown_within(&self, p: Point2, radius: f64) -> usize {
        let res = self.params.resolution;
        let o = self.origin;
        let (cols, rows) = self.window(p, radius);
        let r2 = radius * radius;
        let mut n = 0usize;
        for j in rows {
            let cy = o.y + (j as f64 + 0.5) * res - p.y;
            let row = &self.logodds[j * self.width..(j + 1) * self.width];
            // Branch-free (unknown is exactly -0.0, on the bits), so that it vectorises:
            // the filter and the assigner ask this of hundreds of points per cycle.
            for (i, l) in row.iter().enumerate().take(cols.end).skip(cols.start) {
                let cx = o.x + (i as f64 + 0.5) * res - p.x;
                let inside = cx * cx + cy * cy <= r2;
                n += usize::from(inside & (l.to_bits() == 0x8000_0000));
            }
        }
        n
    }

    /// Unknown cells whose centre lies within `radius` of both `a` and `b`.
    ///
    /// ```
    /// use hyplan_core::{Bounds, Point2};
    /// use sim::{Mapping, OccupancyGrid};
    /// let p = Point2::new;
    /// let map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(4.0, 4.0)), Mapping::default());
    /// assert_eq!(map.count_unknown_within_both(p(2.0, 2.0), p(2.0, 2.0), 0.5),
    ///            map.count_unknown_within(p(2.0, 2.0), 0.5));
    /// assert_eq!(map.count_unknown_within_both(p(1.0, 2.0), p(3.0, 2.0), 0.5), 0);
    /// ```
    #[must_use]
    pub fn count_unknown_within_both(&self, a: Point2, b: Point2, radius: f64) -> usize {
        let res = self.params.resolution;
        let o = self.origin;
        let (cols, rows) = self.window(a, radius);
        let r2 = radius * radius;
        let mut n = 0usize;
        for j in rows {
            let y = o.y + (j as f64 + 0.5) * res;
            let row = &self.logodds[j * self.width..(j + 1) * self.width];
            for (i, l) in row.iter().enumerate().take(cols.end).skip(cols.start) {
                let x = o.x + (i as f64 + 0.5) * res;
                let inside = (x - a.x).powi(2) + (y - a.y).powi(2) <= r2
                    && (x - b.x).powi(2) + (y - b.y).powi(2) <= r2;
                n += usize::from(inside && l.to_bits() == 0x8000_0000);
            }
        }
        n
    }

    /// Sets cell `(i, j)` to the ROS value `v` (-1 unknown, 0 free, anything else
    /// occupied) with one update's log-odds, for hand-made maps in tests and tools; a
    /// cell outside the grid is ignored.
    pub fn set_value(&mut self, i: usize, j: usize, v: i8) {
        if i < self.width && j < self.height {
            let c = self.cell_center(i, j);
            self.touch(c, 0.0);
            self.logodds[j * self.width + i] = match v {
                UNKNOWN => -0.0,
                FREE => self.params.l_miss as f32,
                _ => self.params.l_hit as f32,
            };
        }
    }

    /// Marks the unknown cells whose centre lies within `radius` of `center` free (one
    /// miss): the robot's footprint, which a scanner mounted ahead of the centre never
    /// sees but which the robot, standing there, knows to be free. Known cells keep
    /// their value.
    pub fn mark_footprint_free(&mut self, center: Point2, radius: f64) {
        self.touch(center, radius);
        let (cols, rows) = self.window(center, radius);
        for j in rows {
            for i in cols.clone() {
                if (self.cell_center(i, j) - center).norm() <= radius && self.value(i, j) == UNKNOWN
                {
                    self.logodds[j * self.width + i] = self.params.l_miss as f32;
                }
            }
        }
    }

    /// Whether the cell holding `p` is occupied.
    #[must_use]
    pub fn occupied_at(&self, p: Point2) -> bool {
        self.cell_of(p)
            .is_some_and(|(i, j)| self.value(i, j) == OCCUPIED)
    }
}

/// 64 bytes of 0 or 1 as the bits of a word, byte `k` to bit `k`: eight bytes at a time,
/// by a product that moves byte `k`'s bit to bit `56 + k` (the other products of the
/// eight land below bit 56 or past bit 63, each on a bit of its own, so nothing carries).
fn pack_bytes(bytes: &[u8; 64]) -> u64 {
    bytes
        .chunks_exact(8)
        .enumerate()
        .fold(0, |word, (g, eight)| {
            let x = u64::from_le_bytes(eight.try_into().expect("eight bytes"));
            word | (x.wrapping_mul(0x0102_0408_1020_4080) >> 56) << (8 * g)
        })
}

/// The ROS value of a cell's log-odds: unknown cells hold -0.0 (no update yet), occupied
/// ones a positive value.
fn ros_value(l: f32) -> i8 {
    // On the bits, so that it has no branch: -0.0 (never crossed) is the sign bit
    // alone; a positive log-odds is a positive integer (no log-odds is NaN).
    let bits = l.to_bits() as i32;
    if bits == i32::MIN {
        UNKNOWN
    } else if bits > 0 {
        OCCUPIED
    } else {
        FREE
    }
}

/// Free cells of `logodds` where `mask` is set (zipped: the shorter decides).
fn free_cells(logodds: &[f32], mask: &[bool]) -> usize {
    // Free: crossed (not -0.0) and log-odds <= 0, i.e. +0.0 or a negative number other
    // than -0.0. On the bits, so that the loop has no branch and vectorises.
    logodds
        .iter()
        .zip(mask)
        .map(|(&l, &m)| {
            let b = l.to_bits();
            let free = (b == 0) | ((b >> 31) == 1 && b != 0x8000_0000);
            usize::from(free & m)
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The blocks passed over at once hide no occupied cell: every cell holding a
    /// positive log-odds comes out, in row-major order, with a grid whose last block is
    /// partial and cells set at block edges.
    #[test]
    fn occupied_cells_are_every_positive_cell() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(3.37, 2.11));
        let mut g = OccupancyGrid::new(bounds, Mapping::default());
        let n = g.width() * g.height();
        assert_ne!(n % 64, 0);
        for k in 0..n {
            if rng.random_bool(0.01) || k % 64 == 0 || k % 64 == 63 || k == n - 1 {
                g.logodds[k] = if rng.random_bool(0.8) { 0.5 } else { -0.5 };
            }
        }
        let want: Vec<(usize, usize)> = (0..n)
            .filter(|&k| g.logodds[k] > 0.0)
            .map(|k| (k % g.width(), k / g.width()))
            .collect();
        assert!(want.len() > 10);
        assert_eq!(g.occupied_cells().collect::<Vec<_>>(), want);
    }

    /// The built map is written as map_saver writes one (P5, 254 / 0 / 205, trinary) and
    /// envmap's loader reads it back with its documented rule for unknown cells.
    #[test]
    fn write_ros_is_map_saver_trinary() {
        let bounds = Bounds::new(Point2::new(-1.0, 2.0), Point2::new(0.5, 3.0));
        let params = Mapping {
            resolution: 0.5,
            ..Mapping::default()
        };
        let mut g = OccupancyGrid::new(bounds, params);
        assert_eq!((g.width(), g.height()), (3, 2));
        g.set_value(0, 0, FREE);
        g.set_value(1, 0, OCCUPIED);
        g.set_value(2, 1, FREE);
        assert_eq!(g.counts(), [2, 1, 3]);
        let dir = std::env::temp_dir().join(format!("sim-mapping-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let yaml = dir.join("map.yaml");
        g.write_ros(&yaml).unwrap();
        let pgm = std::fs::read(dir.join("map.pgm")).unwrap();
        assert!(pgm.starts_with(b"P5\n# CREATOR: hyplan"));
        // Top row (j = 1) first: unknown, unknown, free; then free, occupied, unknown.
        assert!(pgm.ends_with(b"\n3 2\n255\n\xcd\xcd\xfe\xfe\x00\xcd"));
        let text = std::fs::read_to_string(&yaml).unwrap();
        for line in [
            "mode: trinary",
            "negate: 0",
            "occupied_thresh: 0.65",
            "free_thresh: 0.196",
            "origin: [-1.0, 2.0, 0.0]",
        ] {
            assert!(text.lines().any(|l| l == line), "{line:?} not in {text}");
        }
        for (unknown_free, unknown) in [(false, Zone::Forbidden), (true, Zone::Free)] {
            let opts = envmap::LoadOptions {
                unknown_free,
                ..envmap::LoadOptions::default()
            };
            let back = envmap::load_map(&yaml, &opts).unwrap().map;
            let zones: Vec<Zone> = (0..2)
                .flat_map(|j| (0..3).map(move |i| (i, j)))
                .map(|(i, j)| back.cell_zone(i, j))
                .collect();
            let (f, x, u) = (Zone::Free, Zone::Forbidden, unknown);
            assert_eq!(zones, [f, x, u, u, u, f], "unknown_free {unknown_free}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
