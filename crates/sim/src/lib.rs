//! Seed 004's navigation in a deterministic 2-D simulation: a stand-in for the paper's
//! ROS Kinetic + Gazebo 7 set-up (seed `004_3e5a323113b41ded.txt`).
//!
//! A differential-drive robot (eqs. 1-4) with a 180-degree laser drives from a start to
//! a goal through a world of walls, boxes, polygons, discs or a loaded map, among people
//! walking scripted routes. It builds an occupancy grid from its scans, plans with
//! Dijkstra (the paper's Algorithm 3) or any planner of the workspace on an inflated
//! costmap, follows the path, and stops and re-plans when something newly sensed blocks
//! the path ahead.
//!
//! # Contents
//!
//! - [`kinematics`]: [`Robot`], [`Pose`], [`Twist`], [`WheelSpeeds`], eqs. (2)-(4)
//!   ([`jacobian`], [`jacobian_inverse`], [`wheel_speeds`], [`twist_of`]), wheel
//!   saturation ([`saturate`]) and exact arc integration ([`integrate`]).
//! - [`world`]: [`Shape`], [`Person`], [`Walk`], [`StaticWorld`], [`World`].
//! - [`laser`]: [`Laser`], [`LaserModel`], [`Scan`]: exact ray casts, seeded noise.
//! - [`mapping`]: [`Mapping`], [`OccupancyGrid`]: clamped log-odds, ROS values -1/0/100.
//! - [`costmap`]: [`CostmapParams`], [`CostmapBuilder`], [`Costmap`], [`ObstacleMemory`].
//! - [`planner`]: [`GlobalPlanner`]: Dijkstra on the costmap, or any [`hyplan_core::Planner`].
//! - [`control`]: [`Controller`]: regulated pure pursuit with a collision check.
//! - [`tracking`]: [`Tracker`], [`Mover`]: people's velocities from successive scans.
//! - [`navigator`]: [`Navigation`], [`Navigator`], [`NavEvent`], [`NavState`].
//! - [`scenario`]: [`Scenario`] (RON files), [`ScenarioError`].
//! - [`run()`]: the simulation loop, [`Outcome`], [`TICKS_PER_SECOND`].
//! - [`record`]: [`Trace`], [`Row`], [`Event`], [`Summary`], CSV / JSON / SVG outputs
//!   ([`write_all`], [`OutputError`]).
//! - [`replay`]: the paper's three navigation scenarios against its figures.
//! - [`soak`]: generated rooms with people, for the safety figures.
//! - [`mod@explore`]: the exploration phase: global and local RRT frontier detectors, the
//!   filter, the assigner, the nearest-frontier baseline, coverage ([`explore()`]).
//!
//! # Conventions
//!
//! Metres, seconds, radians (degrees only where a field name says `_deg`); x right, y up,
//! headings counter-clockwise from +x; maps in the ROS frame (origin at the lower-left
//! corner). Time is an integer tick of 5 ms; nothing reads the wall clock, and the same
//! scenario and seed give the same trace bit for bit.
//!
//! # Example
//!
//! ```
//! use sim::{GlobalPlanner, Scenario};
//! let text = r#"SimScenario(
//!     name: "hall",
//!     world: (size: (6.0, 3.0), shapes: [Box(center: (3.0, 0.5), size: (0.6, 1.0))]),
//!     start: (0.5, 1.5), goal: (5.5, 1.5),
//! )"#;
//! let path = std::path::Path::new("hall.ron");
//! let scenario = Scenario::parse(text, path)?;
//! let world = scenario.build_world(path)?;
//! let out = sim::run(&scenario, &world, 7, GlobalPlanner::Dijkstra);
//! assert!(out.trace.summary.reached);
//! assert_eq!(out.trace.summary.contacts_at_fault, 0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Features
//!
//! None.

pub mod control;
pub mod costmap;
mod engine;
pub mod explore;
pub mod kinematics;
pub mod laser;
pub mod mapping;
pub mod navigator;
mod people;
pub mod planner;
pub mod record;
pub mod replay;
mod run;
pub mod scenario;
pub mod soak;
pub mod tracking;
mod validate;
pub mod world;

pub use control::{Command, Controller, FollowInput, LocalController};
pub use costmap::{Costmap, CostmapBuilder, CostmapParams, ObstacleMemory};
pub use engine::{
    FixedGoal, Flow, GoalSource, NOISE_STREAM, Observer, PLANNER_STREAM, Sim, TICKS_PER_SECOND,
    TickInfo, every, stream, time_of,
};
pub use explore::{Exploration, ExploreOutcome, Strategy, explore};
pub use kinematics::{
    Pose, Robot, Twist, WheelSpeeds, integrate, jacobian, jacobian_inverse, saturate, twist_of,
    wheel_speeds,
};
pub use laser::{Laser, LaserModel, Scan};
pub use mapping::{Mapping, OccupancyGrid};
pub use navigator::{NavEvent, NavState, Navigation, Navigator};
pub use people::{PeopleModel, Scripted};
pub use planner::GlobalPlanner;
pub use record::{
    Contact, ContactClass, Event, EventKind, OutputError, Row, Summary, Trace, write_all,
};
pub use run::{Outcome, Recorder, run};
pub use scenario::{MapSpec, Scenario, ScenarioError, WorldSpec};
pub use tracking::{Mover, Tracker};
pub use world::{Person, Shape, StaticWorld, Walk, World};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
