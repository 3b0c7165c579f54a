//! A robot driven by its caller one control period at a time: the loop a learning
//! environment steps (the Python bindings' `hyplan.Sim` and `hyplan.gym.NavEnv`).
//!
//! The caller's command replaces the navigator's; the robot reaches it at its own
//! accelerations (the local controller's `limit`), the laser fires at its rate, people
//! walk, and nothing else of the navigation stack runs (no map, no costmap, no plans).
//! As everywhere in the simulator, nothing stops the body where it touches a wall or a
//! person: contacts are reported in the [`Observation`], and the caller decides.

use hyplan_core::Point2;

use crate::engine::{GoalSource, Observer, Sim, TickInfo, noise_stream};
use crate::kinematics::{Pose, Twist};
use crate::planner::GlobalPlanner;
use crate::scenario::Scenario;
use crate::tracking::Mover;
use crate::world::{Disc, World};

/// Random stream of the first observation's scan (taken before any tick).
const FIRST_SCAN_STREAM: u64 = 5;

/// What the caller sees after a control period.
#[derive(Debug, Clone, Default)]
pub struct Observation {
    /// Simulated time, s.
    pub t: f64,
    /// The robot's pose.
    pub pose: Pose,
    /// The command in force (the caller's, after the acceleration limits).
    pub twist: Twist,
    /// The latest scan's ranges, m, REP 117 (`inf`: nothing within range; `-inf`: closer
    /// than the shortest range), taken at most one laser period ago.
    pub ranges: Vec<f64>,
    /// The people the tracker follows in the scans, with their velocities.
    pub tracked: Vec<Mover>,
    /// The people as they truly are now.
    pub people: Vec<Disc>,
    /// Whether the body overlapped the static world on a laser tick of the period.
    pub static_contact: bool,
    /// The people (indices into the scenario's) whose bodies the robot's overlapped on a
    /// laser tick of the period.
    pub people_contact: Vec<usize>,
    /// The smallest distance, m, between the body and the static world over the
    /// period's laser ticks (negative: overlapping).
    pub clearance: f64,
    /// Distance from the robot to the scenario's goal, m.
    pub goal_distance: f64,
    /// Bearing of the goal from the robot's heading, rad, in (-pi, pi].
    pub goal_bearing: f64,
    /// Whether the robot is within the navigation's goal tolerance of the goal.
    pub reached: bool,
    /// Whether the scenario's time limit has passed.
    pub timed_out: bool,
}

/// The robot of a scenario, driven by its caller.
///
/// ```
/// use sim::{Driven, Scenario, Twist};
/// let text = r#"SimScenario(name: "hall", world: (size: (6.0, 3.0)),
///     start: (0.5, 1.5), goal: (5.5, 1.5))"#;
/// let path = std::path::Path::new("hall.ron");
/// let scenario = Scenario::parse(text, path)?;
/// let world = scenario.build_world(path)?;
/// let mut robot = Driven::new(&scenario, &world, 7);
/// let start = robot.observation().goal_distance;
/// for _ in 0..20 {
///     robot.step(Twist { v: 0.3, omega: 0.0 });
/// }
/// let seen = robot.observation();
/// assert!(seen.goal_distance < start - 0.2);
/// assert_eq!(seen.ranges.len(), scenario.laser.beams);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Driven<'w> {
    sim: Sim<'w>,
    seen: Observation,
    goal: Point2,
}

impl std::fmt::Debug for Driven<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Driven")
            .field("scenario", &self.sim.scenario.name)
            .field("seen", &self.seen)
            .finish_non_exhaustive()
    }
}

impl<'w> Driven<'w> {
    /// The robot at the scenario's start; the first observation is a scan from there.
    #[must_use]
    pub fn new(scenario: &'w Scenario, world: &'w World, seed: u64) -> Self {
        let goal = Point2::new(scenario.goal.0, scenario.goal.1);
        let sim = Sim::new(scenario, world, seed, GlobalPlanner::Dijkstra, goal).sensing_only();
        let seen = first_observation(&sim, goal, seed);
        Self { sim, seen, goal }
    }

    /// Back to the start with the noise of `seed`: what [`Driven::new`] gives, without
    /// building the simulation again.
    ///
    /// ```
    /// use sim::{Driven, Scenario, Twist};
    /// let text = r#"SimScenario(name: "hall", world: (size: (6.0, 3.0)),
    ///     start: (0.5, 1.5), goal: (5.5, 1.5))"#;
    /// let path = std::path::Path::new("hall.ron");
    /// let scenario = Scenario::parse(text, path)?;
    /// let world = scenario.build_world(path)?;
    /// let mut robot = Driven::new(&scenario, &world, 7);
    /// let first = robot.step(Twist { v: 0.3, omega: 0.1 }).ranges.clone();
    /// robot.step(Twist { v: 0.3, omega: 0.1 });
    /// robot.reset(7);
    /// assert_eq!(robot.observation().t, 0.0);
    /// assert_eq!(robot.step(Twist { v: 0.3, omega: 0.1 }).ranges, first);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn reset(&mut self, seed: u64) {
        self.sim.restart(seed);
        self.seen = first_observation(&self.sim, self.goal, seed);
    }

    /// The same robot without the people tracker: [`Observation::tracked`] stays empty,
    /// and each scan costs less (for a caller that does not read the tracks).
    #[must_use]
    pub fn without_tracker(self) -> Self {
        Self {
            sim: self.sim.without_tracker(),
            ..self
        }
    }

    /// One control period with the command `want` (limited by the robot's accelerations
    /// and speeds); the observation at its end.
    pub fn step(&mut self, want: Twist) -> &Observation {
        let mut source = Commanded(want);
        let mut watch = Watch {
            seen: &mut self.seen,
        };
        watch.seen.static_contact = false;
        watch.seen.people_contact.clear();
        watch.seen.clearance = f64::INFINITY;
        loop {
            // The source never stops the run: the caller decides when it ends.
            let _ = self.sim.advance(&mut source, &mut [&mut watch]);
            if self.sim.is_control_tick(self.sim.tick()) {
                break;
            }
        }
        self.seen.people.clear();
        self.seen.people.extend_from_slice(self.sim.people());
        finish(&self.sim, self.goal, &mut self.seen);
        &self.seen
    }

    /// The observation after the last step (or at the start).
    #[must_use]
    pub const fn observation(&self) -> &Observation {
        &self.seen
    }

    /// The simulation underneath (pose, laser, scenario, tick).
    #[must_use]
    pub const fn sim(&self) -> &Sim<'w> {
        &self.sim
    }

    /// The control period, s: one [`Driven::step`].
    #[must_use]
    pub fn period(&self) -> f64 {
        1.0 / self.sim.scenario.controller.rate_hz
    }
}

/// The observation at the start: a scan from there, with a stream of its own (the run's
/// noise stream starts with the first tick's scan).
fn first_observation(sim: &Sim<'_>, goal: Point2, seed: u64) -> Observation {
    let pose = sim.pose();
    let people = sim.world.people_at(0.0);
    let (o, h) = sim.laser().origin(&pose);
    let mut scan = sim.laser().cast(&sim.world.statics, &people, o, h);
    sim.laser()
        .add_noise(&mut scan, &mut noise_stream(seed, FIRST_SCAN_STREAM));
    let (clearance, people_contact) = nearest_contact(sim, &people);
    let mut seen = Observation {
        ranges: scan.ranges,
        people,
        clearance,
        static_contact: clearance < 0.0,
        people_contact,
        ..Observation::default()
    };
    finish(sim, goal, &mut seen);
    seen
}

/// Pose, command, time, tracked people and the goal's distance and bearing.
fn finish(sim: &Sim<'_>, goal: Point2, seen: &mut Observation) {
    let pose = sim.pose();
    seen.t = sim.time();
    seen.pose = pose;
    seen.twist = sim.twist();
    seen.tracked = sim.tracker.movers(sim.tick());
    let d = goal - sim.here();
    seen.goal_distance = d.norm();
    seen.goal_bearing = crate::kinematics::wrap_angle(d.y.atan2(d.x) - pose.phi);
    seen.reached = seen.goal_distance <= sim.scenario.navigation.goal_tolerance;
    seen.timed_out = seen.t >= sim.scenario.time_limit;
}

/// The caller's command on every control tick.
struct Commanded(Twist);

impl GoalSource for Commanded {
    fn command(&mut self, _sim: &Sim<'_>) -> Option<Twist> {
        Some(self.0)
    }
}

/// Keeps the latest scan and the period's contacts.
struct Watch<'a> {
    seen: &'a mut Observation,
}

impl Observer for Watch<'_> {
    fn sensed(&mut self, _sim: &Sim<'_>, scan: &crate::laser::Scan) {
        self.seen.ranges.clear();
        self.seen.ranges.extend_from_slice(&scan.ranges);
    }

    fn ticked(&mut self, sim: &Sim<'_>, info: &TickInfo<'_>) {
        if !info.sensed {
            return;
        }
        let (clearance, people) = nearest_contact(sim, sim.people());
        self.seen.clearance = self.seen.clearance.min(clearance);
        self.seen.static_contact |= clearance < 0.0;
        for k in people {
            if !self.seen.people_contact.contains(&k) {
                self.seen.people_contact.push(k);
            }
        }
    }
}

/// The body's distance to the static world, m (negative: overlapping), and the people
/// whose bodies overlap it.
fn nearest_contact(sim: &Sim<'_>, people: &[Disc]) -> (f64, Vec<usize>) {
    let here = sim.here();
    let radius = sim.scenario.robot.body_radius;
    let statics = &sim.world.statics;
    let (d, _) = statics.nearest(here);
    let clearance = if d < radius && statics.inside(here) {
        -d - radius
    } else {
        d - radius
    };
    let touching = people
        .iter()
        .enumerate()
        .filter(|(_, p)| (p.center - here).norm() < p.radius + radius)
        .map(|(k, _)| k)
        .collect();
    (clearance, touching)
}
