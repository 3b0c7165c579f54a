//! Typed errors of post-processing.

/// Why a post-processing step refused its input or could not finish.
///
/// Every public function of the crate reports bad input through this enum and never
/// panics on it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PostprocError {
    /// The path has fewer than two nodes.
    #[error("path has {nodes} node(s), at least 2 are needed")]
    TooFewNodes {
        /// Number of nodes given.
        nodes: usize,
    },
    /// Two consecutive nodes are the same point (a zero-length segment has no heading).
    #[error("nodes {index} and {} are the same point ({x}, {y})", index + 1)]
    RepeatedNode {
        /// Index of the first of the two equal nodes.
        index: usize,
        /// Its x coordinate, world units.
        x: f64,
        /// Its y coordinate, world units.
        y: f64,
    },
    /// A node has a NaN or infinite coordinate.
    #[error("node {index} has a non-finite coordinate ({x}, {y})")]
    NonFinite {
        /// Index of the node.
        index: usize,
        /// Its x coordinate as given.
        x: f64,
        /// Its y coordinate as given.
        y: f64,
    },
    /// A robot limit is not a finite positive number.
    #[error("invalid limit {name} = {value}: must be finite and > 0")]
    InvalidLimit {
        /// The field name (`v_max`, `omega_max`, `a_max`).
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// The sample spacing is not a finite positive number, or so small that the curve
    /// would need more than [`MAX_SAMPLES`](crate::MAX_SAMPLES) samples.
    #[error("invalid spacing {value}: {reason}")]
    InvalidSpacing {
        /// The spacing given, world units.
        value: f64,
        /// The rule it breaks.
        reason: &'static str,
    },
    /// A segment of the input path is not free for the oracle, so no repair can fall back
    /// on it.
    #[error("input segment {index} from ({}, {}) to ({}, {}) is not free", from.x, from.y, to.x, to.y)]
    SegmentNotFree {
        /// Index of the segment (between nodes `index` and `index + 1`).
        index: usize,
        /// Its first end, world units.
        from: hyplan_core::Point2,
        /// Its second end, world units.
        to: hyplan_core::Point2,
    },
    /// A smoothing method name that is none of `none`, `prune`, `pchip`, `bspline`,
    /// `bspline-interp`.
    #[error(
        "unknown smoothing method {name:?} (expected none, prune, pchip, bspline or bspline-interp)"
    )]
    UnknownMethod {
        /// The name given.
        name: String,
    },
    /// The smoothed curve still collides after every repair was tried.
    #[error("smoothed curve could not be repaired near ({}, {})", at.x, at.y)]
    CannotRepair {
        /// A sample of the curve where the collision remains, world units.
        at: hyplan_core::Point2,
    },
}

/// Checks a path: at least two nodes, finite coordinates, no repeated consecutive nodes.
pub(crate) fn validate_path(path: &[hyplan_core::Point2]) -> Result<(), PostprocError> {
    if path.len() < 2 {
        return Err(PostprocError::TooFewNodes { nodes: path.len() });
    }
    for (index, p) in path.iter().enumerate() {
        if !(p.x.is_finite() && p.y.is_finite()) {
            return Err(PostprocError::NonFinite {
                index,
                x: p.x,
                y: p.y,
            });
        }
    }
    for (index, w) in path.windows(2).enumerate() {
        if w[0] == w[1] {
            return Err(PostprocError::RepeatedNode {
                index,
                x: w[0].x,
                y: w[0].y,
            });
        }
    }
    Ok(())
}
