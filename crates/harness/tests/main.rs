//! Public-API tests of `harness`: scenario validation and Monte-Carlo runs.

mod budgets;
#[cfg(feature = "plot")]
mod figure;
mod ompl_log;
mod runs;
mod scenarios;
