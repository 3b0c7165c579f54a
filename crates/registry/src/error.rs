//! [`RegistryError`]: a planner configuration that cannot be read.

/// A planner configuration that cannot be read.
///
/// ```
/// let e = "nope".parse::<registry::PlannerConfig>().unwrap_err();
/// assert!(matches!(e, registry::RegistryError::UnknownPlanner { .. }));
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RegistryError {
    /// No planner has this name.
    #[error("unknown planner `{name}` (known: {known})")]
    UnknownPlanner {
        /// The name given.
        name: String,
        /// The known names, comma-separated.
        known: String,
    },
    /// A `NAME:key=value,...` text or a parameter that does not fit the planner.
    #[error("planner `{spec}`: {reason}")]
    BadParameter {
        /// The text given.
        spec: String,
        /// What is wrong, naming the key and the value.
        reason: String,
    },
}
