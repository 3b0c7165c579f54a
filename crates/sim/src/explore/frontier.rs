//! The baseline: classic nearest-frontier exploration (Yamauchi 1997). Frontier cells are
//! free cells of the built map with an unknown 4-neighbour; they are grouped into
//! 8-connected clusters; the robot goes to the cluster whose closest cell is the fewest
//! costmap steps away, through cells its centre may occupy (free or unknown, outside the
//! inscribed radius).
//!
//! Choices: distances are breadth-first steps on the 8-connected costmap grid (every step
//! counts one cell, diagonal or not): enough to rank clusters, no heavier than the map;
//! clusters of fewer than `min_cells` cells are ignored (laser speckle).

use envmap::{
    Connectivity, INSCRIBED_INFLATED_OBSTACLE, Mask, StepsFlood, clusters, nearest_passable,
};
use hyplan_core::Point2;

use crate::costmap::Costmap;
use crate::mapping::OccupancyGrid;

/// Free cells with an unknown 4-neighbour, row-major order.
#[must_use]
pub fn frontier_cells(map: &OccupancyGrid) -> Vec<(usize, usize)> {
    let (w, h) = (map.width(), map.height());
    let (unknown, free) = map.unknown_and_free_bits();
    let words = w.div_ceil(64);
    // A row's words at a time (no per-cell branches), the cells beside along the row by
    // shifts carried across words; bits past the row's end are clear.
    fn row(bits: &[u64], words: usize, j: usize) -> &[u64] {
        &bits[j * words..(j + 1) * words]
    }
    let mut cells = Vec::new();
    for j in 0..h {
        let (u, f) = (row(&unknown, words, j), row(&free, words, j));
        let below = j.checked_sub(1).map(|b| row(&unknown, words, b));
        let above = (j + 1 < h).then(|| row(&unknown, words, j + 1));
        for x in 0..words {
            if f[x] == 0 {
                continue;
            }
            let left = (u[x] << 1) | x.checked_sub(1).map_or(0, |p| u[p] >> 63);
            let right = (u[x] >> 1) | u.get(x + 1).map_or(0, |n| n << 63);
            let beside = below.map_or(0, |b| b[x]) | above.map_or(0, |a| a[x]);
            let mut frontier = f[x] & (left | right | beside);
            while frontier != 0 {
                cells.push((64 * x + frontier.trailing_zeros() as usize, j));
                frontier &= frontier - 1;
            }
        }
    }
    cells
}

/// The frontier cells of `map` in 8-connected clusters (each in discovery order, clusters
/// ordered by their first cell).
#[must_use]
pub fn frontier_clusters(map: &OccupancyGrid) -> Vec<Vec<(usize, usize)>> {
    let cells = frontier_cells(map);
    let mut is_frontier = Mask::new(map.width(), map.height());
    for &(i, j) in &cells {
        is_frontier.set(i, j, true);
    }
    clusters(&is_frontier, cells, Connectivity::Eight)
}

/// Breadth-first steps from `from` over the costmap cells below the inscribed cost
/// (`u32::MAX` where unreachable); the start cell is always entered, or, when it is at
/// the inscribed cost or above, the nearest cell below it within the planner's start
/// slack (else a robot whose centre is a little too near an obstacle on the costmap
/// would find every cell unreachable).
#[must_use]
pub fn costmap_steps(costmap: &Costmap, from: Point2) -> Vec<u32> {
    let mut flood = TravelFlood::new(costmap, from, 0.0, None);
    flood.finish();
    flood.into_buffers().into_steps()
}

/// [`travel`] to frontiers with the costmap flooded only as far as the questions need:
/// the breadth-first steps of [`costmap_steps`] grown on demand (a choice among
/// frontiers a few metres away need not flood a whole building), exact all the same.
///
/// ```
/// use hyplan_core::{Bounds, Point2};
/// use sim::{CostmapBuilder, CostmapParams, StaticWorld, TravelFlood, costmap_steps, travel};
/// let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(8.0, 8.0));
/// let builder = CostmapBuilder::new(bounds, &StaticWorld::default(), CostmapParams::default(), 0.18);
/// let costmap = builder.build(None, &[]);
/// let (robot, frontier) = (Point2::new(1.0, 1.0), Point2::new(3.0, 1.0));
/// let mut flood = TravelFlood::new(&costmap, robot, 0.5, None);
/// let lazily = flood.travel(frontier);
/// assert_eq!(lazily, travel(&costmap, &costmap_steps(&costmap, robot), frontier, 0.5));
/// assert!(!flood.finished(), "a frontier 2 m away floods 2 m, not the 8 m square");
/// ```
#[derive(Debug)]
pub struct TravelFlood<'c> {
    costmap: &'c Costmap,
    flood: StepsFlood,
    /// How far from a frontier its nearest reachable cell may be, m.
    radius: f64,
}

impl<'c> TravelFlood<'c> {
    /// Travel from `from` on `costmap` to within `radius` of the frontiers asked about,
    /// with the buffers of an earlier flood (`reuse`, of any grid) when given.
    #[must_use]
    pub fn new(costmap: &'c Costmap, from: Point2, radius: f64, reuse: Option<StepsFlood>) -> Self {
        let mut flood = flood_buffers(costmap, reuse);
        flood.restart(start_cell(costmap, from));
        Self {
            costmap,
            flood,
            radius,
        }
    }

    /// The flood's buffers, for the next one.
    #[must_use]
    pub fn into_buffers(self) -> StepsFlood {
        self.flood
    }

    /// Whether the flood reached every cell it can.
    #[must_use]
    pub fn finished(&self) -> bool {
        self.flood.finished()
    }

    /// The least travel a frontier whose [`known`](Self::known) travel is `None` or
    /// above this can have, m (infinite once finished).
    #[must_use]
    pub fn floor(&self) -> f64 {
        match self.flood.unreached_from() {
            u32::MAX => f64::INFINITY,
            s => f64::from(s) * self.costmap.map.resolution(),
        }
    }

    /// [`travel`] over the cells reached so far: exact when at most [`floor`](Self::floor).
    #[must_use]
    pub fn known(&self, target: Point2) -> Option<f64> {
        travel(self.costmap, self.flood.steps(), target, self.radius)
    }

    /// Floods further: half as far again, and at least a metre.
    pub fn grow(&mut self) {
        let res = self.costmap.map.resolution();
        let level = self.flood.unreached_from().saturating_sub(1);
        let more = (level / 2).max((1.0 / res).ceil() as u32);
        self.grow_to(level.saturating_add(more));
    }

    /// Floods every cell that can be reached.
    pub fn finish(&mut self) {
        self.grow_to(u32::MAX);
    }

    fn grow_to(&mut self, level: u32) {
        let costs = &self.costmap.costs;
        self.flood
            .grow_to(level, |c| costs[c] < INSCRIBED_INFLATED_OBSTACLE);
    }

    /// The exact [`travel`] to `target`, flooding as far as it takes.
    pub fn travel(&mut self, target: Point2) -> Option<f64> {
        loop {
            let known = self.known(target);
            if self.finished() || known.is_some_and(|t| t <= self.floor()) {
                return known;
            }
            match known {
                Some(t) => self.grow_to((t / self.costmap.map.resolution()).ceil() as u32),
                None => self.grow(),
            }
        }
    }
}

/// `reuse` if it floods a grid of `costmap`'s size, else new buffers.
fn flood_buffers(costmap: &Costmap, reuse: Option<StepsFlood>) -> StepsFlood {
    let (w, h) = (costmap.map.width(), costmap.map.height());
    reuse
        .filter(|f| f.size() == (w, h))
        .unwrap_or_else(|| StepsFlood::new(w, h, Connectivity::Eight))
}

/// Whether costmap cell `k` (row-major) is one the robot's centre may cross.
fn open(costmap: &Costmap, k: usize) -> bool {
    costmap.costs[k] < INSCRIBED_INFLATED_OBSTACLE
}

/// Where a flood from `from` starts on `costmap`: its cell, always entered, or, when it is
/// at the inscribed cost or above, the nearest cell below it within the planner's start
/// slack. `None` off the costmap.
fn start_cell(costmap: &Costmap, from: Point2) -> Option<(usize, usize)> {
    let (w, h) = (costmap.map.width(), costmap.map.height());
    costmap.map.world_to_cell(from).map(|cell| {
        let rings = crate::planner::start_rings(costmap.map.resolution());
        nearest_passable((w, h), cell, rings, |i, j| open(costmap, j * w + i)).unwrap_or(cell)
    })
}

/// Whether none of `candidates` (costmap cells and their points, those `skip` holds for
/// left out) can be reached from the flood start `start` ([`start_cell`]): each
/// candidate's pocket of open cells is flooded (once, whatever number of candidates it
/// holds) and found not to hold the start. `false` as soon as one pocket holds it, or
/// grows past `budget` cells: the flood from the start then decides. `flood` is lent
/// buffers.
///
/// The flood from the start enters only open cells after the start, and open cells
/// neighbour each other both ways, so it reaches exactly the start's pocket. A start
/// that is not open has no open neighbour either (it would have started from that one,
/// the nearest within the start slack) and reaches nothing but itself. Pockets behind
/// doorways narrower than the robot are small beside the building a flood from the
/// robot covers before it can say "none".
fn cut_off(
    costmap: &Costmap,
    start: (usize, usize),
    candidates: &[(usize, Point2)],
    skip: impl Fn(Point2) -> bool,
    flood: &mut StepsFlood,
    budget: usize,
) -> bool {
    let w = costmap.map.width();
    let s = start.1 * w + start.0;
    let mut shut = vec![0u64; costmap.costs.len().div_ceil(64)];
    let is_shut = |shut: &[u64], c: usize| shut[c / 64] >> (c % 64) & 1 != 0;
    for &(k, p) in candidates {
        if k == s {
            return false;
        }
        if !open(costmap, k) || is_shut(&shut, k) || skip(p) {
            continue;
        }
        flood.restart([(k % w, k / w)]);
        loop {
            if flood.steps()[s] != u32::MAX || flood.reached().len() > budget {
                return false;
            }
            if flood.finished() {
                break;
            }
            let level = flood.unreached_from();
            flood.grow_to(level, |c| open(costmap, c));
        }
        for &c in flood.reached() {
            shut[c as usize / 64] |= 1 << (c % 64);
        }
    }
    true
}

/// The travel to `target` on `costmap`, m: over the reachable cells within `radius` of
/// it, the least of [`costmap_steps`]' `steps` times the cell side plus the straight line
/// on to the target; `None` when no reachable cell is that near.
///
/// ```
/// use hyplan_core::{Bounds, Point2};
/// use sim::{CostmapBuilder, CostmapParams, StaticWorld, costmap_steps, travel};
/// let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(4.0, 4.0));
/// let builder = CostmapBuilder::new(bounds, &StaticWorld::default(), CostmapParams::default(), 0.18);
/// let costmap = builder.build(None, &[]);
/// let steps = costmap_steps(&costmap, Point2::new(1.0, 1.0));
/// let t = travel(&costmap, &steps, Point2::new(3.0, 1.0), 0.5).unwrap();
/// assert!((t - 2.0).abs() < 0.1);
/// ```
#[must_use]
pub fn travel(costmap: &Costmap, steps: &[u32], target: Point2, radius: f64) -> Option<f64> {
    let map = &costmap.map;
    let frame = map.frame();
    let res = map.resolution();
    let mut best: Option<f64> = None;
    for j in frame.rows(target.y - radius, target.y + radius) {
        for i in frame.columns(target.x - radius, target.x + radius) {
            let s = steps[j * frame.width + i];
            let d = (map.cell_center(i, j) - target).norm();
            if s == u32::MAX || d > radius {
                continue;
            }
            let t = f64::from(s) * res + d;
            if best.is_none_or(|b| t < b) {
                best = Some(t);
            }
        }
    }
    best
}

/// The goal of nearest-frontier exploration: the centre of the reachable frontier cell
/// closest to `robot` (in costmap steps) among clusters of at least `min_cells` cells,
/// skipping cells for which `skip` holds (blacklisted goals); `None` when there is none.
/// On equal steps, the first cell of the first cluster ([`frontier_clusters`]' order).
///
/// The costmap is flooded from the robot only as far as the nearest frontier: the
/// answer of [`costmap_steps`] over the whole costmap, at the cost of the rooms between.
/// A "none" comes first from the frontiers' own pockets of the costmap, when none of them
/// holds the robot (frontiers behind doorways narrower than it), without flooding the
/// building.
///
/// ```
/// use hyplan_core::{Bounds, Point2};
/// use sim::{CostmapBuilder, CostmapParams, FREE, Mapping, OccupancyGrid, StaticWorld};
/// let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(4.0, 4.0));
/// // Known free below y = 3 m, unknown above: the frontier is the row under y = 3 m.
/// let mut map = OccupancyGrid::new(bounds, Mapping::default());
/// for j in 0..map.height() {
///     for i in 0..map.width() {
///         if map.cell_center(i, j).y < 3.0 {
///             map.set_value(i, j, FREE);
///         }
///     }
/// }
/// let builder = CostmapBuilder::new(bounds, &StaticWorld::default(), CostmapParams::default(), 0.18);
/// let costmap = builder.build(None, &[]);
/// let goal = sim::nearest_frontier(&map, &costmap, Point2::new(1.0, 1.0), 5, |_| false).unwrap();
/// assert!((goal.y - 2.975).abs() < 1e-9 && goal.x < 3.0);
/// ```
#[must_use]
pub fn nearest_frontier(
    map: &OccupancyGrid,
    costmap: &Costmap,
    robot: Point2,
    min_cells: usize,
    skip: impl Fn(Point2) -> bool,
) -> Option<Point2> {
    nearest_frontier_with(map, costmap, robot, min_cells, skip, &mut None, true)
}

/// [`nearest_frontier`] flooding in the buffers of an earlier flood (`buffers`, of any
/// grid; this flood's are left there for the next call): the same answer, without a
/// grid's worth of steps to allocate and fill at every goal choice. With `pockets_first`
/// (worth it where the last answer was "none": such answers come in runs while the robot
/// waits), the frontiers' pockets are asked first whether any can be reached at all.
pub(crate) fn nearest_frontier_with(
    map: &OccupancyGrid,
    costmap: &Costmap,
    robot: Point2,
    min_cells: usize,
    skip: impl Fn(Point2) -> bool,
    buffers: &mut Option<StepsFlood>,
    pockets_first: bool,
) -> Option<Point2> {
    let frame = costmap.map.frame();
    // The candidates in the order of the clusters and of their cells: ties go to the first.
    // `skip` (a blacklist's scan) is asked only of a cell that would be the best so far.
    let candidates: Vec<(usize, Point2)> = frontier_clusters(map)
        .into_iter()
        .filter(|cluster| cluster.len() >= min_cells)
        .flatten()
        .filter_map(|(i, j)| {
            let p = map.cell_center(i, j);
            frame.index_of(p).map(|k| (k, p))
        })
        .collect();
    if candidates.is_empty() {
        return None;
    }
    // When no frontier can be reached (the robot's last rooms explored, the rest behind
    // doorways too narrow for it), the flood from the robot would cover every cell it
    // can reach to say so, at every goal choice while the robot waits: the pockets the
    // candidates lie in say it first.
    let mut lent = flood_buffers(costmap, buffers.take());
    let budget = costmap.costs.len() / 64;
    if pockets_first
        && let Some(start) = start_cell(costmap, robot)
        && cut_off(costmap, start, &candidates, &skip, &mut lent, budget)
    {
        *buffers = Some(lent);
        return None;
    }
    // A breadth-first flood gives a cell its final steps when it reaches it, and every
    // cell not yet reached is at least `unreached_from` steps away: a nearest candidate
    // below that is the nearest of all, ties included.
    let mut flood = TravelFlood::new(costmap, robot, 0.0, Some(lent));
    let found = loop {
        let steps = flood.flood.steps();
        let mut best: Option<(u32, Point2)> = None;
        for &(k, p) in &candidates {
            if steps[k] != u32::MAX && best.is_none_or(|(b, _)| steps[k] < b) && !skip(p) {
                best = Some((steps[k], p));
            }
        }
        match best {
            Some((s, p)) if flood.finished() || s < flood.flood.unreached_from() => {
                break Some(p);
            }
            None if flood.finished() => break None,
            _ => flood.grow(),
        }
    };
    *buffers = Some(flood.into_buffers());
    found
}
