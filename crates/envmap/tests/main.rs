//! Public-API tests of envmap, one binary.

mod connectivity;
#[cfg(feature = "image")]
mod data;
mod errors;
#[cfg(feature = "image")]
mod limits;
mod pipeline;
mod properties;
#[cfg(feature = "image")]
mod ros_round_trip;
