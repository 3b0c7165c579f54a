//! Public-API tests of the hybrid planners, as one binary: the conformance suite shared by
//! the four planners, the U-shaped trap of seed 000, and the papers' qualitative claims
//! (with the room of seed 000 that the room example and bench share).

mod claims;
mod conformance;
mod fixtures;
mod hard_maps;
mod room;
mod utrap;
