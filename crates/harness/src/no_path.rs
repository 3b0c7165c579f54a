//! Why a plan ended without a path, as the CLI's JSON and the Python bindings report it.

use hyplan_core::{NoPathCause, PlanError};
use serde::Serialize;

/// Why a run found no path: `hyplan plan --json`'s `no_path` and the Python bindings'
/// `NoPathError.result`.
#[derive(Debug, Clone, Serialize)]
pub struct NoPathRecord {
    /// `disconnected` (proved before planning: start and goal not connected in the zones
    /// the planner may use), `exhausted` (a complete search ran out of nodes), `budget`
    /// (iterations or time ran out) or `invalid` (the query or a parameter was refused).
    pub kind: &'static str,
    /// For `disconnected`: `wall` (obstacles separate start and goal) or `risk-band` (the
    /// high-risk band closes every passage).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cause: Option<&'static str>,
    /// For `risk-band`: the band's radius on the map, in the input's units.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub band_radius: Option<f64>,
    /// For `risk-band`: every safety radius strictly below this (input units) leaves a
    /// passage in the safe zone (the widest path's bottleneck).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_safety_radius: Option<f64>,
    /// For `budget`: the iteration cap the run had (absent when unlimited).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_iterations: Option<u64>,
    /// For `budget`: the time limit the run had, seconds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_limit_s: Option<f64>,
    /// The planner's message; for `budget`, with the budget used and how to raise it.
    pub message: String,
}

impl NoPathRecord {
    /// The record of a "no path" error; lengths divided by `scale` (world units per input
    /// unit).
    #[must_use]
    pub fn new(e: &PlanError, scale: f64) -> Self {
        let (kind, cause, band, max) = match e {
            PlanError::Disconnected { cause, .. } => match cause {
                NoPathCause::RiskBand {
                    band_radius,
                    max_radius,
                } => (
                    "disconnected",
                    Some("risk-band"),
                    Some(band_radius / scale),
                    Some(max_radius / scale),
                ),
                _ => ("disconnected", Some("wall"), None, None),
            },
            PlanError::NoPath { .. } => ("exhausted", None, None, None),
            PlanError::BudgetExhausted { .. } => ("budget", None, None, None),
            // Not a search outcome: the query or a parameter was refused.
            _ => ("invalid", None, None, None),
        };
        Self {
            kind,
            cause,
            band_radius: band,
            max_safety_radius: max,
            max_iterations: None,
            time_limit_s: None,
            message: e.to_string(),
        }
    }

    /// For a `budget` record: names the budget the run had (`budget`, as
    /// [`PlannerConfig::budget_on`](crate::PlannerConfig::budget_on) gives it) and how the
    /// caller raises it (`raise`, e.g. "--max-iter N or --time-limit S"); other records are
    /// returned unchanged.
    ///
    /// ```
    /// use hyplan_core::{Budget, PlanError, PlanStats};
    /// let e = PlanError::BudgetExhausted { stats: PlanStats::default() };
    /// let r = harness::NoPathRecord::new(&e, 1.0)
    ///     .with_budget(Some(Budget::iterations(100_000)), "--max-iter N");
    /// assert_eq!(r.max_iterations, Some(100_000));
    /// assert!(r.message.contains("100000 iterations") && r.message.contains("--max-iter N"));
    /// ```
    #[must_use]
    pub fn with_budget(mut self, budget: Option<hyplan_core::Budget>, raise: &str) -> Self {
        let Some(b) = budget.filter(|_| self.kind == "budget") else {
            return self;
        };
        self.max_iterations = b.max_iterations.filter(|&n| n != u64::MAX);
        self.time_limit_s = b.max_time.map(|t| t.as_secs_f64());
        let mut limits = Vec::new();
        if let Some(n) = self.max_iterations {
            limits.push(format!("{n} iterations"));
        }
        if let Some(t) = self.time_limit_s {
            limits.push(format!("{t} s"));
        }
        self.message = format!(
            "{}; the budget was {}: raise it with {raise}",
            self.message,
            if limits.is_empty() {
                "unlimited".to_string()
            } else {
                limits.join(" and ")
            }
        );
        self
    }
}
