//! Parameter checks shared by every planner: one rule per kind of value, one message.
//!
//! ```
//! use hyplan_core::check;
//! assert!(check::positive("step", 0.5).is_ok());
//! assert!(check::probability("goal_bias", 1.5).is_err());
//! ```

use crate::PlanError;

/// Checks that a length parameter `name` is finite and > 0.
///
/// # Errors
///
/// [`PlanError::InvalidParameter`] named `name` otherwise.
pub fn positive(name: &'static str, value: f64) -> Result<(), PlanError> {
    require(
        value.is_finite() && value > 0.0,
        name,
        value,
        "must be finite and > 0 (world units)",
    )
}

/// Checks that `name` is finite and >= 0.
///
/// # Errors
///
/// [`PlanError::InvalidParameter`] named `name` otherwise.
pub fn non_negative(name: &'static str, value: f64) -> Result<(), PlanError> {
    require(
        value.is_finite() && value >= 0.0,
        name,
        value,
        "must be finite and >= 0",
    )
}

/// Checks that `name` (a goal bias, say) is a probability in [0, 1].
///
/// # Errors
///
/// [`PlanError::InvalidParameter`] named `name` otherwise (NaN included).
pub fn probability(name: &'static str, value: f64) -> Result<(), PlanError> {
    require(
        (0.0..=1.0).contains(&value),
        name,
        value,
        "must be a probability in [0, 1]",
    )
}

/// Checks a count >= 1.
///
/// # Errors
///
/// [`PlanError::InvalidParameter`] named `name` otherwise.
pub fn count(name: &'static str, value: usize) -> Result<(), PlanError> {
    require(value >= 1, name, value, "must be at least 1")
}

/// `Ok` when `ok`, else the one error every check gives: `name`, the value as written, and
/// the rule it broke.
fn require(
    ok: bool,
    name: &'static str,
    value: impl std::fmt::Display,
    reason: &'static str,
) -> Result<(), PlanError> {
    if ok {
        Ok(())
    } else {
        Err(PlanError::InvalidParameter {
            name,
            value: value.to_string(),
            reason,
        })
    }
}
