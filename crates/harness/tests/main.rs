//! Public-API tests of `harness`: scenario validation and Monte-Carlo runs.

mod budgets;
mod runs;
mod scenarios;
