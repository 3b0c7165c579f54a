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
///
/// With the `serde` feature a budget reads and writes as `(max_iterations: N,
/// time_limit_s: Some(S))`, the time in seconds; a missing field keeps its default.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct Budget {
    /// Maximum number of iterations (planner-specific: samples drawn, nodes expanded).
    pub max_iterations: u64,
    /// Optional wall-clock limit.
    #[cfg_attr(feature = "serde", serde(rename = "time_limit_s", with = "seconds"))]
    pub max_time: Option<Duration>,
}

/// A time limit as seconds (`f64`), so scenario files say `time_limit_s: Some(0.5)`.
#[cfg(feature = "serde")]
mod seconds {
    use std::time::Duration;

    use serde::{Deserialize, Deserializer, Serializer, de::Error};

    #[allow(clippy::ref_option)] // serde's `with` hands the field by reference
    pub fn serialize<S: Serializer>(t: &Option<Duration>, s: S) -> Result<S::Ok, S::Error> {
        match t {
            Some(t) => s.serialize_some(&t.as_secs_f64()),
            None => s.serialize_none(),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Duration>, D::Error> {
        match Option::<f64>::deserialize(d)? {
            None => Ok(None),
            Some(s) => Duration::try_from_secs_f64(s).map(Some).map_err(|_| {
                D::Error::custom(format!("time_limit_s = {s}: must be finite and >= 0"))
            }),
        }
    }
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

    /// The budget of a command line's `--max-iter` / `--time-limit` (and the Python
    /// bindings' `max_iter` / `time_limit`): the iteration cap given, else unlimited
    /// iterations under a time limit, else 100 000 iterations.
    ///
    /// ```
    /// use std::time::Duration;
    /// use hyplan_core::Budget;
    /// assert_eq!(Budget::of_limits(None, None), Budget::iterations(100_000));
    /// let t = Duration::from_millis(50);
    /// assert_eq!(Budget::of_limits(None, Some(t)), Budget::iterations(u64::MAX).with_time(t));
    /// assert_eq!(Budget::of_limits(Some(7), Some(t)), Budget::iterations(7).with_time(t));
    /// ```
    #[must_use]
    pub fn of_limits(max_iterations: Option<u64>, time_limit: Option<Duration>) -> Self {
        let cap = max_iterations.unwrap_or(if time_limit.is_some() {
            u64::MAX
        } else {
            100_000
        });
        let budget = Self::iterations(cap);
        match time_limit {
            Some(t) => budget.with_time(t),
            None => budget,
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
