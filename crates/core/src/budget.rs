//! Iteration and time budgets.

use std::time::{Duration, Instant};

/// How long a planner may run: an iteration cap and an optional wall-clock cap.
///
/// Only the iteration cap is deterministic: two runs with the same seed stop at the same
/// iteration whatever the machine is doing. Reproduction scenarios therefore use iterations,
/// and a time limit is a safety net for interactive use.
///
/// An unset cap (`max_iterations: None`, the default) means the planner's own rule: the grid
/// searches run until they find the path or prove there is none ([`Budget::for_search`]);
/// the planners that sample take [`Budget::samples_for`] the map ([`Budget::for_sampling`]),
/// a deterministic number that grows with the map's size.
///
/// ```
/// use hyplan_core::Budget;
/// use std::time::Duration;
/// let b = Budget::iterations(10_000).with_time(Duration::from_millis(50));
/// assert_eq!(b.max_iterations, Some(10_000));
/// assert!(b.validate().is_ok());
/// // Unset: a search runs to the end, a sampler takes the map's rule.
/// assert_eq!(Budget::default().for_search(), Budget::unlimited());
/// assert_eq!(Budget::default().for_sampling(Some(4_000_000)), Budget::iterations(1_000_000));
/// ```
///
/// With the `serde` feature a budget reads and writes as `(max_iterations: N,
/// time_limit_s: Some(S))`, the time in seconds; a missing field keeps its default (unset).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct Budget {
    /// Maximum number of iterations (planner-specific: samples drawn, nodes expanded,
    /// generations); `None`: the planner's default rule ([`Budget::for_search`],
    /// [`Budget::for_sampling`]).
    #[cfg_attr(feature = "serde", serde(with = "iterations"))]
    pub max_iterations: Option<u64>,
    /// Optional wall-clock limit.
    #[cfg_attr(feature = "serde", serde(rename = "time_limit_s", with = "seconds"))]
    pub max_time: Option<Duration>,
}

/// An iteration cap as a bare number (`max_iterations: 3000`) or `None` (the planner's
/// rule); `Some(3000)` reads too.
#[cfg(feature = "serde")]
mod iterations {
    use std::fmt;

    use serde::Serializer;
    use serde::de::{self, Deserializer, Visitor};

    #[allow(clippy::ref_option)] // serde's `with` hands the field by reference
    pub fn serialize<S: Serializer>(n: &Option<u64>, s: S) -> Result<S::Ok, S::Error> {
        match n {
            Some(n) => s.serialize_u64(*n),
            None => s.serialize_none(),
        }
    }

    struct Cap;

    impl<'de> Visitor<'de> for Cap {
        type Value = Option<u64>;

        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str("a number of iterations >= 1, or None for the planner's default rule")
        }

        fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
            Ok(Some(v))
        }

        fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
            u64::try_from(v)
                .map(Some)
                .map_err(|_| E::custom(format!("max_iterations = {v}: must be >= 1")))
        }

        fn visit_none<E: de::Error>(self) -> Result<Self::Value, E> {
            Ok(None)
        }

        fn visit_some<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
            d.deserialize_any(self)
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<u64>, D::Error> {
        d.deserialize_any(Cap)
    }
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

impl Budget {
    /// The least default sample budget of the planners that sample: 100,000 iterations.
    pub const MIN_SAMPLES: u64 = 100_000;

    /// A budget of `n` iterations, no time limit.
    #[must_use]
    pub const fn iterations(n: u64) -> Self {
        Self {
            max_iterations: Some(n),
            max_time: None,
        }
    }

    /// No iteration cap and no time limit: a search runs to its end (a sampler until it
    /// finds a path, or its map's connectivity proves there is none).
    #[must_use]
    pub const fn unlimited() -> Self {
        Self::iterations(u64::MAX)
    }

    /// The same budget with a wall-clock limit added.
    #[must_use]
    pub const fn with_time(self, limit: Duration) -> Self {
        Self {
            max_time: Some(limit),
            ..self
        }
    }

    /// The default sample budget of a planner that samples, on a map of `cells` cells
    /// (`None`: a workspace without cells): one sample per four cells, at least
    /// [`MIN_SAMPLES`](Self::MIN_SAMPLES). Deterministic, so a run stops at the same
    /// iteration on every machine; it grows with the map because the samples a tree needs
    /// to pass a door grow with the area around it.
    ///
    /// ```
    /// use hyplan_core::Budget;
    /// assert_eq!(Budget::samples_for(None), 100_000);
    /// assert_eq!(Budget::samples_for(Some(640 * 480)), 100_000);
    /// assert_eq!(Budget::samples_for(Some(2000 * 2000)), 1_000_000);
    /// ```
    #[must_use]
    pub fn samples_for(cells: Option<usize>) -> u64 {
        let per_map = cells.map_or(0, |c| (c / 4) as u64);
        per_map.max(Self::MIN_SAMPLES)
    }

    /// The budget a complete search runs with: the cap set, else none (`u64::MAX`): it runs
    /// until it finds the path or proves there is none.
    #[must_use]
    pub fn for_search(self) -> Self {
        Self {
            max_iterations: Some(self.max_iterations.unwrap_or(u64::MAX)),
            ..self
        }
    }

    /// The budget a planner that samples runs with on a map of `cells` cells (`None`: a
    /// workspace without cells): the cap set, else [`samples_for`](Self::samples_for) the
    /// map.
    #[must_use]
    pub fn for_sampling(self, cells: Option<usize>) -> Self {
        Self {
            max_iterations: Some(
                self.max_iterations
                    .unwrap_or_else(|| Self::samples_for(cells)),
            ),
            ..self
        }
    }

    /// The budget of a command line's `--max-iter` / `--time-limit` (and the Python
    /// bindings' `max_iter` / `time_limit`) over a planner's own `budget`: an iteration cap
    /// given replaces the planner's; a time limit alone lifts the iteration cap (the clock
    /// decides); neither keeps the planner's budget, so its default rule applies.
    ///
    /// ```
    /// use std::time::Duration;
    /// use hyplan_core::Budget;
    /// let own = Budget::default();
    /// assert_eq!(own.with_limits(None, None), own);
    /// let t = Duration::from_millis(50);
    /// assert_eq!(own.with_limits(None, Some(t)), Budget::unlimited().with_time(t));
    /// assert_eq!(own.with_limits(Some(7), Some(t)), Budget::iterations(7).with_time(t));
    /// ```
    #[must_use]
    pub fn with_limits(self, max_iterations: Option<u64>, time_limit: Option<Duration>) -> Self {
        match (max_iterations, time_limit) {
            (None, None) => self,
            (Some(n), None) => Self {
                max_iterations: Some(n),
                ..self
            },
            (n, Some(t)) => Self::iterations(n.unwrap_or(u64::MAX)).with_time(t),
        }
    }

    /// Whether the budget is spent after `iterations` iterations begun at `started`.
    ///
    /// The clock is read only when a time limit is set. An unset cap counts as
    /// [`MIN_SAMPLES`](Self::MIN_SAMPLES): planners apply their rule first
    /// ([`for_search`](Self::for_search), [`for_sampling`](Self::for_sampling)); this keeps one that does not from running forever.
    #[must_use]
    pub fn exhausted(&self, iterations: u64, started: Instant) -> bool {
        self.iterations_spent(iterations) || self.time_spent(started)
    }

    /// The iteration half of [`exhausted`](Self::exhausted): whether `iterations` reach
    /// the cap (an unset cap counting as [`MIN_SAMPLES`](Self::MIN_SAMPLES)).
    ///
    /// ```
    /// use hyplan_core::Budget;
    /// assert!(Budget::iterations(10).iterations_spent(10));
    /// assert!(!Budget::iterations(10).iterations_spent(9));
    /// ```
    #[must_use]
    pub fn iterations_spent(&self, iterations: u64) -> bool {
        iterations >= self.max_iterations.unwrap_or(Self::MIN_SAMPLES)
    }

    /// The time half of [`exhausted`](Self::exhausted): whether the time limit, if any,
    /// has passed since `started` (the clock is read only when one is set).
    ///
    /// ```
    /// use std::time::{Duration, Instant};
    /// use hyplan_core::Budget;
    /// let long = Budget::iterations(10).with_time(Duration::from_secs(60));
    /// assert!(!long.time_spent(Instant::now()));
    /// assert!(!Budget::iterations(10).time_spent(Instant::now()));
    /// ```
    #[must_use]
    pub fn time_spent(&self, started: Instant) -> bool {
        self.max_time
            .is_some_and(|limit| started.elapsed() >= limit)
    }

    /// Checks that the budget allows at least one iteration and a non-zero time.
    ///
    /// # Errors
    ///
    /// [`crate::PlanError::InvalidParameter`] naming `budget.max_iterations` or
    /// `budget.max_time` when either is zero.
    pub fn validate(&self) -> Result<(), crate::PlanError> {
        if self.max_iterations == Some(0) {
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
