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
//! - The engine: [`Sim`], one tick loop whose state is one struct; [`GoalSource`] (where
//!   the robot goes: [`FixedGoal`], exploration's detectors, a caller) and [`Observer`]
//!   (what is recorded: [`Recorder`], [`CoverageMeter`], [`TrackRecorder`],
//!   [`FrameRecorder`], [`ContactCounter`], `BagRecorder` with feature `mcap`) plug into
//!   it; [`run()`] ([`run_with`] with more observers) and [`explore()`] are the two
//!   ready-made runs. [`Driven`] hands the commands to a caller, one control period
//!   and one [`Observation`] at a time (a learning environment's loop).
//!   [`TICKS_PER_SECOND`], [`stream`] (the seeded random streams).
//! - The robot: [`Robot`], [`Pose`], [`Twist`], [`WheelSpeeds`], eqs. (2)-(4)
//!   ([`jacobian`], [`jacobian_inverse`], [`wheel_speeds`], [`twist_of`]), wheel
//!   saturation ([`saturate`]) and exact arc integration ([`integrate`]).
//! - The world: [`Shape`], [`StaticWorld`], [`World`], [`Disc`]; people: [`Person`],
//!   [`Walk`] and the [`PeopleModel`] trait ([`Scripted`] walkers; [`SocialForce`],
//!   Helbing and Molnár's social forces, [`SocialForceParams`]; [`Orca`], van den Berg
//!   et al.'s reciprocal velocity obstacles, [`OrcaParams`]), chosen by
//!   [`PeopleModelKind`]; [`people_on_map`] ([`MapCrowd`], [`MapCrowdError`]): walkers
//!   placed on a loaded map's floor at a density ([`PERSON_CLEARANCE`],
//!   [`MAX_MAP_PEOPLE`], [`PEOPLE_STREAM`]), and [`add_crowd`] to a scenario on a map.
//! - Sensing and mapping: [`Laser`], [`LaserModel`], [`Scan`] (exact ray casts, seeded
//!   noise); [`Mapping`], [`OccupancyGrid`] (clamped log-odds, ROS values [`FREE`],
//!   [`OCCUPIED`], [`UNKNOWN`]); [`Tracker`], [`Mover`] (people's velocities).
//! - Navigation: [`CostmapParams`], [`CostmapBuilder`], [`Costmap`], [`ObstacleMemory`];
//!   [`GlobalPlanner`] (Dijkstra on the costmap, or any [`hyplan_core::Planner`]);
//!   the [`LocalController`] trait ([`Controller`]: regulated pure pursuit with a
//!   collision check; [`RolloutController`]: `base_local_planner`'s trajectory roll-out
//!   and DWA, [`Rollout`]), chosen by [`LocalPlanner`]; [`Navigator`], [`Navigation`], [`NavEvent`], [`NavState`].
//! - Exploration: [`Exploration`], [`Strategy`], [`ExploreOutcome`], [`Coverage`],
//!   [`RrtDetector`] ([`DetectorKind`]), [`Filter`], [`Assigner`],
//!   [`nearest_frontier`] (the baseline), [`ViewPoints`], [`explore_then_navigate`].
//! - Profiles: [`Profile`] (`tutorial`, the stack of `rrt_exploration_tutorials` with
//!   every value's source; `hyplan`, our defaults), [`DetectorCost`] (the reference
//!   detectors' compute time), [`FilterPool`], [`AssignerMode`], [`RevenueDistance`].
//! - Files: [`Scenario`] (RON), [`ScenarioError`], [`MapSpec`] (a map file, or a generated
//!   building at [`BUILDING_RESOLUTION`]); [`Trace`], [`Row`], [`Event`],
//!   [`Summary`] and their CSV / JSON / SVG outputs ([`write_all`], [`OutputError`]);
//!   [`soak`] (generated rooms with people, for the safety figures).
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
//! - `mcap`: `BagRecorder`, a run written as a ROS 2 bag (MCAP) for Foxglove and RViz.

mod agent;
#[cfg(feature = "mcap")]
mod bag_observer;
mod boxgrid;
mod building;
mod control;
mod costmap;
mod crowd;
mod engine;
mod explore;
mod grid_cast;
mod half_planes;
mod kinematics;
mod laser;
mod map_crowd;
mod mapping;
mod monitor;
mod navigator;
mod orca;
mod people;
mod planner;
mod profile;
mod record;
mod rollout;
mod run;
mod scenario;
mod soak;
mod social_force;
mod tracking;
mod validate;
mod world;

pub use agent::{Driven, Observation};
#[cfg(feature = "mcap")]
pub use bag_observer::BagRecorder;
pub use building::BUILDING_RESOLUTION;
pub use control::{Command, Controller, FollowInput, LocalController};
pub use costmap::{
    Costmap, CostmapBuilder, CostmapCache, CostmapParams, MEMORY_RESOLUTION, ObstacleMemory,
    rasterize,
};
pub use crowd::{
    Alone, CROWD_FOV_DEG, CrowdCell, CrowdFlow, CrowdMeter, CrowdMetrics, HELD_FOR, HELD_WITHIN,
    PEOPLE_PATIENCE, SPEED_LIMITS, TRACK_GATE, WALKING_SPEED, crowd, crowd_robot, measure,
    people_alone,
};
pub use engine::{
    FixedGoal, Flow, GoalSource, NOISE_STREAM, NoiseRng, Observer, PEOPLE_STREAM, PLANNER_STREAM,
    Sim, TICKS_PER_SECOND, TickInfo, every, noise_stream, stream, time_of,
};
pub use explore::{
    Assigner, AssignerMode, ContactCounter, Coverage, CoverageMeter, DetectorCost, DetectorKind,
    Edge, Exploration, ExploreOutcome, Filter, FilterPool, FrameRecorder, GLOBAL_STREAM, GoalEnd,
    GoalRecord, LOCAL_STREAM, LeftCause, LeftRegion, MapFrames, Region, RegionError,
    RevenueDistance, RrtDetector, SelfMapped, Snapshot, Strategy, TrackRecorder, TravelFlood,
    ViewPoints, animation_png, built_cost, built_cost_reach, costmap_steps, edge_check, explore,
    explore_observed, explore_then_navigate, explore_with, frontier_cells, frontier_clusters,
    information_gain, left_by_cause, left_unknown, mean_shift, nearest_frontier, reachable_free,
    region_of, revenue, sees, snapshot_scene, snapshot_svg, travel,
};
pub use kinematics::{
    Pose, Robot, Twist, WheelSpeeds, integrate, jacobian, jacobian_inverse, pose_rate, saturate,
    twist_of, wheel_speeds, wrap_angle,
};
pub use laser::{Laser, LaserModel, NearSegments, Scan};
pub use map_crowd::{
    MAX_MAP_PEOPLE, MapCrowd, MapCrowdError, PERSON_CLEARANCE, ROUTE_CLEARANCES, add_crowd,
    people_on_map,
};
pub use mapping::{FREE, Mapping, OCCUPIED, OccupancyGrid, UNKNOWN};
pub use monitor::CollisionMonitor;
pub use navigator::{NavEvent, NavState, Navigation, Navigator};
pub use orca::{Orca, OrcaParams};
pub use people::{PeopleModel, Scripted};
pub use planner::{GlobalPlanner, PlanScratch};
pub use profile::Profile;
pub use record::{
    Contact, ContactClass, Event, EventKind, OutputError, PERSONAL_SPACE, Row, Summary, Trace,
    animation_scene, trajectory_scene, velocity_svg, write_all,
};
pub use rollout::{LocalPlanner, Rollout, RolloutController};
pub use run::{Outcome, Recorder, run, run_with};
pub use scenario::{MapSpec, Scenario, ScenarioError, WorldSpec};
pub use soak::{SoakSummary, room, room_at, soak, soak_each, soak_rooms, soak_with};
pub use social_force::{
    CUTOFF_RANGES, KEEP_RIGHT, PeopleModelKind, STEP, SocialForce, SocialForceParams,
};
pub use tracking::{Mover, Tracker};
pub use world::{Disc, OFFSTAGE, Person, Segment, Shape, StaticWorld, Walk, World};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
