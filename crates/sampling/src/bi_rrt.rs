//! Bi-RRT: two RRTs, one from the start and one from the goal, grown in turn and joined when
//! a new node of one comes within a free step of the other.

use std::ops::ControlFlow;
use std::time::Instant;

use hyplan_core::{Budget, Plan, PlanError, Planner, PlannerInfo, Progress, Query, Workspace};
use rand::{Rng, RngCore};

use crate::common::{self, GrowTree};
use crate::toolkit::{self, CountingChecker};

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
pub struct BiRrt {
    /// Maximum length of a new edge (and of the joining edge), world units, finite and > 0.
    /// Default 1.0.
    pub step: f64,
    /// Iteration (samples drawn, one tree extended per iteration) and optional time limits.
    /// Default 10 000 iterations.
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
    /// Plans a path for `query` in `ws`, drawing every random number from `rng`.
    ///
    /// # Errors
    ///
    /// [`PlanError::InvalidParameter`] for a bad step or budget; [`PlanError::InvalidStart`] /
    /// [`PlanError::InvalidGoal`] for a query outside the workspace or blocked;
    /// [`PlanError::BudgetExhausted`] (with the statistics) when the trees did not meet.
    pub fn plan<W: Workspace + ?Sized, R: Rng + ?Sized>(
        &self,
        ws: &W,
        query: &Query,
        rng: &mut R,
    ) -> Result<Plan, PlanError> {
        self.plan_with(ws, query, rng, &mut common::keep_going)
    }

    /// [`plan`](Self::plan) with an observer, called every 64 iterations;
    /// `ControlFlow::Break(())` stops the run ([`PlanError::BudgetExhausted`]).
    ///
    /// # Errors
    ///
    /// As [`plan`](Self::plan).
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
        let started = Instant::now();
        toolkit::validate_step_and_budget(self.step, &self.budget, ws, query)?;
        let goal = query.goal;
        let mut checker = CountingChecker::new(ws);
        // trees[0] grows from the start, trees[1] from the goal centre.
        let mut trees = [
            GrowTree::rooted_at(query.start),
            GrowTree::rooted_at(goal.center()),
        ];
        let mut iterations = 0_u64;
        // (start-tree node, goal-tree node) where the trees met; goal node None = start tree
        // reached the goal region by itself.
        let mut joined: Option<(usize, Option<usize>)> =
            goal.contains(query.start).then_some((0, None));
        let mut active = 0_usize;

        while joined.is_none() && !self.budget.exhausted(iterations, started) {
            iterations += 1;
            if iterations.is_multiple_of(common::OBSERVE_EVERY) {
                let progress = Progress {
                    iterations,
                    nodes: (trees[0].len() + trees[1].len()) as u64,
                    best_cost: None,
                };
                if observer(&progress).is_break() {
                    break;
                }
            }
            let other = 1 - active;
            // Sample: uniform in the bounds.
            let sample = toolkit::sample_uniform(ws, rng);
            // Nearest: the active tree's node closest to the sample.
            let Some((near, _)) = trees[active].index.nearest(sample) else {
                break;
            };
            let near_point = trees[active].index.point(near);
            // Steer: at most one step towards the sample.
            let new_point = toolkit::steer(near_point, sample, self.step);
            // Segment free: the edge, exactly; then add the node.
            if new_point != near_point && checker.segment_free(near_point, new_point) {
                let new = trees[active].add(new_point, near);
                // Goal test: the start tree inside a goal disc ends the search by itself.
                if active == 0 && goal.radius() > 0.0 && goal.contains(new_point) {
                    joined = Some((new, None));
                } else if let Some((meet, d)) = trees[other].index.nearest(new_point)
                    // Join: the other tree's nearest node within a step, through a free edge.
                    && d <= self.step
                    && checker.segment_free(new_point, trees[other].index.point(meet))
                {
                    joined = Some(if active == 0 {
                        (new, Some(meet))
                    } else {
                        (meet, Some(new))
                    });
                }
            }
            // Swap: the other tree grows next.
            active = other;
        }

        let nodes = trees[0].len() + trees[1].len();
        let stats = common::stats(iterations, nodes, checker.checks, started);
        common::two_tree_plan(&trees, joined, stats)
    }
}

impl Planner for BiRrt {
    fn info(&self) -> PlannerInfo {
        PlannerInfo {
            name: "bi-rrt",
            optimizing: false,
            proves_no_path: false,
            grid_only: false,
        }
    }

    fn plan(
        &self,
        ws: &dyn Workspace,
        query: &Query,
        rng: &mut dyn RngCore,
    ) -> Result<Plan, PlanError> {
        BiRrt::plan(self, ws, query, rng)
    }
}
