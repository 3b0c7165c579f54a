//! The shared vocabulary of hyplan.
//!
//! Every other crate of the workspace speaks these types, and nothing else is needed to plug
//! a world or a planner of your own into hyplan. The crate is deliberately tiny (nalgebra,
//! `rand_core` and `thiserror` only) so that a user who brings their own world never builds
//! image decoding or plotting.
//!
//! # Contents
//!
//! - [`Point2`]: a point in world units.
//! - [`Bounds`]: the axis-aligned box a workspace lives in.
//! - [`Zone`]: the three zones of a safe map (safe, high-risk, forbidden).
//! - [`Workspace`]: the queries a planner asks of the world (`is_free`, `segment_free`,
//!   `clearance`, `zone`, `sample_free`, `disconnection`).
//! - [`Query`] and [`Goal`]: start point and goal point or goal disc.
//! - [`Plan`], [`Tree`] and [`PlanStats`]: what a planner returns.
//! - [`PlanError`]: typed failures, including "no path" with the statistics of the attempt;
//!   [`NoPathCause`]: what separates start and goal when a connectivity check proves it.
//! - [`Budget`]: iteration and time limits; [`check`]: the parameter checks every planner
//!   uses (positive, non-negative, probability, count).
//! - [`Planner`] and [`PlannerInfo`]: the object-safe trait the harness holds as
//!   `Box<dyn Planner>`.
//! - [`path_length`]: the length of a polyline.
//!
//! # Conventions
//!
//! All coordinates are world coordinates (metres, millimetres or cells: whatever the map's
//! resolution says), with x to the right and y up. Grid maps place their origin at the
//! lower-left corner of cell (0, 0), as ROS does.
//!
//! # Example
//!
//! ```
//! use hyplan_core::{Bounds, Goal, Point2, Query, Workspace, Zone};
//!
//! /// An empty 10 x 10 square with a wall x in [4, 5].
//! struct Wall;
//! impl Workspace for Wall {
//!     fn bounds(&self) -> Bounds {
//!         Bounds::new(Point2::new(0.0, 0.0), Point2::new(10.0, 10.0))
//!     }
//!     fn is_free(&self, p: Point2) -> bool {
//!         self.bounds().contains(p) && !(4.0..=5.0).contains(&p.x)
//!     }
//!     fn segment_free(&self, a: Point2, b: Point2) -> bool {
//!         self.is_free(a) && self.is_free(b) && (a.x.max(b.x) < 4.0 || a.x.min(b.x) > 5.0)
//!     }
//! }
//!
//! let query = Query::new(Point2::new(1.0, 1.0), Goal::disc(Point2::new(9.0, 9.0), 0.5));
//! assert!(query.validate(&Wall).is_ok());
//! assert!(!Wall.segment_free(query.start, query.goal.center()));
//! assert_eq!(Wall.zone(Point2::new(4.5, 1.0)), Zone::Forbidden);
//! ```
//!
//! # Features
//!
//! - `serde`: `Serialize`/`Deserialize` for the plain data types (off by default).

mod budget;
pub mod check;
mod error;
mod geometry;
mod grid;
mod plan;
mod planner;
mod query;
mod workspace;

pub use budget::Budget;
pub use error::{NoPathCause, PlanError};
pub use geometry::{Bounds, Point2, path_length};
pub use plan::{Plan, PlanStats, Progress, Tree};
pub use planner::{Planner, PlannerInfo};
pub use query::{Goal, Query};
pub use workspace::{Workspace, Zone, uniform01};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
