//! Public-API tests of envmap, one binary.

mod data;
mod errors;
mod pipeline;
mod properties;
mod ros_round_trip;
