//! What planners return.

use std::time::Duration;

use crate::Point2;

/// Counters of one planning call.
///
/// Fields a planner does not use stay zero.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PlanStats {
    /// Main-loop iterations (samples drawn by sampling planners).
    pub iterations: u64,
    /// Nodes in the tree(s) or graph vertices created.
    pub nodes: u64,
    /// Calls of `is_free` and `segment_free`.
    pub collision_checks: u64,
    /// Nodes expanded by a graph search (popped from the open list and not stale).
    pub expansions: u64,
    /// Entries pushed on a graph search's open list.
    pub pushes: u64,
    /// Wall-clock time of the call.
    pub elapsed: Duration,
}

/// A search tree as plain data: points and, for each point, the index of its parent.
///
/// Roots have `parent[i] == None`. Plots draw one segment per non-root node.
#[derive(Debug, Clone, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Tree {
    /// Node positions, world units.
    pub points: Vec<Point2>,
    /// Parent index of each node (`None` for a root).
    pub parent: Vec<Option<u32>>,
}

impl Tree {
    /// Number of nodes.
    #[must_use]
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether the tree has no node.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The edges `(parent point, child point)` of the tree.
    pub fn edges(&self) -> impl Iterator<Item = (Point2, Point2)> + '_ {
        self.parent
            .iter()
            .zip(&self.points)
            .filter_map(|(p, &c)| p.map(|p| (self.points[p as usize], c)))
    }
}

/// A successful plan: a polyline from the start to the goal region, with its cost.
///
/// `path[0]` is the query's start, bit for bit; the last point lies in the goal region.
#[derive(Debug, Clone, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Plan {
    /// Waypoints, world units.
    pub path: Vec<Point2>,
    /// The planner's cost of the path (its length unless the planner adds other terms).
    pub cost: f64,
    /// The search tree(s), for plots and hybrids; empty for graph searches.
    pub trees: Vec<Tree>,
    /// When `path` is a dense sampling of a smooth curve, the nodes the curve is built on
    /// (after node reduction): what papers count as the path's nodes, segments and turns.
    /// Empty when `path` is itself the planner's polyline.
    pub waypoints: Vec<Point2>,
    /// Counters of the call.
    pub stats: PlanStats,
}

impl Plan {
    /// The polyline of the plan's nodes: [`waypoints`](Plan::waypoints) when the planner
    /// returned a dense curve, else [`path`](Plan::path).
    #[must_use]
    pub fn nodes(&self) -> &[Point2] {
        if self.waypoints.is_empty() {
            &self.path
        } else {
            &self.waypoints
        }
    }

    /// Euclidean length of the path, world units.
    #[must_use]
    pub fn length(&self) -> f64 {
        crate::path_length(&self.path)
    }
}

/// A snapshot handed to progress observers during long runs.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Progress {
    /// Iterations done so far.
    pub iterations: u64,
    /// Nodes created so far.
    pub nodes: u64,
    /// Cost of the best path found so far, if any.
    pub best_cost: Option<f64>,
}
