//! Public-API tests of `harness`: scenario validation and Monte-Carlo runs.

mod budgets;
mod ompl_log;
mod runs;
mod scenarios;
