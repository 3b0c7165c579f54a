//! Criterion benches of hyplan's hot paths live in this package's `benches/` folder; the
//! library holds the workloads they share with the examples.

pub mod crowd;
pub mod grid;

/// A map of the repository (`path` from the workspace root) read as the OMPL peer of
/// `cargo xtask bench-peers` reads it: gray below 128 is an obstacle, no safety band.
///
/// # Panics
///
/// When the map cannot be read (a bench's workload is the repository's own file).
///
/// ```
/// let loaded = hyplan_benches::load_as_peer("data/generated/rects100.pgm");
/// assert_eq!(loaded.map.width(), 100);
/// ```
#[must_use]
pub fn load_as_peer(path: &str) -> envmap::LoadedMap {
    let path = format!("{}/../{path}", env!("CARGO_MANIFEST_DIR"));
    let opts = envmap::LoadOptions {
        threshold: 128,
        safety_radius: Some(0.0),
        ..envmap::LoadOptions::default()
    };
    envmap::load_map(path.as_ref(), &opts).unwrap_or_else(|e| panic!("{path}: {e}"))
}
