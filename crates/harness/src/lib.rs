//! Scenarios, Monte-Carlo runs, metrics and statistics for hyplan's planners.
//!
//! A [`Scenario`] (one RON file under `scenarios/`) names a map, a query, robot limits,
//! the planners to run with their parameters, the number of runs and a base seed, and the
//! published numbers of the paper it replays. [`run_planner`] runs one planner of it the
//! given number of times, each run seeded by [`run_seed`] from the run index alone, so a
//! parallel run gives the serial run's numbers bit for bit (timings aside). Each run is
//! measured into [`RunMetrics`] and summarised by [`Summary`].
//!
//! # Contents
//!
//! - [`Scenario`], [`MapSpec`], [`PlannerSpec`], [`Published`], [`Claim`]: the scenario
//!   format; [`Scenario::load`] reads and validates a file, [`ScenarioError`] names the
//!   file, line and field of a problem.
//! - [`World`]: a scenario's map built and its query placed; [`Scenario::build_world`].
//! - [`Furniture`], [`draw_room`]: room pictures drawn in code from their furniture.
//! - [`PlannerConfig`]: the planner registry (crate `registry`, re-exported), one typed
//!   configuration per planner, by name; [`PlannerConfig::build`] makes the planner,
//!   `"rrt:step=2".parse()` reads the command line's form.
//! - [`RunMetrics`], [`measure`]: what one run is scored on; [`post_process`]: smoothing,
//!   node metrics and transfer time of one plan, shared with `hyplan plan`;
//!   [`NoPathRecord`]: why a plan ended without a path.
//! - [`run_planner`], [`run_seed`]: Monte-Carlo runs.
//! - [`Summary`], [`Stat`]: mean, standard deviation, median, success rate;
//!   [`stats::mann_whitney_u`] and [`stats::decide_less`]: the rank test that decides a
//!   paper's ordering claim on our runs, with its p-value and effect size.
//! - [`report`]: the replay's claims decided on the runs, and its Markdown report.
//! - [`bench`](mod@bench): `hyplan bench`'s runs on a user's problems: [`bench::run_once`], the
//!   summary and pairwise rank tests, [`bench::ompl_log`], OMPL's benchmark log format, and
//!   [`bench::shard`], experiments cut into shards that merge (manifests, exact-cover check).
//! - `world_figure`, `draw_world`, `chart_metrics` (feature `plot`): a scenario's world
//!   with a run's trees and path (PNG or SVG), box plots of run metrics (SVG), drawn by
//!   crate `viz`; `Scene` (`viz::PlanFigure`), `chart_box`, `chart_success` re-exported.
//!
//! # Features
//!
//! - `parallel` (default): runs spread over threads with rayon; results equal the serial run's.
//! - `plot` (default): world figures and charts, through crate `viz`.

pub mod bench;
#[cfg(feature = "plot")]
mod figure;
mod map_build;
mod metrics;
mod no_path;
pub mod report;
mod room;
mod runner;
mod scenario;
pub mod stats;

/// An obstacle of a scenario's drawn grid: `envmap`'s shapes.
pub use envmap::Shape;
#[cfg(feature = "plot")]
pub use figure::{chart_metrics, draw_world, world_figure};
pub use metrics::{Processed, RunMetrics, Scoring, measure, post_process};
pub use no_path::NoPathRecord;
/// Robot limits of a scenario (speed, turn rate, acceleration): `postproc`'s type.
pub use postproc::Limits;
/// The planner registry (crate `registry`): one typed configuration per planner, by name.
pub use registry::{Explored, PlannerConfig, RegistryError, ron_options};
pub use room::{Furniture, draw_room};
pub use runner::{prepare_map, run_planner, run_seed};
pub use scenario::{
    Claim, ClaimKind, MAX_RUNS, MapSpec, PlannerSpec, Published, Scenario, ScenarioError, Source,
    World,
};
pub use stats::{Stat, Summary};
/// The plan figure and charts are `viz`'s; `Scene` is the plan figure's old name here.
#[cfg(feature = "plot")]
pub use viz::{
    CURVE_COLOUR, FigureError, Mark, PATH_COLOUR, PlanFigure as Scene, START_COLOUR, TREE_COLOURS,
    chart_box, chart_success,
};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
