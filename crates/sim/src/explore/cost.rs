//! What an iteration of the reference detectors costs in time: a deterministic model of
//! `rrt_exploration`'s `global_rrt_detector.cpp` / `local_rrt_detector.cpp` loop, so that
//! a tree grows only as fast as the reference's could.
//!
//! One iteration of the reference (`functions.cpp`):
//! - `Nearest(V, x)` takes the node list by value (a copy of every node, each its own
//!   heap vector) and scans it; the edges are published as one line list each
//!   iteration: a cost per node;
//! - `ObstacleFree(xnear, xnew, mapsub)` takes the map message by value (one copy of the
//!   map's cells) and walks the edge in steps of `rez = 0.2 x resolution`, for
//!   `stepz = ceil(|edge| in metres) / rez` steps (the length rounded up to whole
//!   metres), stopping at the first unknown cell; each step calls `gridValue` twice, and
//!   `gridValue` copies the map's cells (`std::vector<signed char> Data=mapData.data`):
//!   two map copies per step;
//! - the loop runs at most at 100 Hz (`ros::Rate rate(100)`); an iteration that takes
//!   longer delays the next.
//!
//! The time of an iteration is therefore
//! `iteration + nodes x node + copies x (copy + cells x cell)`, with
//! `copies = 1 + 2 x steps`. The constants are this machine's for the same operations
//! in Rust (a `Vec<i8>` clone is a `std::vector<signed char>` copy: an allocation and a
//! `memcpy`), measured by `cargo run --release -p hyplan-benches --example
//! detector_cost` (docs/papers/004-exploration.md gives the figures).

use serde::{Deserialize, Serialize};

/// Constants of the reference detectors' compute time (see the module doc).
///
/// ```
/// use sim::DetectorCost;
/// let c = DetectorCost::reference();
/// // An edge of 1 m on a 0.1 m map walks 1 / 0.02 = 50 steps.
/// assert_eq!(c.steps(1.0, None, 0.1), 50);
/// // A 15 m global edge on the 22 m world's 0.1 m map (220 x 220 cells) costs less than
/// // the loop's 10 ms period; a 20 m one on a 0.05 m map (440 x 440) more.
/// let short = c.iteration_s(1000, c.steps(15.0, None, 0.1), 220 * 220);
/// let long = c.iteration_s(1000, c.steps(20.0, None, 0.05), 440 * 440);
/// assert!(short < 1.0 / c.loop_rate_hz && long > 1.0 / c.loop_rate_hz);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct DetectorCost {
    /// The loop's ceiling, Hz (`ros::Rate rate(100)`).
    pub loop_rate_hz: f64,
    /// The edge walk's step as a fraction of the map's resolution (`rez`, 0.2).
    pub step_fraction: f64,
    /// Fixed cost of an iteration (sampling, steering, publishing), s.
    pub iteration: f64,
    /// Cost per tree node (copying it for `Nearest`, its distance, its line points), s.
    pub node: f64,
    /// Fixed cost of one copy of the map's cells (allocation and release), s.
    pub copy: f64,
    /// Cost per map cell copied, s.
    pub cell: f64,
}

impl Default for DetectorCost {
    fn default() -> Self {
        Self::reference()
    }
}

impl DetectorCost {
    /// The constants measured on our machine (2 cores, x86-64; see the module doc for
    /// the command): a map copy costs 0.031 ns per cell (the fitted fixed cost of an
    /// allocation was below zero: 0), a node 36 ns; the fixed cost of an iteration
    /// fitted to 0.
    #[must_use]
    pub const fn reference() -> Self {
        Self {
            loop_rate_hz: 100.0,
            step_fraction: 0.2,
            iteration: 0.0,
            node: 36.0e-9,
            copy: 0.0,
            cell: 0.031e-9,
        }
    }

    /// Steps of the reference's edge walk for an edge of `length` m on a map of
    /// `resolution` m: `ceil(length) / (step_fraction x resolution)`, or up to the first
    /// unknown point when the walk stopped there, `unknown_at` m from the edge's start.
    #[must_use]
    pub fn steps(&self, length: f64, unknown_at: Option<f64>, resolution: f64) -> u64 {
        let rez = self.step_fraction * resolution;
        // The reference divides in single precision, where 1 / (0.2 x 0.1) is 50.0000009;
        // in double it is 49.9999999: a hair of slack keeps the whole steps whole.
        let all = (length.ceil() / rez + 1e-9).floor().max(0.0);
        let walked = unknown_at.map_or(all, |d| (d / rez).ceil().clamp(1.0, all.max(1.0)));
        walked as u64
    }

    /// Seconds of one iteration with `nodes` tree nodes, `steps` edge steps and a map of
    /// `cells` cells.
    #[must_use]
    pub fn iteration_s(&self, nodes: usize, steps: u64, cells: usize) -> f64 {
        let copies = 1.0 + 2.0 * steps as f64;
        self.iteration + nodes as f64 * self.node + copies * (self.copy + cells as f64 * self.cell)
    }

    /// Seconds until the next iteration may start after one that took `took` s: the
    /// loop's period, or longer when the iteration overran it.
    #[must_use]
    pub fn next_after(&self, took: f64) -> f64 {
        took.max(1.0 / self.loop_rate_hz)
    }

    /// The first invalid field as `(field, value)`.
    #[must_use]
    pub fn problem(&self) -> Option<(&'static str, f64)> {
        [
            ("loop_rate_hz", self.loop_rate_hz, true),
            ("step_fraction", self.step_fraction, true),
            ("iteration", self.iteration, false),
            ("node", self.node, false),
            ("copy", self.copy, false),
            ("cell", self.cell, false),
        ]
        .into_iter()
        .find(|&(_, v, positive)| !(v.is_finite() && (v > 0.0 || (!positive && v == 0.0))))
        .map(|(f, v, _)| (f, v))
    }
}
