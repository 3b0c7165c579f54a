//! Graph search for hyplan: generic A*, Dijkstra and back-tracking over graphs given as
//! closures, and fast flat-array grid searches on [`envmap::GridMap`].
//!
//! # Contents
//!
//! Generic, over any graph given as closures (`successors(n) -> (node, f64 cost)`,
//! `heuristic(n) -> f64`, `success(n) -> bool`), with plain `f64` costs:
//!
//! - [`astar`]: optimal with an admissible heuristic; ties go to the larger g.
//! - [`dijkstra`]: optimal, no heuristic.
//! - [`backtrack`]: depth-first with undo, children best-first by `f = g + h`, dead ends
//!   remembered, bounded by [`BacktrackLimits`] (seed 000's "BT"); not optimal.
//! - [`SearchResult`], [`SearchStats`], [`NotFound`]: what they return.
//!
//! On grid maps, with scratch memory reused across queries ([`GridSearch`], 14 bytes per
//! cell):
//!
//! - [`GridSearch::astar`], [`GridSearch::dijkstra`]: 4/8-connected, octile costs, corner
//!   cutting off by default ([`GridOptions`], [`Connectivity`]).
//! - [`GridSearch::cost_to_go`]: one-to-all Dijkstra, a [`CostField`] for navigation.
//! - [`GridSearch::theta_star`], [`GridSearch::lazy_theta_star`]: any-angle Theta*, eager
//!   and lazy.
//! - [`JumpPointSearch`]: jump point search, A*'s optimal costs on 8-connected grids
//!   without corner cutting, expanding only jump points, with straight jumps scanned 64
//!   cells at a time over packed bit rows (prepared once per map); [`JpsError`] when the
//!   move rules rule it out.
//! - [`GridAstar`], [`GridDijkstra`], [`ThetaStar`], [`LazyThetaStar`], [`Jps`]: the same as
//!   [`hyplan_core::Planner`]s on world points.
//!
//! MovingAI benchmark files: [`read_scen`], [`parse_scen`], [`ScenEntry`], [`ScenError`].
//!
//! # Conventions
//!
//! - Grid cells are `(i, j)`: column, row **from the bottom** (y up), as everywhere in
//!   hyplan. MovingAI files count rows from the top: [`ScenEntry::to_cell`] converts.
//! - Grid costs are in cells: 1 per straight move, sqrt 2 per diagonal (octile). With corner
//!   cutting off (the default, MovingAI's rule), a diagonal move needs both orthogonal
//!   neighbours free, so the segment between the two cell centres touches no blocked cell.
//! - Which zones block is the map's [`GridMap::blocked_from`](envmap::GridMap::blocked_from).
//! - Planners work in world units: paths start at the query's start point, pass through cell
//!   centres and end at the goal.
//!
//! # Example
//!
//! ```
//! use envmap::GridMap;
//! use search::{GridOptions, GridSearch};
//! let map = GridMap::from_ascii("
//!     .....
//!     .###.
//!     .#...
//!     .....
//! ")?;
//! let mut search = GridSearch::new(&map, GridOptions::default())?;
//! let path = search.astar((0, 3), (2, 1))?; // top-left to the pocket
//! assert_eq!(path.cells.last(), Some(&(2, 1)));
//! assert_eq!(path.cost, 6.0); // down the left side, round the corner without cutting it
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Features
//!
//! - `grid` (default): the grid searches on [`envmap::GridMap`] and their planners. Without
//!   it, `search` is the generic algorithms and the `.scen` reader alone, and builds no map
//!   or image crate (`cargo tree -p search --no-default-features`).
//!
//! # The core types
//!
//! The planners take and return `hyplan-core`'s types, re-exported here so one dependency
//! is enough: [`Workspace`], [`Query`], [`Goal`], [`Plan`], [`PlanError`], [`Budget`],
//! [`Point2`], [`Planner`]. Randomness is not used by `search`.

mod astar;
mod backtrack;
mod dijkstra;
#[cfg(feature = "grid")]
mod grid;
mod heap;
mod movingai;
#[cfg(feature = "grid")]
mod planners;
mod result;

pub use hyplan_core::{Budget, Goal, Plan, PlanError, Planner, Point2, Query, Workspace};

pub use astar::astar;
pub use backtrack::{BacktrackLimits, backtrack};
pub use dijkstra::dijkstra;
#[cfg(feature = "grid")]
pub use grid::{
    Connectivity, CostField, GridOptions, GridPath, GridSearch, GridSearchError, JpsError,
    JumpPointSearch,
};
pub use movingai::{ScenEntry, ScenError, parse_scen, read_scen};
#[cfg(feature = "grid")]
pub use planners::{GridAstar, GridDijkstra, Jps, LazyThetaStar, ThetaStar};
pub use result::{NotFound, SearchResult, SearchStats};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
