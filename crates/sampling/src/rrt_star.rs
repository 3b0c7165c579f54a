//! RRT*: RRT with choose-parent and rewiring (Karaman and Frazzoli 2011), the asymptotically
//! optimal variant that seed `003` builds on.

use std::ops::ControlFlow;
use std::time::Instant;

use hyplan_core::{
    Budget, Plan, PlanError, Planner, PlannerInfo, Progress, Query, Tree, Workspace,
};
use rand::{Rng, RngCore};

use crate::common;
use crate::toolkit::{self, CountingChecker, StarTree};

/// How RRT* picks the neighbours it considers as parents and rewires.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum RewireRadius {
    /// The ball of radius `gamma * sqrt(ln n / n)` (n = nodes in the tree), capped by the
    /// step, with `gamma = 1.1 * 2 * sqrt(1.5 * area / pi)` computed from the workspace
    /// bounds (OMPL's `r_rrt` with its default rewire factor 1.1).
    Auto,
    /// The ball of radius `gamma * sqrt(ln n / n)`, capped by the step; `gamma` in world
    /// units, finite and > 0.
    Gamma(f64),
    /// The `k` nearest nodes (k >= 1).
    KNearest(usize),
}

/// The RRT* planner's parameters.
///
/// Each iteration samples, steers from the nearest node as RRT does, then chooses as parent
/// the neighbour that gives the new node the cheapest path from the start (edge checked
/// exactly), and rewires the neighbours through the new node when that shortens their
/// paths. Costs are path lengths in world units.
///
/// With `stop_at_first_solution` the run ends as soon as a node reaches the goal region
/// (OMPL's RRT* with an infinite cost threshold); otherwise it uses the whole budget and
/// returns the cheapest goal node, whose cost never increases with more iterations.
///
/// Goal handling is RRT's (see [`Rrt`](crate::Rrt)): a disc goal is reached by any node in
/// it, an exact goal point is joined by an exact edge check from a node within one step.
///
/// ```
/// use envmap::GridMap;
/// use hyplan_core::{Budget, Goal, Point2, Query};
/// use rand::SeedableRng;
/// use sampling::RrtStar;
///
/// let map = GridMap::from_ascii("
///     ..........
///     ....##....
///     ....##....
///     ..........
/// ")?;
/// let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(9.5, 3.5)));
/// let planner = RrtStar {
///     step: 2.0,
///     budget: Budget::iterations(2_000),
///     stop_at_first_solution: false,
///     ..RrtStar::default()
/// };
/// let plan = planner.plan(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(1))?;
/// assert_eq!(*plan.path.last().unwrap(), Point2::new(9.5, 3.5));
/// assert!(plan.cost < 11.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct RrtStar {
    /// Maximum length of a new edge, world units, finite and > 0. Default 1.0.
    pub step: f64,
    /// Probability in [0, 1] of sampling the goal centre. Default 0.05 (OMPL's).
    pub goal_bias: f64,
    /// Iteration (samples drawn) and optional time limits.
    /// Default: unset, [`Budget::samples_for`](hyplan_core::Budget::samples_for) the map
    /// (100 000 iterations, or one per four cells of a grid map when that is more).
    pub budget: Budget,
    /// Neighbourhood rule for choose-parent and rewiring. Default [`RewireRadius::Auto`].
    pub rewire: RewireRadius,
    /// Stop at the first node that reaches the goal (default `true`), or spend the whole
    /// budget improving the path.
    pub stop_at_first_solution: bool,
}

impl Default for RrtStar {
    fn default() -> Self {
        Self {
            step: 1.0,
            goal_bias: 0.05,
            budget: Budget::default(),
            rewire: RewireRadius::Auto,
            stop_at_first_solution: true,
        }
    }
}

impl RrtStar {
    fn validate_rewire(&self) -> Result<(), PlanError> {
        match self.rewire {
            RewireRadius::Gamma(g) if !(g.is_finite() && g > 0.0) => {
                Err(PlanError::InvalidParameter {
                    name: "rewire.gamma",
                    value: format!("{g}"),
                    reason: "must be finite and > 0 (world units)",
                })
            }
            RewireRadius::KNearest(0) => Err(PlanError::InvalidParameter {
                name: "rewire.k",
                value: "0".into(),
                reason: "must be at least 1",
            }),
            _ => Ok(()),
        }
    }

    /// Plans a path for `query` in `ws`, drawing every random number from `rng`.
    ///
    /// # Errors
    ///
    /// [`PlanError::InvalidParameter`] for a bad step, goal bias, rewiring rule or budget;
    /// [`PlanError::InvalidStart`] / [`PlanError::InvalidGoal`] for a query outside the
    /// workspace or blocked; [`PlanError::BudgetExhausted`] (with the statistics) when no
    /// node reached the goal region within the budget.
    pub fn plan<W: Workspace + ?Sized, R: Rng + ?Sized>(
        &self,
        ws: &W,
        query: &Query,
        rng: &mut R,
    ) -> Result<Plan, PlanError> {
        self.plan_with(ws, query, rng, &mut common::keep_going)
    }

    /// [`plan`](Self::plan) with an observer, called every 64 iterations with the progress
    /// (including the best cost so far); `ControlFlow::Break(())` stops the run and returns
    /// the best path found so far, or [`PlanError::BudgetExhausted`] if there is none.
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
        let budget = self.budget.for_sampling(ws.cells());
        toolkit::validate_step_and_budget(self.step, &budget, ws, query)?;
        hyplan_core::check::probability("goal_bias", self.goal_bias)?;
        self.validate_rewire()?;
        toolkit::check_connected(ws, query, started)?;
        let goal = query.goal;
        let bounds = ws.bounds();
        let gamma = match self.rewire {
            RewireRadius::Auto => {
                1.1 * 2.0 * (1.5 * bounds.width() * bounds.height() / std::f64::consts::PI).sqrt()
            }
            RewireRadius::Gamma(g) => g,
            RewireRadius::KNearest(_) => 0.0,
        };
        let mut checker = CountingChecker::new(ws);
        let mut tree = StarTree::rooted_at(query.start);
        // Nodes in the goal region; the best is chosen at the end (rewiring changes costs).
        let mut goal_nodes: Vec<usize> = Vec::new();
        let mut exact_goal_node: Option<usize> = None;
        if goal.contains(query.start) {
            goal_nodes.push(0);
        }
        let mut iterations = 0_u64;
        let mut near: Vec<(usize, f64)> = Vec::new();
        let mut candidates: Vec<(f64, usize, f64)> = Vec::new();

        while (!self.stop_at_first_solution || goal_nodes.is_empty())
            && !budget.exhausted(iterations, started)
        {
            iterations += 1;
            if iterations.is_multiple_of(common::OBSERVE_EVERY) {
                let progress = Progress {
                    iterations,
                    nodes: tree.parent.len() as u64,
                    best_cost: goal_nodes
                        .iter()
                        .map(|&g| tree.cost[g])
                        .min_by(f64::total_cmp),
                };
                if observer(&progress).is_break() {
                    break;
                }
            }
            // Sample: the goal centre with probability goal_bias, else uniform in the bounds.
            let sample = toolkit::sample_goal_biased(ws, goal.center(), self.goal_bias, rng);
            // Nearest: the tree node closest to the sample.
            let Some((nearest, _)) = tree.index.nearest(sample) else {
                break;
            };
            let nearest_point = tree.index.point(nearest);
            // Steer: at most one step towards the sample.
            let new_point = toolkit::steer(nearest_point, sample, self.step);
            if new_point == nearest_point {
                continue;
            }
            // Segment free: the edge from the nearest node, exactly.
            if !checker.segment_free(nearest_point, new_point) {
                continue;
            }
            // Near: the neighbours considered as parents and for rewiring.
            let n = tree.parent.len() as f64;
            match self.rewire {
                RewireRadius::KNearest(k) => near = tree.index.nearest_k(new_point, k),
                _ => {
                    let radius = (gamma * ((n + 1.0).ln() / (n + 1.0)).sqrt()).min(self.step);
                    tree.index.within_into(new_point, radius, &mut near);
                }
            }
            // Choose parent: the cheapest cost-to-come through a free edge; the nearest node
            // is known to be free, so candidates cheaper than it are checked in cost order.
            let nearest_cost = tree.cost[nearest] + (new_point - nearest_point).norm();
            candidates.clear();
            candidates.extend(
                near.iter()
                    .filter(|&&(i, _)| i != nearest)
                    .map(|&(i, d)| (tree.cost[i] + d, i, d))
                    .filter(|&(c, _, _)| c < nearest_cost),
            );
            candidates.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            let mut parent = (nearest, nearest_cost);
            for &(c, i, _) in &candidates {
                if checker.segment_free(tree.index.point(i), new_point) {
                    parent = (i, c);
                    break;
                }
            }
            // Add the new node under its chosen parent.
            let new = tree.add(new_point, parent.0, parent.1);
            // Rewire: neighbours that become cheaper through the new node change parent.
            for &(i, d) in &near {
                if i == parent.0 {
                    continue;
                }
                let through_new = parent.1 + d;
                if through_new < tree.cost[i]
                    && checker.segment_free(new_point, tree.index.point(i))
                {
                    tree.reparent(i, new, through_new);
                }
            }
            // Goal test: in the goal region, or an exact goal point one free step away.
            if goal.contains(new_point) {
                goal_nodes.push(new);
            } else if exact_goal_node.is_none()
                && let Some(g) = common::exact_goal_within(&goal, new_point, self.step)
                && checker.segment_free(new_point, g)
            {
                let id = tree.add(g, new, parent.1 + (g - new_point).norm());
                exact_goal_node = Some(id);
                goal_nodes.push(id);
            }
        }

        let points = tree.points();
        let stats = common::stats(iterations, points.len(), checker.checks, started);
        let best = goal_nodes
            .iter()
            .copied()
            .min_by(|&a, &b| tree.cost[a].total_cmp(&tree.cost[b]).then(a.cmp(&b)));
        let tree = Tree {
            points,
            parent: tree.parent,
        };
        common::tree_plan(tree, best, stats)
    }
}

impl Planner for RrtStar {
    fn info(&self) -> PlannerInfo {
        PlannerInfo {
            name: "rrt-star",
            optimizing: !self.stop_at_first_solution,
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
        RrtStar::plan(self, ws, query, rng)
    }
}
