//! Seed 004's exploration phase (section II, Algorithms 1-2): RRT frontier detectors grow
//! on the map being built, a filter clusters what they publish, an assigner sends the
//! robot to the best frontier, until no frontier is left; and the classic nearest-frontier
//! method beside them as the baseline.
//!
//! The public reference is the ROS package `rrt_exploration` (global and local detectors,
//! `filter.py`, `assigner.py`). Where the paper is silent we follow it; every choice is
//! written where it is made, and collected in `docs/papers/004-exploration.md`.
//!
//! Its items are re-exported at the crate's root.
//!
//! # Units
//!
//! Metres and seconds. The growth rate eta is a length in metres (the reference's unit;
//! the paper does not state its own, see the docs page).

mod assigner;
mod cost;
mod detector;
mod explorer;
mod figure;
mod filter;
mod frontier;
mod left;
mod params;
mod run;
mod selfmap;
mod viewpoint;

pub use assigner::{Assigner, revenue};
pub use cost::DetectorCost;
pub use detector::{DetectorKind, Edge, Region, RegionError, RrtDetector, edge_check};
pub use explorer::{GLOBAL_STREAM, LOCAL_STREAM};
pub use figure::{animation_png, snapshot_scene, snapshot_svg};
pub use filter::{Filter, built_cost, built_cost_reach, information_gain, mean_shift};
pub use frontier::{
    TravelFlood, costmap_steps, frontier_cells, frontier_clusters, nearest_frontier, travel,
};
pub use left::{LeftCause, LeftRegion, left_by_cause, left_unknown};
pub use params::{AssignerMode, Exploration, FilterPool, RevenueDistance, Strategy};
pub use run::{
    ContactCounter, Coverage, CoverageMeter, ExploreOutcome, FrameRecorder, GoalEnd, GoalRecord,
    MapFrames, Snapshot, TrackRecorder, explore, explore_observed, explore_with, reachable_free,
    region_of,
};
pub use selfmap::{SelfMapped, explore_then_navigate};
pub use viewpoint::{ViewPoints, sees};
