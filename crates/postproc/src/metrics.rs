//! The path metrics the seed papers report.

use hyplan_core::Point2;

use crate::{discrete_curvature, turning_angles};

/// Seed 001's turn threshold: a heading change of more than 10 degrees is a turn
/// (section 3.3: the angle between consecutive segments is below 170 degrees).
pub const DEFAULT_TURN_THRESHOLD_DEG: f64 = 10.0;

/// Length, nodes, segments, turns and maximum curvature of a polyline.
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::PathMetrics;
/// let path = [
///     Point2::new(0.0, 0.0),
///     Point2::new(4.0, 0.0),
///     Point2::new(8.0, 0.5), // about 7 degrees: not a turn
///     Point2::new(8.0, 4.0), // about 83 degrees: a turn
/// ];
/// let m = PathMetrics::of(&path);
/// assert_eq!((m.nodes, m.segments, m.turns), (4, 3, 1));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PathMetrics {
    /// Euclidean length, world units.
    pub length: f64,
    /// Number of nodes (points) of the polyline, start and end included.
    pub nodes: usize,
    /// Number of segments (`nodes - 1`, 0 for an empty path).
    pub segments: usize,
    /// Heading changes above the threshold between consecutive segments (seed 001, 3.3).
    pub turns: usize,
    /// Largest absolute [`discrete_curvature`] over the vertices, 1 / world units. For a
    /// densely resampled curve it approximates the curve's maximum curvature; for a raw
    /// polyline it is the sharpest corner's angle over its mean neighbouring segment length.
    pub max_curvature: f64,
}

impl PathMetrics {
    /// The metrics of `path` with the default 10 degree turn threshold.
    #[must_use]
    pub fn of(path: &[Point2]) -> Self {
        Self::with_turn_threshold(path, DEFAULT_TURN_THRESHOLD_DEG.to_radians())
    }

    /// The metrics of `path`, counting heading changes above `threshold` radians as turns.
    #[must_use]
    pub fn with_turn_threshold(path: &[Point2], threshold: f64) -> Self {
        Self {
            length: hyplan_core::path_length(path),
            nodes: path.len(),
            segments: path.len().saturating_sub(1),
            turns: count_turns(path, threshold),
            max_curvature: discrete_curvature(path)
                .iter()
                .fold(0.0_f64, |m, k| m.max(k.abs())),
        }
    }
}

/// The number of vertices where the heading changes by more than `threshold` radians
/// (seed 001, section 3.3, with `threshold` = 10 degrees).
///
/// Zero-length segments carry no heading and are skipped. A densely sampled smooth curve
/// turns a little at each sample, so count turns on the node path, not on samples.
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// let square = [
///     Point2::new(0.0, 0.0),
///     Point2::new(1.0, 0.0),
///     Point2::new(1.0, 1.0),
///     Point2::new(0.0, 1.0),
/// ];
/// assert_eq!(postproc::count_turns(&square, 10f64.to_radians()), 2);
/// ```
#[must_use]
pub fn count_turns(path: &[Point2], threshold: f64) -> usize {
    let mut clean = path.to_vec();
    clean.dedup();
    turning_angles(&clean)
        .iter()
        .filter(|a| a.abs() > threshold)
        .count()
}
