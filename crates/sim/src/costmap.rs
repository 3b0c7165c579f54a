//! What the robot plans and steers with: the known map plus what the laser sees now,
//! inflated by the robot's radius with envmap's (Nav2's) inflation costs.
//!
//! Two pieces:
//! - [`ObstacleMemory`]: the latest laser hits, one exact point per 5 cm cell with the tick
//!   it was seen, forgotten after a while or as soon as a newer beam passes through it.
//!   The controller and the blocked-path test read it.
//! - [`Costmap`]: lethal cells (prior map, occupied cells of the built map, remembered
//!   hits) inflated through [`envmap::Inflation`], as a [`GridMap`] whose zones the
//!   planner uses: `Forbidden` within the inscribed radius, `Risk` within the preferred
//!   clearance, `Free` beyond.

use envmap::{CellFrame, GridMap, INSCRIBED_INFLATED_OBSTACLE, Inflation, LETHAL_OBSTACLE, Mask};
use hyplan_core::{Bounds, Point2, Zone};
use serde::{Deserialize, Serialize};

use crate::laser::Scan;
use crate::mapping::OccupancyGrid;
use crate::world::{Segment, StaticWorld};

/// Costmap parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CostmapParams {
    /// Cell side, m (0.05: the tutorial's global costmap, and the built map's cells; a
    /// coarser costmap adds up to a cell of fatness on each side of a door).
    pub resolution: f64,
    /// Footprint padding added to the body radius, m (0.03, as the tutorial's costmap).
    pub padding: f64,
    /// Cells within this distance of an obstacle, beyond the inscribed radius, are
    /// avoided when a path exists without them, m.
    pub preferred_clearance: f64,
    /// Nav2 inflation radius, m (0.55 in the tutorial).
    pub inflation_radius: f64,
    /// Nav2 cost scaling factor, 1/m (10 in the tutorial).
    pub cost_scaling_factor: f64,
    /// Laser hits farther than this from the scanner are not marked, m (3.5).
    pub obstacle_range: f64,
    /// Laser hits are remembered this long unless a newer beam passes through them, s.
    pub memory: f64,
}

impl Default for CostmapParams {
    fn default() -> Self {
        Self {
            resolution: 0.05,
            padding: 0.03,
            preferred_clearance: 0.5,
            inflation_radius: 0.55,
            cost_scaling_factor: 10.0,
            obstacle_range: 3.5,
            memory: 1.0,
        }
    }
}

/// Side of an [`ObstacleMemory`] cell, m.
pub const MEMORY_RESOLUTION: f64 = 0.05;

/// Length below which [`ObstacleMemory`]'s list of written cells is not compacted.
const MIN_COMPACT: usize = 4096;

/// Recent laser hits: per 5 cm cell, the last hit point and when it was seen.
#[derive(Debug, Clone)]
pub struct ObstacleMemory {
    frame: CellFrame,
    /// Tick of the last hit plus one (0: never).
    stamp: Vec<u64>,
    point: Vec<[f32; 2]>,
    /// Every cell written within the memory length (and some expired ones, dropped in
    /// batches), to list the points without visiting the whole grid.
    recent: Vec<u32>,
    /// Whether a cell is in `recent`.
    listed: Vec<bool>,
    /// Length of `recent` at which expired cells are next dropped.
    compact_at: usize,
    /// The latest scan, for clearing by newer beams.
    latest: Option<Scan>,
    /// Memory length, ticks.
    keep: u64,
    /// Cells the static prior map explains (see [`ObstacleMemory::with_prior`]).
    explained: Vec<bool>,
    obstacle_range: f64,
    /// Tick and origin of each scan whose hits may still be remembered, oldest first.
    origins: std::collections::VecDeque<(u64, Point2)>,
}

impl ObstacleMemory {
    /// An empty memory over `bounds`, forgetting after `keep_ticks`.
    #[must_use]
    pub fn new(bounds: Bounds, keep_ticks: u64, obstacle_range: f64) -> Self {
        let frame = CellFrame::covering(bounds, MEMORY_RESOLUTION);
        let (width, height) = (frame.width, frame.height);
        Self {
            frame,
            stamp: vec![0; width * height],
            explained: vec![false; width * height],
            point: vec![[0.0; 2]; width * height],
            recent: Vec::new(),
            listed: vec![false; width * height],
            compact_at: MIN_COMPACT,
            latest: None,
            keep: keep_ticks,
            obstacle_range,
            origins: std::collections::VecDeque::new(),
        }
    }

    /// How far a scan taken from `origin` at `tick` is read by the clearing of
    /// remembered hits (a hit is cleared when the latest scan's beam toward it goes
    /// [`MEMORY_RESOLUTION`] twice past it), m: every hit alive after `tick` is within
    /// the obstacle range of the scanner that saw it, one of the scans of the memory's
    /// length. A centimetre more for the points' `f32` rounding.
    #[must_use]
    pub fn clearing_reach(&self, origin: Point2, tick: u64) -> f64 {
        let farthest = self
            .origins
            .iter()
            .filter(|&&(t, _)| t + self.keep >= tick)
            .map(|(_, o)| (o - origin).norm())
            .fold(0.0, f64::max);
        self.obstacle_range + farthest + 2.0 * MEMORY_RESOLUTION + 0.01
    }

    fn cell(&self, p: Point2) -> Option<(usize, usize)> {
        self.frame.cell_of(p)
    }

    /// The same memory, told which cells the static prior map `mapped` explains, so that
    /// [`ObstacleMemory::loose_within`] can tell hits that may be people.
    #[must_use]
    pub fn with_prior(mut self, bounds: Bounds, mapped: &StaticWorld) -> Self {
        let (w, h, explained) = crate::tracking::static_prior(bounds, mapped, MEMORY_RESOLUTION);
        if (w, h) == (self.frame.width, self.frame.height) {
            self.explained = explained;
        }
        self
    }

    /// Marks the cells of `scan`'s hits that `is_wall` says are walls as explained, for
    /// good: on a map the robot builds itself (no prior), a hit on a cell its own map
    /// holds occupied is a wall, not a person who may step closer. Without this every
    /// wall of an unknown building counts as a possible person, and the robot creeps or
    /// stops in doorways it fits through.
    pub fn explain(&mut self, scan: &Scan, is_wall: impl Fn(Point2) -> bool) {
        for k in 0..scan.ranges.len() {
            if scan.ranges[k] > self.obstacle_range {
                continue;
            }
            let Some(p) = scan.hit(k) else { continue };
            if let Some(c) = self.frame.index_of(p)
                && !self.explained[c]
                && is_wall(p)
            {
                self.explained[c] = true;
            }
        }
    }

    /// Whether a remembered hit that the static prior does not explain (maybe a person)
    /// lies within `radius` of `p` at `tick`.
    #[must_use]
    pub fn loose_within(&self, p: Point2, radius: f64, tick: u64) -> bool {
        self.cells_near(p, radius, tick).any(|c| {
            !self.explained[c]
                && self
                    .remembered(c, tick)
                    .is_some_and(|q| (q - p).norm() <= radius && !self.cleared(c, q, tick))
        })
    }

    /// Distance from `p` to the nearest remembered hit the static prior does not explain
    /// (maybe a person) within `radius` and on the side of `p` that `ahead` points to
    /// (`(q - p) . ahead >= 0`), at `tick`.
    #[must_use]
    pub fn nearest_loose_ahead(
        &self,
        p: Point2,
        ahead: nalgebra::Vector2<f64>,
        radius: f64,
        tick: u64,
    ) -> Option<f64> {
        self.nearest_where(p, radius, tick, |c, q| {
            !self.explained[c] && (q - p).dot(&ahead) >= 0.0
        })
        .map(|(d, _)| d)
    }

    /// Records the hits of a scan taken at `tick`.
    pub fn insert(&mut self, scan: Scan, tick: u64) {
        let now = tick + 1;
        let keep = self.keep;
        while self.origins.front().is_some_and(|&(t, _)| t + keep < tick) {
            self.origins.pop_front();
        }
        self.origins.push_back((tick, scan.origin));
        // Drop expired cells from the list once it has doubled, not at every scan: the
        // list is only read through `points`, which skips them anyway.
        if self.recent.len() >= self.compact_at {
            let (stamp, listed) = (&self.stamp, &mut self.listed);
            self.recent.retain(|&k| {
                let s = stamp[k as usize];
                let alive = s != 0 && s + keep >= now;
                listed[k as usize] = alive;
                alive
            });
            self.compact_at = (2 * self.recent.len()).max(MIN_COMPACT);
        }
        for k in 0..scan.ranges.len() {
            if scan.ranges[k] > self.obstacle_range {
                continue;
            }
            // A beam too close to measure marks its shortest range: something is at
            // the scanner.
            let p = if scan.too_close(k) {
                scan.origin + scan.directions[k] * scan.range_min
            } else {
                let Some(p) = scan.hit(k) else { continue };
                p
            };
            let Some((i, j)) = self.cell(p) else { continue };
            let c = j * self.frame.width + i;
            if !self.listed[c] {
                self.listed[c] = true;
                self.recent.push(c as u32);
            }
            self.stamp[c] = now;
            self.point[c] = [p.x as f32, p.y as f32];
        }
        self.latest = Some(scan);
    }

    /// The remembered point in cell `c` if still valid at `tick`.
    fn valid(&self, c: usize, tick: u64) -> Option<Point2> {
        let p = self.remembered(c, tick)?;
        (!self.cleared(c, p, tick)).then_some(p)
    }

    /// The point last seen in cell `c`, unless its memory expired by `tick` (whether a
    /// newer beam cleared it is [`ObstacleMemory::cleared`]'s question, asked last by the
    /// queries because it costs an arctangent).
    fn remembered(&self, c: usize, tick: u64) -> Option<Point2> {
        let s = self.stamp[c];
        if s == 0 || s + self.keep < tick + 1 {
            return None;
        }
        Some(Point2::new(
            f64::from(self.point[c][0]),
            f64::from(self.point[c][1]),
        ))
    }

    /// Whether a beam of the latest scan, newer than point `p` of cell `c`, went past it
    /// (people move on).
    fn cleared(&self, c: usize, p: Point2, tick: u64) -> bool {
        if self.stamp[c] == tick + 1 {
            return false;
        }
        let Some(scan) = &self.latest else {
            return false;
        };
        let v = p - scan.origin;
        let d = v.norm();
        scan.beam_toward(v.y.atan2(v.x))
            .is_some_and(|k| scan.ranges[k] > d + 2.0 * MEMORY_RESOLUTION && d > 0.0)
    }

    /// Whether any remembered obstacle lies within `radius` of `p` at `tick`.
    #[must_use]
    pub fn any_within(&self, p: Point2, radius: f64, tick: u64) -> bool {
        self.cells_near(p, radius, tick).any(|c| {
            self.remembered(c, tick)
                .is_some_and(|q| (q - p).norm() <= radius && !self.cleared(c, q, tick))
        })
    }

    /// The cells of the square around `p` that holds every point within `radius` whose
    /// memory has not expired at `tick` (one comparison per cell, on a row at a time).
    fn cells_near(&self, p: Point2, radius: f64, tick: u64) -> impl Iterator<Item = usize> + '_ {
        let r = (radius / MEMORY_RESOLUTION).ceil() as i64 + 1;
        let (u, v) = self.frame.coords(p);
        let (ci, cj) = (u.floor() as i64, v.floor() as i64);
        let (w, h) = (self.frame.width as i64, self.frame.height as i64);
        let (i0, i1) = ((ci - r).max(0), (ci + r).min(w - 1));
        // Alive: stamped (not 0) and `stamp + keep >= tick + 1`.
        let oldest = (tick + 1).saturating_sub(self.keep).max(1);
        ((cj - r).max(0)..=(cj + r).min(h - 1)).flat_map(move |j| {
            let start = j as usize * self.frame.width;
            let row = if i0 <= i1 {
                &self.stamp[start + i0 as usize..=start + i1 as usize]
            } else {
                &[]
            };
            row.iter()
                .enumerate()
                .filter(move |&(_, &s)| s >= oldest)
                .map(move |(k, _)| start + i0 as usize + k)
        })
    }

    /// The nearest remembered obstacle within `radius` of `p` at `tick`.
    #[must_use]
    pub fn nearest_within(&self, p: Point2, radius: f64, tick: u64) -> Option<(f64, Point2)> {
        self.nearest_where(p, radius, tick, |_, _| true)
    }

    /// The nearest remembered obstacle within `radius` of `p` at `tick` whose cell and
    /// point pass `keep`.
    fn nearest_where(
        &self,
        p: Point2,
        radius: f64,
        tick: u64,
        keep: impl Fn(usize, Point2) -> bool,
    ) -> Option<(f64, Point2)> {
        let mut best: Option<(f64, Point2)> = None;
        for c in self.cells_near(p, radius, tick) {
            if let Some(q) = self.remembered(c, tick) {
                let d = (q - p).norm();
                if d <= radius
                    && best.is_none_or(|b| d < b.0)
                    && keep(c, q)
                    && !self.cleared(c, q, tick)
                {
                    best = Some((d, q));
                }
            }
        }
        best
    }

    /// Every valid remembered point at `tick`.
    #[must_use]
    pub fn points(&self, tick: u64) -> Vec<Point2> {
        self.recent
            .iter()
            .filter_map(|&c| self.valid(c as usize, tick))
            .collect()
    }
}

/// The planner's map: Nav2 costs and the zones derived from them.
#[derive(Debug, Clone)]
pub struct Costmap {
    /// Nav2 cost per cell (0..=254), row-major from the bottom row.
    pub costs: Vec<u8>,
    /// Zones for the planner (see the module doc).
    pub map: GridMap,
}

impl Costmap {
    /// The costmap ROS would publish: 254 -> 100, 253 -> 99, 1..=252 -> 1..=98, 0 -> 0.
    #[must_use]
    pub fn ros_values(&self) -> Vec<i8> {
        self.costs.iter().map(|&c| ros_cost(c)).collect()
    }
}

/// A Nav2 cost as ROS publishes it: 254 -> 100, 253 -> 99, 1..=252 -> 1..=98, 0 -> 0.
#[must_use]
pub const fn ros_cost(c: u8) -> i8 {
    match c {
        LETHAL_OBSTACLE => 100,
        INSCRIBED_INFLATED_OBSTACLE => 99,
        0 => 0,
        c => (1 + (c as u32 - 1) * 97 / 251) as i8,
    }
}

/// Builds costmaps on one grid.
#[derive(Debug, Clone)]
pub struct CostmapBuilder {
    /// Parameters.
    pub params: CostmapParams,
    /// Robot body radius, m.
    pub body_radius: f64,
    frame: CellFrame,
    /// Lethal cells of the prior map.
    prior: Vec<bool>,
}

impl CostmapBuilder {
    /// A builder over `bounds` whose prior map is `mapped` rasterised (a cell is lethal
    /// when an obstacle reaches into it).
    #[must_use]
    pub fn new(
        bounds: Bounds,
        mapped: &StaticWorld,
        params: CostmapParams,
        body_radius: f64,
    ) -> Self {
        let (width, height, prior) = rasterize(bounds, mapped, params.resolution);
        Self {
            params,
            body_radius,
            frame: CellFrame::new(bounds.min, params.resolution, width, height),
            prior,
        }
    }

    /// The inflation used: inscribed radius = body + padding + one cell diagonal, so that
    /// every point of a free cell is at least body + padding from every obstacle point
    /// (both the point and the obstacle may sit half a diagonal off their cell centres),
    /// and a path the planner finds is one the controller's exact arc test (body +
    /// margin from the real hits) lets the robot drive. At 0.05 m cells this is 0.279 m
    /// for the default robot: a door of about 0.6 m passes.
    #[must_use]
    pub fn inflation(&self) -> Inflation {
        self.inflation_with(self.params.resolution * std::f64::consts::SQRT_2)
    }

    /// The tight inflation: inscribed radius = body + padding between cell centres, as
    /// Nav2 measures it (0.208 m for the default robot), without
    /// [`inflation`](Self::inflation)'s cell of fatness; see
    /// [`build_tight`](Self::build_tight).
    #[must_use]
    pub fn tight_inflation(&self) -> Inflation {
        self.inflation_with(0.0)
    }

    fn inflation_with(&self, cell_slack: f64) -> Inflation {
        let inscribed = self.body_radius + self.params.padding + cell_slack;
        Inflation {
            inscribed_radius: inscribed,
            inflation_radius: self.params.inflation_radius.max(inscribed),
            cost_scaling_factor: self.params.cost_scaling_factor,
        }
    }

    /// The costmap of the navigator's last try, when no plan exists on
    /// [`build`](Self::build)'s: the same lethal cells under the
    /// [`tight_inflation`](Self::tight_inflation), so gaps about 0.07 m narrower pass.
    ///
    /// A robot can drive through a gap while the map around it is half seen; once the
    /// laser maps the gap's sides cell by cell, the cell of fatness can close it behind
    /// the robot, and every plan out fails (measured on a real floor's chairs,
    /// measurements/issue-27.md). On this costmap the robot plans its way out; the
    /// controller's arc test (body + margin from the real hits) still keeps the body
    /// clear along such a path.
    ///
    /// ```
    /// use hyplan_core::{Bounds, Point2};
    /// use sim::{CostmapBuilder, CostmapParams, StaticWorld};
    /// let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(4.0, 4.0));
    /// let builder = CostmapBuilder::new(bounds, &StaticWorld::default(), CostmapParams::default(), 0.18);
    /// // Two hits 0.55 m apart: closed on the usual costmap, open on the tight one.
    /// let hits = [Point2::new(1.725, 2.025), Point2::new(2.275, 2.025)];
    /// let gap = Point2::new(2.025, 2.025);
    /// let (i, j) = builder.build(None, &hits).map.world_to_cell(gap).unwrap();
    /// assert!(!builder.build(None, &hits).map.cell_free(i, j));
    /// assert!(builder.build_tight(None, &hits).map.cell_free(i, j));
    /// ```
    #[must_use]
    pub fn build_tight(&self, built: Option<&OccupancyGrid>, hits: &[Point2]) -> Costmap {
        self.costmap_with(&self.lethal(built, hits), &self.tight_inflation())
    }

    /// The costmap of the prior map, the built map's occupied cells and `hits`.
    #[must_use]
    pub fn build(&self, built: Option<&OccupancyGrid>, hits: &[Point2]) -> Costmap {
        self.costmap_with(&self.lethal(built, hits), &self.inflation())
    }

    /// The costmap of the lethal cells `lethal` under `inflation`.
    fn costmap_with(&self, lethal: &Mask, inflation: &Inflation) -> Costmap {
        let costs = self.inflate(lethal, inflation);
        let risk_from = risk_from(inflation, self.params.preferred_clearance);
        let zones = costs.iter().map(|&c| zone_of(c, risk_from)).collect();
        let f = self.frame;
        let map = GridMap::from_zones(f.width, f.height, f.resolution, f.origin, zones)
            .expect("the builder's own size and frame are valid");
        Costmap { costs, map }
    }

    /// [`build`](Self::build)'s costmap, kept in `cache` and inflated again only around
    /// the lethal cells that changed since the cache's last build: the same costs and
    /// zones, at a cost set by what changed rather than by the grid (which a navigator
    /// that plans every few seconds on a large building would pay at every plan).
    ///
    /// ```
    /// use hyplan_core::{Bounds, Point2};
    /// use sim::{CostmapBuilder, CostmapCache, CostmapParams, StaticWorld};
    /// let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(4.0, 4.0));
    /// let builder = CostmapBuilder::new(bounds, &StaticWorld::default(), CostmapParams::default(), 0.18);
    /// let mut cache = CostmapCache::default();
    /// let hits = [Point2::new(2.0, 2.0)];
    /// builder.rebuild(&mut cache, None, &hits);
    /// let again = builder.rebuild(&mut cache, None, &[]);
    /// assert_eq!(again.costs, builder.build(None, &[]).costs);
    /// ```
    pub fn rebuild<'c>(
        &self,
        cache: &'c mut CostmapCache,
        built: Option<&OccupancyGrid>,
        hits: &[Point2],
    ) -> &'c Costmap {
        self.rebuild_with(cache, built, hits, &self.inflation())
    }

    /// [`build_tight`](Self::build_tight)'s costmap kept in `cache`, as
    /// [`rebuild`](Self::rebuild) keeps [`build`](Self::build)'s (a cache serves one of
    /// the two only).
    pub fn rebuild_tight<'c>(
        &self,
        cache: &'c mut CostmapCache,
        built: Option<&OccupancyGrid>,
        hits: &[Point2],
    ) -> &'c Costmap {
        self.rebuild_with(cache, built, hits, &self.tight_inflation())
    }

    fn rebuild_with<'c>(
        &self,
        cache: &'c mut CostmapCache,
        built: Option<&OccupancyGrid>,
        hits: &[Point2],
        inflation: &Inflation,
    ) -> &'c Costmap {
        let f = self.frame;
        let kept = cache
            .costmap
            .as_ref()
            .is_some_and(|c| c.costs.len() == f.cells())
            && cache
                .lethal
                .as_ref()
                .is_some_and(|l| l.cells().len() == f.cells());
        if !kept {
            let (lethal, parts) = self.lethal_parts(built, hits);
            cache.costmap = Some(self.costmap_with(&lethal, inflation));
            cache.lethal = Some(lethal);
            cache.parts = parts;
            return cache.costmap.as_ref().expect("just built");
        }
        let window = match self.update_lethal(cache, built, hits) {
            Some(window) => window,
            None => {
                let (lethal, parts) = self.lethal_parts(built, hits);
                let last = cache.lethal.as_ref().expect("kept above");
                let window = changed_window(last.cells(), lethal.cells(), f.width);
                cache.lethal = Some(lethal);
                cache.parts = parts;
                window
            }
        };
        let (Some(costmap), Some(lethal)) = (cache.costmap.as_mut(), cache.lethal.as_ref()) else {
            unreachable!("kept above");
        };
        let Some((columns, rows)) = window else {
            return costmap;
        };
        // A cell's cost depends on the lethal cells within the inflation radius: the
        // cells that may change are the window grown by that reach, and the lethal cells
        // that decide them lie within the reach of those.
        let reach = (inflation.inflation_radius / f.resolution).ceil() as usize + 1;
        let grow = |r: std::ops::Range<usize>, by: usize, n: usize| {
            r.start.saturating_sub(by)..(r.end + by).min(n)
        };
        let (ci, cj) = (grow(columns, reach, f.width), grow(rows, reach, f.height));
        let (ni, nj) = (
            grow(ci.clone(), reach, f.width),
            grow(cj.clone(), reach, f.height),
        );
        let sub_w = ni.len();
        let cells = nj
            .clone()
            .flat_map(|j| {
                lethal.cells()[j * f.width + ni.start..j * f.width + ni.end]
                    .iter()
                    .copied()
            })
            .collect();
        let sub = Mask::from_cells(sub_w, nj.len(), cells).expect("a window of the grid");
        let costs = self.inflate(&sub, inflation);
        let risk_from = risk_from(inflation, self.params.preferred_clearance);
        let zones = costmap.map.zones_mut();
        for j in cj {
            let from = (j - nj.start) * sub_w + (ci.start - ni.start);
            let row = &costs[from..from + ci.len()];
            let at = j * f.width + ci.start;
            costmap.costs[at..at + ci.len()].copy_from_slice(row);
            for (z, &c) in zones[at..at + ci.len()].iter_mut().zip(row) {
                *z = zone_of(c, risk_from);
            }
        }
        costmap
    }

    /// Brings the cache's lethal cells (of this builder's size) up to date in place when
    /// they came from the same built map (`built`, on the costmap's own cells): only the
    /// blocks the map changed in since, and the cells of the last hits and of `hits`,
    /// are read. Returns the window
    /// of the cells that changed (`None` inside: none did), or `None` when the cache
    /// cannot be brought up to date so (the caller builds the lethal cells afresh).
    fn update_lethal(
        &self,
        cache: &mut CostmapCache,
        built: Option<&OccupancyGrid>,
        hits: &[Point2],
    ) -> Option<Option<(std::ops::Range<usize>, std::ops::Range<usize>)>> {
        let g = built?;
        let parts = cache.parts.as_mut()?;
        let lethal = cache.lethal.as_mut()?;
        let f = self.frame;
        if parts.grid != g.id() || parts.version > g.version() {
            return None;
        }
        // Each cell whose value this build may change, with its value before (a cell
        // written twice is listed twice; its first entry holds the value before).
        let mut touched: Vec<(usize, bool)> = Vec::new();
        let w = f.width;
        let (maps, cells) = (parts.maps.cells_mut(), lethal.cells_mut());
        for (columns, rows) in g.changed_blocks(parts.version) {
            for j in rows {
                for i in columns.clone() {
                    let k = j * w + i;
                    let now = self.prior[k] || g.is_occupied(i, j);
                    maps[k] = now;
                    if cells[k] != now {
                        touched.push((k, cells[k]));
                        cells[k] = now;
                    }
                }
            }
        }
        parts.version = g.version();
        for &k in &parts.hits {
            touched.push((k, cells[k]));
            cells[k] = maps[k];
        }
        parts.hits.clear();
        for &p in hits {
            if let Some((i, j)) = f.cell_of(p) {
                let k = j * w + i;
                touched.push((k, cells[k]));
                cells[k] = true;
                parts.hits.push(k);
            }
        }
        let mut window: Option<(usize, usize, usize, usize)> = None;
        for &(k, before) in &touched {
            if cells[k] != before {
                let (i, j) = (k % w, k / w);
                window = Some(window.map_or((i, i, j, j), |(i0, i1, j0, j1)| {
                    (i0.min(i), i1.max(i), j0.min(j), j1.max(j))
                }));
            }
        }
        Some(window.map(|(i0, i1, j0, j1)| (i0..i1 + 1, j0..j1 + 1)))
    }

    /// [`lethal`](Self::lethal), and what it was made of when the built map lies on the
    /// costmap's own cells (see [`LethalParts`]).
    fn lethal_parts(
        &self,
        built: Option<&OccupancyGrid>,
        hits: &[Point2],
    ) -> (Mask, Option<LethalParts>) {
        let f = self.frame;
        let Some(g) = built.filter(|g| g.frame() == f) else {
            return (self.lethal(built, hits), None);
        };
        let maps = self.lethal(Some(g), &[]);
        let mut lethal = maps.clone();
        let mut marked = Vec::with_capacity(hits.len());
        for &p in hits {
            if let Some((i, j)) = f.cell_of(p) {
                lethal.set(i, j, true);
                marked.push(j * f.width + i);
            }
        }
        let parts = LethalParts {
            maps,
            grid: g.id(),
            version: g.version(),
            hits: marked,
        };
        (lethal, Some(parts))
    }

    /// The lethal cells: the prior map's, the built map's occupied ones and the hits'.
    fn lethal(&self, built: Option<&OccupancyGrid>, hits: &[Point2]) -> Mask {
        let f = self.frame;
        let mut mask = Mask::new(f.width, f.height);
        mask.cells_mut().copy_from_slice(&self.prior);
        let mut mark = |p: Point2| {
            if let Some((i, j)) = f.cell_of(p) {
                mask.set(i, j, true);
            }
        };
        if let Some(g) = built {
            for (i, j) in g.occupied_cells() {
                mark(g.cell_center(i, j));
            }
        }
        for &p in hits {
            mark(p);
        }
        mask
    }

    fn inflate(&self, lethal: &Mask, inflation: &Inflation) -> Vec<u8> {
        inflation
            .inflate(lethal, self.params.resolution)
            .expect("the builder's own parameters are valid")
    }
}

/// The least cost of a `Risk` cell under `inflation`: the cost at the preferred
/// clearance.
fn risk_from(inflation: &Inflation, preferred_clearance: f64) -> u8 {
    inflation.cost(preferred_clearance).max(1)
}

/// The zone of a cell of cost `c`.
fn zone_of(c: u8, risk_from: u8) -> Zone {
    if c >= INSCRIBED_INFLATED_OBSTACLE {
        Zone::Forbidden
    } else if c >= risk_from {
        Zone::Risk
    } else {
        Zone::Free
    }
}

/// A costmap kept between builds ([`CostmapBuilder::rebuild`]).
#[derive(Debug, Clone, Default)]
pub struct CostmapCache {
    /// The lethal cells the costmap was built from.
    lethal: Option<Mask>,
    costmap: Option<Costmap>,
    /// What the lethal cells were made of, when they came from a built map on the
    /// costmap's own cells.
    parts: Option<LethalParts>,
}

/// The lethal cells of the prior map and of a built map's occupied cells, at one of the
/// built map's versions, and the cells the hits then added: what the next build needs to
/// read again only where the built map changed since and where the hits were.
#[derive(Debug, Clone)]
struct LethalParts {
    /// Prior and built map, without the hits.
    maps: Mask,
    /// The built map's identity and version (`OccupancyGrid::id`, `version`).
    grid: u64,
    version: u64,
    /// The cells the hits marked.
    hits: Vec<usize>,
}

impl CostmapCache {
    /// The costmap of the last build, if any.
    ///
    /// ```
    /// assert!(sim::CostmapCache::default().costmap().is_none());
    /// ```
    #[must_use]
    pub fn costmap(&self) -> Option<&Costmap> {
        self.costmap.as_ref()
    }
}

/// The smallest window (columns, rows) of a `width`-wide row-major grid holding every
/// cell where `old` and `new` differ; `None` when they are equal.
pub(crate) fn changed_window<T: Copy + Into<u8>>(
    old: &[T],
    new: &[T],
    width: usize,
) -> Option<(std::ops::Range<usize>, std::ops::Range<usize>)> {
    let mut window: Option<(usize, usize, usize, usize)> = None;
    for (j, (a, b)) in old.chunks(width).zip(new.chunks(width)).enumerate() {
        // A row's bytes folded without an early exit, which compiles to vector
        // instructions: a slice comparison of an enum goes element by element (ten
        // times slower on a costmap's rows).
        let differ = a
            .iter()
            .zip(b)
            .fold(0u8, |acc, (&x, &y)| acc | (x.into() ^ y.into()));
        if differ == 0 {
            continue;
        }
        let first = a
            .iter()
            .zip(b)
            .position(|(&x, &y)| x.into() != y.into())
            .unwrap_or(0);
        let last = width
            - 1
            - a.iter()
                .zip(b)
                .rev()
                .position(|(&x, &y)| x.into() != y.into())
                .unwrap_or(0);
        window = Some(match window {
            None => (first, last, j, j),
            Some((i0, i1, j0, _)) => (i0.min(first), i1.max(last), j0, j),
        });
    }
    window.map(|(i0, i1, j0, j1)| (i0..i1 + 1, j0..j1 + 1))
}

/// Marks the cells of a `res`-sided grid at `origin` (`width` x `height`, row-major from
/// the bottom row) whose centre lies within half a cell diagonal (plus `tolerance`) of one
/// of `segments`: [`rasterize`]'s rule for an obstacle's outline.
pub(crate) fn mark_near_segments(
    cells: &mut [bool],
    frame: CellFrame,
    segments: &[Segment],
    tolerance: f64,
) {
    let half_diag = frame.resolution * std::f64::consts::FRAC_1_SQRT_2;
    for s in segments {
        let (lo, hi) = (s.a.y.min(s.b.y), s.a.y.max(s.b.y));
        for j in frame.rows(lo - half_diag, hi + half_diag) {
            let (lo, hi) = (s.a.x.min(s.b.x), s.a.x.max(s.b.x));
            for i in frame.columns(lo - half_diag, hi + half_diag) {
                let c = frame.cell_center(i, j);
                let k = j * frame.width + i;
                if !cells[k]
                    && (crate::world::closest_on_segment(c, s.a, s.b) - c).norm()
                        <= half_diag + tolerance
                {
                    cells[k] = true;
                }
            }
        }
    }
}

/// The cells of a `res`-sided grid over `bounds` that the static geometry `mapped` reaches
/// into (a cell whose centre lies within half a cell diagonal of an obstacle, or a cell a
/// forbidden cell of a loaded map overlaps): (columns, rows, row-major cells from the
/// bottom row).
#[must_use]
pub fn rasterize(bounds: Bounds, mapped: &StaticWorld, res: f64) -> (usize, usize, Vec<bool>) {
    let frame = CellFrame::covering(bounds, res);
    let (width, height) = (frame.width, frame.height);
    let half_diag = res * std::f64::consts::FRAC_1_SQRT_2;
    let mut prior = vec![false; frame.cells()];
    mark_near_segments(&mut prior, frame, &mapped.segments, 0.0);
    // Each other shape marks the cells of its bounding box that it reaches into.
    let mut mark_box = |lo: Point2, hi: Point2, hit: &dyn Fn(Point2) -> bool| {
        for j in frame.rows(lo.y, hi.y) {
            for i in frame.columns(lo.x, hi.x) {
                if !prior[j * width + i] && hit(frame.cell_center(i, j)) {
                    prior[j * width + i] = true;
                }
            }
        }
    };
    let pad = nalgebra::Vector2::new(half_diag, half_diag);
    for poly in &mapped.polygons {
        let lo = poly
            .iter()
            .fold(Point2::new(f64::INFINITY, f64::INFINITY), |m, p| {
                Point2::new(m.x.min(p.x), m.y.min(p.y))
            });
        let hi = poly
            .iter()
            .fold(Point2::new(f64::NEG_INFINITY, f64::NEG_INFINITY), |m, p| {
                Point2::new(m.x.max(p.x), m.y.max(p.y))
            });
        mark_box(lo, hi, &|c| crate::world::point_in_polygon(c, poly));
    }
    for d in &mapped.discs {
        let r = nalgebra::Vector2::new(d.radius, d.radius) + pad;
        mark_box(d.center - r, d.center + r, &|c| {
            (c - d.center).norm() <= d.radius + half_diag
        });
    }
    if let Some(g) = &mapped.grid {
        // Every costmap cell a forbidden grid cell overlaps (sampled at the grid's
        // corners and centre) is lethal.
        for gj in 0..g.height() {
            for gi in 0..g.width() {
                if g.cell_zone(gi, gj) != Zone::Forbidden {
                    continue;
                }
                let c = g.cell_center(gi, gj);
                let h = g.resolution() / 2.0 * 0.999;
                for (dx, dy) in [(0.0, 0.0), (-h, -h), (h, -h), (-h, h), (h, h)] {
                    if let Some(k) = frame.index_of(Point2::new(c.x + dx, c.y + dy)) {
                        prior[k] = true;
                    }
                }
            }
        }
    }
    (width, height, prior)
}

#[cfg(test)]
mod tests {
    use super::changed_window;
    use hyplan_core::Zone;
    use proptest::prelude::*;

    fn zone(k: u8) -> Zone {
        [Zone::Free, Zone::Risk, Zone::Forbidden][usize::from(k % 3)]
    }

    proptest! {
        /// The window is the bounding box of the cells that differ.
        #[test]
        fn the_window_bounds_the_changed_cells(
            width in 1usize..70,
            height in 1usize..6,
            cells in prop::collection::vec(0u8..3, 420),
            flips in prop::collection::vec((0usize..420, 1u8..3), 0..4),
        ) {
            let n = width * height;
            let old: Vec<Zone> = cells[..n].iter().map(|&k| zone(k)).collect();
            let mut new = old.clone();
            for &(at, by) in &flips {
                let at = at % n;
                new[at] = zone(u8::from(old[at]) + by);
            }
            let differ: Vec<(usize, usize)> = (0..n)
                .filter(|&k| old[k] != new[k])
                .map(|k| (k % width, k / width))
                .collect();
            let expected = (!differ.is_empty()).then(|| {
                let i0 = differ.iter().map(|c| c.0).min().unwrap();
                let i1 = differ.iter().map(|c| c.0).max().unwrap();
                let j0 = differ.iter().map(|c| c.1).min().unwrap();
                let j1 = differ.iter().map(|c| c.1).max().unwrap();
                (i0..i1 + 1, j0..j1 + 1)
            });
            prop_assert_eq!(changed_window(&old, &new, width), expected);
        }
    }
}
