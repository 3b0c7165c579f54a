//! Public-API tests of `search`, one binary.

mod common;
mod generic;
mod grid;
mod jps;
mod movingai;
mod planners;
mod props;
