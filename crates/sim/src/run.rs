//! The simulation loop: integer ticks, laser, map, navigator, exact motion, contacts.
//!
//! Time is a tick counter ([`TICKS_PER_SECOND`] = 200, 5 ms); rates are rounded to whole
//! ticks (laser 40 Hz = every 5 ticks, control 10 Hz = every 20, map 2 Hz = every 100).
//! Nothing reads the wall clock. Randomness comes from two ChaCha8 streams of the run's
//! seed: stream 1 for laser noise, stream 2 for the global planner, so changing the
//! planner never changes the noise and vice versa.

use hyplan_core::Point2;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::costmap::{CostmapBuilder, ObstacleMemory};
use crate::kinematics::{self, Twist};
use crate::laser::LaserModel;
use crate::mapping::OccupancyGrid;
use crate::navigator::{NavEvent, NavState, Navigator};
use crate::planner::GlobalPlanner;
use crate::record::{Contact, ContactClass, Event, EventKind, Row, Summary, Trace};
use crate::scenario::Scenario;
use crate::tracking::Tracker;
use crate::world::World;

/// Simulation ticks per second.
pub const TICKS_PER_SECOND: u64 = 200;

/// Laser-noise stream of a run's seed.
pub const NOISE_STREAM: u64 = 1;
/// Planner stream of a run's seed.
pub const PLANNER_STREAM: u64 = 2;

/// Everything a run produced.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Outcome {
    /// The trace.
    pub trace: Trace,
    /// The paths planned, with the time they were planned, s.
    pub plans: Vec<(f64, Vec<(f64, f64)>)>,
    /// The map built from the scans (not serialised).
    #[serde(skip)]
    pub map: Option<OccupancyGrid>,
}

fn stream(seed: u64, s: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(s);
    rng
}

fn every(hz: f64) -> u64 {
    ((TICKS_PER_SECOND as f64 / hz).round() as u64).max(1)
}

/// What the robot builds from its scans, empty at the start of a run: the occupancy
/// grid, the obstacle memory, the people tracker and the costmap builder (the world's
/// mapped part as prior). Navigation and exploration start from the same.
pub(crate) struct Perception {
    pub map: OccupancyGrid,
    pub memory: ObstacleMemory,
    pub tracker: Tracker,
    pub costmaps: CostmapBuilder,
}

impl Perception {
    pub(crate) fn new(scenario: &Scenario, world: &World) -> Self {
        let keep = (scenario.costmap.memory * TICKS_PER_SECOND as f64).round() as u64;
        Self {
            map: OccupancyGrid::new(world.bounds, scenario.mapping),
            memory: ObstacleMemory::new(world.bounds, keep, scenario.costmap.obstacle_range)
                .with_prior(world.bounds, &world.mapped),
            tracker: Tracker::new(
                world.bounds,
                &world.mapped,
                scenario.costmap.obstacle_range,
                TICKS_PER_SECOND as f64,
            ),
            costmaps: CostmapBuilder::new(
                world.bounds,
                &world.mapped,
                scenario.costmap,
                scenario.robot.body_radius,
            ),
        }
    }
}

/// Runs a scenario with `seed` and `planner` until the goal is reached, the navigator
/// gives up, or the time limit.
#[must_use]
pub fn run(scenario: &Scenario, world: &World, seed: u64, planner: GlobalPlanner) -> Outcome {
    let dt = 1.0 / TICKS_PER_SECOND as f64;
    let robot = scenario.robot;
    let laser = LaserModel::new(scenario.laser);
    let laser_every = every(scenario.laser.rate_hz);
    let control_every = every(scenario.controller.rate_hz);
    let map_every = {
        let m = every(1.0 / scenario.mapping.period);
        // On a laser tick, so that it uses a scan.
        m.div_ceil(laser_every) * laser_every
    };
    let max_ticks = (scenario.time_limit * TICKS_PER_SECOND as f64).ceil() as u64;
    let mut noise_rng = stream(seed, NOISE_STREAM);
    let Perception {
        mut map,
        mut memory,
        mut tracker,
        costmaps,
    } = Perception::new(scenario, world);
    let planner_name = planner.name();
    let goal = Point2::new(scenario.goal.0, scenario.goal.1);
    let mut nav = Navigator::new(
        scenario.navigation,
        scenario.controller,
        planner,
        costmaps,
        robot,
        goal,
        stream(seed, PLANNER_STREAM),
    );
    let mut pose = scenario.start_pose();
    let mut twist = Twist::default();
    let mut rows = Vec::new();
    let mut events = Vec::new();
    let mut plans = Vec::new();
    let mut in_contact_static = false;
    let mut near: Option<(Point2, f64)> = None;
    let mut in_contact_person = vec![false; world.people.len()];
    let mut contacts = Vec::new();
    let mut travel_time = None;
    let mut nav_events = Vec::new();
    let mut distance = 0.0;
    let mut end_tick = 0;
    for tick in 0..=max_ticks {
        end_tick = tick;
        let t = tick as f64 * dt;
        let people = world.people_at(t);
        if tick % laser_every == 0 {
            let (o, h) = laser.origin(&pose);
            let mut scan = laser.cast(&world.statics, &people, o, h);
            laser.add_noise(&mut scan, &mut noise_rng);
            if tick % map_every == 0 {
                map.integrate(&scan);
            }
            tracker.update(&scan, tick);
            memory.insert(scan, tick);
        }
        let mut done = false;
        if tick % control_every == 0 {
            nav_events.clear();
            let plans_before = nav.path().to_vec();
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
            for &e in &nav_events {
                events.push(Event {
                    t,
                    kind: EventKind::Nav(e),
                });
                if matches!(e, NavEvent::Plan | NavEvent::Replan) && nav.path() != plans_before {
                    plans.push((t, nav.path().iter().map(|p| (p.x, p.y)).collect()));
                }
                if e == NavEvent::GoalReached {
                    travel_time = Some(t);
                }
            }
            done = matches!(nav.state(), NavState::Reached | NavState::Failed);
        }
        // Distances and contacts at this instant.
        let here = Point2::new(pose.x, pose.y);
        let record = tick % laser_every == 0 || done;
        // The exact distance to the static world is needed on recorded ticks and when
        // the robot may be touching: the last exact distance minus the distance moved
        // since bounds it from below.
        let exact = record
            || near.is_none_or(|(p, d): (Point2, f64)| {
                d - (here - p).norm() <= robot.body_radius + 0.01
            });
        let (d_wall, q_wall) = if exact {
            let (d, q) = world.statics.nearest(here);
            near = Some((here, d));
            (d, q)
        } else {
            (f64::INFINITY, here)
        };
        let d_wall = if d_wall < robot.body_radius && world.statics.inside(here) {
            -d_wall
        } else {
            d_wall
        } - robot.body_radius;
        let heading = nalgebra::Vector2::new(pose.phi.cos(), pose.phi.sin());
        let classify = |toward: Point2| {
            let dir = toward - here;
            let n = dir.norm();
            let approach = if n > 0.0 {
                twist.v * heading.dot(&dir) / n
            } else {
                twist.v
            };
            if twist.v.abs() <= 1e-3 {
                ContactClass::RobotStopped
            } else if approach > 1e-3 {
                ContactClass::AtFault
            } else {
                ContactClass::NotApproaching
            }
        };
        // Off the exact ticks the state cannot have changed (see above).
        let touching = if exact {
            d_wall < 0.0
        } else {
            in_contact_static
        };
        if touching && !in_contact_static {
            let c = Contact {
                t,
                with: "static".into(),
                class: classify(q_wall),
            };
            events.push(Event {
                t,
                kind: EventKind::Contact(c.class),
            });
            contacts.push(c);
        }
        in_contact_static = touching;
        let mut d_person = f64::INFINITY;
        for (k, p) in people.iter().enumerate() {
            let d = (p.center - here).norm() - p.radius - robot.body_radius;
            d_person = d_person.min(d);
            let touching = d < 0.0;
            if touching && !in_contact_person[k] {
                let c = Contact {
                    t,
                    with: format!("person {k}"),
                    class: classify(p.center),
                };
                events.push(Event {
                    t,
                    kind: EventKind::Contact(c.class),
                });
                contacts.push(c);
            }
            in_contact_person[k] = touching;
        }
        if record {
            let w = kinematics::wheel_speeds(&robot, twist);
            rows.push(Row {
                t,
                x: pose.x,
                y: pose.y,
                phi: pose.phi,
                v: twist.v,
                omega: twist.omega,
                wheel_right: w.right,
                wheel_left: w.left,
                d_obstacle: d_wall,
                d_person: d_person.is_finite().then_some(d_person),
            });
        }
        if done {
            break;
        }
        let next = kinematics::integrate(pose, twist, dt);
        distance += ((next.x - pose.x).powi(2) + (next.y - pose.y).powi(2)).sqrt();
        pose = next;
    }
    let count = |e: NavEvent| {
        events
            .iter()
            .filter(|x| x.kind == EventKind::Nav(e))
            .count()
    };
    let summary = Summary {
        scenario: scenario.name.clone(),
        seed,
        planner: planner_name,
        reached: travel_time.is_some(),
        travel_time,
        end_time: end_tick as f64 * dt,
        distance,
        replans: count(NavEvent::Replan),
        stops: count(NavEvent::Stop),
        failures: count(NavEvent::Failure),
        min_obstacle_distance: rows
            .iter()
            .map(|r| r.d_obstacle)
            .fold(f64::INFINITY, f64::min),
        min_person_distance: rows
            .iter()
            .filter_map(|r| r.d_person)
            .fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.min(d)))),
        contacts_at_fault: contacts
            .iter()
            .filter(|c| c.class == ContactClass::AtFault)
            .count(),
        contacts_robot_stopped: contacts
            .iter()
            .filter(|c| c.class == ContactClass::RobotStopped)
            .count(),
        contacts_not_approaching: contacts
            .iter()
            .filter(|c| c.class == ContactClass::NotApproaching)
            .count(),
    };
    Outcome {
        trace: Trace {
            summary,
            rows,
            events,
            contacts,
        },
        plans,
        map: Some(map),
    }
}
