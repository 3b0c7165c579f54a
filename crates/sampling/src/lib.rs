//! Sampling planners for hyplan: RRT, RRT*, Bi-RRT and RRT-Connect on any
//! [`Workspace`].
//!
//! Every planner is a plain parameter struct with documented defaults and one entry point,
//! `plan(&self, workspace, query, rng)`, returning a [`Plan`] (path,
//! tree(s), statistics) or a typed [`PlanError`]. Each also
//! implements [`Planner`] for use as `Box<dyn Planner>`.
//!
//! # Contents
//!
//! - [`Rrt`]: the rapidly-exploring random tree (seed `000_9b224721fe327833.txt` section 4.2).
//! - [`RrtStar`] and [`RewireRadius`]: RRT with choose-parent and rewiring; first solution or
//!   the whole budget.
//! - [`BiRrt`]: two trees grown in turn, joined by one free step.
//! - [`RrtConnect`]: two trees, greedy connect.
//! - [`NearestIndex`]: the crate's k-d tree (leaves scanned in vector registers) behind one
//!   small type, plain distances.
//! - [`GrowTree`]: the one tree of the family (node ids, parent links, optional
//!   costs-to-come, the nearest index) with its operations: [`extend`](GrowTree::extend)
//!   (one RRT step, an [`Extension`]), [`step_towards`](GrowTree::step_towards) (a
//!   [`Step`] left to the caller to check), the exact goal join, RRT*'s choose-parent,
//!   rewiring and [`reparent`](GrowTree::reparent), branches and the [`Tree`] of a plan.
//!   The hybrids and the exploration's frontier detectors grow this tree too.
//! - [`Run`]: the frame of a run (checks, iterations against the budget, the observer
//!   every [`OBSERVE_EVERY`] iterations, statistics), and [`Search`], what one call of a
//!   planner plans in and with (workspace, query, RNG, observer).
//! - [`impl_planner!`]: the [`Planner`] implementation (and the generic `plan` and
//!   `plan_with`) of a planner, written once.
//! - [`toolkit`], re-exported here: the building blocks the planners are made of, for
//!   planners in other crates: [`steer`], [`sample_uniform`], [`sample_goal_biased`],
//!   [`sample_accepted`], [`CountingChecker`], [`branch`], [`plan_of_path`],
//!   [`validate_step_and_budget`], and [`check_connected`] / [`require_connected`] (the
//!   connectivity proof before sampling). Parameter checks are [`hyplan_core::check`]'s,
//!   shared by every planner.
//!
//! # Guarantees
//!
//! - Every edge is checked with [`Workspace::segment_free`],
//!   which is exact for the workspace's own model (a grid map checks every cell a segment
//!   touches): a returned path never crosses a blocked cell, not even at a corner. Checks are
//!   counted in [`PlanStats::collision_checks`](hyplan_core::PlanStats::collision_checks).
//! - `path[0]` is the query's start bit for bit and the last point lies in the goal region
//!   (exactly on the goal for [`Goal::Point`]).
//! - The only randomness is the RNG passed in: the same seed gives the same tree, bit for bit,
//!   with an iteration budget (a time limit depends on the machine).
//! - Bad input (step <= 0 or NaN, goal bias outside [0, 1], zero budget, start or goal
//!   outside the map or blocked) is a typed error, never a panic; a spent budget is
//!   [`PlanError::BudgetExhausted`] with the
//!   statistics of the attempt.
//! - Probabilistically complete: a planner stops before its budget only with a path or a
//!   proof that none exists ([`PlanError::Disconnected`],
//!   from [`Workspace::disconnection`]: on a grid map, start and goal
//!   not connected through passable cells, with the cause).
//!
//! # Conventions
//!
//! World coordinates, x right and y up, in the workspace's units; `step` and goal radii in
//! the same units.
//!
//! # Example
//!
//! ```
//! use envmap::GridMap;
//! use hyplan_core::{Budget, Goal, Point2, Query, Workspace};
//! use rand::SeedableRng;
//! use sampling::{RrtConnect, Rrt};
//!
//! let map = GridMap::from_ascii("
//!     ............
//!     .....##.....
//!     .....##.....
//!     .....##.....
//!     ............
//! ")?;
//! let query = Query::new(Point2::new(0.5, 2.5), Goal::Point(Point2::new(11.5, 2.5)));
//! let rrt = Rrt { step: 1.5, budget: Budget::iterations(5_000), ..Rrt::default() };
//! let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(42);
//! let plan = rrt.plan(&map, &query, &mut rng)?;
//! assert!(plan.path.windows(2).all(|w| map.segment_free(w[0], w[1])));
//! let again = rrt.plan(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(42))?;
//! assert_eq!(plan.path, again.path);
//! let connect = RrtConnect { step: 1.5, ..RrtConnect::default() };
//! assert!(connect.plan(&map, &query, &mut rng).is_ok());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Features
//!
//! None.
//!
//! # The core types and `rand`
//!
//! The planners take and return `hyplan-core`'s types, re-exported here so one dependency
//! is enough: [`Workspace`], [`Query`], [`Goal`], [`Plan`], [`PlanError`], [`Budget`],
//! [`Point2`], [`Bounds`], [`Planner`], [`PlannerInfo`], [`Progress`], [`Tree`]. The RNG argument is any [`rand::Rng`] of `rand` 0.9
//! (re-exported as [`rand`]); `rand_chacha`'s `ChaCha8Rng` 0.9 is what hyplan itself uses.

mod bi_rrt;
mod common;
mod kdtree;
mod macros;
mod nearest;
mod rrt;
mod rrt_connect;
mod rrt_star;
mod run;
pub mod toolkit;
mod tree;

pub use hyplan_core::{
    Bounds, Budget, Goal, Plan, PlanError, Planner, PlannerInfo, Point2, Progress, Query, Tree,
    Workspace,
};
pub use rand;

pub use bi_rrt::BiRrt;
pub use nearest::NearestIndex;
pub use rrt::Rrt;
pub use rrt_connect::RrtConnect;
pub use rrt_star::{RewireRadius, RrtStar};
pub use run::{OBSERVE_EVERY, Run, Search};
pub use toolkit::{
    CountingChecker, branch, check_connected, plan_of_path, require_connected, sample_accepted,
    sample_goal_biased, sample_uniform, steer, validate_step_and_budget,
};
pub use tree::{Extension, GrowTree, Step};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
