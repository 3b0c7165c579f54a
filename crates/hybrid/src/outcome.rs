//! What the hybrid planners return beyond a [`Plan`]: each stage's path.

use hyplan_core::{Plan, Point2};

/// A plan with the path of every stage of the paper's method, for figures and for the
/// papers' tables (seed 000 counts the nodes of the reduced path, seed 003 draws the raw,
/// pruned and smoothed paths).
///
/// Returned by each planner's `plan_detailed`; `plan` returns [`Staged::plan`] only.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Staged {
    /// The final result: `plan.path` is the path the paper's method returns (dense curve
    /// samples for the smoothing methods), `plan.trees` the search tree.
    pub plan: Plan,
    /// The search's path before any post-processing (tree branch, plus A* cells for
    /// `hybrid-rrt-astar`), world units.
    pub raw: Vec<Point2>,
    /// The path after node reduction, refinement or pruning, before smoothing (equal to
    /// `raw` when the method has no such step), world units.
    pub reduced: Vec<Point2>,
    /// Local repairs the smoothing step made where the first curve collided.
    pub smoothing_repairs: usize,
    /// Whether the smoothing step gave up and the reduced polyline was returned instead.
    pub smoothing_refused: bool,
    /// Grid A* searches run (refinement stretches of seed 001, sub-searches of seed 002).
    pub astar_runs: u32,
    /// Of those, how many gave up (hit their expansion limit or found no path).
    pub astar_failures: u32,
    /// Back-tracking steps taken (`rrt-astar-bt`): nodes added under an earlier node than
    /// the one added just before (the search resumed from an older option).
    pub backtracks: u32,
    /// Times the open list ran dry and the search went on from the tree node nearest to a
    /// fresh sample (`rrt-astar-bt` with back-tracking).
    pub restarts: u32,
}
