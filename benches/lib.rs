//! Criterion benches of hyplan's hot paths live in this package's `benches/` folder; the
//! library holds the workloads they share with the examples.

pub mod crowd;
pub mod grid;
mod peers;

pub use peers::{PEER_CASES, PeerCase, load_as_peer, peer_load_options};
