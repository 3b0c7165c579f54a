//! Crowds: generated halls and corridors where people come in at doors and walk across,
//! at a chosen density, and the figures crowd-navigation work reports for a robot among
//! them.
//!
//! A crowd scenario ([`crowd`]) is drawn from its own ChaCha8 stream (`seed`, stream
//! `index`), so any run replays alone:
//! - [`CrowdFlow::Doors`]: a 16 x 10 m hall with two 1.2 m doors in its top wall and two
//!   in its bottom wall; each person comes in at one door and leaves at another;
//! - [`CrowdFlow::Crossing`]: the same hall with a 6 m opening in the top and bottom walls;
//!   people cross it from bottom to top and from top to bottom, across the robot's way;
//! - [`CrowdFlow::Corridor`]: a 20 x 3 m corridor; people come in at either end in groups
//!   of one to three ([`crate::Person::group`]), seven in ten toward the robot.
//!
//! The robot crosses the hall (14 m) or the corridor (16 m) along its length. People are
//! [`Walk::Through`] walkers: they appear at their door, walk to another and leave. They
//! arrive as a Poisson stream whose rate keeps `density` people per 100 m^2 of floor in the
//! room on average, and the room starts at that occupancy (people already on their way,
//! none within 1.5 m of the robot). Walking speeds are normal, mean 1.34 m/s, standard
//! deviation 0.26 m/s ([`WALKING_SPEED`], the desired-speed distribution Helbing and
//! Molnár 1995 take from measurements), cut to 0.8-1.8 m/s ([`SPEED_LIMITS`]).
//!
//! [`measure`] runs a scenario three times, with the people, without them, and the people
//! alone, and reports [`CrowdMetrics`]; [`CrowdCell`] sums many.

use hyplan_core::Point2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Exp, Normal};
use serde::{Deserialize, Serialize};

use crate::engine::{Observer, TICKS_PER_SECOND, time_of};
use crate::kinematics::{Pose, Robot};
use crate::laser::Scan;
use crate::planner::GlobalPlanner;
use crate::scenario::Scenario;
use crate::social_force::{PeopleModelKind, SocialForceParams};
use crate::tracking::MIN_POINTS;
use crate::world::{OFFSTAGE, Person, Shape, Walk, World, pt};

/// Mean and standard deviation of people's walking speed, m/s (Helbing and Molnár 1995,
/// Phys. Rev. E 51, 4282: desired speeds "Gaussian distributed with mean 1.34 m/s and
/// standard deviation 0.26 m/s").
pub const WALKING_SPEED: (f64, f64) = (1.34, 0.26);

/// Walking speeds are drawn again until they fall within these limits, m/s (ours: no one
/// shuffles or runs through the room).
pub const SPEED_LIMITS: (f64, f64) = (0.8, 1.8);

/// Where people walk in a crowd scenario.
///
/// ```
/// let flow: sim::CrowdFlow = "corridor".parse().unwrap();
/// assert_eq!(flow, sim::CrowdFlow::Corridor);
/// assert_eq!(flow.to_string(), "corridor");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum CrowdFlow {
    /// A hall with doors; people come in at one and leave at another.
    Doors,
    /// A corridor with groups coming toward the robot and going its way.
    Corridor,
    /// A hall crossed by two opposite streams, across the robot's way.
    Crossing,
}

impl CrowdFlow {
    /// Every flow, in table order.
    pub const ALL: [Self; 3] = [Self::Doors, Self::Corridor, Self::Crossing];

    /// The floor area that `density` counts people on, m^2.
    #[must_use]
    pub const fn area(self) -> f64 {
        match self {
            Self::Doors | Self::Crossing => HALL.0 * HALL.1,
            Self::Corridor => CORRIDOR.0 * CORRIDOR.1,
        }
    }
}

impl std::fmt::Display for CrowdFlow {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Doors => "doors",
            Self::Corridor => "corridor",
            Self::Crossing => "crossing",
        })
    }
}

impl std::str::FromStr for CrowdFlow {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|f| f.to_string() == s)
            .ok_or_else(|| format!("unknown crowd flow `{s}` (doors, corridor, crossing)"))
    }
}

/// The hall's floor (doors and crossing), m.
const HALL: (f64, f64) = (16.0, 10.0);
/// The strip outside the hall's top and bottom walls where people come in from, m.
const LOBBY: f64 = 2.0;
/// The corridor's floor, m.
const CORRIDOR: (f64, f64) = (20.0, 3.0);
/// Wall thickness, m.
const WALL: f64 = 0.2;
/// How long the robot of a crowd scenario waits for people before their blocks count
/// as failures, s (`navigation.people_patience`).
pub const PEOPLE_PATIENCE: f64 = 30.0;

/// The field of view of the crowd robot's scanner, degrees: 270, a Hokuyo UTM-30LX's
/// (mounted over the base, it sees beside and behind the robot's shoulders), at seed
/// 004's angle between beams (1,080 beams, 40 Hz; [`crate::Laser::with_fov`]). Seed 004's
/// 180-degree scanner cannot see a person who comes from behind beside the robot until
/// they are level with it, too late to stop: people who do not look walked into the
/// moving robot so in 9 of 4,008 runs at density 1 (docs/measurements/issue-29.md).
pub const CROWD_FOV_DEG: f64 = 270.0;

/// The crowd scenario `index` of a set seeded `seed`: `flow` at `density` people per
/// 100 m^2, people under social forces who see the robot (set `people_model` for
/// others), the robot's defaults with its collision monitor on ([`crate::CollisionMonitor`]), a
/// 270-degree scanner ([`CROWD_FOV_DEG`]) and a known map.
///
/// ```
/// let sc = sim::crowd(sim::CrowdFlow::Doors, 1.0, 7, 0);
/// let world = sc.build_world(std::path::Path::new(&sc.name)).unwrap();
/// assert!(!world.people.is_empty());
/// assert!(sc.people.iter().all(|p| (0.8..=1.8).contains(&p.speed)));
/// assert!(sc.navigation.collision_monitor.is_some());
/// assert_eq!(sc.laser.fov_deg, sim::CROWD_FOV_DEG);
/// let empty = sim::crowd(sim::CrowdFlow::Doors, 0.0, 7, 0);
/// assert!(empty.people.is_empty());
/// ```
#[must_use]
pub fn crowd(flow: CrowdFlow, density: f64, seed: u64, index: u64) -> Scenario {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index);
    let (size, shapes, start, goal) = match flow {
        CrowdFlow::Doors => hall(&[(4.0, 1.2), (12.0, 1.2)]),
        CrowdFlow::Crossing => hall(&[(8.0, 6.0)]),
        CrowdFlow::Corridor => corridor(),
    };
    let route = (pt(goal) - pt(start)).norm();
    let time_limit = (3.0 * route / Robot::default().v_max).ceil();
    let people = if density > 0.0 && density.is_finite() {
        people(flow, density, time_limit, start, &mut rng)
    } else {
        Vec::new()
    };
    let mut scenario = Scenario {
        people_model: PeopleModelKind::SocialForce(SocialForceParams::default()),
        ..Scenario::generated(
            (
                format!("crowd-{flow}-{density}-{seed}-{index}"),
                format!("generated {flow} crowd, density {density} per 100 m^2"),
            ),
            (size, shapes),
            people,
            (start, 0.0, goal),
            time_limit,
        )
    };
    crowd_robot(&mut scenario);
    scenario
}

/// Sets `scenario`'s robot up as the crowd scenarios' ([`crowd`]): its collision monitor
/// on ([`crate::CollisionMonitor`]'s defaults, unless it has one), waiting up to
/// [`PEOPLE_PATIENCE`] for people before their blocks count as failures, and a
/// 270-degree scanner ([`CROWD_FOV_DEG`]) at its angle between beams.
///
/// ```
/// let mut sc = sim::crowd(sim::CrowdFlow::Doors, 0.0, 1, 0);
/// sc.navigation = Default::default();
/// sim::crowd_robot(&mut sc);
/// assert_eq!(sc.navigation.people_patience, sim::PEOPLE_PATIENCE);
/// assert!(sc.navigation.collision_monitor.is_some());
/// assert_eq!(sc.laser.fov_deg, sim::CROWD_FOV_DEG);
/// ```
pub fn crowd_robot(scenario: &mut Scenario) {
    let nav = &mut scenario.navigation;
    nav.collision_monitor = Some(nav.collision_monitor.unwrap_or_default());
    nav.people_patience = PEOPLE_PATIENCE;
    scenario.laser = scenario.laser.with_fov(CROWD_FOV_DEG);
}

type Layout = ((f64, f64), Vec<Shape>, (f64, f64), (f64, f64));

fn wall(from: (f64, f64), to: (f64, f64)) -> Shape {
    Shape::Wall {
        from,
        to,
        thickness: WALL,
    }
}

/// The hall with `doors` (centre x, width) in its top and bottom walls, between two
/// lobbies.
fn hall(doors: &[(f64, f64)]) -> Layout {
    let (w, h) = HALL;
    let (y0, y1) = (LOBBY, LOBBY + h);
    let mut shapes = vec![
        wall((0.1, y0), (0.1, y1)),
        wall((w - 0.1, y0), (w - 0.1, y1)),
    ];
    for y in [y0, y1] {
        let mut x = 0.0;
        for &(c, width) in doors {
            shapes.push(wall((x, y), (c - width / 2.0, y)));
            x = c + width / 2.0;
        }
        shapes.push(wall((x, y), (w, y)));
    }
    let mid = y0 + h / 2.0;
    ((w, h + 2.0 * LOBBY), shapes, (1.0, mid), (w - 1.0, mid))
}

/// The corridor, closed at both ends.
fn corridor() -> Layout {
    let (w, h) = CORRIDOR;
    let shapes = vec![
        wall((0.0, 0.1), (w, 0.1)),
        wall((0.0, h - 0.1), (w, h - 0.1)),
        wall((0.1, 0.0), (0.1, h)),
        wall((w - 0.1, 0.0), (w - 0.1, h)),
    ];
    ((w, h), shapes, (2.0, h / 2.0), (w - 2.0, h / 2.0))
}

/// A route of `flow` and its group size: way-points from the entry to the exit.
fn route(flow: CrowdFlow, rng: &mut ChaCha8Rng) -> (Vec<(f64, f64)>, usize) {
    let (y0, y1) = (LOBBY, LOBBY + HALL.1);
    match flow {
        CrowdFlow::Doors => {
            // Doors 0, 1 at the bottom, 2, 3 at the top; x jittered within the door.
            let door = |k: usize, rng: &mut ChaCha8Rng| {
                let x = [4.0, 12.0][k % 2] + rng.random_range(-0.3..0.3);
                let (outside, inside) = if k < 2 {
                    (y0 - 1.0, y0 + 0.6)
                } else {
                    (y1 + 1.0, y1 - 0.6)
                };
                ((x, outside), (x, inside))
            };
            let from = rng.random_range(0..4);
            let to = (from + rng.random_range(1..4)) % 4;
            let (a_out, a_in) = door(from, rng);
            let (b_out, b_in) = door(to, rng);
            (vec![a_out, a_in, b_in, b_out], 1)
        }
        CrowdFlow::Crossing => {
            let x = rng.random_range(5.5..10.5);
            let (bottom, top) = ((x, y0 - 1.0), (x, y1 + 1.0));
            let path = if rng.random_bool(0.5) {
                vec![bottom, top]
            } else {
                vec![top, bottom]
            };
            (path, 1)
        }
        CrowdFlow::Corridor => {
            let (cw, ch) = CORRIDOR;
            let y = rng.random_range(0.6..ch - 0.6);
            let (near, far) = ((0.6, y), (cw - 0.6, y));
            let path = if rng.random_bool(0.7) {
                vec![far, near]
            } else {
                vec![near, far]
            };
            let size = match rng.random_range(0.0..1.0) {
                u if u < 0.5 => 1,
                u if u < 0.85 => 2,
                _ => 3,
            };
            (path, size)
        }
    }
}

/// Length of a polyline, m.
fn length(path: &[(f64, f64)]) -> f64 {
    path.windows(2).map(|s| (pt(s[1]) - pt(s[0])).norm()).sum()
}

/// The point `s` metres along `path`, and the index of the leg it is on.
fn along(path: &[(f64, f64)], mut s: f64) -> ((f64, f64), usize) {
    for (k, leg) in path.windows(2).enumerate() {
        let (a, b) = (pt(leg[0]), pt(leg[1]));
        let len = (b - a).norm();
        if s <= len && len > 0.0 {
            let p = a + (b - a) * (s / len);
            return ((p.x, p.y), k);
        }
        s -= len;
    }
    (path[path.len() - 1], path.len().saturating_sub(2))
}

/// A walking speed: [`WALKING_SPEED`]'s normal, drawn again until within
/// [`SPEED_LIMITS`].
pub(crate) fn walking_speed(rng: &mut impl Rng) -> f64 {
    let speeds = Normal::new(WALKING_SPEED.0, WALKING_SPEED.1).expect("a valid normal");
    loop {
        let v: f64 = speeds.sample(rng);
        if (SPEED_LIMITS.0..=SPEED_LIMITS.1).contains(&v) {
            break v;
        }
    }
}

/// The people of a crowd: a Poisson stream over `[-T, time_limit]`, `T` the time a person
/// takes to cross, each arrival a group; those who set off before 0 start on their way.
fn people(
    flow: CrowdFlow,
    density: f64,
    time_limit: f64,
    robot: (f64, f64),
    rng: &mut ChaCha8Rng,
) -> Vec<Person> {
    // Mean route length and group size, from draws of the same generator's routes.
    let mut probe = ChaCha8Rng::seed_from_u64(0x5eed);
    let samples: Vec<(f64, usize)> = (0..256)
        .map(|_| {
            let (p, g) = route(flow, &mut probe);
            (length(&p), g)
        })
        .collect();
    let mean_len = samples.iter().map(|s| s.0).sum::<f64>() / samples.len() as f64;
    let mean_group = samples.iter().map(|s| s.1 as f64).sum::<f64>() / samples.len() as f64;
    let crossing = mean_len / WALKING_SPEED.0;
    let in_room = density * flow.area() / 100.0;
    // People in the room = arrival rate x group size x crossing time (Little's law).
    let rate = in_room / (mean_group * crossing);
    let gaps = Exp::new(rate).expect("a positive rate");
    let mut out: Vec<Person> = Vec::new();
    let mut t = -crossing * 1.5;
    let mut group = 0u32;
    // A cap on what input controls: at most ten thousand people.
    while out.len() < 10_000 {
        t += gaps.sample(rng);
        if t > time_limit {
            break;
        }
        let (path, size) = route(flow, rng);
        let v = walking_speed(rng);
        group += 1;
        for m in 0..size {
            // Members side by side, 0.6 m apart across the walking direction.
            let dir = (pt(path[1]) - pt(path[0])).normalize();
            let side = nalgebra::Vector2::new(-dir.y, dir.x)
                * (0.6 * (m as f64 - (size - 1) as f64 / 2.0));
            let mut p: Vec<(f64, f64)> = path
                .iter()
                .map(|&(x, y)| (x + side.x, y + side.y))
                .collect();
            if flow == CrowdFlow::Corridor {
                let (_, ch) = CORRIDOR;
                for q in &mut p {
                    q.1 = q.1.clamp(0.5, ch - 0.5);
                }
            }
            let mut start = t;
            if t < 0.0 {
                // Already on the way at 0: start where they would be now.
                let walked = -t * v;
                if walked >= length(&p) - 0.5 {
                    continue;
                }
                let (here, leg) = along(&p, walked);
                let free = (pt(here) - pt(robot)).norm() > 1.5
                    && out
                        .iter()
                        .filter(|o| o.start == 0.0)
                        .all(|o| (pt(o.path[0]) - pt(here)).norm() > 0.6);
                if !free {
                    continue;
                }
                p = std::iter::once(here)
                    .chain(p[leg + 1..].iter().copied())
                    .collect();
                start = 0.0;
            }
            out.push(Person {
                path: p,
                speed: v,
                start,
                radius: 0.25,
                walk: Walk::Through,
                group: (size > 1).then_some(group),
            });
        }
    }
    out
}

/// The figures of one run among people, as crowd-navigation work reports them.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct CrowdMetrics {
    /// The goal was reached.
    pub reached: bool,
    /// The run hit the scenario's time limit without reaching the goal.
    pub timed_out: bool,
    /// Contacts of any kind with a person or a wall.
    pub contacts: usize,
    /// Contacts the robot caused (moving toward what it touched).
    pub contacts_at_fault: usize,
    /// Time to the goal, s.
    pub travel_time: Option<f64>,
    /// Time to the goal in the same scenario without people, s.
    pub travel_time_alone: Option<f64>,
    /// Distance driven, m.
    pub path_length: f64,
    /// Smallest gap between the robot's body and a person's, m.
    pub min_person_distance: Option<f64>,
    /// Time the robot's body spent within [`crate::PERSONAL_SPACE`] of a person's edge, s.
    pub personal_space_time: f64,
    /// People who left the room during the run and also without a robot.
    pub people_arrived: usize,
    /// Their delay caused by the robot: the sum over them of their arrival time with the
    /// robot less without it, s.
    pub people_delay: f64,
    /// People held in place ([`HELD_WITHIN`], [`HELD_FOR`]) walking without the robot over
    /// the same time: held by the walls or each other, which the robot's figures then
    /// include (a person standing in a corridor for good blocks it).
    #[serde(default)]
    pub people_held_alone: usize,
    /// Laser scans with people moving in view (at least four hits on them, the tracker's
    /// smallest cluster).
    pub scans_with_people: usize,
    /// Person sightings (a moving person seen in a scan).
    pub sightings: usize,
    /// Sightings no track matched (no mover within [`TRACK_GATE`] of the person).
    pub missed: usize,
    /// Movers no person on stage was within [`TRACK_GATE`] of.
    pub false_tracks: usize,
    /// Sum of the distances from each matched mover to the person's centre, m.
    pub track_error_sum: f64,
}

impl CrowdMetrics {
    /// Time to goal over the time without people (`None` unless both reached).
    #[must_use]
    pub fn time_ratio(&self) -> Option<f64> {
        Some(self.travel_time? / self.travel_time_alone?)
    }
}

/// A tracked mover matches a person whose centre is within this distance, m (a person's
/// radius and the centroid's offset to their visible side, with margin).
pub const TRACK_GATE: f64 = 0.6;

/// People moving slower than this are not expected to be tracked (the tracker leaves
/// standing things to the obstacle memory), m/s.
const MOVING: f64 = 0.1;

/// Watches a run among people: when each [`Walk::Through`] person leaves the world, and
/// the people tracker against the true people.
#[derive(Debug, Clone, Default)]
pub struct CrowdMeter {
    /// Per person, the time they left the world, s.
    pub arrivals: Vec<Option<f64>>,
    /// Tracking figures (the `scans_with_people` .. `track_error_sum` fields).
    pub metrics: CrowdMetrics,
    /// Everyone's centre at the last scan (for who is moving).
    last_scan: Vec<(f64, Point2)>,
    /// Everyone's centre at the last tick (for who left).
    last_tick: Option<Vec<Point2>>,
}

impl CrowdMeter {
    /// A meter for `n` people.
    #[must_use]
    pub fn new(n: usize) -> Self {
        Self {
            arrivals: vec![None; n],
            metrics: CrowdMetrics::default(),
            last_scan: Vec::new(),
            last_tick: None,
        }
    }
}

fn offstage(p: Point2) -> bool {
    !crate::world::Disc {
        center: p,
        radius: 0.0,
    }
    .on_stage()
}

/// Records arrivals: a person seen on stage at the last tick and off stage now.
fn arrivals(arrived: &mut [Option<f64>], was: &[Point2], now: &[Point2], t: f64) {
    for ((a, w), n) in arrived.iter_mut().zip(was).zip(now) {
        if a.is_none() && !offstage(*w) && offstage(*n) {
            *a = Some(t);
        }
    }
}

impl Observer for CrowdMeter {
    fn scan_reach(&self, sim: &crate::Sim<'_>) -> f64 {
        sim.scenario.costmap.obstacle_range
    }

    fn sensed(&mut self, sim: &crate::Sim<'_>, scan: &Scan) {
        let t = sim.time();
        let people = sim.people();
        let range = sim.scenario.costmap.obstacle_range;
        let mut hits = vec![0usize; people.len()];
        for k in 0..scan.ranges.len() {
            let Some(h) = scan.hit(k) else { continue };
            if (h - scan.origin).norm() > range {
                continue;
            }
            if let Some(i) = people
                .iter()
                .position(|p| (h - p.center).norm() <= p.radius + 0.05)
            {
                hits[i] += 1;
            }
        }
        let moving = |i: usize| {
            self.last_scan.get(i).is_some_and(|&(t0, c0)| {
                t > t0 && (people[i].center - c0).norm() / (t - t0) > MOVING
            })
        };
        let tick = (t * TICKS_PER_SECOND as f64).round() as u64;
        let movers = sim.tracker.movers(tick);
        let m = &mut self.metrics;
        let seen: Vec<usize> = (0..people.len())
            .filter(|&i| hits[i] >= MIN_POINTS && moving(i))
            .collect();
        if !seen.is_empty() {
            m.scans_with_people += 1;
        }
        for &i in &seen {
            m.sightings += 1;
            let nearest = movers
                .iter()
                .map(|mv| (mv.center - people[i].center).norm())
                .fold(f64::INFINITY, f64::min);
            if nearest <= TRACK_GATE {
                m.track_error_sum += nearest;
            } else {
                m.missed += 1;
            }
        }
        m.false_tracks += movers
            .iter()
            .filter(|mv| {
                people
                    .iter()
                    .all(|p| (mv.center - p.center).norm() > TRACK_GATE)
            })
            .count();
        self.last_scan = people.iter().map(|p| (t, p.center)).collect();
    }

    fn ticked(&mut self, sim: &crate::Sim<'_>, info: &crate::TickInfo<'_>) {
        let now: Vec<Point2> = sim.people().iter().map(|p| p.center).collect();
        if let Some(was) = self.last_tick.take() {
            arrivals(&mut self.arrivals, &was, &now, info.t);
        }
        self.last_tick = Some(now);
    }
}

/// A person who stays within this distance of one place for [`HELD_FOR`] is held in
/// place, m (a person waiting to set off, or standing at the end of a one-way route, is
/// not).
pub const HELD_WITHIN: f64 = 0.3;

/// How long a person held in place stays within [`HELD_WITHIN`] of one place, s.
pub const HELD_FOR: f64 = 20.0;

/// The people of a world walking with no robot in it ([`people_alone`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Alone {
    /// When each person left the world, s.
    pub arrivals: Vec<Option<f64>>,
    /// How many were held in place (within [`HELD_WITHIN`] of one place for [`HELD_FOR`]
    /// or more) on the way: by the walls or by each other, since no robot was there.
    pub held: usize,
}

/// The people model of `scenario` stepped alone in `world`, tick by tick, until `until`,
/// s: when each person leaves the world, and how many are held in place on the way.
///
/// ```
/// let sc = sim::crowd(sim::CrowdFlow::Crossing, 1.0, 1, 0);
/// let world = sc.build_world(std::path::Path::new(&sc.name))?;
/// let alone = sim::people_alone(&sc, &world, 30.0);
/// assert_eq!(alone.arrivals.len(), world.people.len());
/// assert_eq!(alone.held, 0, "nothing holds people crossing an empty hall");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn people_alone(scenario: &Scenario, world: &World, until: f64) -> Alone {
    let mut model = scenario
        .people_model
        .build(world, scenario.robot.body_radius);
    let away = Pose {
        x: -OFFSTAGE.0,
        y: -OFFSTAGE.1,
        phi: 0.0,
    };
    let n = world.people.len();
    let mut out = vec![None; n];
    // Per person: where they stood since when, and whether they were held.
    let mut anchors: Vec<Option<(Point2, f64)>> = vec![None; n];
    let mut held = vec![false; n];
    let mut was: Vec<Point2> = Vec::new();
    let mut tick = 0u64;
    loop {
        let t = time_of(tick);
        if t > until {
            break;
        }
        let now: Vec<Point2> = model.people(t, away).iter().map(|d| d.center).collect();
        if !was.is_empty() {
            arrivals(&mut out, &was, &now, t);
        }
        for (k, (p, &here)) in world.people.iter().zip(&now).enumerate() {
            let done = matches!(p.walk, crate::Walk::Once)
                && p.path
                    .last()
                    .is_some_and(|&(x, y)| (Point2::new(x, y) - here).norm() <= HELD_WITHIN);
            if t < p.start || offstage(here) || done {
                anchors[k] = None;
                continue;
            }
            match anchors[k] {
                Some((at, since)) if (here - at).norm() <= HELD_WITHIN => {
                    held[k] |= t - since >= HELD_FOR;
                }
                _ => anchors[k] = Some((here, t)),
            }
        }
        was = now;
        tick += 1;
    }
    Alone {
        arrivals: out,
        held: held.iter().filter(|&&h| h).count(),
    }
}

/// Runs `scenario` with its people, without them, and the people alone, with `seed` and
/// the planner `planner` makes (called twice), and measures the run among people:
/// [`run_with`](crate::run_with) with a [`CrowdMeter`], then [`CrowdMeter::finish`].
///
/// ```no_run
/// let sc = sim::crowd(sim::CrowdFlow::Crossing, 1.0, 1, 0);
/// let world = sc.build_world(std::path::Path::new(&sc.name)).unwrap();
/// let m = sim::measure(&sc, &world, 0, || sim::GlobalPlanner::Dijkstra);
/// println!("reached {}, {:?} x the time alone", m.reached, m.time_ratio());
/// ```
#[must_use]
pub fn measure(
    scenario: &Scenario,
    world: &World,
    seed: u64,
    planner: impl Fn() -> GlobalPlanner,
) -> CrowdMetrics {
    let mut meter = CrowdMeter::new(world.people.len());
    let out = crate::run_with(scenario, world, seed, planner(), &mut [&mut meter]);
    meter.finish(scenario, world, seed, &out, planner())
}

impl CrowdMeter {
    /// The figures of the run `out` this meter watched (`scenario` in `world`, `seed`):
    /// runs the scenario again without people (with `planner`) and the people alone.
    #[must_use]
    pub fn finish(
        self,
        scenario: &Scenario,
        world: &World,
        seed: u64,
        out: &crate::Outcome,
        planner: GlobalPlanner,
    ) -> CrowdMetrics {
        let s = &out.trace.summary;
        let mut alone_world = world.clone();
        alone_world.people.clear();
        let mut alone_sc = scenario.clone();
        alone_sc.people.clear();
        let alone = crate::run(&alone_sc, &alone_world, seed, planner);
        let reference = people_alone(scenario, world, s.end_time);
        let (mut arrived, mut delay) = (0, 0.0);
        for (with, without) in self.arrivals.iter().zip(&reference.arrivals) {
            if let (Some(a), Some(b)) = (with, without) {
                arrived += 1;
                delay += a - b;
            }
        }
        CrowdMetrics {
            reached: s.reached,
            timed_out: !s.reached && s.end_time + 1e-9 >= scenario.time_limit,
            contacts: out.trace.contacts.len(),
            contacts_at_fault: s.contacts_at_fault,
            travel_time: s.travel_time,
            travel_time_alone: alone.trace.summary.travel_time,
            path_length: s.distance,
            min_person_distance: s.min_person_distance,
            personal_space_time: s.personal_space_time,
            people_arrived: arrived,
            people_delay: delay,
            people_held_alone: reference.held,
            ..self.metrics
        }
    }
}

/// Many runs' [`CrowdMetrics`], summed: one cell of a crowd table.
///
/// ```
/// let mut cell = sim::CrowdCell::default();
/// cell.add(&sim::CrowdMetrics { reached: true, travel_time: Some(60.0),
///     travel_time_alone: Some(50.0), ..Default::default() });
/// cell.add(&sim::CrowdMetrics { timed_out: true, ..Default::default() });
/// assert_eq!((cell.runs, cell.reached, cell.timed_out), (2, 1, 1));
/// assert_eq!(cell.time_ratios, [1.2]);
/// ```
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct CrowdCell {
    /// Runs.
    pub runs: usize,
    /// Runs that reached the goal.
    pub reached: usize,
    /// Runs that hit the time limit.
    pub timed_out: usize,
    /// Runs with any contact.
    pub with_contact: usize,
    /// Runs with a contact the robot caused.
    pub with_at_fault: usize,
    /// Contacts the robot caused, over all runs.
    pub contacts_at_fault: usize,
    /// Time to goal over the time without people, per run that reached both (for
    /// medians: `harness::stats::median`).
    pub time_ratios: Vec<f64>,
    /// Distance driven, m, summed over the runs that reached the goal.
    pub path_length: f64,
    /// Smallest robot-person gap per run that met a person, m.
    pub min_person_distance: Vec<f64>,
    /// Time within personal space, summed, s.
    pub personal_space_time: f64,
    /// People who left the room, with and without the robot, summed.
    pub people_arrived: usize,
    /// Their delay caused by the robot, summed, s.
    pub people_delay: f64,
    /// Person sightings by the laser, summed.
    pub sightings: usize,
    /// Sightings no track matched.
    pub missed: usize,
    /// Movers matching no person.
    pub false_tracks: usize,
    /// Scans with people moving in view.
    pub scans_with_people: usize,
    /// Sum of matched track errors, m.
    pub track_error_sum: f64,
}

impl CrowdCell {
    /// Adds one run.
    pub fn add(&mut self, m: &CrowdMetrics) {
        self.runs += 1;
        self.reached += usize::from(m.reached);
        self.timed_out += usize::from(m.timed_out);
        self.with_contact += usize::from(m.contacts > 0);
        self.with_at_fault += usize::from(m.contacts_at_fault > 0);
        self.contacts_at_fault += m.contacts_at_fault;
        self.time_ratios.extend(m.time_ratio());
        if m.reached {
            self.path_length += m.path_length;
        }
        self.min_person_distance.extend(m.min_person_distance);
        self.personal_space_time += m.personal_space_time;
        self.people_arrived += m.people_arrived;
        self.people_delay += m.people_delay;
        self.sightings += m.sightings;
        self.missed += m.missed;
        self.false_tracks += m.false_tracks;
        self.scans_with_people += m.scans_with_people;
        self.track_error_sum += m.track_error_sum;
    }

    /// Mean distance driven per run that reached the goal, m.
    #[must_use]
    pub fn mean_path_length(&self) -> Option<f64> {
        (self.reached > 0).then(|| self.path_length / self.reached as f64)
    }

    /// Mean delay per person who left the room, s.
    #[must_use]
    pub fn mean_people_delay(&self) -> Option<f64> {
        (self.people_arrived > 0).then(|| self.people_delay / self.people_arrived as f64)
    }

    /// Mean distance from a matched track to the person's centre, m.
    #[must_use]
    pub fn mean_track_error(&self) -> Option<f64> {
        let matched = self.sightings - self.missed;
        (matched > 0).then(|| self.track_error_sum / matched as f64)
    }

    /// The fraction of sightings no track matched.
    #[must_use]
    pub fn missed_rate(&self) -> Option<f64> {
        (self.sightings > 0).then(|| self.missed as f64 / self.sightings as f64)
    }
}
