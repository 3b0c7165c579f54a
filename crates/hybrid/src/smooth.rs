//! The smoothing steps of seeds 000 (PCHIP through the reduced nodes) and 003 (clamped
//! cubic B-spline over a densified control polygon): `postproc`'s checked fit of the
//! nodes the planner reduced itself, with the hybrids' rules.
//!
//! `postproc::smooth_checked` prunes before it fits, while seed 000 reduces in exactly one
//! pass and seed 003 prunes against another zone than the one its curve is checked
//! against; so the planners prune themselves and call [`postproc::fit_checked`] here.

use hyplan_core::{PlanStats, Point2, Tree};
use postproc::{Fit, FitOptions, OnFailure};

use crate::Staged;

/// Rounds of midpoint insertion (PCHIP) before colliding pieces are straightened: three,
/// one fewer than `postproc`'s default, so a planner gives up on a curve sooner (the
/// papers say nothing of repairs).
const INSERT_ROUNDS: usize = 3;

/// A checked curve: the samples and what it took to get them.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Checked {
    /// Samples, first and last = the input's ends bit for bit; every consecutive pair was
    /// accepted by the oracle.
    pub points: Vec<Point2>,
    /// Local repairs made (inserted nodes, straightened pieces, raised multiplicities).
    pub repairs: usize,
    /// Whether the curve was refused and the input polyline returned (densified).
    pub refused: bool,
}

/// `fit` over `nodes` (a free polyline without repeated consecutive points), sampled at
/// most `spacing` apart and checked with `free`; a curve the repairs cannot save is
/// refused and the nodes returned as a polyline (a planner's result must be a path).
pub(crate) fn fit_checked(
    nodes: &[Point2],
    fit: Fit,
    spacing: f64,
    free: impl FnMut(Point2, Point2) -> bool,
) -> Checked {
    let options = FitOptions {
        insert_rounds: INSERT_ROUNDS,
        on_failure: OnFailure::Polyline,
    };
    match postproc::fit_checked(nodes, fit, spacing, options, free) {
        Ok(s) => Checked {
            points: s.points,
            repairs: s.repairs.len(),
            refused: s.refused,
        },
        // Nodes or spacing postproc refuses (validated by the planners, so not expected):
        // the polyline as it is.
        Err(_) => Checked {
            points: postproc::densify(nodes, spacing),
            repairs: 0,
            refused: true,
        },
    }
}

/// The smoothing stage of a hybrid: `fit` over the `reduced` path when `smoothing` is on
/// and the path has a corner to round (three nodes or more), else the reduced path as it
/// is.
pub(crate) fn fit_if(
    smoothing: bool,
    reduced: &[Point2],
    fit: impl FnOnce(&[Point2]) -> Checked,
) -> Checked {
    if smoothing && reduced.len() >= 3 {
        fit(reduced)
    } else {
        Checked {
            points: reduced.to_vec(),
            repairs: 0,
            refused: false,
        }
    }
}

impl Checked {
    /// The staged result of a search-then-smooth hybrid with this curve as its path (cost:
    /// its length), `tree` as its search tree and the reduced nodes as its waypoints (the
    /// curve passes through them, or they are its control points) when `smoothing` is on.
    pub(crate) fn into_staged(
        self,
        smoothing: bool,
        tree: Tree,
        stats: PlanStats,
        raw: Vec<Point2>,
        reduced: Vec<Point2>,
    ) -> Staged {
        let mut plan = sampling::plan_of_path(self.points, vec![tree], stats);
        if smoothing {
            plan.waypoints.clone_from(&reduced);
        }
        Staged {
            plan,
            raw,
            reduced,
            smoothing_repairs: self.repairs,
            smoothing_refused: self.refused,
            ..Staged::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pchip_straightens_when_only_the_polyline_is_free() {
        let nodes = [[0.0, 0.0], [4.0, 1.0], [5.0, 5.0]].map(Point2::from);
        // Accept only pieces lying on the input polyline.
        let on = |p: Point2| {
            nodes.windows(2).any(|w| {
                let d = w[1] - w[0];
                let t = ((p - w[0]).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
                (p - (w[0] + d * t)).norm() < 1e-9
            })
        };
        let c = fit_checked(&nodes, Fit::Pchip, 0.25, |a, b| on(a) && on(b));
        assert!(c.repairs > 0);
        assert_eq!(c.points[0], nodes[0]);
        assert_eq!(*c.points.last().unwrap(), nodes[2]);
        assert!(c.points.iter().all(|&p| on(p)));
    }

    #[test]
    fn bspline_ends_are_exact() {
        let ctrl = [[0.0, 0.0], [2.0, 3.0], [5.0, 3.0], [6.0, 0.0]].map(Point2::from);
        let c = fit_checked(&ctrl, Fit::BSpline, 0.1, |_, _| true);
        assert!(!c.refused);
        assert_eq!(c.points[0], ctrl[0]);
        assert_eq!(*c.points.last().unwrap(), ctrl[3]);
    }
}
