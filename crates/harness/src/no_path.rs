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
    /// The planner's message.
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
            message: e.to_string(),
        }
    }
}
