//! RRT-Connect (Kuffner and LaValle 2000): two trees; one extends a step towards a random
//! sample, the other then greedily connects towards the new node, step after step, until it
//! reaches it or is blocked. The trees swap roles every iteration.

use hyplan_core::{Budget, Plan, PlanError, Point2, Workspace};

use crate::common;
use crate::toolkit::CountingChecker;
use crate::tree::Lead;
use crate::{GrowTree, Search};

/// The outcome of one extension step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ExtendStatus {
    /// The target itself was added (node id).
    Reached(usize),
    /// A node one step towards the target was added (node id).
    Advanced(usize),
    /// The edge was blocked; nothing was added.
    Trapped,
}

/// The RRT-Connect planner's parameters.
///
/// Edges are checked exactly with [`Workspace::segment_free`]. The goal tree is rooted at the
/// goal centre, so with an exact goal the path ends on it; with a goal disc a start-tree node
/// inside the disc also ends the search. There is no goal bias (OMPL's RRTConnect has none
/// either): the other tree is the target.
///
/// ```
/// use envmap::GridMap;
/// use hyplan_core::{Goal, Point2, Query};
/// use rand::SeedableRng;
/// use sampling::RrtConnect;
///
/// let map = GridMap::from_ascii("
///     ..........
///     ....##....
///     ....##....
///     ..........
/// ")?;
/// let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(9.5, 3.5)));
/// let planner = RrtConnect { step: 2.0, ..RrtConnect::default() };
/// let plan = planner.plan(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(3))?;
/// assert_eq!(plan.path[0], query.start);
/// assert_eq!(*plan.path.last().unwrap(), Point2::new(9.5, 3.5));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct RrtConnect {
    /// Maximum length of one edge, world units, finite and > 0. Default 1.0.
    pub step: f64,
    /// Iteration (samples drawn) and optional time limits.
    /// Default: unset, [`Budget::samples_for`](hyplan_core::Budget::samples_for) the map
    /// (100 000 iterations, or one per four cells of a grid map when that is more).
    pub budget: Budget,
}

impl Default for RrtConnect {
    fn default() -> Self {
        Self {
            step: 1.0,
            budget: Budget::default(),
        }
    }
}

/// One step of `tree` from its node nearest to `target` towards it: `lead`'s node when it
/// leads there (the last step's new node), replaced by the new node's lead.
fn extend<W: Workspace + ?Sized>(
    tree: &mut GrowTree,
    target: Point2,
    step: f64,
    checker: &mut CountingChecker<'_, W>,
    lead: &mut Option<Lead>,
) -> ExtendStatus {
    // Nearest and steer: at most one step from the nearest node towards the target.
    let Some(s) = tree.step_led(target, step, lead.take()) else {
        return ExtendStatus::Trapped;
    };
    if s.from == target {
        return ExtendStatus::Reached(s.near);
    }
    // Segment free: exactly; then add.
    if !checker.segment_free(s.from, s.to) {
        return ExtendStatus::Trapped;
    }
    let new;
    (new, *lead) = tree.add_step(&s, target);
    if s.to == target {
        ExtendStatus::Reached(new)
    } else {
        ExtendStatus::Advanced(new)
    }
}

impl RrtConnect {
    /// One call of [`plan_with`](Self::plan_with).
    fn search<W: Workspace + ?Sized>(&self, search: Search<'_, W>) -> Result<Plan, PlanError> {
        common::grow_two_trees(self.step, &self.budget, search, |turn| {
            let (active, other) = (turn.active, turn.other);
            // Extend: the active tree one step towards the sample.
            let new = match extend(
                &mut turn.trees[active],
                turn.sample,
                self.step,
                turn.checker,
                &mut None,
            ) {
                ExtendStatus::Trapped => return None,
                ExtendStatus::Reached(n) | ExtendStatus::Advanced(n) => n,
            };
            let target = turn.trees[active].point(new);
            // Goal test: the start tree inside a goal disc ends the search by itself.
            if turn.ends_in_goal(active, target) {
                return Some((new, None));
            }
            // Connect: the other tree steps towards the new node until it reaches it or is
            // blocked; each step from the last one's new node, which is the nearest.
            let mut lead = None;
            loop {
                match extend(
                    &mut turn.trees[other],
                    target,
                    self.step,
                    turn.checker,
                    &mut lead,
                ) {
                    ExtendStatus::Advanced(m) => {
                        if turn.ends_in_goal(other, turn.trees[other].point(m)) {
                            return Some((m, None));
                        }
                    }
                    ExtendStatus::Reached(m) => return Some(turn.joined(new, m)),
                    ExtendStatus::Trapped => return None,
                }
            }
        })
    }
}

crate::impl_planner!(RrtConnect, "rrt-connect", optimizing: |_rrt_connect| false, plan: search);
