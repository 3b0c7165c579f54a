//! Public-API tests of `harness`: scenario validation and Monte-Carlo runs.

mod runs;
mod scenarios;
