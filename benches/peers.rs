//! The cases `cargo xtask bench-peers` compares with OMPL 1.5, and the peer's reading of
//! their maps: one table for the xtask and for the examples that time one case alone
//! (`rrt_only`).

use envmap::{InputFrame, LoadOptions};
use hyplan_core::{Goal, Query};

/// One comparison setting: a map, a query in the map's input coordinates (x = column,
/// y = row from the top), the step (OMPL's range), the goal bias and the goal radius (0: an
/// exact point).
#[derive(Debug, Clone, Copy)]
pub struct PeerCase {
    /// The row's name.
    pub name: &'static str,
    /// The map file, from the workspace root.
    pub map: &'static str,
    /// Start, input coordinates.
    pub start: (f64, f64),
    /// Goal centre, input coordinates.
    pub goal: (f64, f64),
    /// Step (OMPL's `--range`).
    pub step: f64,
    /// Goal bias (RRT and RRT\*; OMPL's RRTConnect has none).
    pub goal_bias: f64,
    /// Goal disc radius; 0 for an exact goal point.
    pub goal_radius: f64,
}

impl PeerCase {
    /// A case with OMPL's default goal bias, 0.05.
    const fn new(
        name: &'static str,
        map: &'static str,
        start: (f64, f64),
        goal: (f64, f64),
        step: f64,
        goal_radius: f64,
    ) -> Self {
        Self {
            name,
            map,
            start,
            goal,
            step,
            goal_bias: 0.05,
            goal_radius,
        }
    }

    /// The case's query in world coordinates, for a map read with `frame`.
    ///
    /// ```
    /// let case = &hyplan_benches::PEER_CASES[0];
    /// let loaded = hyplan_benches::load_as_peer(case.map);
    /// assert!(case.query(&loaded.frame).validate(&loaded.map).is_ok());
    /// ```
    #[must_use]
    pub fn query(&self, frame: &InputFrame) -> Query {
        let center = frame.to_world(self.goal.0, self.goal.1);
        let goal = if self.goal_radius > 0.0 {
            Goal::disc(center, self.goal_radius)
        } else {
            Goal::Point(center)
        };
        Query::new(frame.to_world(self.start.0, self.start.1), goal)
    }
}

/// One case a row of `bench-peers`' table.
#[rustfmt::skip]
pub const PEER_CASES: &[PeerCase] = &[
    //             name           map                                start           goal            step  goal radius
    PeerCase::new("rects100",    "data/generated/rects100.pgm",     (5.5, 5.5),     (94.5, 94.5),   5.0,  0.0),
    PeerCase::new("maze101",     "data/generated/maze.pgm",         (2.5, 2.5),     (98.5, 98.5),   3.0,  0.0),
    PeerCase::new("room960x640", "scenarios/maps/room_960x640.pgm", (20.0, 320.0),  (900.0, 520.0), 40.0, 20.0),
    PeerCase::new("arena.map",   "data/movingai/arena.map",         (1.5, 45.5),    (47.5, 9.5),    3.0,  0.0),
];

/// How the OMPL peer reads a map: gray below 128 is an obstacle, no safety band.
#[must_use]
pub fn peer_load_options() -> LoadOptions {
    LoadOptions {
        threshold: 128,
        safety_radius: Some(0.0),
        ..LoadOptions::default()
    }
}

/// A map of the repository (`path` from the workspace root) read as the OMPL peer reads it
/// ([`peer_load_options`]).
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
    envmap::load_map(path.as_ref(), &peer_load_options()).unwrap_or_else(|e| panic!("{path}: {e}"))
}
