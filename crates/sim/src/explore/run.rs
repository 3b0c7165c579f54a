//! The exploration loop: the navigation simulation of [`crate::run()`] (same ticks, laser,
//! map, costmap and navigator) with the detectors, the filter and the assigner choosing
//! the navigator's goals, and the coverage of the true world sampled as the map grows.
//!
//! Rates: detectors `detector_rate_hz` (100 Hz, one iteration every 2 ticks, each
//! detector), filter and assigner every `cycle` (0.5 s), coverage at every map update
//! (1 s), track at the control rate (10 Hz). Randomness: the run's laser-noise and
//! planner streams, and one ChaCha8 stream per detector ([`GLOBAL_STREAM`],
//! [`LOCAL_STREAM`]), so a run is bit-identical per seed whatever else runs beside it.
//!
//! Choices beyond the reference: at every map update the unknown cells under the robot's
//! body are marked free (a scanner mounted ahead of the centre never sees them, and the
//! trees are rooted there); the robot first turns a full circle on the spot
//! (`initial_turn`; filter and assigner wait for it, the detectors already grow); a goal is given up (and another chosen) as soon as the
//! filter's test fails on it (its cell became an obstacle's neighbour or its unknown area
//! fell below `min_gain`), where the reference keeps driving to it; goals the navigator
//! reached or gave up on are blacklisted; exploration ends after `finish_after` seconds
//! without any frontier and without a goal.
//!
//! With `view_points` ([`crate::explore::viewpoint`]) the navigator's goal is a view point
//! of the frontier: the filter's test and the blacklist apply to the frontier, the
//! robot turns to face it on arrival, and the goal ends at the next map update after
//! that (or earlier, when the frontier is seen on the way); after a goal given up (no
//! plan, or stuck) with less than 0.2 m driven, the next goal is a step into the open
//! ([`crate::explore::ViewPoints::open_cell`]: the nearest reachable cell out of every
//! obstacle's inflation, at least 0.5 m away), which is neither tested nor blacklisted.
//! Every goal's story is kept in
//! [`ExploreOutcome::goal_log`] (the `explore_why` example prints it).

use envmap::{CellFrame, Connectivity, Mask, distance_transform, flood_fill, nearest_passable};
use hyplan_core::{Bounds, Point2};

use crate::costmap::{mark_near_segments, rasterize};
use crate::engine::{Each, Observer, Sim, TICKS_PER_SECOND, TickInfo, time_of};
use crate::explore::detector::{Region, RegionError};
use crate::explore::explorer::Explorer;
use crate::explore::params::Strategy;
use crate::kinematics::Pose;
use crate::laser::Scan;
use crate::mapping::OccupancyGrid;
use crate::planner::GlobalPlanner;
use crate::scenario::Scenario;
use crate::world::World;

/// One coverage sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coverage {
    /// Simulated time, s.
    pub t: f64,
    /// Reachable free area of the true world known free on the built map, m^2.
    pub known_free: f64,
    /// `known_free` / reachable free area.
    pub fraction: f64,
}

/// The state kept at a chosen time, for figures.
#[derive(Debug, Clone)]
pub struct Snapshot {
    /// Simulated time, s.
    pub t: f64,
    /// The robot.
    pub pose: Pose,
    /// Edges of the global tree.
    pub global_edges: Vec<(Point2, Point2)>,
    /// Edges of the local tree.
    pub local_edges: Vec<(Point2, Point2)>,
    /// Points published since the start.
    pub published: Vec<Point2>,
    /// Frontiers kept by the filter (RRT) or the baseline's goal candidates.
    pub frontiers: Vec<Point2>,
    /// The goal being driven to.
    pub goal: Option<Point2>,
    /// The built map.
    pub map: OccupancyGrid,
}

/// Why a goal stopped being the goal.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GoalEnd {
    /// The navigator reached it.
    Reached,
    /// The navigator gave up (no plan, or blocked again, `max_failures` times in a row).
    GaveUp,
    /// The robot did not move 0.2 m for `stuck_after` seconds.
    Stuck,
    /// The robot came no nearer to it along the navigator's paths for
    /// `progress_timeout` seconds.
    NoProgress,
    /// The filter's costmap test failed on it (an obstacle came near).
    Cost,
    /// The filter's gain test failed on it (its unknown area was seen), with
    /// [`Exploration::drop_seen_goals`](crate::Exploration::drop_seen_goals) only.
    Gain,
    /// The assigner sent the robot to another frontier on its way
    /// ([`AssignerMode::Reference`](crate::AssignerMode::Reference)); not blacklisted.
    Retargeted,
    /// Still the goal when the run ended.
    Open,
}

/// One goal's story, for the diagnosis of what an exploration left unknown.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GoalRecord {
    /// When it was sent, s.
    pub t: f64,
    /// The goal sent to the navigator.
    pub goal: Point2,
    /// The frontier it was chosen for (the goal itself without view points); blacklisted
    /// when the goal ends, whatever the reason.
    pub target: Point2,
    /// When it stopped being the goal, s.
    pub ended: f64,
    /// Why.
    pub end: GoalEnd,
    /// Plans the navigator made for it (first plan and re-plans).
    pub plans: u32,
    /// Planning failures (no path, or blocked again at once).
    pub failures: u32,
    /// Stops for a blocked path.
    pub stops: u32,
    /// Distance driven while it was the goal, m.
    pub driven: f64,
}

/// Everything an exploration produced.
#[derive(Debug, Clone)]
pub struct ExploreOutcome {
    /// Scenario name.
    pub scenario: String,
    /// The detector.
    pub strategy: Strategy,
    /// The seed.
    pub seed: u64,
    /// Coverage over time (at every map update, and at the end).
    pub coverage: Vec<Coverage>,
    /// The robot's track: time, x, y, heading (10 Hz).
    pub track: Vec<(f64, Pose)>,
    /// Goals sent to the navigator, with the time.
    pub goals: Vec<(f64, Point2)>,
    /// The frontiers of the goals the navigator gave up on (no plan, or stuck): the goals
    /// themselves without view points.
    pub blacklisted: Vec<Point2>,
    /// Every goal, in order: when and why it ended, what the navigator did for it.
    pub goal_log: Vec<GoalRecord>,
    /// Frontier points the detectors published.
    pub published: usize,
    /// Snapshots at the scenario's chosen times (and one at the end).
    pub snapshots: Vec<Snapshot>,
    /// The built map at the end.
    pub map: OccupancyGrid,
    /// Reachable free area of the true world, m^2.
    pub reachable_area: f64,
    /// Whether the exploration ended by itself (no frontier left for `finish_after`);
    /// false when the time limit stopped it.
    pub finished: bool,
    /// Simulated time at the end, s.
    pub end_time: f64,
    /// Distance driven, m.
    pub distance: f64,
    /// Frames of the map being built (`frame_period`).
    pub frames: MapFrames,
    /// Laser ticks on which the robot's body overlapped the true static world.
    pub contact_ticks: usize,
    /// Plans found only on the tight costmap ([`crate::CostmapBuilder::build_tight`]):
    /// how often the robot was hemmed in on its usual one.
    pub tight_plans: u32,
    /// Iterations of the global and the local detector (0 for one not run).
    pub detector_iterations: [u64; 2],
    /// With the scenario's `detector_cost`: the detectors' summed compute time, s.
    pub detector_busy: f64,
}

impl ExploreOutcome {
    /// First time coverage reached `fraction`, s.
    #[must_use]
    pub fn time_to(&self, fraction: f64) -> Option<f64> {
        self.coverage
            .iter()
            .find(|c| c.fraction >= fraction)
            .map(|c| c.t)
    }

    /// Final coverage fraction.
    #[must_use]
    pub fn final_coverage(&self) -> f64 {
        self.coverage.last().map_or(0.0, |c| c.fraction)
    }

    /// Reachable free area still not known free at the end, m^2 ("missed").
    #[must_use]
    pub fn missed_area(&self) -> f64 {
        self.reachable_area - self.coverage.last().map_or(0.0, |c| c.known_free)
    }

    /// The end of the run in two lines, as `hyplan explore` prints it: coverage of the
    /// reachable free area with the times it reached 95 % and 99 % and the area missed;
    /// then distance driven, goals, goals blacklisted, points published, contact ticks and
    /// plans on the tight costmap.
    #[must_use]
    pub fn summary(&self) -> String {
        let time = |f: f64| {
            self.time_to(f)
                .map_or("not reached".to_string(), |t| format!("{t:.0} s"))
        };
        format!(
            "coverage {:.2} % of {:.1} m^2 reachable free; 95 % at {}, 99 % at {}; missed {:.2} m^2\n\
             distance {:.1} m, goals {}, blacklisted {}, points published {}, contact ticks {}, tight plans {}",
            100.0 * self.final_coverage(),
            self.reachable_area,
            time(0.95),
            time(0.99),
            self.missed_area(),
            self.distance,
            self.goals.len(),
            self.blacklisted.len(),
            self.published,
            self.contact_ticks,
            self.tight_plans
        )
    }

    /// Coverage over time as CSV (`t,known_free_m2,coverage`).
    #[must_use]
    pub fn coverage_csv(&self) -> String {
        let mut s = String::from("t,known_free_m2,coverage\n");
        for c in &self.coverage {
            s.push_str(&format!(
                "{:.3},{:.4},{:.6}\n",
                c.t, c.known_free, c.fraction
            ));
        }
        s
    }

    /// The track as CSV (`t,x,y,phi`).
    #[must_use]
    pub fn track_csv(&self) -> String {
        let mut s = String::from("t,x,y,phi\n");
        for (t, p) in &self.track {
            s.push_str(&format!("{t:.3},{:.4},{:.4},{:.4}\n", p.x, p.y, p.phi));
        }
        s
    }
}

/// The cells of a `res` grid over `bounds` that are free in the true world (no obstacle
/// reaches into them) and reachable for a round robot of `radius` from `start`:
/// (columns, mask). With `radius` 0, every free cell 4-connected to `start`'s cell.
///
/// Reachable for the footprint: the cells the body covers while its centre moves over
/// the cells whose centre lies at least `radius` plus half a cell from every obstacle
/// cell's centre, 4-connected to the start (its own cell, or the nearest such cell within
/// half a metre): a room behind a door narrower than the robot does not count, the
/// corners of a room it enters do.
///
/// "Reaches into" is [`rasterize`]'s rule for shapes, a cell whose centre lies within half
/// a cell diagonal of an obstacle's outline, applied to a loaded map's obstacle outline
/// too (the boundaries of its forbidden pixels): so a free pixel that shares an edge or a
/// corner with a forbidden one is not counted, as a cell a wall's face runs along is not
/// counted in a world of shapes. Without it, a map aligned with the mapping grid counts
/// the row of cells in front of every wall, which the laser's hits on the wall's face
/// mark occupied (a hit on a cell boundary falls on either side with the range noise, and
/// on the near side when the beam travels towards -x or -y).
#[must_use]
pub fn reachable_free(world: &World, res: f64, start: Point2, radius: f64) -> (usize, Vec<bool>) {
    let (w, h, mut occupied) = rasterize(world.bounds, &world.statics, res);
    let frame = CellFrame::new(world.bounds.min, res, w, h);
    // The margin keeps a cell that only touches a corner on the same side of the rule
    // whatever the rounding (on a map aligned with this grid, touching is the usual case).
    mark_near_segments(&mut occupied, frame, &world.statics.grid_segments, 1e-9);
    let Some(start) = frame.cell_of(start) else {
        return (w, vec![false; w * h]);
    };
    let free = occupied.iter().map(|&o| !o).collect();
    let free = Mask::from_cells(w, h, free).expect("a cell per cell");
    if radius <= 0.0 {
        let reach = flood_fill(&free, start, Connectivity::Four);
        return (w, reach.cells().to_vec());
    }
    let body = radius / res + 0.5;
    let walls = Mask::from_cells(w, h, occupied).expect("a cell per cell");
    let clear = distance_transform(&walls);
    let centres = clear
        .dist_sq()
        .iter()
        .map(|&d| f64::from(d) >= body * body)
        .collect();
    let centres = Mask::from_cells(w, h, centres).expect("a cell per cell");
    let rings = crate::planner::start_rings(res);
    let Some(start) = nearest_passable((w, h), start, rings, |i, j| centres.get(i, j)) else {
        return (w, vec![false; w * h]);
    };
    let driven = flood_fill(&centres, start, Connectivity::Four);
    let swept = distance_transform(&driven);
    let reach = swept
        .dist_sq()
        .iter()
        .zip(free.cells())
        .map(|(&d, &f)| f && f64::from(d) <= body * body)
        .collect();
    (w, reach)
}

/// The region of the scenario's exploration (its corners, or the world's bounds) with
/// the start as root.
///
/// # Errors
///
/// [`RegionError`] when the corners are not four, enclose nothing or leave out the start.
pub fn region_of(scenario: &Scenario, bounds: Bounds) -> Result<Region, RegionError> {
    let mut points: Vec<Point2> = match &scenario.exploration.region {
        Some(c) => c.iter().map(|&p| crate::world::pt(p)).collect(),
        None => vec![
            bounds.min,
            Point2::new(bounds.max.x, bounds.min.y),
            bounds.max,
            Point2::new(bounds.min.x, bounds.max.y),
        ],
    };
    points.push(crate::world::pt(scenario.start));
    Region::from_points(&points)
}

/// Explores `world` from the scenario's start with `strategy` until no frontier is left
/// (see the module doc) or the scenario's time limit.
///
/// # Errors
///
/// [`RegionError`] when the scenario's region is invalid (a validated scenario's is not).
pub fn explore(
    scenario: &Scenario,
    world: &World,
    seed: u64,
    strategy: Strategy,
) -> Result<ExploreOutcome, RegionError> {
    explore_with(scenario, world, seed, strategy, &mut |_| {})
}

/// [`explore`], calling `progress` with every coverage sample as the run goes.
///
/// # Errors
///
/// As [`explore`].
pub fn explore_with(
    scenario: &Scenario,
    world: &World,
    seed: u64,
    strategy: Strategy,
    progress: &mut dyn FnMut(&Coverage),
) -> Result<ExploreOutcome, RegionError> {
    explore_observed(scenario, world, seed, strategy, progress, &mut [])
}

/// [`explore_with`], with `observers` watching the run after its own (a ROS 2 bag,
/// a log): they see every tick, and the explorer's frontiers and trees through
/// [`TickInfo::goals`](crate::TickInfo::goals). They do not change the run.
///
/// ```no_run
/// use sim::{Observer, Sim, Strategy, TickInfo};
/// /// Counts the frontiers the explorer shows at each tick.
/// #[derive(Default)]
/// struct Shown(usize);
/// impl Observer for Shown {
///     fn ticked(&mut self, _sim: &Sim<'_>, info: &TickInfo<'_>) {
///         self.0 += info.goals.frontiers().len();
///     }
/// }
/// let (scenario, world) = sim::Scenario::load("scenarios/sim/explore-22m.ron".as_ref())?;
/// let mut shown = Shown::default();
/// let out =
///     sim::explore_observed(&scenario, &world, 1, Strategy::Both, &mut |_| {}, &mut [&mut shown])?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// As [`explore`].
pub fn explore_observed(
    scenario: &Scenario,
    world: &World,
    seed: u64,
    strategy: Strategy,
    progress: &mut dyn FnMut(&Coverage),
    observers: &mut [&mut dyn Observer],
) -> Result<ExploreOutcome, RegionError> {
    let region = region_of(scenario, world.bounds)?;
    let start = crate::world::pt(scenario.start);
    let mut sim =
        Sim::new(scenario, world, seed, GlobalPlanner::Dijkstra, start).clearing_footprint();
    let mut explorer = Explorer::new(
        scenario,
        region,
        sim.nav.costmaps.inflation(),
        seed,
        strategy,
    );
    // The explorer ends the run at `stop_at_coverage`: it reads the meter's last sample.
    let latest = std::rc::Rc::new(std::cell::Cell::new(0.0));
    explorer.coverage_seen = scenario
        .exploration
        .stop_at_coverage
        .map(|f| (f, std::rc::Rc::clone(&latest)));
    let mut sample = |c: &Coverage| {
        latest.set(c.fraction);
        progress(c);
    };
    let mut coverage = CoverageMeter::new(
        world,
        scenario.mapping.resolution,
        start,
        scenario.robot.body_radius,
        &sim.map,
        &mut sample,
    );
    let mut track = TrackRecorder::default();
    let mut frames = FrameRecorder::new(scenario.exploration.frame_period);
    let mut contacts = ContactCounter::default();
    let end_tick = sim.run(
        &mut explorer,
        &mut [
            &mut coverage,
            &mut track,
            &mut frames,
            &mut contacts,
            &mut Each(observers),
        ],
    );
    let end_time = time_of(end_tick);
    explorer.finish(end_time, sim.pose(), &sim.map);
    let reachable_area = coverage.reachable_area();
    let distance = sim.distance();
    let coverage = coverage.finish(end_time);
    Ok(ExploreOutcome {
        scenario: scenario.name.clone(),
        strategy,
        seed,
        coverage,
        track: track.track,
        goals: explorer.goals,
        blacklisted: explorer.failed,
        goal_log: explorer.goal_log,
        published: explorer.all_published.len(),
        snapshots: explorer.snapshots,
        map: sim.map,
        reachable_area,
        finished: explorer.finished,
        end_time,
        distance,
        frames: frames.frames,
        contact_ticks: contacts.ticks,
        tight_plans: sim.nav.tight_plans(),
        detector_iterations: explorer.iterations,
        detector_busy: explorer.busy,
    })
}

/// Coverage of the true world's reachable free area by the built map, sampled at every
/// map update (cells recounted in the update's window only).
pub struct CoverageMeter<'p> {
    reach: Vec<bool>,
    reach_count: usize,
    cell_area: f64,
    free_count: usize,
    before: usize,
    samples: Vec<Coverage>,
    progress: &'p mut dyn FnMut(&Coverage),
}

impl<'p> CoverageMeter<'p> {
    /// The meter of `world`'s cells of side `res` reachable from `start` by a robot of
    /// `radius` ([`reachable_free`]), starting from `map`; `progress` sees every sample.
    pub fn new(
        world: &World,
        res: f64,
        start: Point2,
        radius: f64,
        map: &OccupancyGrid,
        progress: &'p mut dyn FnMut(&Coverage),
    ) -> Self {
        let (_, reach) = reachable_free(world, res, start, radius);
        let reach_count = reach.iter().filter(|r| **r).count();
        Self {
            free_count: map.count_free(&reach),
            reach,
            reach_count,
            cell_area: res * res,
            before: 0,
            samples: Vec::new(),
            progress,
        }
    }

    /// Reachable free area of the true world, m^2.
    #[must_use]
    pub fn reachable_area(&self) -> f64 {
        self.reach_count as f64 * self.cell_area
    }

    fn sample(&self, t: f64) -> Coverage {
        let n = self.free_count;
        Coverage {
            t,
            known_free: n as f64 * self.cell_area,
            fraction: if self.reach_count == 0 {
                0.0
            } else {
                n as f64 / self.reach_count as f64
            },
        }
    }

    /// The samples, with one at `end_time` unless the last is that late.
    #[must_use]
    pub fn finish(self, end_time: f64) -> Vec<Coverage> {
        let mut samples = self.samples.clone();
        if samples.last().is_none_or(|c: &Coverage| c.t < end_time) {
            samples.push(self.sample(end_time));
        }
        samples
    }
}

impl Observer for CoverageMeter<'_> {
    fn scan_reach(&self, sim: &Sim<'_>) -> f64 {
        // What the map update traces (`update_area`).
        sim.scenario.mapping.max_range
    }

    fn map_updating(&mut self, sim: &Sim<'_>, scan: &Scan) {
        // Only cells in the box of the traced beams and the footprint change: recount those.
        self.before = sim.map.count_free_in(&self.reach, sim.update_area(scan));
    }

    fn map_updated(&mut self, sim: &Sim<'_>, scan: &Scan) {
        let after = sim.map.count_free_in(&self.reach, sim.update_area(scan));
        self.free_count = self.free_count - self.before + after;
        debug_assert_eq!(
            self.free_count,
            sim.map.count_free(&self.reach),
            "window missed a cell"
        );
        let c = self.sample(sim.time());
        self.samples.push(c);
        (self.progress)(&c);
    }
}

/// The robot's pose at every control step.
#[derive(Debug, Default)]
pub struct TrackRecorder {
    /// Time, s, and pose.
    pub track: Vec<(f64, Pose)>,
}

impl Observer for TrackRecorder {
    fn scan_reach(&self, _sim: &Sim<'_>) -> f64 {
        0.0
    }

    fn ticked(&mut self, sim: &Sim<'_>, info: &TickInfo<'_>) {
        if info.controlled {
            self.track.push((info.t, sim.pose()));
        }
    }
}

/// The built map every `period` seconds (ROS values), for an animation.
#[derive(Debug, Default)]
pub struct FrameRecorder {
    every: Option<u64>,
    /// The frames so far.
    pub frames: MapFrames,
}

impl FrameRecorder {
    /// Frames every `period` seconds, none without one.
    #[must_use]
    pub fn new(period: Option<f64>) -> Self {
        Self {
            every: period.map(|f| ((f * TICKS_PER_SECOND as f64).round() as u64).max(1)),
            frames: MapFrames::default(),
        }
    }
}

impl Observer for FrameRecorder {
    fn scan_reach(&self, _sim: &Sim<'_>) -> f64 {
        0.0
    }

    fn ticked(&mut self, sim: &Sim<'_>, info: &TickInfo<'_>) {
        if self.every.is_some_and(|k| info.tick.is_multiple_of(k)) {
            self.frames.push(info.t, sim.pose(), &sim.map.ros_values());
        }
    }
}

/// Frames of a map being built, each kept as the cells changed since the frame before:
/// a long exploration of a large map keeps what was mapped, not a copy of the whole grid
/// per frame (a 100 x 100 m map at 0.05 m is 4 MB a frame).
///
/// ```
/// use sim::Pose;
/// let mut frames = sim::MapFrames::default();
/// frames.push(0.0, Pose::default(), &[-1, -1, -1]);
/// frames.push(10.0, Pose { x: 1.0, ..Pose::default() }, &[0, 100, -1]);
/// let all: Vec<_> = frames.replay().map(|(t, _, v)| (t, v)).collect();
/// assert_eq!(all, vec![(0.0, vec![-1, -1, -1]), (10.0, vec![0, 100, -1])]);
/// ```
#[derive(Debug, Clone, Default)]
pub struct MapFrames {
    /// The last frame's values, which the next one is compared with.
    last: Vec<i8>,
    changes: Vec<FrameChange>,
}

/// One frame of [`MapFrames`].
#[derive(Debug, Clone)]
struct FrameChange {
    /// Time, s.
    t: f64,
    pose: Pose,
    /// The cells (index, value) that changed since the frame before.
    cells: Vec<(u32, i8)>,
}

impl MapFrames {
    /// Adds a frame: time `t`, the robot, the map's values (every frame the same size; a
    /// frame of another size starts afresh).
    pub fn push(&mut self, t: f64, pose: Pose, values: &[i8]) {
        if self.last.len() != values.len() {
            self.changes.clear();
            self.last = vec![i8::MIN; values.len()];
        }
        let changed = self
            .last
            .iter_mut()
            .zip(values)
            .enumerate()
            .filter(|(_, (old, new))| old != new)
            .map(|(k, (old, &new))| {
                *old = new;
                (k as u32, new)
            })
            .collect();
        self.changes.push(FrameChange {
            t,
            pose,
            cells: changed,
        });
    }

    /// The number of frames.
    #[must_use]
    pub fn len(&self) -> usize {
        self.changes.len()
    }

    /// Whether no frame was kept.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.changes.is_empty()
    }

    /// The frames in order: time, robot, the map's values.
    pub fn replay(&self) -> impl ExactSizeIterator<Item = (f64, Pose, Vec<i8>)> + '_ {
        let mut values = vec![i8::MIN; self.last.len()];
        self.changes.iter().map(move |frame| {
            for &(k, v) in &frame.cells {
                values[k as usize] = v;
            }
            (frame.t, frame.pose, values.clone())
        })
    }
}

/// Laser ticks on which the robot's body overlapped the true static world.
#[derive(Debug, Default)]
pub struct ContactCounter {
    /// The count.
    pub ticks: usize,
}

impl Observer for ContactCounter {
    fn scan_reach(&self, _sim: &Sim<'_>) -> f64 {
        0.0
    }

    fn ticked(&mut self, sim: &Sim<'_>, info: &TickInfo<'_>) {
        if info.sensed {
            let here = sim.here();
            let (d, _) = sim.world.statics.nearest(here);
            if d < sim.scenario.robot.body_radius || sim.world.statics.inside(here) {
                self.ticks += 1;
            }
        }
    }
}
