//! Public-API tests of `search`, one binary.

mod common;
mod generic;
mod grid;
mod movingai;
mod planners;
mod props;
