//! hyplan's planner registry: every planner's name, one-line help, parameters and
//! capabilities, and [`PlannerConfig`], its typed configuration.
//!
//! One enum, [`PlannerConfig`], has a variant per planner struct of the workspace; its
//! serde form is the variant holding the struct's fields, so a scenario file says
//! `Rrt(step: 2.0, budget: (max_iterations: 3000))` (RON with [`ron_options`]) and a
//! missing field keeps the planner's default. The command line names the same variant in
//! kebab case (`rrt-astar-bt`) and sets fields as `key=value` pairs. Everything else is
//! derived from it: [`PlannerKind`] (the names, typed), the help lines, the parameters
//! (names, types and defaults read from the structs' serde form) and [`Capabilities`].
//! The command line's help, `hyplan planners`, the harness, xtask and the Python bindings
//! read this crate and keep no list of their own.
//!
//! The crate is light on purpose: the planner crates, serde, RON and strum, nothing that
//! draws or spreads work over threads.
//!
//! # Contents
//!
//! - [`PlannerConfig`]: a planner and its parameters; [`PlannerConfig::by_name`],
//!   `"rrt:step=2".parse()` ([`PlannerConfig::from_spec`]), [`PlannerConfig::build`],
//!   [`PlannerConfig::budget_on`], [`PlannerConfig::with_limits`].
//! - [`PlannerKind`]: a planner's name alone, typed.
//! - [`Param`]: one parameter's name, type, default and doc
//!   ([`PlannerConfig::parameters`]).
//! - [`Capabilities`], [`Family`], [`Explored`]: what a planner can do and needs.
//! - [`ron_options`]: the RON dialect of scenario files.
//! - [`RegistryError`]: an unknown name, a bad `key=value` pair.
//!
//! ```
//! use registry::{PlannerConfig, PlannerKind};
//! for kind in PlannerKind::all() {
//!     let c = PlannerConfig::from(kind);
//!     assert_eq!(c.name(), kind.name());
//!     assert!(!c.help().is_empty());
//! }
//! ```

mod capabilities;
mod config;
mod error;
mod params;
mod spec;
mod types;

pub use capabilities::{Capabilities, Explored, Family};
pub use config::{PlannerConfig, PlannerKind};
pub use error::RegistryError;
pub use params::Param;
pub use spec::ron_options;

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
