//! A navigation run: the engine with a fixed goal and the trace recorder.

use hyplan_core::Point2;
use serde::{Deserialize, Serialize};

use crate::engine::{Each, FixedGoal, Observer, Sim, TickInfo, time_of};
use crate::kinematics;
use crate::mapping::OccupancyGrid;
use crate::navigator::NavEvent;
use crate::planner::GlobalPlanner;
use crate::record::{Contact, ContactClass, Event, EventKind, Row, Summary, Trace};
use crate::scenario::Scenario;
use crate::world::World;

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

/// Runs a scenario with `seed` and `planner` until the goal is reached, the navigator
/// gives up, or the time limit.
#[must_use]
pub fn run(scenario: &Scenario, world: &World, seed: u64, planner: GlobalPlanner) -> Outcome {
    run_with(scenario, world, seed, planner, &mut [])
}

/// [`run()`], with more `observers` watching beside the trace's recorder (a bag writer,
/// a log); they do not change the run.
#[must_use]
pub fn run_with(
    scenario: &Scenario,
    world: &World,
    seed: u64,
    planner: GlobalPlanner,
    observers: &mut [&mut dyn Observer],
) -> Outcome {
    let planner_name = planner.name();
    let goal = Point2::new(scenario.goal.0, scenario.goal.1);
    let mut sim = Sim::new(scenario, world, seed, planner, goal);
    let mut recorder = Recorder::new(world.people.len());
    let end_tick = sim.run(&mut FixedGoal, &mut [&mut recorder, &mut Each(observers)]);
    let end_time = time_of(end_tick);
    let trace = recorder.finish(
        scenario.name.clone(),
        seed,
        planner_name,
        end_time,
        sim.distance(),
    );
    Outcome {
        trace,
        plans: recorder.plans,
        map: Some(sim.map),
    }
}

/// Records a navigation run's trace: rows on laser ticks, the navigator's events, the
/// contacts with walls and people (classified by who moved), and the plans.
#[derive(Debug, Default)]
pub struct Recorder {
    rows: Vec<Row>,
    events: Vec<Event>,
    contacts: Vec<Contact>,
    /// The paths planned, with the time they were planned, s.
    pub plans: Vec<(f64, Vec<(f64, f64)>)>,
    travel_time: Option<f64>,
    in_contact_static: bool,
    in_contact_person: Vec<bool>,
    /// Where the exact distance to the static world was last taken, and its value.
    near: Option<(Point2, f64)>,
    path_version: u64,
    /// Ticks with the body within [`crate::PERSONAL_SPACE`] of a person's edge.
    personal_ticks: u64,
}

impl Recorder {
    /// A recorder for a world with `people` people.
    #[must_use]
    pub fn new(people: usize) -> Self {
        Self {
            in_contact_person: vec![false; people],
            ..Self::default()
        }
    }

    fn contact(&mut self, t: f64, with: String, class: ContactClass) {
        self.events.push(Event {
            t,
            kind: EventKind::Contact(class),
        });
        self.contacts.push(Contact { t, with, class });
    }

    fn nav_events(&mut self, sim: &Sim<'_>, info: &TickInfo<'_>) {
        for &e in info.events {
            self.events.push(Event {
                t: info.t,
                kind: EventKind::Nav(e),
            });
            if matches!(e, NavEvent::Plan | NavEvent::Replan)
                && sim.nav.path_version() != self.path_version
            {
                self.path_version = sim.nav.path_version();
                let path = sim.nav.path().iter().map(|p| (p.x, p.y)).collect();
                self.plans.push((info.t, path));
            }
            if e == NavEvent::GoalReached {
                self.travel_time = Some(info.t);
            }
        }
    }

    /// The trace of the run.
    #[must_use]
    pub fn finish(
        &mut self,
        scenario: String,
        seed: u64,
        planner: String,
        end_time: f64,
        distance: f64,
    ) -> Trace {
        let events = std::mem::take(&mut self.events);
        let contacts = std::mem::take(&mut self.contacts);
        let rows = std::mem::take(&mut self.rows);
        let count = |e: NavEvent| {
            events
                .iter()
                .filter(|x| x.kind == EventKind::Nav(e))
                .count()
        };
        let of_class = |class| contacts.iter().filter(|c| c.class == class).count();
        let summary = Summary {
            scenario,
            seed,
            planner,
            reached: self.travel_time.is_some(),
            travel_time: self.travel_time,
            end_time,
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
            personal_space_time: crate::engine::time_of(self.personal_ticks),
            contacts_at_fault: of_class(ContactClass::AtFault),
            contacts_robot_stopped: of_class(ContactClass::RobotStopped),
            contacts_not_approaching: of_class(ContactClass::NotApproaching),
        };
        Trace {
            summary,
            rows,
            events,
            contacts,
        }
    }
}

impl Observer for Recorder {
    fn scan_reach(&self, _sim: &Sim<'_>) -> f64 {
        0.0
    }

    fn ticked(&mut self, sim: &Sim<'_>, info: &TickInfo<'_>) {
        let t = info.t;
        self.nav_events(sim, info);
        let robot = sim.scenario.robot;
        let (pose, twist) = (sim.pose(), sim.twist());
        let here = sim.here();
        let record = info.sensed || info.stopped;
        // The exact distance to the static world is needed on recorded ticks and when
        // the robot may be touching: the last exact distance minus the distance moved
        // since bounds it from below.
        let exact = record
            || self.near.is_none_or(|(p, d): (Point2, f64)| {
                d - (here - p).norm() <= robot.body_radius + 0.01
            });
        let statics = &sim.world.statics;
        let (d_wall, q_wall) = if exact {
            let (d, q) = statics.nearest(here);
            self.near = Some((here, d));
            (d, q)
        } else {
            (f64::INFINITY, here)
        };
        let d_wall = if d_wall < robot.body_radius && statics.inside(here) {
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
            self.in_contact_static
        };
        if touching && !self.in_contact_static {
            self.contact(t, "static".into(), classify(q_wall));
        }
        self.in_contact_static = touching;
        let mut d_person = f64::INFINITY;
        for (k, p) in sim.people().iter().enumerate() {
            if !p.on_stage() {
                self.in_contact_person[k] = false;
                continue;
            }
            let d = (p.center - here).norm() - p.radius - robot.body_radius;
            d_person = d_person.min(d);
            let touching = d < 0.0;
            if touching && !self.in_contact_person[k] {
                self.contact(t, format!("person {k}"), classify(p.center));
            }
            self.in_contact_person[k] = touching;
        }
        if d_person < crate::record::PERSONAL_SPACE {
            self.personal_ticks += 1;
        }
        if record {
            let w = kinematics::wheel_speeds(&robot, twist);
            self.rows.push(Row {
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
    }
}
