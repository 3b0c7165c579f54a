//! The one simulation engine: integer ticks, laser, map, tracker, navigator, exact motion.
//!
//! Time is a tick counter ([`TICKS_PER_SECOND`] = 200, 5 ms); rates are rounded to whole
//! ticks (laser 40 Hz = every 5 ticks, control 10 Hz = every 20, map 2 Hz = every 100).
//! Nothing reads the wall clock. Randomness comes from ChaCha8 streams of the run's seed:
//! [`NOISE_STREAM`] seeds the laser noise ([`noise_stream`]), [`PLANNER_STREAM`] the
//! global planner (goal sources draw their own), so changing the planner never changes
//! the noise.
//!
//! A tick: the people move ([`PeopleModel`]); on laser ticks the robot scans, integrates
//! the scan into its map on map ticks, and feeds the tracker and the obstacle memory; the
//! [`GoalSource`] decides (a fixed goal, an exploration strategy, a caller); on control
//! ticks the navigator (or the goal source's own command) sets the twist; the
//! [`Observer`]s see the tick; the robot moves along the exact arc.

use hyplan_core::{Bounds, Point2};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_xoshiro::Xoshiro256PlusPlus;

use crate::costmap::{CostmapBuilder, ObstacleMemory};
use crate::kinematics::{self, Pose, Twist};
use crate::laser::{LaserModel, NearSegments, Scan};
use crate::mapping::OccupancyGrid;
use crate::navigator::{NavEvent, Navigator};
use crate::people::PeopleModel;
use crate::planner::GlobalPlanner;
use crate::scenario::Scenario;
use crate::tracking::Tracker;
use crate::world::{Disc, World};

/// Simulation ticks per second.
pub const TICKS_PER_SECOND: u64 = 200;

/// Laser-noise stream of a run's seed.
pub const NOISE_STREAM: u64 = 1;
/// Planner stream of a run's seed.
pub const PLANNER_STREAM: u64 = 2;
/// Stream of a run's seed that people placed on a map are drawn from
/// ([`crate::people_on_map`]).
pub const PEOPLE_STREAM: u64 = 3;

/// The ChaCha8 stream `s` of `seed`: each consumer of randomness draws from its own.
///
/// ```
/// use rand::Rng;
/// let mut a = sim::stream(7, sim::NOISE_STREAM);
/// let mut b = sim::stream(7, sim::NOISE_STREAM);
/// assert_eq!(a.random::<u64>(), b.random::<u64>());
/// ```
#[must_use]
pub fn stream(seed: u64, s: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(s);
    rng
}

/// The generator of the laser's range noise.
///
/// Xoshiro256++, not ChaCha8: the noise draws one number per beam (2,880 in a 0.1 s
/// control period of a 720-beam laser at 40 Hz), and ChaCha8's block refills alone were
/// 9 % of a driven step's time; xoshiro256++ draws in a few instructions and passes
/// TestU01's BigCrush, which is all the Gaussian noise needs of it. Nothing here needs a
/// cryptographic stream.
pub type NoiseRng = Xoshiro256PlusPlus;

/// The laser-noise generator of stream `s` of `seed`: seeded from [`stream`]`(seed, s)`, so
/// it stays a pure function of the run's seed.
///
/// ```
/// use rand::Rng;
/// let mut a = sim::noise_stream(7, sim::NOISE_STREAM);
/// let mut b = sim::noise_stream(7, sim::NOISE_STREAM);
/// assert_eq!(a.random::<u64>(), b.random::<u64>());
/// ```
#[must_use]
pub fn noise_stream(seed: u64, s: u64) -> NoiseRng {
    NoiseRng::from_rng(&mut stream(seed, s))
}

/// Ticks between two events at `hz`, at least one.
///
/// ```
/// assert_eq!(sim::every(40.0), 5);
/// ```
#[must_use]
pub fn every(hz: f64) -> u64 {
    ((TICKS_PER_SECOND as f64 / hz).round() as u64).max(1)
}

/// The time of `tick`, s (a product with the tick length, as every time of a run is
/// computed, so that times compare bit for bit).
///
/// ```
/// assert_eq!(sim::time_of(200), 1.0);
/// ```
#[must_use]
pub fn time_of(tick: u64) -> f64 {
    tick as f64 * (1.0 / TICKS_PER_SECOND as f64)
}

/// Whether the run goes on after this step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Flow {
    /// Keep going.
    Continue,
    /// End the run at this tick (the observers still see it).
    Stop,
}

/// What happened in one tick, for the observers.
#[derive(Clone, Copy)]
pub struct TickInfo<'a> {
    /// The tick.
    pub tick: u64,
    /// Its time, s.
    pub t: f64,
    /// The laser scanned.
    pub sensed: bool,
    /// A control step ran (the navigator's or the goal source's command).
    pub controlled: bool,
    /// The navigator's events of this tick's control step.
    pub events: &'a [NavEvent],
    /// The goal source ended the run at this tick.
    pub stopped: bool,
    /// The goal source, for what it shows ([`GoalSource::frontiers`],
    /// [`GoalSource::tree_edges`]).
    pub goals: &'a dyn GoalSource,
}

impl std::fmt::Debug for TickInfo<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TickInfo")
            .field("tick", &self.tick)
            .field("t", &self.t)
            .field("sensed", &self.sensed)
            .field("controlled", &self.controlled)
            .field("events", &self.events)
            .field("stopped", &self.stopped)
            .finish_non_exhaustive()
    }
}

/// Chooses where the robot goes: a fixed goal, an exploration strategy, a script.
///
/// Every method has a default, so a source implements what it needs.
pub trait GoalSource {
    /// Every tick, after sensing and before control: may give the navigator a goal
    /// ([`Navigator::set_goal`]); [`Flow::Stop`] ends the run before this tick's control.
    fn decide(&mut self, _sim: &mut Sim<'_>) -> Flow {
        Flow::Continue
    }
    /// On control ticks: the command wanted instead of the navigator's (turning on the
    /// spot, facing a frontier), limited by the controller's acceleration; `None` lets the
    /// navigator drive.
    fn command(&mut self, _sim: &Sim<'_>) -> Option<Twist> {
        None
    }
    /// After a control step, with the navigator's events; [`Flow::Stop`] ends the run at
    /// this tick.
    fn controlled(&mut self, _sim: &Sim<'_>, _events: &[NavEvent]) -> Flow {
        Flow::Continue
    }
    /// After the robot moved from `from` to `to`, a distance `step`.
    fn moved(&mut self, _from: Pose, _to: Pose, _step: f64) {}
    /// The frontier points it currently considers (exploration), for observers that
    /// show them.
    fn frontiers(&self) -> Vec<Point2> {
        Vec::new()
    }
    /// Appends the edges of the trees it grows (the RRT detectors) to `out`, for
    /// observers that show them. A buffer the caller keeps: a grown tree's edges are
    /// megabytes, and a fresh vector each time costs its page faults again.
    fn tree_edges(&self, _out: &mut Vec<(Point2, Point2)>) {}
}

/// Watches a run: traces, coverage, snapshots, animation frames, logs.
pub trait Observer {
    /// How far from the scanner this observer reads the scans it is shown, m. A beam
    /// whose range is beyond what every reader of the run reads (the map update, the
    /// costmap, the tracker and the observers) may read `INFINITY`, so that the laser is
    /// cast only that far. The whole scan by default; an observer that reads no scan
    /// says 0.
    fn scan_reach(&self, _sim: &Sim<'_>) -> f64 {
        f64::INFINITY
    }
    /// Before a scan is integrated into the map.
    fn map_updating(&mut self, _sim: &Sim<'_>, _scan: &Scan) {}
    /// After the scan was integrated (and the footprint cleared, if the run does).
    fn map_updated(&mut self, _sim: &Sim<'_>, _scan: &Scan) {}
    /// On every laser tick, after the map update (if any): the scan just taken.
    fn sensed(&mut self, _sim: &Sim<'_>, _scan: &Scan) {}
    /// At the end of every tick, before the robot moves.
    fn ticked(&mut self, _sim: &Sim<'_>, _info: &TickInfo<'_>) {}
}

/// Several observers as one, in order: a ready-made run's own observers and its caller's.
pub(crate) struct Each<'a, 'o>(pub(crate) &'a mut [&'o mut dyn Observer]);

impl Observer for Each<'_, '_> {
    fn scan_reach(&self, sim: &Sim<'_>) -> f64 {
        self.0.iter().map(|o| o.scan_reach(sim)).fold(0.0, f64::max)
    }
    fn map_updating(&mut self, sim: &Sim<'_>, scan: &Scan) {
        self.0.iter_mut().for_each(|o| o.map_updating(sim, scan));
    }
    fn map_updated(&mut self, sim: &Sim<'_>, scan: &Scan) {
        self.0.iter_mut().for_each(|o| o.map_updated(sim, scan));
    }
    fn sensed(&mut self, sim: &Sim<'_>, scan: &Scan) {
        self.0.iter_mut().for_each(|o| o.sensed(sim, scan));
    }
    fn ticked(&mut self, sim: &Sim<'_>, info: &TickInfo<'_>) {
        self.0.iter_mut().for_each(|o| o.ticked(sim, info));
    }
}

/// The goal source of a plain navigation run: the navigator's goal, until it is reached
/// or given up.
#[derive(Debug, Clone, Copy, Default)]
pub struct FixedGoal;

impl GoalSource for FixedGoal {
    fn controlled(&mut self, sim: &Sim<'_>, _events: &[NavEvent]) -> Flow {
        use crate::navigator::NavState;
        if matches!(sim.nav.state(), NavState::Reached | NavState::Failed) {
            Flow::Stop
        } else {
            Flow::Continue
        }
    }
}

/// Tick periods of a run.
#[derive(Debug, Clone, Copy)]
struct Rates {
    laser: u64,
    control: u64,
    map: u64,
    max_ticks: u64,
}

/// One simulated robot in one world: its state is this struct, its loop [`Sim::run`].
///
/// ```
/// use sim::{FixedGoal, GlobalPlanner, Scenario, Sim};
/// let text = r#"SimScenario(name: "hall", world: (size: (6.0, 3.0)),
///     start: (0.5, 1.5), goal: (5.5, 1.5))"#;
/// let path = std::path::Path::new("hall.ron");
/// let scenario = Scenario::parse(text, path)?;
/// let world = scenario.build_world(path)?;
/// let goal = hyplan_core::Point2::new(5.5, 1.5);
/// let mut sim = Sim::new(&scenario, &world, 7, GlobalPlanner::Dijkstra, goal);
/// sim.run(&mut FixedGoal, &mut []);
/// assert!(sim.pose().x > 5.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Sim<'w> {
    /// The scenario.
    pub scenario: &'w Scenario,
    /// The true world.
    pub world: &'w World,
    /// The navigator: global planner, costmaps, local controller.
    pub nav: Navigator,
    /// The map built from the scans.
    pub map: OccupancyGrid,
    /// Recent laser hits, for the costmap and the collision checks.
    pub memory: ObstacleMemory,
    /// Moving obstacles tracked from the scans.
    pub tracker: Tracker,
    people_model: Box<dyn PeopleModel + 'w>,
    people: Vec<Disc>,
    laser: LaserModel,
    /// The world's walls in buckets, for scans cast only as far as they are read.
    near: NearSegments,
    noise: NoiseRng,
    rates: Rates,
    clear_footprint: bool,
    sensing_only: bool,
    tracking: bool,
    whole_scans: bool,
    tick: u64,
    pose: Pose,
    twist: Twist,
    distance: f64,
    map_version: u64,
    events: Vec<NavEvent>,
}

impl<'w> Sim<'w> {
    /// A robot at the scenario's start, navigating toward `goal` with `planner`; the
    /// people move as the scenario's `people_model` says (scripted routes by default).
    #[must_use]
    pub fn new(
        scenario: &'w Scenario,
        world: &'w World,
        seed: u64,
        planner: GlobalPlanner,
        goal: Point2,
    ) -> Self {
        let laser_every = every(scenario.laser.rate_hz);
        let rates = Rates {
            laser: laser_every,
            control: every(scenario.controller.rate_hz),
            // On a laser tick, so that it uses a scan.
            map: every(1.0 / scenario.mapping.period).div_ceil(laser_every) * laser_every,
            max_ticks: (scenario.time_limit * TICKS_PER_SECOND as f64).ceil() as u64,
        };
        let keep = (scenario.costmap.memory * TICKS_PER_SECOND as f64).round() as u64;
        let costmaps = CostmapBuilder::new(
            world.bounds,
            &world.mapped,
            scenario.costmap,
            scenario.robot.body_radius,
        );
        Self {
            scenario,
            world,
            nav: Navigator::new(
                scenario.navigation,
                scenario
                    .local_planner
                    .build(scenario.controller, &scenario.costmap),
                planner,
                costmaps,
                scenario.robot,
                goal,
                stream(seed, PLANNER_STREAM),
            ),
            map: OccupancyGrid::new(world.bounds, scenario.mapping),
            memory: ObstacleMemory::new(world.bounds, keep, scenario.costmap.obstacle_range)
                .with_prior(world.bounds, &world.mapped),
            tracker: Tracker::new(
                world.bounds,
                &world.mapped,
                scenario.costmap.obstacle_range,
                TICKS_PER_SECOND as f64,
            ),
            people_model: scenario
                .people_model
                .build(world, scenario.robot.body_radius),
            people: Vec::new(),
            laser: LaserModel::new(scenario.laser),
            near: NearSegments::new(&world.statics),
            noise: noise_stream(seed, NOISE_STREAM),
            rates,
            clear_footprint: false,
            sensing_only: false,
            tracking: true,
            whole_scans: false,
            tick: 0,
            pose: scenario.start_pose(),
            twist: Twist::default(),
            distance: 0.0,
            map_version: 0,
            events: Vec::new(),
        }
    }

    /// Marks the unknown cells under the robot's body free at every map update (a
    /// scanner mounted ahead of the centre never sees them): exploration's choice.
    #[must_use]
    pub fn clearing_footprint(mut self) -> Self {
        self.clear_footprint = true;
        self
    }

    /// Scans feed the people tracker and the observers only: no map is built and no
    /// obstacle memory kept. For a caller that drives the robot itself (every control
    /// tick's command comes from [`GoalSource::command`]), which needs neither.
    #[must_use]
    pub fn sensing_only(mut self) -> Self {
        self.sensing_only = true;
        self
    }

    /// Every scan cast to the laser's range, as if the run read every beam to the end:
    /// the same run, at the cost of the whole casts (by default each scan is cast only
    /// as far as the run reads it, see [`Observer::scan_reach`]). For comparisons.
    #[must_use]
    pub fn with_whole_scans(mut self) -> Self {
        self.whole_scans = true;
        self
    }

    /// No people tracker: the navigator sees no movers and [`Sim::tracker`] stays empty.
    /// For a caller that drives the robot itself and does not read the tracks.
    #[must_use]
    pub fn without_tracker(mut self) -> Self {
        self.tracking = false;
        self
    }

    /// Back to the scenario's start at tick 0, with the laser noise of `seed` and no
    /// tracks, keeping everything built from the world (costmaps, priors): a new episode
    /// without the cost of [`Sim::new`]. Only for a [`Sim::sensing_only`] run (the map,
    /// the obstacle memory and the navigator are not reset); the people models start
    /// over when time goes back to 0.
    pub(crate) fn restart(&mut self, seed: u64) {
        debug_assert!(self.sensing_only, "only a sensing-only run restarts");
        self.tick = 0;
        self.pose = self.scenario.start_pose();
        self.twist = Twist::default();
        self.distance = 0.0;
        self.people.clear();
        self.events.clear();
        self.noise = noise_stream(seed, NOISE_STREAM);
        self.tracker.forget();
    }

    /// Replaces the people's model (scripted walkers by default).
    #[must_use]
    pub fn with_people(mut self, model: Box<dyn PeopleModel + 'w>) -> Self {
        self.people_model = model;
        self
    }

    /// The current tick.
    #[must_use]
    pub const fn tick(&self) -> u64 {
        self.tick
    }

    /// The current time, s.
    #[must_use]
    pub fn time(&self) -> f64 {
        time_of(self.tick)
    }

    /// The robot's pose.
    #[must_use]
    pub const fn pose(&self) -> Pose {
        self.pose
    }

    /// The robot's position.
    #[must_use]
    pub fn here(&self) -> Point2 {
        Point2::new(self.pose.x, self.pose.y)
    }

    /// The command in force.
    #[must_use]
    pub const fn twist(&self) -> Twist {
        self.twist
    }

    /// Distance driven, m.
    #[must_use]
    pub const fn distance(&self) -> f64 {
        self.distance
    }

    /// Map updates so far.
    #[must_use]
    pub const fn map_version(&self) -> u64 {
        self.map_version
    }

    /// The people now.
    #[must_use]
    pub fn people(&self) -> &[Disc] {
        &self.people
    }

    /// The laser hits the robot remembers (what the controllers and the collision
    /// monitor read).
    #[must_use]
    pub const fn memory(&self) -> &ObstacleMemory {
        &self.memory
    }

    /// The laser.
    #[must_use]
    pub const fn laser(&self) -> &LaserModel {
        &self.laser
    }

    /// Whether `tick` is a control tick.
    #[must_use]
    pub const fn is_control_tick(&self, tick: u64) -> bool {
        tick.is_multiple_of(self.rates.control)
    }

    /// Runs ticks until the goal source or the navigator's end stops it, or the
    /// scenario's time limit; returns the last tick.
    pub fn run(&mut self, goals: &mut dyn GoalSource, observers: &mut [&mut dyn Observer]) -> u64 {
        while self.tick <= self.rates.max_ticks {
            if self.step(goals, observers) == Flow::Stop {
                return self.tick;
            }
            self.tick += 1;
        }
        self.tick - 1
    }

    /// One tick, then the tick counter moves on unless the tick stopped the run: one turn
    /// of [`Sim::run`]'s loop, for a caller that runs the loop itself.
    pub fn advance(
        &mut self,
        goals: &mut dyn GoalSource,
        observers: &mut [&mut dyn Observer],
    ) -> Flow {
        let flow = self.step(goals, observers);
        if flow == Flow::Continue {
            self.tick += 1;
        }
        flow
    }

    /// One tick (see the module doc). Does not advance the tick counter past a stop.
    pub fn step(
        &mut self,
        goals: &mut dyn GoalSource,
        observers: &mut [&mut dyn Observer],
    ) -> Flow {
        let tick = self.tick;
        let t = self.time();
        self.people = self.people_model.people(t, self.pose);
        let sensed = tick.is_multiple_of(self.rates.laser);
        if sensed {
            self.sense(tick, observers);
        }
        let mut flow = goals.decide(self);
        self.events.clear();
        let controlled = flow == Flow::Continue && tick.is_multiple_of(self.rates.control);
        if controlled {
            let prev = self.twist;
            self.twist = match goals.command(self) {
                Some(want) => self
                    .nav
                    .controller
                    .limit(&self.scenario.robot, self.twist, want),
                None => {
                    let movers = self.tracker.movers(tick);
                    self.nav.step(
                        self.pose,
                        self.twist,
                        &self.memory,
                        &movers,
                        Some(&self.map),
                        tick,
                        TICKS_PER_SECOND as f64,
                        &mut self.events,
                    )
                }
            };
            // The monitor guards the navigation stack's commands; a caller that drives
            // the robot itself (`sensing_only`, no memory of hits) gets its own.
            if let Some(m) = &self.scenario.navigation.collision_monitor
                && !self.sensing_only
            {
                let robot = &self.scenario.robot;
                let controller = &self.nav.controller;
                self.twist = m.limit(
                    robot,
                    self.rates.control as f64 / TICKS_PER_SECOND as f64,
                    self.pose,
                    prev,
                    self.twist,
                    &self.memory,
                    tick,
                    |t| controller.limit(robot, prev, t),
                );
            }
            flow = goals.controlled(self, &self.events);
        }
        let info = TickInfo {
            tick,
            t,
            sensed,
            controlled,
            events: &self.events,
            stopped: flow == Flow::Stop,
            goals: &*goals,
        };
        for o in observers.iter_mut() {
            o.ticked(self, &info);
        }
        if flow == Flow::Continue {
            let dt = 1.0 / TICKS_PER_SECOND as f64;
            let next = kinematics::integrate(self.pose, self.twist, dt);
            let step = ((next.x - self.pose.x).powi(2) + (next.y - self.pose.y).powi(2)).sqrt();
            self.distance += step;
            goals.moved(self.pose, next, step);
            self.pose = next;
        }
        flow
    }

    fn sense(&mut self, tick: u64, observers: &mut [&mut dyn Observer]) {
        let (o, h) = self.laser.origin(&self.pose);
        let need = self.scan_need(o, tick);
        // Observers that read farther get the whole scan; the run reads the same.
        let whole = observers.iter().any(|ob| ob.scan_reach(self) > need);
        let scan = self.laser.scan_within(
            &self.world.statics,
            &self.people,
            o,
            h,
            need,
            whole,
            &mut self.near,
            &mut self.noise,
        );
        if !self.sensing_only && tick.is_multiple_of(self.rates.map) {
            for ob in observers.iter_mut() {
                ob.map_updating(self, &scan);
            }
            self.map.integrate(&scan);
            self.map_version += 1;
            if self.clear_footprint {
                self.map
                    .mark_footprint_free(self.here(), self.scenario.robot.body_radius);
            }
            for ob in observers.iter_mut() {
                ob.map_updated(self, &scan);
            }
        }
        if self.tracking {
            self.tracker.update(&scan, tick);
        }
        if self.sensing_only {
            for ob in observers.iter_mut() {
                ob.sensed(self, &scan);
            }
            return;
        }
        if !self.scenario.known_map {
            // A hit on a wall lands in the wall's cell or, with the range noise, in the
            // free cell before it: an occupied cell among the 3 x 3 around it explains it.
            let map = &self.map;
            self.memory.explain(&scan, |p| {
                map.cell_of(p)
                    .is_some_and(|c| map.nearest_occupied_centre(p, c, 1).is_finite())
            });
        }
        for ob in observers.iter_mut() {
            ob.sensed(self, &scan);
        }
        self.memory.insert(scan, tick);
    }

    /// How far the run reads the scan taken from `origin` at `tick`: the map update, the
    /// tracker and the obstacle memory's clearing (a remembered hit is cleared by a beam
    /// that goes past it); 1 cm more for the rounding of their comparisons.
    fn scan_need(&self, origin: Point2, tick: u64) -> f64 {
        if self.whole_scans {
            return f64::INFINITY;
        }
        let mut need = self
            .scenario
            .mapping
            .max_range
            .max(self.memory.clearing_reach(origin, tick));
        if self.tracking {
            need = need.max(self.tracker.reach());
        }
        need + 0.01
    }

    /// The box of cells a map update may change: the traced beams' box and the robot's
    /// footprint, with two cells of margin for the rounding.
    #[must_use]
    pub fn update_area(&self, scan: &Scan) -> Bounds {
        let res = self.scenario.mapping.resolution;
        let here = self.here();
        let traced = scan.traced_bounds(self.scenario.mapping.max_range);
        let (m, r) = (2.0 * res, self.scenario.robot.body_radius + 2.0 * res);
        Bounds::new(
            Point2::new(
                (traced.min.x - m).min(here.x - r),
                (traced.min.y - m).min(here.y - r),
            ),
            Point2::new(
                (traced.max.x + m).max(here.x + r),
                (traced.max.y + m).max(here.y + r),
            ),
        )
    }
}
