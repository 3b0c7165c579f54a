//! Public-API tests of `sampling`, one binary.

mod fixtures;
mod nearest;
mod planners;
mod random_map;
