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

use hyplan_core::{Bounds, Point2};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::costmap::{mark_near_segments, rasterize};
use crate::explore::assigner::Assigner;
use crate::explore::detector::{GlobalRrtDetector, LocalRrtDetector, Region, RegionError};
use crate::explore::filter::{Filter, built_cost, built_cost_reach, information_gain};
use crate::explore::frontier::{costmap_steps, frontier_clusters, nearest_frontier};
use crate::explore::params::Strategy;
use crate::explore::viewpoint::ViewPoints;
use crate::kinematics::{self, Pose, Twist};
use crate::laser::LaserModel;
use crate::mapping::{OccupancyGrid, UNKNOWN};
use crate::navigator::{NavEvent, NavState, Navigator};
use crate::planner::GlobalPlanner;
use crate::run::{NOISE_STREAM, PLANNER_STREAM, TICKS_PER_SECOND};
use crate::scenario::Scenario;
use crate::world::World;

/// Global detector stream of a run's seed.
pub const GLOBAL_STREAM: u64 = 3;
/// Local detector stream of a run's seed.
pub const LOCAL_STREAM: u64 = 4;

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
    /// The filter's costmap test failed on it (an obstacle came near).
    Cost,
    /// The filter's gain test failed on it (its unknown area was seen).
    Gain,
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
    /// Frames of the map being built (`frame_period`): time, robot, ROS values.
    pub frames: Vec<(f64, Pose, Vec<i8>)>,
    /// Laser ticks on which the robot's body overlapped the true static world.
    pub contact_ticks: usize,
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
/// reaches into them) and 4-connected to `start`'s cell: (columns, mask).
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
pub fn reachable_free(world: &World, res: f64, start: Point2) -> (usize, Vec<bool>) {
    let (w, h, mut occupied) = rasterize(world.bounds, &world.statics, res);
    // The margin keeps a cell that only touches a corner on the same side of the rule
    // whatever the rounding (on a map aligned with this grid, touching is the usual case).
    mark_near_segments(
        &mut occupied,
        (w, h),
        world.bounds.min,
        res,
        &world.statics.grid_segments,
        1e-9,
    );
    let mut reach = vec![false; w * h];
    let u = ((start.x - world.bounds.min.x) / res).floor();
    let v = ((start.y - world.bounds.min.y) / res).floor();
    if !(u >= 0.0 && v >= 0.0 && (u as usize) < w && (v as usize) < h) {
        return (w, reach);
    }
    let s = v as usize * w + u as usize;
    if occupied[s] {
        return (w, reach);
    }
    reach[s] = true;
    let mut stack = vec![s];
    while let Some(c) = stack.pop() {
        let (i, j) = (c % w, c / w);
        let mut push = |n: usize| {
            if !occupied[n] && !reach[n] {
                reach[n] = true;
                stack.push(n);
            }
        };
        if i > 0 {
            push(c - 1);
        }
        if i + 1 < w {
            push(c + 1);
        }
        if j > 0 {
            push(c - w);
        }
        if j + 1 < h {
            push(c + w);
        }
    }
    (w, reach)
}

/// The centres of the unknown 4-neighbours of `frontier` cells, each once, in order:
/// what the baseline wants to see.
fn unknown_beside(
    map: &OccupancyGrid,
    frontier: impl Iterator<Item = (usize, usize)>,
) -> Vec<Point2> {
    let (w, h) = (map.width(), map.height());
    let mut seen = std::collections::HashSet::new();
    let mut out = Vec::new();
    for (i, j) in frontier {
        for (a, b) in [
            (i + 1, j),
            (i.wrapping_sub(1), j),
            (i, j + 1),
            (i, j.wrapping_sub(1)),
        ] {
            if a < w && b < h && map.value(a, b) == UNKNOWN && seen.insert((a, b)) {
                out.push(map.cell_center(a, b));
            }
        }
    }
    out
}

/// The turn at a view point: whether the frontier is in view, and the map version when
/// the robot stood still facing it (the look is over at the next map update).
#[derive(Debug, Clone, Copy, Default)]
struct Look {
    aligned: bool,
    settled: Option<u64>,
}

fn stream(seed: u64, s: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(s);
    rng
}

fn every(hz: f64) -> u64 {
    ((TICKS_PER_SECOND as f64 / hz).round() as u64).max(1)
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
#[allow(clippy::too_many_lines)]
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
#[allow(clippy::too_many_lines)]
pub fn explore_with(
    scenario: &Scenario,
    world: &World,
    seed: u64,
    strategy: Strategy,
    progress: &mut dyn FnMut(&Coverage),
) -> Result<ExploreOutcome, RegionError> {
    let ex = &scenario.exploration;
    let region = region_of(scenario, world.bounds)?;
    let dt = 1.0 / TICKS_PER_SECOND as f64;
    let robot = scenario.robot;
    let laser = LaserModel::new(scenario.laser);
    let laser_every = every(scenario.laser.rate_hz);
    let control_every = every(scenario.controller.rate_hz);
    let map_every = every(1.0 / scenario.mapping.period).div_ceil(laser_every) * laser_every;
    let detector_every = every(ex.detector_rate_hz);
    let cycle_every = every(1.0 / ex.cycle);
    let max_ticks = (scenario.time_limit * TICKS_PER_SECOND as f64).ceil() as u64;
    let stuck_ticks = (ex.stuck_after * TICKS_PER_SECOND as f64).round() as u64;
    let finish_ticks = (ex.finish_after * TICKS_PER_SECOND as f64).round() as u64;
    let snapshot_ticks: Vec<u64> = ex
        .snapshots
        .iter()
        .map(|t| (t * TICKS_PER_SECOND as f64).round() as u64)
        .collect();
    let mut noise_rng = stream(seed, NOISE_STREAM);
    let crate::run::Perception {
        mut map,
        mut memory,
        mut tracker,
        costmaps,
    } = crate::run::Perception::new(scenario, world);
    let res = scenario.mapping.resolution;
    let start = crate::world::pt(scenario.start);
    let (_, reach) = reachable_free(world, res, start);
    let reach_count = reach.iter().filter(|r| **r).count();
    let cell_area = res * res;
    let reachable_area = reach_count as f64 * cell_area;
    let mut nav = Navigator::new(
        scenario.navigation,
        scenario.controller,
        GlobalPlanner::Dijkstra,
        costmaps.clone(),
        robot,
        start,
        stream(seed, PLANNER_STREAM),
    );
    let rrt = strategy != Strategy::Frontier;
    let inflation = costmaps.inflation();
    let mut global = matches!(strategy, Strategy::Global | Strategy::Both)
        .then(|| GlobalRrtDetector::new(region, ex.eta_global, stream(seed, GLOBAL_STREAM)));
    let mut local = matches!(strategy, Strategy::Local | Strategy::Both)
        .then(|| LocalRrtDetector::new(region, ex.eta_local, stream(seed, LOCAL_STREAM)));
    let mut filter = Filter::new(
        ex.bandwidth,
        ex.costmap_threshold,
        ex.filter_radius,
        ex.min_gain,
    );
    let mut assigner = Assigner {
        info_radius: ex.info_radius,
        info_multiplier: ex.info_multiplier,
        hysteresis_radius: ex.hysteresis_radius,
        hysteresis_gain: ex.hysteresis_gain,
        blacklist_radius: ex.blacklist_radius,
        blacklist: Vec::new(),
    };
    let mut pose = scenario.start_pose();
    let mut twist = Twist::default();
    let mut published = Vec::new();
    let mut all_published = Vec::new();
    let mut coverage = Vec::new();
    let mut track = Vec::new();
    let mut goals = Vec::new();
    let mut failed = Vec::new();
    let mut goal_log: Vec<GoalRecord> = Vec::new();
    let mut snapshots = Vec::new();
    let mut frames = Vec::new();
    let frame_every = ex
        .frame_period
        .map(|f| ((f * TICKS_PER_SECOND as f64).round() as u64).max(1));
    let mut goal: Option<Point2> = None;
    // With view points: the frontier the goal looks at, and the turn towards it there.
    let mut target: Option<Point2> = None;
    let mut look: Option<Look> = None;
    // After a goal given up without moving: the next goal is a step into the open.
    let mut recovering = false;
    let min_view = scenario.laser.range_min + scenario.laser.mount_offset.abs() + robot.body_radius;
    let half_fov = scenario.laser.fov_deg.to_radians() / 2.0;
    let look_tolerance = if half_fov >= std::f64::consts::PI {
        std::f64::consts::PI
    } else {
        (half_fov - 20f64.to_radians()).max(5f64.to_radians())
    };
    let mut candidates: Vec<Point2> = Vec::new();
    let mut idle_since: Option<u64> = None;
    let mut map_version = 0u64;
    let mut cached: Option<(u64, crate::costmap::Costmap)> = None;
    // Where the robot was when it last moved 0.2 m, and when.
    let mut anchor = (start, 0u64);
    let mut finished = false;
    let mut distance = 0.0;
    let mut contact_ticks = 0;
    let mut nav_events = Vec::new();
    let mut end_tick = 0;
    // Heading turned so far in the initial turn; `None` once it is over.
    let mut turned = ex.initial_turn.then_some(0.0);
    // Free reachable cells of the built map, kept up to date window by window.
    let mut free_count = map.count_free(&reach);
    let sample = |n: usize, t: f64| Coverage {
        t,
        known_free: n as f64 * cell_area,
        fraction: if reach_count == 0 {
            0.0
        } else {
            n as f64 / reach_count as f64
        },
    };
    let snapshot = |t: f64,
                    pose: Pose,
                    map: &OccupancyGrid,
                    global: &Option<GlobalRrtDetector>,
                    local: &Option<LocalRrtDetector>,
                    published: &[Point2],
                    frontiers: &[Point2],
                    goal: Option<Point2>| Snapshot {
        t,
        pose,
        global_edges: global
            .as_ref()
            .map(GlobalRrtDetector::edges)
            .unwrap_or_default(),
        local_edges: local
            .as_ref()
            .map(LocalRrtDetector::edges)
            .unwrap_or_default(),
        published: published.to_vec(),
        frontiers: frontiers.to_vec(),
        goal,
        map: map.clone(),
    };
    for tick in 0..=max_ticks {
        end_tick = tick;
        let t = tick as f64 * dt;
        let here = Point2::new(pose.x, pose.y);
        let people = world.people_at(t);
        if tick % laser_every == 0 {
            let (o, h) = laser.origin(&pose);
            let mut scan = laser.cast(&world.statics, &people, o, h);
            laser.add_noise(&mut scan, &mut noise_rng);
            if tick % map_every == 0 {
                // Only cells in the box of the traced beams and the footprint change
                // (two cells of margin for the rounding): recount those.
                let traced = scan.traced_bounds(scenario.mapping.max_range);
                let (m, r) = (2.0 * res, robot.body_radius + 2.0 * res);
                let area = Bounds::new(
                    Point2::new(
                        (traced.min.x - m).min(here.x - r),
                        (traced.min.y - m).min(here.y - r),
                    ),
                    Point2::new(
                        (traced.max.x + m).max(here.x + r),
                        (traced.max.y + m).max(here.y + r),
                    ),
                );
                let before = map.count_free_in(&reach, area);
                map.integrate(&scan);
                map_version += 1;
                map.mark_footprint_free(here, robot.body_radius);
                free_count = free_count - before + map.count_free_in(&reach, area);
                debug_assert_eq!(free_count, map.count_free(&reach), "window missed a cell");
                coverage.push(sample(free_count, t));
                progress(&coverage[coverage.len() - 1]);
            }
            tracker.update(&scan, tick);
            memory.insert(scan, tick);
            let (d, _) = world.statics.nearest(here);
            if d < robot.body_radius || world.statics.inside(here) {
                contact_ticks += 1;
            }
        }
        if tick % detector_every == 0 {
            if let Some(g) = global.as_mut()
                && let Some(p) = g.step(&map)
            {
                published.push(p);
            }
            if let Some(l) = local.as_mut()
                && let Some(p) = l.step(&map, here)
            {
                published.push(p);
            }
        }
        if tick % cycle_every == 0 && turned.is_none() {
            let cost = |p: Point2| built_cost(&map, &inflation, p);
            // With view points the robot never stands on a frontier: only a frontier on
            // an occupied cell is dropped for its cost (see the module doc).
            let frontier_cost = |p: Point2| {
                if !ex.view_points {
                    cost(p)
                } else if map.occupied_at(p) {
                    100
                } else {
                    0
                }
            };
            if rrt {
                all_published.extend_from_slice(&published);
                // Where `frontier_cost` reads the map: `built_cost`'s square, or the
                // point's own cell.
                let cost_reach = if ex.view_points {
                    0.0
                } else {
                    built_cost_reach(&inflation, res)
                };
                candidates = filter
                    .update(&published, &map, frontier_cost, cost_reach)
                    .to_vec();
                published.clear();
            }
            if let Some(g) = goal {
                let state = nav.state();
                // The frontier sought: the goal itself, or the target of its view point.
                let f = target.unwrap_or(g);
                let too_costly = frontier_cost(f) > ex.costmap_threshold;
                let too_little =
                    !too_costly && information_gain(&map, f, ex.filter_radius) < ex.min_gain;
                if (here - anchor.0).norm() >= 0.2 || look.is_some() {
                    anchor = (here, tick);
                }
                let looked = look.is_some_and(|l| l.settled.is_some_and(|v| map_version > v));
                let end = if state == NavState::Failed {
                    Some(GoalEnd::GaveUp)
                } else if tick - anchor.1 >= stuck_ticks {
                    Some(GoalEnd::Stuck)
                } else if recovering {
                    (state == NavState::Reached).then_some(GoalEnd::Reached)
                } else if too_costly {
                    Some(GoalEnd::Cost)
                } else if too_little {
                    Some(GoalEnd::Gain)
                } else if state == NavState::Reached && (target.is_none() || looked) {
                    Some(GoalEnd::Reached)
                } else {
                    None
                };
                if state == NavState::Reached && target.is_some() && look.is_none() {
                    look = Some(Look::default());
                }
                if let Some(end) = end {
                    let pinned = matches!(end, GoalEnd::GaveUp | GoalEnd::Stuck)
                        && goal_log.last().is_some_and(|r| r.driven < 0.2);
                    if recovering {
                        recovering = false;
                    } else {
                        if matches!(end, GoalEnd::GaveUp | GoalEnd::Stuck) {
                            failed.push(f);
                        }
                        assigner.blacklist.push(f);
                        recovering = pinned && ex.view_points;
                    }
                    goal = None;
                    target = None;
                    look = None;
                    if let Some(r) = goal_log.last_mut() {
                        r.ended = t;
                        r.end = end;
                    }
                }
            }
            if goal.is_none() && ex.view_points {
                // The view points' reachability must be the planner's, which plans on the
                // next control step: its costmap holds the remembered laser hits too,
                // which can close a gap the map leaves open.
                cached = Some((
                    map_version,
                    costmaps.build(Some(&map), &memory.points(tick)),
                ));
            }
            if goal.is_none() {
                // The baseline without view points needs the whole costmap (reachability);
                // the RRT filter and the goal test ask about a few points (`built_cost`).
                // Built only when a goal is chosen, and once per map change.
                if !rrt
                    && !ex.view_points
                    && cached.as_ref().is_none_or(|(at, _)| *at != map_version)
                {
                    cached = Some((map_version, costmaps.build(Some(&map), &[])));
                }
                let costmap = cached.as_ref().map(|(_, c)| c);
                let steps = match costmap {
                    Some(c) if ex.view_points => costmap_steps(c, here),
                    _ => Vec::new(),
                };
                let views = costmap.map(|costmap| ViewPoints {
                    costmap,
                    steps: &steps,
                    max_cost: ex.view_max_cost,
                    range: ex.view_range,
                    min_range: min_view,
                    // A baseline target is an unknown cell's centre: that cell must be
                    // the first one not free. An RRT target is a cluster's centre of
                    // such cells: one of them within the mean-shift bandwidth.
                    slack: if rrt { ex.bandwidth } else { 0.5 * res },
                });
                let views = views.filter(|_| ex.view_points);
                let next = match (rrt, views) {
                    (_, Some(views)) if recovering => views.open_cell(here, 0.5).map(|v| (v, v)),
                    (true, None) => assigner.choose(here, &candidates, &map).map(|f| (f, f)),
                    (true, Some(views)) => assigner
                        .ranked(here, &candidates, &map)
                        .into_iter()
                        .find_map(|f| views.best(&map, f).map(|(_, v)| (f, v))),
                    (false, None) => {
                        let next = costmap.and_then(|costmap| {
                            nearest_frontier(&map, costmap, here, ex.min_frontier_cells, |p| {
                                assigner.blacklisted(p)
                            })
                        });
                        next.map(|f| (f, f))
                    }
                    (false, Some(views)) => {
                        let cells = unknown_beside(
                            &map,
                            frontier_clusters(&map)
                                .into_iter()
                                .filter(|c| c.len() >= ex.min_frontier_cells)
                                .flatten(),
                        );
                        views.nearest(&map, &cells, |p| assigner.blacklisted(p))
                    }
                };
                if !rrt {
                    candidates = next.map(|(f, _)| f).into_iter().collect();
                }
                if let Some((f, g)) = next {
                    goal = Some(g);
                    target = (ex.view_points && !recovering).then_some(f);
                    anchor = (here, tick);
                    nav.set_goal(g);
                    goals.push((t, g));
                    goal_log.push(GoalRecord {
                        t,
                        goal: g,
                        target: f,
                        ended: t,
                        end: GoalEnd::Open,
                        plans: 0,
                        failures: 0,
                        stops: 0,
                        driven: 0.0,
                    });
                }
            }
            if goal.is_none() {
                let since = *idle_since.get_or_insert(tick);
                if tick - since >= finish_ticks {
                    finished = true;
                }
            } else {
                idle_since = None;
            }
        }
        if frame_every.is_some_and(|k| tick % k == 0) {
            frames.push((t, pose, map.ros_values()));
        }
        if snapshot_ticks.contains(&tick) {
            snapshots.push(snapshot(
                t,
                pose,
                &map,
                &global,
                &local,
                &all_published,
                &candidates,
                goal,
            ));
        }
        if finished {
            break;
        }

        if let Some(a) = turned {
            if tick % control_every == 0 {
                let want = if a < std::f64::consts::TAU {
                    Twist {
                        v: 0.0,
                        omega: scenario.controller.rotate_speed,
                    }
                } else {
                    Twist::default()
                };
                twist = nav.controller.limit(&robot, twist, want);
                track.push((t, pose));
                if a >= std::f64::consts::TAU && twist == Twist::default() {
                    turned = None;
                }
            }
        } else if let (Some(f), Some(l)) = (target, look.as_mut()) {
            if tick % control_every == 0 {
                // At the view point: turn until the frontier is well inside the laser's
                // field of view, stop, and let one more map update happen.
                let (o, h) = laser.origin(&pose);
                let err = kinematics::wrap_angle((f.y - o.y).atan2(f.x - o.x) - h);
                let want = if !l.aligned && err.abs() > look_tolerance {
                    Twist {
                        v: 0.0,
                        omega: scenario.controller.rotate_speed.copysign(err),
                    }
                } else {
                    l.aligned = true;
                    Twist::default()
                };
                twist = nav.controller.limit(&robot, twist, want);
                if l.aligned && twist == Twist::default() && l.settled.is_none() {
                    l.settled = Some(map_version);
                }
                track.push((t, pose));
            }
        } else if tick % control_every == 0 {
            nav_events.clear();
            twist = nav.step(
                pose,
                twist,
                &memory,
                &tracker.movers(tick),
                Some(&map),
                tick,
                TICKS_PER_SECOND as f64,
                &mut nav_events,
            );
            if let Some(r) = goal_log.last_mut().filter(|r| r.end == GoalEnd::Open) {
                for e in &nav_events {
                    match e {
                        NavEvent::Plan | NavEvent::Replan => r.plans += 1,
                        NavEvent::Failure => r.failures += 1,
                        NavEvent::Stop => r.stops += 1,
                        NavEvent::GoalReached | NavEvent::GaveUp => {}
                    }
                }
            }
            track.push((t, pose));
        }
        let next = kinematics::integrate(pose, twist, dt);
        if let Some(a) = turned.as_mut() {
            *a += kinematics::wrap_angle(next.phi - pose.phi).abs();
        }
        let step = ((next.x - pose.x).powi(2) + (next.y - pose.y).powi(2)).sqrt();
        distance += step;
        if let Some(r) = goal_log.last_mut().filter(|r| r.end == GoalEnd::Open) {
            r.driven += step;
        }
        pose = next;
    }
    let end_time = end_tick as f64 * dt;
    if let Some(r) = goal_log.last_mut().filter(|r| r.end == GoalEnd::Open) {
        r.ended = end_time;
    }
    if coverage.last().is_none_or(|c: &Coverage| c.t < end_time) {
        coverage.push(sample(free_count, end_time));
    }
    all_published.extend_from_slice(&published);
    snapshots.push(snapshot(
        end_time,
        pose,
        &map,
        &global,
        &local,
        &all_published,
        &candidates,
        goal,
    ));
    Ok(ExploreOutcome {
        scenario: scenario.name.clone(),
        strategy,
        seed,
        coverage,
        track,
        goals,
        blacklisted: failed,
        goal_log,
        published: all_published.len(),
        snapshots,
        map,
        reachable_area,
        finished,
        end_time,
        distance,
        frames,
        contact_ticks,
    })
}
