//! Iteration and time budgets.

use std::time::{Duration, Instant};

/// How long a planner may run: an iteration cap and an optional wall-clock cap.
///
/// Only the iteration cap is deterministic: two runs with the same seed stop at the same
/// iteration whatever the machine is doing. Reproduction scenarios therefore use iterations,
/// and a time limit is a safety net for interactive use.
///
/// ```
/// use hyplan_core::Budget;
/// use std::time::Duration;
/// let b = Budget::iterations(10_000).with_time(Duration::from_millis(50));
/// assert_eq!(b.max_iterations, 10_000);
/// assert!(b.validate().is_ok());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Budget {
    /// Maximum number of iterations (planner-specific: samples drawn, nodes expanded).
    pub max_iterations: u64,
    /// Optional wall-clock limit.
    pub max_time: Option<Duration>,
}

impl Default for Budget {
    /// 10 000 iterations and no time limit (seed 000's RRT-A*-BT budget).
    fn default() -> Self {
        Self::iterations(10_000)
    }
}

impl Budget {
    /// A budget of `n` iterations, no time limit.
    #[must_use]
    pub const fn iterations(n: u64) -> Self {
        Self {
            max_iterations: n,
            max_time: None,
        }
    }

    /// The same budget with a wall-clock limit added.
    #[must_use]
    pub const fn with_time(self, limit: Duration) -> Self {
        Self {
            max_time: Some(limit),
            ..self
        }
    }

    /// Whether the budget is spent after `iterations` iterations begun at `started`.
    ///
    /// The clock is read only when a time limit is set.
    #[must_use]
    pub fn exhausted(&self, iterations: u64, started: Instant) -> bool {
        iterations >= self.max_iterations
            || self
                .max_time
                .is_some_and(|limit| started.elapsed() >= limit)
    }

    /// Checks that the budget allows at least one iteration and a non-zero time.
    ///
    /// # Errors
    ///
    /// [`crate::PlanError::InvalidParameter`] naming `budget.max_iterations` or
    /// `budget.max_time` when either is zero.
    pub fn validate(&self) -> Result<(), crate::PlanError> {
        if self.max_iterations == 0 {
            return Err(crate::PlanError::InvalidParameter {
                name: "budget.max_iterations",
                value: "0".into(),
                reason: "must be at least 1",
            });
        }
        if self.max_time.is_some_and(|t| t.is_zero()) {
            return Err(crate::PlanError::InvalidParameter {
                name: "budget.max_time",
                value: "0 s".into(),
                reason: "must be positive",
            });
        }
        Ok(())
    }
}
