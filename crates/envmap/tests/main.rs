//! Public-API tests of envmap, one binary.

#[cfg(feature = "image")]
mod data;
mod errors;
#[cfg(feature = "image")]
mod limits;
mod connectivity;
mod pipeline;
mod properties;
#[cfg(feature = "image")]
mod ros_round_trip;
