//! Exploration as a goal source of the engine: the detectors, the filter and the
//! assigner choose the navigator's goals (see [`crate::explore::explore`] for the rules).

use hyplan_core::Point2;

use envmap::{Inflation, StepsFlood};

use crate::costmap::CostmapCache;
use crate::engine::{Flow, GoalSource, Sim, TICKS_PER_SECOND, every, stream};
use crate::explore::assigner::Assigner;
use crate::explore::cost::DetectorCost;
use crate::explore::detector::{Region, RrtDetector};
use crate::explore::filter::{Filter, built_cost, built_cost_reach, information_gain};
use crate::explore::frontier::{
    TravelFlood, costmap_steps, frontier_clusters, nearest_frontier_with,
};
use crate::explore::params::{AssignerMode, Exploration, RevenueDistance, Strategy};
use crate::explore::run::{GoalEnd, GoalRecord, Snapshot};
use crate::explore::viewpoint::ViewPoints;
use crate::kinematics::{self, Pose, Twist};
use crate::mapping::{OccupancyGrid, UNKNOWN};
use crate::navigator::{NavEvent, NavState};
use crate::scenario::Scenario;

/// Global detector stream of a run's seed.
pub const GLOBAL_STREAM: u64 = 3;
/// Local detector stream of a run's seed.
pub const LOCAL_STREAM: u64 = 4;

/// The turn at a view point: whether the frontier is in view, and the map version when
/// the robot stood still facing it (the look is over at the next map update).
#[derive(Debug, Clone, Copy, Default)]
struct Look {
    aligned: bool,
    settled: Option<u64>,
}

/// Tick periods and thresholds, fixed for a run.
#[derive(Debug, Clone)]
struct Clock {
    detector: u64,
    cycle: u64,
    stuck: u64,
    progress: Option<u64>,
    finish: u64,
    snapshots: Vec<u64>,
}

/// The exploration's goal source and its records.
#[derive(Debug)]
pub(crate) struct Explorer {
    ex: Exploration,
    clock: Clock,
    rrt: bool,
    res: f64,
    rotate_speed: f64,
    inflation: Inflation,
    min_view: f64,
    look_tolerance: f64,
    global: Option<RrtDetector>,
    local: Option<RrtDetector>,
    filter: Filter,
    assigner: Assigner,
    published: Vec<Point2>,
    pub all_published: Vec<Point2>,
    candidates: Vec<Point2>,
    pub goals: Vec<(f64, Point2)>,
    pub failed: Vec<Point2>,
    pub goal_log: Vec<GoalRecord>,
    pub snapshots: Vec<Snapshot>,
    goal: Option<Point2>,
    /// With view points: the frontier the goal looks at, and the turn towards it there.
    target: Option<Point2>,
    look: Option<Look>,
    /// After a goal given up without moving: the next goal is a step into the open.
    recovering: bool,
    idle_since: Option<u64>,
    /// The costmap of the view points and the baseline's reachability, and the map
    /// version it was built at.
    costmap: CostmapCache,
    costmap_at: Option<u64>,
    /// The buffers of the assigner's travel flood, kept between goal choices.
    flood: Option<StepsFlood>,
    /// Whether the baseline's last goal choice found no frontier it could reach.
    none_reachable: bool,
    /// The costmap of the final pass.
    final_costmap: CostmapCache,
    /// Where the robot was when it last moved 0.2 m, and when.
    anchor: (Point2, u64),
    /// The least length of path the robot had still ahead to the goal, and when it got
    /// there.
    progress: (f64, u64),
    pub finished: bool,
    /// Heading turned so far in the initial turn; `None` once it is over.
    turned: Option<f64>,
    /// Frontiers given up on (no plan, stuck) with the unknown area around them then:
    /// lifted from the blacklist when the map near them changes.
    given_up: Vec<GivenUp>,
    /// Frontiers the final pass sent the robot to: each once.
    final_tries: Vec<Point2>,
    /// Whether the goal in force was sent by the final pass (cleared by every
    /// [`send`](Explorer::send)): the filter's costmap test does not end it.
    final_goal: bool,
    /// The last frontier assigned (the start before the first: the reference's assigner
    /// first sends the robot where it stands).
    last_goal: Point2,
    /// With a detector cost: when the global and the local detector may next run, s.
    ready: [f64; 2],
    /// With a detector cost: the detectors' summed compute time, s.
    pub busy: f64,
    /// Iterations of the global and the local detector.
    pub iterations: [u64; 2],
    /// With `stop_at_coverage`: the fraction that ends the run, and the coverage meter's
    /// last sample.
    pub coverage_seen: Option<(f64, std::rc::Rc<std::cell::Cell<f64>>)>,
}

/// A frontier given up on, and what the map around it looked like then.
#[derive(Debug, Clone, Copy)]
struct GivenUp {
    at: Point2,
    /// Unknown area within the blacklist radius, m^2.
    unknown: f64,
    /// Times it may still be lifted.
    lifts: u8,
}

/// Change of the unknown area near a given-up frontier that lifts it from the blacklist,
/// m^2 (forty 5 cm cells: a few laser beams' worth, not noise).
const LIFT_AREA: f64 = 0.1;
/// Times a given-up frontier may be lifted: a goal that fails three times is left.
const MAX_LIFTS: u8 = 2;

impl Explorer {
    pub(crate) fn new(
        scenario: &Scenario,
        region: Region,
        inflation: Inflation,
        seed: u64,
        strategy: Strategy,
    ) -> Self {
        let ex = scenario.exploration.clone();
        let at = |s: f64| (s * TICKS_PER_SECOND as f64).round() as u64;
        let half_fov = scenario.laser.fov_deg.to_radians() / 2.0;
        let look_tolerance = if half_fov >= std::f64::consts::PI {
            std::f64::consts::PI
        } else {
            (half_fov - 20f64.to_radians()).max(5f64.to_radians())
        };
        Self {
            clock: Clock {
                detector: every(ex.detector_rate_hz),
                cycle: every(1.0 / ex.cycle),
                stuck: at(ex.stuck_after),
                progress: ex.progress_timeout.map(at),
                finish: at(ex.finish_after),
                snapshots: ex.snapshots.iter().map(|&t| at(t)).collect(),
            },
            rrt: strategy != Strategy::Frontier,
            res: scenario.mapping.resolution,
            rotate_speed: scenario.controller.rotate_speed,
            inflation,
            min_view: scenario.laser.range_min
                + scenario.laser.mount_offset.abs()
                + scenario.robot.body_radius,
            look_tolerance,
            global: matches!(strategy, Strategy::Global | Strategy::Both)
                .then(|| RrtDetector::global(region, ex.eta_global, stream(seed, GLOBAL_STREAM))),
            local: matches!(strategy, Strategy::Local | Strategy::Both)
                .then(|| RrtDetector::local(region, ex.eta_local, stream(seed, LOCAL_STREAM))),
            filter: Filter::new(
                ex.bandwidth,
                ex.costmap_threshold,
                ex.filter_radius,
                ex.min_gain,
            )
            .with_pool(ex.filter_pool),
            assigner: Assigner {
                info_radius: ex.info_radius,
                info_multiplier: ex.info_multiplier,
                hysteresis_radius: ex.hysteresis_radius,
                hysteresis_gain: ex.hysteresis_gain,
                blacklist_radius: ex.blacklist_radius,
                blacklist: Vec::new(),
            },
            published: Vec::new(),
            all_published: Vec::new(),
            candidates: Vec::new(),
            goals: Vec::new(),
            failed: Vec::new(),
            goal_log: Vec::new(),
            snapshots: Vec::new(),
            goal: None,
            target: None,
            look: None,
            recovering: false,
            idle_since: None,
            costmap: CostmapCache::default(),
            costmap_at: None,
            flood: None,
            none_reachable: false,
            final_costmap: CostmapCache::default(),
            anchor: (crate::world::pt(scenario.start), 0),
            progress: (f64::INFINITY, 0),
            finished: false,
            turned: ex.initial_turn.then_some(0.0),
            given_up: Vec::new(),
            final_tries: Vec::new(),
            final_goal: false,
            ready: [0.0; 2],
            last_goal: crate::world::pt(scenario.start),
            busy: 0.0,
            iterations: [0; 2],
            coverage_seen: None,
            ex,
        }
    }

    /// The state kept for figures, at `t`.
    pub(crate) fn snapshot(&self, t: f64, pose: Pose, map: &OccupancyGrid) -> Snapshot {
        Snapshot {
            t,
            pose,
            global_edges: self.global.iter().flat_map(RrtDetector::edges).collect(),
            local_edges: self.local.iter().flat_map(RrtDetector::edges).collect(),
            published: self.all_published.clone(),
            frontiers: self.candidates.clone(),
            goal: self.goal,
            map: map.clone(),
        }
    }

    /// Closes the records at `end_time`: the open goal, the points published since the
    /// last cycle, the last snapshot.
    pub(crate) fn finish(&mut self, end_time: f64, pose: Pose, map: &OccupancyGrid) {
        if let Some(r) = self.goal_log.last_mut().filter(|r| r.end == GoalEnd::Open) {
            r.ended = end_time;
        }
        self.all_published.extend_from_slice(&self.published);
        let last = self.snapshot(end_time, pose, map);
        self.snapshots.push(last);
    }

    fn frontier_cost(&self, map: &OccupancyGrid, p: Point2) -> i8 {
        frontier_cost(self.ex.view_points, &self.inflation, map, p)
    }

    /// Every `cycle`: the filter, the current goal's end tests, a new goal if needed.
    fn cycle(&mut self, sim: &mut Sim<'_>) {
        let tick = sim.tick();
        if self.rrt {
            self.all_published.extend_from_slice(&self.published);
            // Where `frontier_cost` reads the map: `built_cost`'s square, or the
            // point's own cell.
            let cost_reach = if self.ex.view_points {
                0.0
            } else {
                built_cost_reach(&self.inflation, self.res)
            };
            let (map, views, inflation) = (&sim.map, self.ex.view_points, &self.inflation);
            let cost = |p| frontier_cost(views, inflation, map, p);
            let candidates = self
                .filter
                .update(&self.published, map, cost, cost_reach)
                .to_vec();
            self.candidates = candidates;
            self.published.clear();
        }
        if let Some(g) = self.goal {
            self.test_goal(sim, g);
        }
        if self.goal.is_none() && self.ex.view_points {
            // The view points' reachability must be the planner's, which plans on the
            // next control step: its costmap holds the remembered laser hits too,
            // which can close a gap the map leaves open.
            let hits = sim.memory.points(tick);
            sim.nav
                .costmaps
                .rebuild(&mut self.costmap, Some(&sim.map), &hits);
            self.costmap_at = Some(sim.map_version());
        }
        if self.rrt && self.ex.assigner_mode == AssignerMode::Reference && !self.recovering {
            self.retarget(sim);
        }
        if self.goal.is_none() {
            self.lift_changed(&sim.map);
            self.choose_goal(sim);
        }
        if self.goal.is_none() {
            let since = *self.idle_since.get_or_insert(tick);
            if tick - since >= self.clock.finish && !self.final_pass(sim) {
                self.finished = true;
            }
        } else {
            self.idle_since = None;
        }
    }

    /// Lifts from the blacklist the given-up frontiers whose surroundings changed on the
    /// map since (a door seen open, a wall mapped): the reason they failed may be gone.
    fn lift_changed(&mut self, map: &OccupancyGrid) {
        let radius = self.ex.blacklist_radius;
        for g in &mut self.given_up {
            if g.lifts == 0 {
                continue;
            }
            let unknown = information_gain(map, g.at, radius);
            if (unknown - g.unknown).abs() >= LIFT_AREA {
                g.lifts -= 1;
                g.unknown = unknown;
                self.assigner.blacklist.retain(|b| *b != g.at);
            }
        }
    }

    /// Before the exploration is declared finished: the nearest frontier of the built map
    /// the robot can reach on its current costmap (clusters of `min_frontier_cells`),
    /// whatever the detectors and the blacklist say, each tried once. Whether one was
    /// sent.
    fn final_pass(&mut self, sim: &mut Sim<'_>) -> bool {
        let (here, tick) = (sim.here(), sim.tick());
        let hits = sim.memory.points(tick);
        let radius = self.ex.blacklist_radius;
        let min_cells = self.ex.min_frontier_cells;
        let tried = &self.final_tries;
        let skip = |p: Point2| tried.iter().any(|t| (t - p).norm() <= radius);
        let costmap = sim
            .nav
            .costmaps
            .rebuild(&mut self.final_costmap, Some(&sim.map), &hits);
        // A robot hemmed in on its costmap reaches no frontier there; the navigator's
        // last try plans on the tight costmap, so the pass looks there too.
        let buffers = &mut self.flood;
        let found = nearest_frontier_with(&sim.map, costmap, here, min_cells, skip, buffers, true)
            .or_else(|| {
                let tight = sim.nav.costmaps.build_tight(Some(&sim.map), &[]);
                nearest_frontier_with(&sim.map, &tight, here, min_cells, skip, buffers, true)
            });
        let Some(f) = found else {
            return false;
        };
        self.final_tries.push(f);
        self.idle_since = None;
        self.send(sim, f, f);
        self.final_goal = true;
        true
    }

    /// Ends the goal `g` when the navigator gave up, the robot is stuck, or the filter's
    /// tests fail on its frontier.
    fn test_goal(&mut self, sim: &Sim<'_>, g: Point2) {
        let (tick, t, here, map) = (sim.tick(), sim.time(), sim.here(), &sim.map);
        let state = sim.nav.state();
        // The frontier sought: the goal itself, or the target of its view point.
        let f = self.target.unwrap_or(g);
        // Not for a final-pass goal: the pass chose it as reachable on this costmap, and
        // the test had ended such goals within half a second, undoing the pass
        // (measurements/issue-27.md).
        let too_costly = !self.final_goal && self.frontier_cost(map, f) > self.ex.costmap_threshold;
        let too_little = self.ex.drop_seen_goals
            && !too_costly
            && information_gain(map, f, self.ex.filter_radius) < self.ex.min_gain;
        if (here - self.anchor.0).norm() >= 0.2 || self.look.is_some() {
            self.anchor = (here, tick);
        }
        if self.clock.progress.is_some() {
            match sim.nav.remaining(here) {
                Some(left) if left < self.progress.0 => self.progress = (left, tick),
                _ if self.look.is_some() => self.progress.1 = tick,
                _ => {}
            }
        }
        let version = sim.map_version();
        let looked = self
            .look
            .is_some_and(|l| l.settled.is_some_and(|v| version > v));
        let end = if state == NavState::Failed {
            Some(GoalEnd::GaveUp)
        } else if tick - self.anchor.1 >= self.clock.stuck {
            Some(GoalEnd::Stuck)
        } else if self
            .clock
            .progress
            .is_some_and(|p| tick - self.progress.1 >= p)
        {
            Some(GoalEnd::NoProgress)
        } else if self.recovering {
            (state == NavState::Reached).then_some(GoalEnd::Reached)
        } else if too_costly {
            Some(GoalEnd::Cost)
        } else if too_little {
            Some(GoalEnd::Gain)
        } else if state == NavState::Reached && (self.target.is_none() || looked) {
            Some(GoalEnd::Reached)
        } else {
            None
        };
        if state == NavState::Reached && self.target.is_some() && self.look.is_none() {
            self.look = Some(Look::default());
        }
        let Some(end) = end else { return };
        let given_up = matches!(end, GoalEnd::GaveUp | GoalEnd::Stuck | GoalEnd::NoProgress);
        let pinned = given_up && self.goal_log.last().is_some_and(|r| r.driven < 0.2);
        if self.recovering {
            self.recovering = false;
        } else {
            if given_up {
                self.failed.push(f);
                self.given_up.push(GivenUp {
                    at: f,
                    unknown: information_gain(&sim.map, f, self.ex.blacklist_radius),
                    lifts: MAX_LIFTS,
                });
            }
            self.assigner.blacklist.push(f);
            self.recovering = pinned && self.ex.view_points;
        }
        self.goal = None;
        self.target = None;
        self.look = None;
        if let Some(r) = self.goal_log.last_mut() {
            r.ended = t;
            r.end = end;
        }
    }

    /// The reference assigner's every-cycle choice while the robot drives: the best
    /// frontier by `assigner.py`'s busy scores replaces the goal when it is another
    /// frontier (farther than the mean-shift bandwidth from the goal's; the reference
    /// re-sends even the same one, which only re-plans).
    fn retarget(&mut self, sim: &mut Sim<'_>) {
        let (Some(g), None) = (self.goal, self.look) else {
            return;
        };
        let f = self.target.unwrap_or(g);
        let ranked =
            self.assigner
                .ranked_with(sim.here(), &self.candidates, &sim.map, Some((f, true)));
        let Some(&best) = ranked.first() else { return };
        if (best - f).norm() <= self.ex.bandwidth {
            return;
        }
        if let Some(r) = self.goal_log.last_mut() {
            r.ended = sim.time();
            r.end = GoalEnd::Retargeted;
        }
        self.goal = None;
        self.target = None;
        self.send(sim, best, best);
    }

    /// Picks the next frontier (and its view point) and sends the navigator there.
    fn choose_goal(&mut self, sim: &mut Sim<'_>) {
        let here = sim.here();
        let (ex, rrt, res) = (&self.ex, self.rrt, self.res);
        let map = &sim.map;
        // The baseline without view points, and the assigner's travel, need the whole
        // costmap (reachability); the RRT filter and the goal test ask about a few
        // points (`built_cost`). Built only when a goal is chosen, and once per map
        // change.
        let by_travel = rrt
            && ex.assigner_mode == AssignerMode::Idle
            && ex.revenue_distance == RevenueDistance::Travel;
        if (by_travel || !rrt && !ex.view_points) && self.costmap_at != Some(sim.map_version()) {
            sim.nav.costmaps.rebuild(&mut self.costmap, Some(map), &[]);
            self.costmap_at = Some(sim.map_version());
        }
        let costmap = self.costmap_at.and_then(|_| self.costmap.costmap());
        // The assigner's travel floods the costmap only as far as its choice needs; the
        // view points need every reachable cell.
        let mut flood = costmap
            .filter(|_| by_travel && !ex.view_points)
            .map(|c| TravelFlood::new(c, here, ex.info_radius, self.flood.take()));
        let steps = match costmap {
            Some(c) if ex.view_points => costmap_steps(c, here),
            _ => Vec::new(),
        };
        let views = costmap.map(|costmap| ViewPoints {
            costmap,
            steps: &steps,
            max_cost: ex.view_max_cost,
            range: ex.view_range,
            min_range: self.min_view,
            // A baseline target is an unknown cell's centre: that cell must be
            // the first one not free. An RRT target is a cluster's centre of
            // such cells: one of them within the mean-shift bandwidth.
            slack: if rrt { ex.bandwidth } else { 0.5 * res },
        });
        let views = views.filter(|_| ex.view_points);
        let assigner = &self.assigner;
        let next = match (rrt, views) {
            (_, Some(views)) if self.recovering => views.open_cell(here, 0.5).map(|v| (v, v)),
            (true, None) if ex.assigner_mode == AssignerMode::Reference => {
                let last = (self.last_goal, false);
                assigner
                    .ranked_with(here, &self.candidates, map, Some(last))
                    .first()
                    .map(|&f| (f, f))
            }
            (true, None) if by_travel => flood
                .as_mut()
                .and_then(|flood| assigner.choose_by_travel(&self.candidates, map, flood))
                .map(|f| (f, f)),
            (true, None) => assigner.choose(here, &self.candidates, map).map(|f| (f, f)),
            (true, Some(views)) => assigner
                .ranked(here, &self.candidates, map)
                .into_iter()
                .find_map(|f| views.best(map, f).map(|(_, v)| (f, v))),
            (false, None) => {
                let nearest = costmap.and_then(|costmap| {
                    nearest_frontier_with(
                        map,
                        costmap,
                        here,
                        ex.min_frontier_cells,
                        |p| assigner.blacklisted(p),
                        &mut self.flood,
                        self.none_reachable,
                    )
                });
                self.none_reachable = nearest.is_none();
                nearest.map(|f| (f, f))
            }
            (false, Some(views)) => {
                let cells = unknown_beside(
                    map,
                    frontier_clusters(map)
                        .into_iter()
                        .filter(|c| c.len() >= ex.min_frontier_cells)
                        .flatten(),
                );
                views.nearest(map, &cells, |p| assigner.blacklisted(p))
            }
        };
        if let Some(flood) = flood {
            self.flood = Some(flood.into_buffers());
        }
        if !rrt {
            self.candidates = next.map(|(f, _)| f).into_iter().collect();
        }
        if let Some((f, g)) = next {
            self.send(sim, f, g);
        }
    }

    /// The detectors with the reference's compute time: each runs when its previous
    /// iteration and the loop's period are over, on its own clock (an iteration that
    /// became due within the last tick started when it became due).
    fn timed_detectors(&mut self, sim: &Sim<'_>, cost: &DetectorCost) {
        let (now, here) = (sim.time(), sim.here());
        let tick_s = 1.0 / TICKS_PER_SECOND as f64;
        let [ready_global, ready_local] = &mut self.ready;
        let [n_global, n_local] = &mut self.iterations;
        for (detector, ready, n) in [
            (self.global.as_mut(), ready_global, n_global),
            (self.local.as_mut(), ready_local, n_local),
        ] {
            let Some(d) = detector else { continue };
            if now + 1e-9 < *ready {
                continue;
            }
            *n += 1;
            let start = if now - *ready < tick_s { *ready } else { now };
            let (p, took) = d.step_timed(&sim.map, here, Some(cost));
            *ready = start + cost.next_after(took);
            self.busy += took;
            self.published.extend(p);
        }
    }

    /// Sends the navigator to goal `g` for frontier `f`, and opens the goal's record.
    fn send(&mut self, sim: &mut Sim<'_>, f: Point2, g: Point2) {
        let (tick, t, here) = (sim.tick(), sim.time(), sim.here());
        self.goal = Some(g);
        self.final_goal = false;
        self.last_goal = f;
        self.target = (self.ex.view_points && !self.recovering).then_some(f);
        self.anchor = (here, tick);
        self.progress = (f64::INFINITY, tick);
        sim.nav.set_goal(g);
        self.goals.push((t, g));
        self.goal_log.push(GoalRecord {
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

impl GoalSource for Explorer {
    fn decide(&mut self, sim: &mut Sim<'_>) -> Flow {
        let tick = sim.tick();
        if let Some(cost) = self.ex.detector_cost {
            self.timed_detectors(sim, &cost);
        } else if tick.is_multiple_of(self.clock.detector) {
            let here = sim.here();
            for (k, detector) in [self.global.as_mut(), self.local.as_mut()]
                .into_iter()
                .enumerate()
            {
                if let Some(d) = detector {
                    self.iterations[k] += 1;
                    self.published.extend(d.step(&sim.map, here));
                }
            }
        }
        if tick.is_multiple_of(self.clock.cycle) && self.turned.is_none() {
            self.cycle(sim);
        }
        if self.clock.snapshots.contains(&tick) {
            let s = self.snapshot(sim.time(), sim.pose(), &sim.map);
            self.snapshots.push(s);
        }
        let covered = self
            .coverage_seen
            .as_ref()
            .is_some_and(|(stop, seen)| seen.get() >= *stop);
        if self.finished || covered {
            Flow::Stop
        } else {
            Flow::Continue
        }
    }

    fn command(&mut self, sim: &Sim<'_>) -> Option<Twist> {
        let spin = |omega| Twist { v: 0.0, omega };
        if let Some(a) = self.turned {
            return Some(if a < std::f64::consts::TAU {
                spin(self.rotate_speed)
            } else {
                Twist::default()
            });
        }
        let (Some(f), Some(l)) = (self.target, self.look.as_mut()) else {
            return None;
        };
        // At the view point: turn until the frontier is well inside the laser's field
        // of view, stop, and let one more map update happen.
        let (o, h) = sim.laser().origin(&sim.pose());
        let err = kinematics::wrap_angle((f.y - o.y).atan2(f.x - o.x) - h);
        Some(if !l.aligned && err.abs() > self.look_tolerance {
            spin(self.rotate_speed.copysign(err))
        } else {
            l.aligned = true;
            Twist::default()
        })
    }

    fn controlled(&mut self, sim: &Sim<'_>, events: &[NavEvent]) -> Flow {
        let stopped = sim.twist() == Twist::default();
        if let Some(a) = self.turned {
            if a >= std::f64::consts::TAU && stopped {
                self.turned = None;
            }
        } else if let (Some(_), Some(l)) = (self.target, self.look.as_mut()) {
            if l.aligned && stopped && l.settled.is_none() {
                l.settled = Some(sim.map_version());
            }
        } else if let Some(r) = self.goal_log.last_mut().filter(|r| r.end == GoalEnd::Open) {
            for e in events {
                match e {
                    NavEvent::Plan | NavEvent::Replan => r.plans += 1,
                    NavEvent::Failure => r.failures += 1,
                    NavEvent::Stop => r.stops += 1,
                    NavEvent::GoalReached | NavEvent::GaveUp => {}
                }
            }
        }
        Flow::Continue
    }

    /// The filter's candidates of the last cycle (what the snapshots draw).
    fn frontiers(&self) -> Vec<Point2> {
        self.candidates.clone()
    }

    /// The global tree's edges, then the local tree's.
    fn tree_edges(&self, out: &mut Vec<(Point2, Point2)>) {
        for tree in [self.global.as_ref(), self.local.as_ref()]
            .into_iter()
            .flatten()
        {
            out.extend(tree.edges());
        }
    }

    fn moved(&mut self, from: Pose, to: Pose, step: f64) {
        if let Some(a) = self.turned.as_mut() {
            *a += kinematics::wrap_angle(to.phi - from.phi).abs();
        }
        if let Some(r) = self.goal_log.last_mut().filter(|r| r.end == GoalEnd::Open) {
            r.driven += step;
        }
    }
}

/// The filter's cost of a frontier: with view points the robot never stands on a
/// frontier, so only a frontier on an occupied cell is dropped for its cost.
fn frontier_cost(view_points: bool, inflation: &Inflation, map: &OccupancyGrid, p: Point2) -> i8 {
    if !view_points {
        built_cost(map, inflation, p)
    } else if map.occupied_at(p) {
        100
    } else {
        0
    }
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
