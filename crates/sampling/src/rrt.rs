//! RRT: the rapidly-exploring random tree (LaValle 1998), as seed
//! `000_9b224721fe327833.txt` section 4.2 describes it: grow a tree from the start by
//! extending the nearest node one step towards a random sample, until a node reaches the
//! goal region.

use hyplan_core::{Budget, Plan, PlanError, Workspace};

use crate::toolkit::{self, CountingChecker};
use crate::{Extension, GrowTree, Run, Search};

/// The RRT planner's parameters.
///
/// The goal region comes from the [`Query`](hyplan_core::Query): with
/// [`Goal::Disc`](hyplan_core::Goal::Disc) of radius `r > 0` the search stops at the first
/// node within `r` of the goal centre; with [`Goal::Point`](hyplan_core::Goal::Point) (or
/// radius 0) a node within `step` of the goal is joined to it by an exact edge check, so
/// the path ends exactly at the goal.
///
/// Every edge is checked with [`Workspace::segment_free`], so the returned path is
/// collision-free in the workspace's own (exact) model. The only randomness is the `rng`
/// passed to [`plan`](Rrt::plan): same seed, same tree, bit for bit (with an iteration
/// budget; a time limit can stop two runs at different iterations).
///
/// ```
/// use envmap::GridMap;
/// use hyplan_core::{Goal, Point2, Query};
/// use rand::SeedableRng;
/// use sampling::Rrt;
///
/// let map = GridMap::from_ascii("
///     ..........
///     ..........
///     ....##....
///     ....##....
///     ..........
/// ")?;
/// let query = Query::new(Point2::new(0.5, 0.5), Goal::disc(Point2::new(9.5, 4.5), 0.5));
/// let rrt = Rrt { step: 1.0, ..Rrt::default() };
/// let plan = rrt.plan(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(7))?;
/// assert_eq!(plan.path[0], query.start);
/// assert!(query.goal.contains(*plan.path.last().unwrap()));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct Rrt {
    /// Maximum length of a new edge, world units, finite and > 0. Default 1.0.
    pub step: f64,
    /// Probability in [0, 1] of sampling the goal centre instead of a uniform point.
    /// Default 0.05 (OMPL's).
    pub goal_bias: f64,
    /// Iteration (samples drawn) and optional time limits.
    /// Default: unset, [`Budget::samples_for`](hyplan_core::Budget::samples_for) the map
    /// (100 000 iterations, or one per four cells of a grid map when that is more).
    pub budget: Budget,
}

impl Default for Rrt {
    fn default() -> Self {
        Self {
            step: 1.0,
            goal_bias: 0.05,
            budget: Budget::default(),
        }
    }
}

impl Rrt {
    /// One call of [`plan_with`](Self::plan_with).
    fn search<W: Workspace + ?Sized>(&self, search: Search<'_, W>) -> Result<Plan, PlanError> {
        let mut run = Run::start(self.step, &self.budget, search.ws, search.query)?;
        hyplan_core::check::probability("goal_bias", self.goal_bias)?;
        run.check_connected(search.ws, search.query)?;
        let goal = search.query.goal;
        let mut checker = CountingChecker::new(search.ws);
        let mut tree = GrowTree::rooted_at(search.query.start);
        // The goal-biased samples draw the goal's centre again and again.
        tree.watch_goal(goal.center());
        let mut reached = goal.contains(search.query.start).then_some(0_usize);

        while reached.is_none() && run.next_iteration() {
            if run
                .observe(search.observer, || (tree.len(), None))
                .is_break()
            {
                break;
            }
            // Sample: the goal centre with probability goal_bias, else uniform in the bounds.
            let sample =
                toolkit::sample_goal_biased(search.ws, goal.center(), self.goal_bias, search.rng);
            // Nearest, steer one step towards the sample, check the edge exactly, add.
            let new = match tree.extend(sample, self.step, &mut checker) {
                Extension::Added { new, .. } => new,
                Extension::Refused => continue,
                Extension::NoNode => break,
            };
            // Goal test: inside the goal region, or an exact goal point one free step away.
            reached = if goal.contains(tree.point(new)) {
                Some(new)
            } else {
                tree.join_goal(new, &goal, self.step, &mut checker)
            };
        }

        let stats = run.stats(tree.len(), checker.checks);
        tree.into_plan(reached, stats)
    }
}

crate::impl_planner!(Rrt, "rrt", optimizing: |_rrt| false, plan: search);
