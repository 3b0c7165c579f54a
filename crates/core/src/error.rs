//! Typed planning errors.

use crate::{PlanStats, Point2};

/// Why a planner returned no plan.
///
/// Bad input (start, goal, parameters) is reported before any work is done. A failed search
/// keeps its [`PlanStats`], so a harness can still record time and nodes for failed runs.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PlanError {
    /// The start is outside the workspace bounds, not finite, or not free.
    #[error("invalid start ({}, {}): {reason}", point.x, point.y)]
    InvalidStart {
        /// The start as given.
        point: Point2,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The goal is outside the workspace bounds, not finite, not free, or has a bad radius.
    #[error("invalid goal ({}, {}): {reason}", point.x, point.y)]
    InvalidGoal {
        /// The goal centre as given.
        point: Point2,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A planner parameter is out of its range.
    #[error("invalid parameter {name} = {value}: {reason}")]
    InvalidParameter {
        /// The parameter's name, as in the planner struct (`step`, `goal_bias`, ...).
        name: &'static str,
        /// The value given, formatted.
        value: String,
        /// The allowed range or rule.
        reason: &'static str,
    },
    /// The search proved that no path exists (the reachable graph was exhausted).
    #[error("no path: the reachable space was exhausted after {} expansions", stats.expansions)]
    NoPath {
        /// What the search did before giving up.
        stats: PlanStats,
    },
    /// A check made before planning proved that start and goal are not connected in the
    /// zones the planner may use (a grid map's connectivity), and says why.
    #[error("no path: {cause}")]
    Disconnected {
        /// What separates start and goal.
        cause: NoPathCause,
        /// What the planner did before giving up (the check's time; no search).
        stats: PlanStats,
    },
    /// The iteration or time budget ran out before a path was found.
    #[error("no path within the budget ({} iterations, {:.3} s)", stats.iterations, stats.elapsed.as_secs_f64())]
    BudgetExhausted {
        /// What the planner did before giving up.
        stats: PlanStats,
    },
}

impl PlanError {
    /// The statistics of a failed search, when the failure came after work was done.
    #[must_use]
    pub fn stats(&self) -> Option<&PlanStats> {
        match self {
            Self::NoPath { stats }
            | Self::BudgetExhausted { stats }
            | Self::Disconnected { stats, .. } => Some(stats),
            _ => None,
        }
    }

    /// Why start and goal are not connected, when a connectivity check proved it.
    #[must_use]
    pub fn cause(&self) -> Option<&NoPathCause> {
        match self {
            Self::Disconnected { cause, .. } => Some(cause),
            _ => None,
        }
    }

    /// True for "no path" outcomes (proved or budget), false for bad input.
    #[must_use]
    pub fn is_no_path(&self) -> bool {
        self.stats().is_some()
    }
}

/// What separates start and goal when no path can exist (see [`PlanError::Disconnected`]).
///
/// Distances are world units.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum NoPathCause {
    /// Obstacles (the cells every planner must avoid) wall the goal off from the start: no
    /// planner and no safety radius can join them.
    #[error("an obstacle wall separates start and goal (no safety radius helps)")]
    Wall,
    /// The obstacles leave a passage, but the high-risk band around them closes it for a
    /// planner that must keep out of the band.
    #[error(
        "the risk band of radius {band_radius} closes every passage between start and goal; \
         a safety radius below {max_radius} leaves one open"
    )]
    RiskBand {
        /// The band's width as found on the map: the largest distance from a high-risk cell
        /// centre to the nearest obstacle cell centre.
        band_radius: f64,
        /// The widest path's bottleneck: with any safety radius strictly below this (the
        /// band recomputed from the same obstacles), a path in the safe zone joins start
        /// and goal.
        max_radius: f64,
    },
}
