//! Bi-RRT: two RRTs, one from the start and one from the goal, grown in turn and joined when
//! a new node of one comes within a free step of the other.

use hyplan_core::{Budget, Plan, PlanError, Workspace};

use crate::common;
use crate::{Extension, Search};

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
    /// One call of [`plan_with`](Self::plan_with).
    fn search<W: Workspace + ?Sized>(&self, search: Search<'_, W>) -> Result<Plan, PlanError> {
        common::grow_two_trees(self.step, &self.budget, search, |turn| {
            let (active, other) = (turn.active, turn.other);
            // Extend: nearest node, one step towards the sample, exact edge check, add.
            let extension = turn.trees[active].extend(turn.sample, self.step, turn.checker);
            let Extension::Added { new, .. } = extension else {
                return None;
            };
            let new_point = turn.trees[active].point(new);
            // Goal test: the start tree inside a goal disc ends the search by itself.
            if turn.ends_in_goal(active, new_point) {
                return Some((new, None));
            }
            // Join: the other tree's nearest node within a step, through a free edge.
            let (meet, d) = turn.trees[other].nearest(new_point)?;
            let free = d <= self.step
                && turn
                    .checker
                    .segment_free(new_point, turn.trees[other].point(meet));
            free.then(|| turn.joined(new, meet))
        })
    }
}

crate::impl_planner!(BiRrt, "bi-rrt", optimizing: |_bi_rrt| false, plan: search);
