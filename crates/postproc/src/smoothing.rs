//! The choices of smoothing: the method, the repair rule, what a smoothed path carries,
//! and the options of fitting a curve over given nodes.

use std::fmt;
use std::str::FromStr;

use hyplan_core::Point2;

use crate::{Curve, Limits, PathMetrics, PostprocError, Timing, time_curve, time_polyline};
// Named in the docs' links.
#[allow(unused_imports)]
use crate::{BSpline, Pchip, fit_checked, prune_pairwise, shortcut_greedy, smooth_checked};

/// How [`smooth_checked`] turns a path into the curve the robot follows.
///
/// Each method first prunes the path the way its paper does, then fits its curve:
///
/// | method | name | pruning | curve |
/// |---|---|---|---|
/// | `None` | `none` | none | the input polyline |
/// | `Prune` | `prune` | [`shortcut_greedy`] (seeds 001/003) | polyline |
/// | `Pchip` | `pchip` | [`prune_pairwise`] (seed 000, 4.5) | [`Pchip`] through the nodes (seed 000, 4.6) |
/// | `BSpline` | `bspline` | [`shortcut_greedy`] | [`BSpline::from_control_points`] (seed 003, 2.3) |
/// | `BSplineInterpolating` | `bspline-interp` | [`shortcut_greedy`] | [`BSpline::interpolating`] |
///
/// `FromStr` and `Display` use the names, so a command line can select a method by name.
///
/// ```
/// use postproc::Smoothing;
/// let m: Smoothing = "pchip".parse()?;
/// assert_eq!(m, Smoothing::Pchip);
/// assert_eq!(m.to_string(), "pchip");
/// assert!("spline".parse::<Smoothing>().is_err());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Smoothing {
    /// Keep the path as it is (it is only resampled).
    #[default]
    #[cfg_attr(feature = "serde", serde(rename = "none"))]
    None,
    /// Greedy shortcut pruning, straight segments.
    #[cfg_attr(feature = "serde", serde(rename = "prune"))]
    Prune,
    /// Pairwise pruning, then PCHIP through the remaining nodes.
    #[cfg_attr(feature = "serde", serde(rename = "pchip"))]
    Pchip,
    /// Greedy pruning, then a clamped cubic B-spline with the nodes as control points.
    #[cfg_attr(feature = "serde", serde(rename = "bspline"))]
    BSpline,
    /// Greedy pruning, then a clamped cubic B-spline through the nodes.
    #[cfg_attr(feature = "serde", serde(rename = "bspline-interp"))]
    BSplineInterpolating,
}

impl Smoothing {
    /// Every method, in the order of the table above.
    pub const ALL: [Self; 5] = [
        Self::None,
        Self::Prune,
        Self::Pchip,
        Self::BSpline,
        Self::BSplineInterpolating,
    ];

    /// The method's name on the command line.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::None => "none",
            Self::Prune => "prune",
            Self::Pchip => "pchip",
            Self::BSpline => "bspline",
            Self::BSplineInterpolating => "bspline-interp",
        }
    }

    /// Whether the method's result is a polyline (`none`, `prune`), which a robot follows
    /// by stopping and turning in place at each node.
    #[must_use]
    pub const fn is_polyline(self) -> bool {
        matches!(self, Self::None | Self::Prune)
    }
}

impl fmt::Display for Smoothing {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Smoothing {
    type Err = PostprocError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| PostprocError::UnknownMethod { name: s.to_owned() })
    }
}

/// One local repair [`smooth_checked`] made where the curve collided.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum Repair {
    /// A node was added at the midpoint of a segment of the (pruned) polyline, so that the
    /// curve through the nodes hugs that segment more closely.
    InsertedNode {
        /// The new node, world units.
        at: Point2,
    },
    /// The curve between two consecutive nodes was replaced by the straight segment.
    Straightened {
        /// First node of the segment, world units.
        from: Point2,
        /// Second node, world units.
        to: Point2,
    },
    /// A control point of a control-point B-spline was repeated once more, pulling the
    /// curve towards it (three copies make the curve pass through it along the polyline).
    RaisedMultiplicity {
        /// The control point, world units.
        node: Point2,
        /// How many copies it has now (2 or 3).
        multiplicity: usize,
    },
}

/// The result of [`smooth_checked`]: a checked polyline of samples and how it was made.
#[derive(Debug, Clone, PartialEq)]
pub struct Smoothed {
    /// The method used.
    pub method: Smoothing,
    /// The curve's defining points after pruning and repairs: the polyline's nodes
    /// (`none`, `prune`), the nodes the curve passes through (`pchip`, `bspline-interp`) or
    /// the control points with their repeats (`bspline`).
    pub nodes: Vec<Point2>,
    /// The final curve as samples at most `spacing` apart, world units. The first and last
    /// samples are the input's end points bit for bit, and the oracle accepted the segment
    /// between every two consecutive samples: this polyline is the checked result.
    pub points: Vec<Point2>,
    /// The fitted curve. Pieces listed as [`Repair::Straightened`] were replaced by
    /// straight segments in [`points`](Smoothed::points) and differ from it there.
    pub curve: Curve,
    /// What was repaired, in order; empty when the first curve was free.
    pub repairs: Vec<Repair>,
    /// Number of oracle calls made (input check, pruning, sample checks).
    pub oracle_calls: usize,
    /// Whether the curve was refused and the nodes returned as a polyline
    /// ([`OnFailure::Polyline`]); always `false` from [`smooth_checked`].
    pub refused: bool,
}

impl Smoothed {
    /// Length of the sampled curve, world units.
    #[must_use]
    pub fn length(&self) -> f64 {
        hyplan_core::path_length(&self.points)
    }

    /// The paper metrics of the result: length and maximum curvature of the samples, nodes,
    /// segments and turns (> 10 degrees) of [`nodes`](Smoothed::nodes), where a turn is
    /// meaningful (repeated control points are counted once).
    #[must_use]
    pub fn metrics(&self) -> PathMetrics {
        let mut nodes = self.nodes.clone();
        nodes.dedup();
        let on_nodes = PathMetrics::of(&nodes);
        let on_samples = PathMetrics::of(&self.points);
        PathMetrics {
            length: on_samples.length,
            max_curvature: if self.method.is_polyline() {
                on_nodes.max_curvature
            } else {
                on_samples.max_curvature
            },
            ..on_nodes
        }
    }

    /// Times the result for a robot with `limits`, from rest to rest: a polyline with
    /// [`time_polyline`] (stop and turn in place at each node), a curve with [`time_curve`]
    /// along its samples.
    ///
    /// # Errors
    ///
    /// [`PostprocError::InvalidLimit`] for a limit that is not finite and positive.
    pub fn time(&self, limits: &Limits) -> Result<Timing, PostprocError> {
        if self.method.is_polyline() {
            time_polyline(&self.nodes, limits)
        } else {
            time_curve(&self.points, limits)
        }
    }
}

/// Rounds of node insertion before colliding pieces are straightened, in
/// [`smooth_checked`] (and [`FitOptions::default`]).
pub const INSERT_ROUNDS: usize = 4;

/// The curve [`fit_checked`] makes over given nodes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fit {
    /// PCHIP through the nodes (seed 000, 4.6).
    Pchip,
    /// Interpolating cubic B-spline through the nodes.
    BSplineInterpolating,
    /// Clamped cubic B-spline with the nodes as control points (seed 003, 2.3).
    BSpline,
}

/// What [`fit_checked`] does when its repairs run out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OnFailure {
    /// Return [`PostprocError::CannotRepair`] ([`smooth_checked`]'s rule).
    Error,
    /// Refuse the curve and return the nodes as a polyline, sampled and checked, with
    /// [`Smoothed::refused`] set: the rule of the planners whose nodes are free by
    /// construction (a planner's result must be a path, not an error).
    Polyline,
}

/// The repair rounds and the failure rule of [`fit_checked`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FitOptions {
    /// Rounds of midpoint insertion before a colliding piece of a curve through the nodes
    /// is straightened ([`INSERT_ROUNDS`] by default).
    pub insert_rounds: usize,
    /// What to do when the repairs run out ([`OnFailure::Error`] by default).
    pub on_failure: OnFailure,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            insert_rounds: INSERT_ROUNDS,
            on_failure: OnFailure::Error,
        }
    }
}
