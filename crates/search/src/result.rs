//! What the searches return.

/// Counters of one search.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SearchStats {
    /// Nodes expanded: taken from the open list (not stale) and their successors generated.
    /// The goal node itself is not counted, as in the `pathfinding` crate's A*.
    pub expansions: u64,
    /// Entries pushed on the open list (the start included); a node whose cost improved
    /// counts again.
    pub pushes: u64,
    /// Distinct nodes reached (pushed at least once), the start included.
    pub reached: u64,
}

/// A path found by a search: the nodes from start to goal (both included) and its cost.
#[derive(Debug, Clone, PartialEq)]
pub struct SearchResult<N> {
    /// Nodes from the start to the goal, both included.
    pub path: Vec<N>,
    /// Sum of the edge costs along `path`.
    pub cost: f64,
    /// Counters of the search.
    pub stats: SearchStats,
}

/// Why a search returned no path; keeps the counters of the attempt.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum NotFound {
    /// Every reachable node was expanded without meeting the goal: no path exists.
    #[error("no path: the reachable graph was exhausted after {} expansions", stats.expansions)]
    Exhausted {
        /// Counters of the search.
        stats: SearchStats,
    },
    /// The search stopped at its expansion budget (back-tracking only).
    #[error("no path within the budget of {} expansions", stats.expansions)]
    BudgetExhausted {
        /// Counters of the search.
        stats: SearchStats,
    },
}

impl NotFound {
    /// The counters of the failed search.
    #[must_use]
    pub const fn stats(&self) -> SearchStats {
        match *self {
            Self::Exhausted { stats } | Self::BudgetExhausted { stats } => stats,
        }
    }
}
