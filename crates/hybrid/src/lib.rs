//! The seed papers' hybrid planners: RRT-A*-BT, RRT + A* refinement, Hybrid RRT-A* and
//! safety-cost RRT*; and GA-PCHIP, the baseline seed 000 compares with.
//!
//! Each planner is a documented reading of its paper (the readings, with what the text
//! says, what is ambiguous and what we chose, are in `docs/papers/`), a plain parameter
//! struct whose [`Default`] holds the paper's values, with one entry point
//! `plan(&self, workspace, query, rng)` and an implementation of
//! [`Planner`](hyplan_core::Planner) for `Box<dyn Planner>`.
//!
//! # Contents
//!
//! | planner | name | seed | needs | avoids |
//! |---|---|---|---|---|
//! | [`RrtAstarBt`] | `rrt-astar-bt` | `000_9b224721fe327833.txt`, 4.2-4.6 | any workspace | what `segment_free` rejects: pass a safe map (`GridMap::avoiding_risk`) |
//! | [`RrtAstarRefine`] | `rrt-astar-refine` | `001_7c0427b868de6fdd.txt`, 2.3 | an `envmap::GridMap` | the map's blocked cells |
//! | [`HybridRrtAstar`] | `hybrid-rrt-astar` | `002_6cddcbbe62b23f10.txt`, III, Fig. 2 | an `envmap::GridMap` | the map's blocked cells |
//! | [`SafeRrtStar`] | `safe-rrt-star` | `003_19d461d9f3ced1b0.txt`, 2.2-2.3 | any workspace (exact zones on a `GridMap`) | Forbidden; pays for Risk, read through `Workspace::zone` |
//! | [`GaPchip`] | `ga-pchip` | seed 000's baseline, its reference \[4\] (Bakdi et al. 2017) | any workspace | what `segment_free` rejects: pass a safe map |
//!
//! - [`Staged`]: a plan with each stage's path (raw, reduced, smoothed) and counters,
//!   from each planner's `plan_detailed`.
//!
//! Planners that run grid A* find the grid through
//! [`Workspace::as_any`](hyplan_core::Workspace::as_any) and return
//! [`PlanError::InvalidParameter`](hyplan_core::PlanError::InvalidParameter) named
//! `workspace` on any other workspace.
//!
//! # Guarantees
//!
//! - Every segment of a returned path passed the workspace's exact `segment_free` (curves
//!   are returned as dense samples, each pair checked).
//! - `path[0]` is the query's start bit for bit; the last point is the goal centre or lies
//!   in the goal region.
//! - The only randomness is the RNG passed in: the same seed gives the same plan, bit for
//!   bit, with an iteration budget.
//! - Bad parameters or queries are typed errors; failures keep their statistics.
//!
//! # Conventions
//!
//! World coordinates, x right and y up, in the workspace's units; every length parameter
//! is in those units. Grid maps have their origin at the lower-left corner of cell (0, 0).
//!
//! # Example
//!
//! ```
//! use envmap::GridMap;
//! use hybrid::{HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
//! use hyplan_core::{Goal, Planner, Point2, Query, Workspace};
//! use rand::SeedableRng;
//!
//! let map = GridMap::from_ascii("
//!     ..............................
//!     ..............................
//!     ..........~~~~~...............
//!     ..........~###~...............
//!     ..........~###~...............
//!     ..........~~~~~...............
//!     ..............................
//!     ..............................
//! ")?;
//! let query = Query::new(Point2::new(1.5, 4.5), Goal::Point(Point2::new(28.5, 4.5)));
//! let planners: Vec<Box<dyn Planner>> = vec![
//!     Box::new(RrtAstarBt { step: 3.0, goal_radius: 1.5, closed_radius: Some(0.75), ..Default::default() }),
//!     Box::new(RrtAstarRefine { step: 2.0, near_radius: 2.0, ..Default::default() }),
//!     Box::new(HybridRrtAstar::default()),
//!     Box::new(SafeRrtStar { step: 2.0, ..Default::default() }),
//! ];
//! for planner in &planners {
//!     let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
//!     let plan = planner.plan(&map, &query, &mut rng)?;
//!     assert_eq!(plan.path[0], query.start);
//!     assert!(plan.path.windows(2).all(|w| map.segment_free(w[0], w[1])));
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Features
//!
//! None.

mod common;
pub mod ga_pchip;
mod hybrid_rrt_astar;
mod outcome;
mod rrt_astar_bt;
mod rrt_astar_refine;
mod safe_rrt_star;
mod smooth;

pub use ga_pchip::GaPchip;
pub use hybrid_rrt_astar::{HybridRrtAstar, SpacingRule};
pub use outcome::Staged;
pub use rrt_astar_bt::RrtAstarBt;
pub use rrt_astar_refine::RrtAstarRefine;
pub use safe_rrt_star::SafeRrtStar;

/// The four hybrids with a common `step` and `budget`, as `hyplan plan --step STEP
/// --goal-radius GOAL_RADIUS` builds them (the goal region is a parameter of RRT-A*-BT
/// and safety-cost RRT* only), every other parameter at its default: the line-up of the
/// hard-map suite (issue 13), its test and its benchmark.
#[must_use]
pub fn four_hybrids(
    step: f64,
    goal_radius: f64,
    budget: hyplan_core::Budget,
) -> Vec<Box<dyn hyplan_core::Planner>> {
    vec![
        Box::new(RrtAstarBt {
            step,
            goal_radius,
            budget,
            ..RrtAstarBt::default()
        }),
        Box::new(RrtAstarRefine {
            step,
            budget,
            ..RrtAstarRefine::default()
        }),
        Box::new(HybridRrtAstar {
            step,
            budget,
            ..HybridRrtAstar::default()
        }),
        Box::new(SafeRrtStar {
            step,
            goal_radius,
            budget,
            ..SafeRrtStar::default()
        }),
    ]
}

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
