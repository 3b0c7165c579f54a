//! Bi-RRT: two RRTs, one from the start and one from the goal, grown in turn and joined when
//! a new node of one comes within a free step of the other.

use std::ops::ControlFlow;

use hyplan_core::{Budget, Plan, PlanError, Progress, Query, Workspace};
use rand::Rng;

use crate::common;
use crate::toolkit::CountingChecker;
use crate::{Extension, GrowTree};

/// The Bi-RRT planner's parameters.
///
/// Each iteration extends one tree by one step towards a uniform sample (as RRT does), then
/// tries to join the new node to the nearest node of the other tree with one exact edge check
/// (when that node is within `step`). The trees swap roles every iteration. The goal tree is
/// rooted at the goal centre, so with an exact goal the path ends exactly on it; with a goal
/// disc a start-tree node inside the disc also ends the search.
///
/// There is no goal bias: the other tree is the target.
///
/// ```
/// use envmap::GridMap;
/// use hyplan_core::{Goal, Point2, Query};
/// use rand::SeedableRng;
/// use sampling::BiRrt;
///
/// let map = GridMap::from_ascii("
///     ..........
///     ....##....
///     ....##....
///     ..........
/// ")?;
/// let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(9.5, 3.5)));
/// let plan = BiRrt::default().plan(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(3))?;
/// assert_eq!(plan.path[0], query.start);
/// assert_eq!(*plan.path.last().unwrap(), Point2::new(9.5, 3.5));
/// assert_eq!(plan.trees.len(), 2);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct BiRrt {
    /// Maximum length of a new edge (and of the joining edge), world units, finite and > 0.
    /// Default 1.0.
    pub step: f64,
    /// Iteration (samples drawn, one tree extended per iteration) and optional time limits.
    /// Default: unset, [`Budget::samples_for`](hyplan_core::Budget::samples_for) the map
    /// (100 000 iterations, or one per four cells of a grid map when that is more).
    pub budget: Budget,
}

impl Default for BiRrt {
    fn default() -> Self {
        Self {
            step: 1.0,
            budget: Budget::default(),
        }
    }
}

impl BiRrt {
    /// Plans a path for `query` in `ws`, drawing every random number from `rng`, with an
    /// observer called every 64 iterations; `ControlFlow::Break(())` stops the run
    /// ([`PlanError::BudgetExhausted`]).
    ///
    /// # Errors
    ///
    /// [`PlanError::InvalidParameter`] for a bad step or budget; [`PlanError::InvalidStart`] /
    /// [`PlanError::InvalidGoal`] for a query outside the workspace or blocked;
    /// [`PlanError::BudgetExhausted`] (with the statistics) when the trees did not meet.
    pub fn plan_with<W, R, F>(
        &self,
        ws: &W,
        query: &Query,
        rng: &mut R,
        observer: &mut F,
    ) -> Result<Plan, PlanError>
    where
        W: Workspace + ?Sized,
        R: Rng + ?Sized,
        F: FnMut(&Progress) -> ControlFlow<()>,
    {
        let (goal, step) = (query.goal, self.step);
        let grow = |trees: &mut [GrowTree; 2],
                    active: usize,
                    sample,
                    checker: &mut CountingChecker<'_, W>| {
            let other = 1 - active;
            // Extend: nearest node, one step towards the sample, exact edge check, add.
            let Extension::Added { new, .. } = trees[active].extend(sample, step, checker) else {
                return None;
            };
            let new_point = trees[active].point(new);
            // Goal test: the start tree inside a goal disc ends the search by itself.
            if active == 0 && goal.radius() > 0.0 && goal.contains(new_point) {
                return Some((new, None));
            }
            // Join: the other tree's nearest node within a step, through a free edge.
            let (meet, d) = trees[other].nearest(new_point)?;
            (d <= step && checker.segment_free(new_point, trees[other].point(meet))).then_some(
                if active == 0 {
                    (new, Some(meet))
                } else {
                    (meet, Some(new))
                },
            )
        };
        common::grow_two_trees(step, &self.budget, ws, query, rng, observer, grow)
    }
}

crate::impl_planner!(BiRrt, "bi-rrt", optimizing: |_bi_rrt| false, plan: plan_with);
