//! Path post-processing for mobile robots: what happens between a planner's zigzag
//! polyline and the curve a robot follows.
//!
//! The crate has no map of its own. Every step that needs the world takes a segment oracle
//! `FnMut(Point2, Point2) -> bool` (true when the closed segment is free), so any
//! [`Workspace`](hyplan_core::Workspace) works: pass `|a, b| map.segment_free(a, b)`.
//!
//! # Contents
//!
//! - Pruning of redundant nodes: [`prune_pairwise`] (seed 000, section 4.5),
//!   [`shortcut_greedy`] (seeds 001 and 003) and [`shortcut_farthest`] (the same shortcut,
//!   looking past hidden nodes).
//! - Curves: [`Pchip`] (monotone cubic Hermite, Fritsch-Carlson, over chord length; seed
//!   000, section 4.6) and [`BSpline`] (clamped cubic, de Boor; with the nodes as control
//!   points as in seed 003, section 2.3, or through the nodes), held together by [`Curve`]
//!   with [`Curve::resample`] at a given spacing.
//! - Geometry and metrics: [`curvature`], [`discrete_curvature`], [`turning_angles`],
//!   [`PathMetrics`] and [`count_turns`] (a turn is a heading change of more than
//!   [`DEFAULT_TURN_THRESHOLD_DEG`] = 10 degrees; seed 001, section 3.3).
//! - Collision-checked smoothing: [`smooth_checked`] with a [`Smoothing`] method returns
//!   [`Smoothed`]: samples at most `spacing` apart whose every consecutive pair the oracle
//!   accepted, and the [`Repair`]s made where the first curve collided. It never returns a
//!   colliding curve.
//! - Time parametrisation under [`Limits`] (`v_max`, `omega_max`, `a_max`), from rest to
//!   rest: [`time_polyline`] (stop and turn in place at each corner), [`time_curve`]
//!   (speed capped by `omega_max / |kappa|`, forward and backward acceleration passes) and
//!   [`straight_time`]; they return a [`Timing`] with the transfer time and the v(t),
//!   omega(t) profile as [`ProfilePoint`]s.
//! - Errors: [`PostprocError`]. Bad input (fewer than two nodes, repeated consecutive nodes,
//!   NaN coordinates, non-positive limits or spacing) is a typed error, never a panic.
//!
//! # Conventions
//!
//! Points are world coordinates (x right, y up) in the map's units; lengths and spacings
//! are in those units, angles in radians, times in seconds, curvature in 1 / world units,
//! positive when turning left. Every function keeps the path's first and last points bit
//! for bit.
//!
//! # Example
//!
//! Smooth a path round a pillar, check it and time it:
//!
//! ```
//! use hyplan_core::Point2;
//! use postproc::{Limits, Smoothing, smooth_checked};
//!
//! // A pillar [4, 6] x [0, 6]; a finely sampling oracle stands in for a map.
//! let free = |a: Point2, b: Point2| {
//!     (0..=100).all(|i| {
//!         let p = a + (b - a) * (f64::from(i) / 100.0);
//!         !((4.0..=6.0).contains(&p.x) && p.y <= 6.0)
//!     })
//! };
//! let path = [
//!     Point2::new(1.0, 1.0),
//!     Point2::new(2.0, 4.0),
//!     Point2::new(3.0, 7.0),
//!     Point2::new(7.0, 7.0),
//!     Point2::new(9.0, 1.0),
//! ];
//! let smoothed = smooth_checked(&path, "pchip".parse()?, 0.25, free)?;
//! assert!(smoothed.points.windows(2).all(|w| free(w[0], w[1])));
//! assert_eq!(smoothed.points[0], path[0]);
//!
//! let limits = Limits::new(0.15, 0.3, 0.2)?; // m/s, rad/s, m/s^2
//! let timing = smoothed.time(&limits)?;
//! assert!(timing.transfer_time >= smoothed.length() / limits.v_max);
//! let polyline = smooth_checked(&path, Smoothing::Prune, 0.25, free)?.time(&limits)?;
//! assert!(timing.transfer_time < polyline.transfer_time); // no stops at the corners
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Features
//!
//! - `serde` (off by default): `Serialize` / `Deserialize` for [`Smoothing`] (as its name),
//!   [`Repair`], [`Limits`], [`Timing`], [`ProfilePoint`] and [`PathMetrics`].
//!
//! Without features the crate depends on `hyplan-core`, nalgebra and thiserror only.

mod bspline;
mod curvature;
mod error;
mod metrics;
mod pchip;
mod prune;
mod resample;
mod smooth;
mod smoothing;
mod timing;

pub use bspline::BSpline;
pub use curvature::{curvature, discrete_curvature, turning_angles};
pub use error::PostprocError;
pub use metrics::{DEFAULT_TURN_THRESHOLD_DEG, PathMetrics, count_turns};
pub use pchip::Pchip;
pub use prune::{prune_pairwise, prune_pairwise_passes, shortcut_farthest, shortcut_greedy};
pub use resample::{Curve, MAX_SAMPLES, densify};
pub use smooth::{check_polyline, fit_checked, smooth_checked};
pub use smoothing::{Fit, FitOptions, INSERT_ROUNDS, OnFailure, Repair, Smoothed, Smoothing};
pub use timing::{Limits, ProfilePoint, Timing, straight_time, time_curve, time_polyline};

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
