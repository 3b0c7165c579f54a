//! Seed 004's exploration phase (section II, Algorithms 1-2): RRT frontier detectors grow
//! on the map being built, a filter clusters what they publish, an assigner sends the
//! robot to the best frontier, until no frontier is left; and the classic nearest-frontier
//! method beside them as the baseline.
//!
//! The public reference is the ROS package `rrt_exploration` (global and local detectors,
//! `filter.py`, `assigner.py`). Where the paper is silent we follow it; every choice is
//! written where it is made, and collected in `docs/papers/004-exploration.md`.
//!
//! # Contents
//!
//! - [`detector`]: [`Region`] (the 5-point rule), [`edge_check`] (three-valued exact cell
//!   walk), [`GlobalRrtDetector`] (Algorithm 2), [`LocalRrtDetector`] (Algorithm 1).
//! - [`filter`]: [`mean_shift`], [`information_gain`], [`Filter`].
//! - [`assigner`]: [`revenue`], [`Assigner`]: best revenue, hysteresis, blacklist.
//! - [`frontier`]: [`frontier_cells`], [`frontier_clusters`], [`nearest_frontier`]: the
//!   baseline.
//! - [`explore()`]: the exploration loop, [`Exploration`] (parameters), [`Strategy`],
//!   [`ExploreOutcome`], [`Coverage`].
//! - [`figure`]: the map with track, trees and frontiers as SVG.
//! - [`viewpoint`]: [`ViewPoints`], [`sees`]: where to stand to see a frontier.
//! - [`selfmap`]: [`explore_then_navigate`]: a navigation scenario on the map the robot
//!   built itself.
//!
//! # Units
//!
//! Metres and seconds. The growth rate eta is a length in metres (the reference's unit;
//! the paper does not state its own, see the docs page).

pub mod assigner;
pub mod detector;
mod explorer;
pub mod figure;
pub mod filter;
pub mod frontier;
mod params;
mod run;
pub mod selfmap;
pub mod viewpoint;

pub use assigner::{Assigner, revenue};
pub use detector::{Edge, GlobalRrtDetector, LocalRrtDetector, Region, RegionError, edge_check};
pub use explorer::{GLOBAL_STREAM, LOCAL_STREAM};
pub use filter::{Filter, information_gain, mean_shift};
pub use frontier::{frontier_cells, frontier_clusters, nearest_frontier};
pub use params::{Exploration, Strategy};
pub use run::{
    ContactCounter, Coverage, CoverageMeter, ExploreOutcome, FrameRecorder, GoalEnd, GoalRecord,
    Snapshot, TrackRecorder, explore, explore_with, reachable_free, region_of,
};
pub use selfmap::{SelfMapped, explore_then_navigate};
pub use viewpoint::{ViewPoints, sees};
