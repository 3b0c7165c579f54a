//! RRT*: RRT with choose-parent and rewiring (Karaman and Frazzoli 2011), the asymptotically
//! optimal variant that seed `003` builds on.

use hyplan_core::{Budget, Plan, PlanError, Point2, Workspace};

use crate::toolkit::{self, CountingChecker};
use crate::{GrowTree, Run, Search};

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

    /// One call of [`plan_with`](Self::plan_with).
    fn search<W: Workspace + ?Sized>(&self, search: Search<'_, W>) -> Result<Plan, PlanError> {
        let mut run = Run::start(self.step, &self.budget, search.ws, search.query)?;
        hyplan_core::check::probability("goal_bias", self.goal_bias)?;
        self.validate_rewire()?;
        run.check_connected(search.ws, search.query)?;
        let goal = search.query.goal;
        let bounds = search.ws.bounds();
        let gamma = match self.rewire {
            RewireRadius::Auto => {
                1.1 * 2.0 * (1.5 * bounds.width() * bounds.height() / std::f64::consts::PI).sqrt()
            }
            RewireRadius::Gamma(g) => g,
            RewireRadius::KNearest(_) => 0.0,
        };
        let mut checker = CountingChecker::new(search.ws);
        let mut tree = GrowTree::with_costs(search.query.start);
        // Nodes in the goal region; the best is chosen at the end (rewiring changes costs).
        let mut goal_nodes: Vec<usize> = Vec::new();
        let mut exact_goal_node: Option<usize> = None;
        if goal.contains(search.query.start) {
            goal_nodes.push(0);
        }
        let mut near: Vec<(usize, f64)> = Vec::new();
        let mut candidates: Vec<(f64, usize)> = Vec::new();

        while (!self.stop_at_first_solution || goal_nodes.is_empty()) && run.next_iteration() {
            let progress = || {
                let best = goal_nodes.iter().map(|&g| tree.cost(g));
                (tree.len(), best.min_by(f64::total_cmp))
            };
            if run.observe(search.observer, progress).is_break() {
                break;
            }
            // Sample: the goal centre with probability goal_bias, else uniform in the bounds.
            let sample =
                toolkit::sample_goal_biased(search.ws, goal.center(), self.goal_bias, search.rng);
            // Nearest and steer: at most one step from the nearest node towards the sample.
            let Some(step) = tree.step_towards(sample, self.step) else {
                break;
            };
            let new_point = step.to;
            // Segment free: the edge from the nearest node, exactly.
            if new_point == step.from || !checker.segment_free(step.from, new_point) {
                continue;
            }
            // Near: the neighbours considered as parents and for rewiring.
            let n = tree.len() as f64;
            match self.rewire {
                RewireRadius::KNearest(k) => near = tree.nearest_k(new_point, k),
                _ => {
                    let radius = (gamma * ((n + 1.0).ln() / (n + 1.0)).sqrt()).min(self.step);
                    tree.within_into(new_point, radius, &mut near);
                }
            }
            // Choose parent: the cheapest cost-to-come through a free edge.
            let through_nearest = tree.cost(step.near) + (new_point - step.from).norm();
            let length = |_: Point2, d: f64| d;
            let (parent, cost) = tree.choose_parent(
                new_point,
                (step.near, through_nearest),
                &near,
                length,
                &mut checker,
                &mut candidates,
            );
            // Add the new node under its chosen parent; rewire the neighbours that become
            // cheaper through it.
            let new = tree.add_with_cost(new_point, parent, cost);
            tree.rewire(new, &near, length, &mut checker);
            // Goal test: in the goal region, or an exact goal point one free step away.
            if goal.contains(new_point) {
                goal_nodes.push(new);
            } else if exact_goal_node.is_none()
                && let Some(id) = tree.join_goal(new, &goal, self.step, &mut checker)
            {
                exact_goal_node = Some(id);
                goal_nodes.push(id);
            }
        }

        let stats = run.stats(tree.len(), checker.checks);
        let best = goal_nodes
            .iter()
            .copied()
            .min_by(|&a, &b| tree.cost(a).total_cmp(&tree.cost(b)).then(a.cmp(&b)));
        tree.into_plan(best, stats)
    }
}

crate::impl_planner!(RrtStar, "rrt-star", optimizing: |planner| !planner.stop_at_first_solution, plan: search);
