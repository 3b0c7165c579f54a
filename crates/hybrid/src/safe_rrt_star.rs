//! Safety-cost RRT*: RRT* whose edge cost adds a penalty for running through the risk
//! zone, then redundant-node removal from the start, then a clamped cubic B-spline.
//!
//! Seed `003_19d461d9f3ced1b0.txt` (MM Science Journal, October 2023), sections 2.1
//! (RRT*: sample, nearest, steer, parent, rewire), 2.2 (risk zones and the safety cost)
//! and 2.3 (redundant-node removal, third-degree B-spline); section 3: "the smoothing
//! method permits the mobile robot to enter the risk region (gray)". The reading
//! (`docs/papers/003-safe-rrt-star.md`, section 3.2): nodes never lie in the risk zone
//! (samples and new nodes there are rejected), edges must avoid Forbidden and cost
//! `|ab| + lambda * (length of ab inside Risk)`, the run stops at the first solution; the
//! path is pruned greedily from the start with segments that avoid Risk and Forbidden,
//! densified so that no control segment is longer than `spline_max_spacing`, and smoothed
//! by the clamped cubic B-spline over those control points, checked against Forbidden
//! only.

use std::time::Instant;

use hyplan_core::{Budget, PlanError, Point2, Query, Workspace, Zone};
use sampling::{CountingChecker, GrowTree, Run, Search};

use crate::Staged;
use crate::common::{self, ZoneView};
use crate::smooth;

/// Safety-cost RRT* with redundant-node removal and B-spline smoothing (seed 003).
///
/// # Zones
///
/// Pass the three-zone map as it is (only Forbidden blocks `segment_free`); the planner
/// reads the risk band through [`Workspace::zone`]. On an [`envmap::GridMap`] (found
/// through [`Workspace::as_any`]) zones are read exactly, cell by cell: the risk length of
/// an edge is the exact length of the segment inside Risk cells. On any other workspace
/// `zone` is sampled along each segment every `step / 16`. Nodes stay out of Risk; edges
/// may cut it (at a cost); the pruned path avoids it except on tree edges kept as they
/// were; the B-spline may enter it at corners but never Forbidden. The width of the risk
/// band is the map's (2 units in our seed-003 maps; the paper gives none).
///
/// # Result
///
/// `path` is the B-spline sampled every `curve_spacing`, every sample pair checked with
/// `segment_free` (colliding spans are pulled onto the control polygon by repeating
/// control points; the pruned polyline is returned if that fails). It starts at the
/// query's start and ends at the goal centre when the last segment to it is free. `cost`
/// is the safety cost of the returned path: length + `safety_weight` x length inside
/// Risk. `stats.nodes` is the tree size. [`plan_detailed`](SafeRrtStar::plan_detailed)
/// also returns the raw RRT* path and the pruned path.
///
/// ```
/// use envmap::GridMap;
/// use hybrid::SafeRrtStar;
/// use hyplan_core::{Goal, Point2, Query, Workspace, Zone};
/// use rand::SeedableRng;
/// let map = GridMap::from_ascii("
///     ......................
///     ......................
///     .........~~~~.........
///     .........~##~.........
///     .........~##~.........
///     .........~~~~.........
///     ......................
///     ......................
/// ")?;
/// let query = Query::new(Point2::new(0.5, 4.0), Goal::Point(Point2::new(21.5, 4.0)));
/// let plan = SafeRrtStar { step: 2.0, ..SafeRrtStar::default() }
///     .plan(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(4))?;
/// assert!(plan.path.windows(2).all(|w| map.segment_free(w[0], w[1])));
/// assert!(plan.path.iter().all(|&p| map.zone(p) != Zone::Forbidden));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`plan_detailed`](Self::plan_detailed) (which also returns the raw RRT* path and the
/// pruned path) and `plan` return [`PlanError::InvalidParameter`] for a bad parameter or
/// budget; [`PlanError::InvalidStart`] / [`PlanError::InvalidGoal`] for a query outside the
/// workspace or in Forbidden; [`PlanError::Disconnected`] when the map proves that no path
/// of this planner can exist (an obstacle wall, or a risk band wider than the edges can
/// cross); [`PlanError::BudgetExhausted`] when no node reached the goal within the budget.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct SafeRrtStar {
    /// "A constant distance": the steering step, world units, finite and > 0. Default 2
    /// (ours; the paper gives none).
    pub step: f64,
    /// A node within this distance of the goal finishes the path, world units, finite and
    /// >= 0. Default 2 (ours).
    pub goal_radius: f64,
    /// Probability in [0, 1] of sampling the goal. Default 0.05 (ours).
    pub goal_bias: f64,
    /// gamma of the neighbour radius `min(gamma * sqrt(ln n / n), max_radius)`, world
    /// units, finite and > 0. Default 62 (ours: Karaman-Frazzoli's gamma* for about 2000
    /// free square units).
    pub gamma: f64,
    /// Cap of the neighbour radius, world units, finite and > 0. Default 5 (ours).
    pub max_radius: f64,
    /// lambda: the cost of one unit of length inside Risk, on top of the length itself,
    /// finite and >= 0 (0 = plain RRT* costs). Default 10 (ours).
    pub safety_weight: f64,
    /// Stop at the first path (default `true`, the paper's "until a path ... is
    /// discovered"), or run the whole budget and keep the cheapest.
    pub stop_at_first_solution: bool,
    /// Rejection draws allowed for one sample in the Free zone, >= 1. Default 1000 (ours).
    pub sample_tries: usize,
    /// d_cp: the pruned path is split into control segments no longer than this before
    /// the B-spline, world units, finite and > 0. Default 5 (ours; the curve then stays
    /// within d_cp / 3 of the corners).
    pub spline_max_spacing: f64,
    /// Spacing of the curve samples, world units, finite and > 0. Default 0.05 (ours).
    pub curve_spacing: f64,
    /// Smooth the pruned path (default `true`); `false` returns the pruned polyline.
    pub smoothing: bool,
    /// N: iteration and optional time limits. Default: unset, [`Budget::samples_for`](hyplan_core::Budget::samples_for) the map
    /// (100 000 iterations, or one per four cells of a grid map when that is more);
    /// the paper's 3000 is in `scenarios/003-*.ron`.
    pub budget: Budget,
}

impl Default for SafeRrtStar {
    fn default() -> Self {
        Self {
            step: 2.0,
            goal_radius: 2.0,
            goal_bias: 0.05,
            gamma: 62.0,
            max_radius: 5.0,
            safety_weight: 10.0,
            stop_at_first_solution: true,
            sample_tries: 1000,
            spline_max_spacing: 5.0,
            curve_spacing: 0.05,
            smoothing: true,
            budget: Budget::default(),
        }
    }
}

impl SafeRrtStar {
    fn validate_params(&self) -> Result<(), PlanError> {
        hyplan_core::check::positive("step", self.step)?;
        hyplan_core::check::non_negative("goal_radius", self.goal_radius)?;
        hyplan_core::check::probability("goal_bias", self.goal_bias)?;
        hyplan_core::check::positive("gamma", self.gamma)?;
        hyplan_core::check::positive("max_radius", self.max_radius)?;
        hyplan_core::check::non_negative("safety_weight", self.safety_weight)?;
        hyplan_core::check::count("sample_tries", self.sample_tries)?;
        hyplan_core::check::positive("spline_max_spacing", self.spline_max_spacing)?;
        hyplan_core::check::positive("curve_spacing", self.curve_spacing)
    }

    /// The proof step before sampling: on a grid map whose only blocked zone is Forbidden,
    /// [`envmap::disconnection_hopping`] (nodes in Free, edges up to
    /// `max(step, goal_radius)` long across the band); on any other workspace, its own
    /// [`Workspace::disconnection`].
    fn check_connected<W: Workspace + ?Sized>(
        &self,
        ws: &W,
        query: &Query,
        started: Instant,
    ) -> Result<(), PlanError> {
        let grid =
            envmap::GridMap::try_of_workspace(ws).filter(|map| map.blocked_from == Zone::Forbidden);
        let cause = match grid {
            Some(map) => envmap::disconnection_hopping(map, query, self.step.max(self.goal_radius)),
            None => ws.disconnection(query),
        };
        sampling::require_connected(cause, started)
    }

    /// One call of [`plan_detailed`](Self::plan_detailed).
    fn staged<W: Workspace + ?Sized>(&self, search: Search<'_, W>) -> Result<Staged, PlanError> {
        self.validate_params()?;
        let mut run = Run::start(self.step, &self.budget, search.ws, search.query)?;
        self.check_connected(search.ws, search.query, run.started())?;
        let goal = search.query.goal;
        let target = goal.center();
        let bounds = search.ws.bounds();
        let view = ZoneView::new(search.ws, self.step / 16.0);
        let lambda = self.safety_weight;
        // Edge cost: length plus lambda times the length inside Risk.
        let edge_cost = |a: Point2, b: Point2| {
            let len = (b - a).norm();
            if lambda == 0.0 {
                len
            } else {
                len + lambda * view.risk_length(a, b)
            }
        };
        let mut checker = CountingChecker::new(search.ws);
        let mut tree = GrowTree::with_costs(search.query.start);
        // Goal links: (tree node, point appended after it, if any).
        let mut links: Vec<(usize, Option<Point2>)> = Vec::new();
        if (search.query.start - target).norm() <= self.goal_radius
            || goal.contains(search.query.start)
        {
            links.extend(
                common::finish_at_goal(&mut checker, &goal, search.query.start).map(|e| (0, e)),
            );
        }
        let mut near: Vec<(usize, f64)> = Vec::new();
        let mut candidates: Vec<(f64, usize)> = Vec::new();

        while (!self.stop_at_first_solution || links.is_empty()) && run.next_iteration() {
            // Sample: the goal, or a point in the Free zone (no samples in Risk, 2.2).
            let sample = if hyplan_core::uniform01(search.rng) < self.goal_bias {
                Some(target)
            } else {
                sampling::sample_accepted(&bounds, self.sample_tries, search.rng, |p| {
                    checker.checks += 1;
                    view.zone(p) == Zone::Free
                })
            };
            let Some(sample) = sample else { continue };
            // Nearest and steer.
            let Some(step) = tree.step_towards(sample, self.step) else {
                break;
            };
            let new_point = step.to;
            if new_point == step.from {
                continue;
            }
            // New nodes stay out of Risk (the goal itself excepted) and edges out of
            // Forbidden.
            checker.checks += 1;
            if (new_point != target && view.zone(new_point) != Zone::Free)
                || !checker.segment_free(step.from, new_point)
            {
                continue;
            }
            // Near: the ball of radius min(gamma sqrt(ln n / n), max_radius).
            let n = tree.len() as f64 + 1.0;
            let radius = (self.gamma * (n.ln() / n).sqrt()).min(self.max_radius);
            tree.within_into(new_point, radius, &mut near);
            // Parent: the cheapest cost-to-come through an edge free of Forbidden.
            let through_nearest = tree.cost(step.near) + edge_cost(step.from, new_point);
            let (parent, cost) = tree.choose_parent(
                new_point,
                (step.near, through_nearest),
                &near,
                |q, _| edge_cost(q, new_point),
                &mut checker,
                &mut candidates,
            );
            let new = tree.add_with_cost(new_point, parent, cost);
            // Rewire: neighbours that become cheaper through the new node.
            tree.rewire(new, &near, |q, _| edge_cost(new_point, q), &mut checker);
            // Goal test.
            if (new_point - target).norm() <= self.goal_radius || goal.contains(new_point) {
                links.extend(
                    common::finish_at_goal(&mut checker, &goal, new_point).map(|e| (new, e)),
                );
            }
        }

        let mut stats = run.stats(tree.len(), checker.checks);
        let link_cost = |&(i, e): &(usize, Option<Point2>)| {
            tree.cost(i) + e.map_or(0.0, |e| edge_cost(tree.point(i), e))
        };
        let best = links
            .iter()
            .min_by(|a, b| link_cost(a).total_cmp(&link_cost(b)).then(a.0.cmp(&b.0)));
        let Some(&(leaf, end)) = best else {
            return Err(PlanError::BudgetExhausted { stats });
        };
        let raw = common::branch_to_goal(&tree, leaf, end);
        // Redundant-node removal (2.3): greedy from the start, segments avoiding Risk too.
        let reduced = postproc::shortcut_greedy(&raw, |a, b| {
            checker.checks += 1;
            view.safe_segment(a, b)
        });
        // B-spline (2.3) over the densified control polygon, checked against Forbidden.
        let curve = smooth::fit_if(self.smoothing, &reduced, |nodes| {
            let control = postproc::densify(nodes, self.spline_max_spacing);
            smooth::fit_checked(
                &control,
                postproc::Fit::BSpline,
                self.curve_spacing,
                |a, b| checker.segment_free(a, b),
            )
        });
        let cost = curve.points.windows(2).map(|w| edge_cost(w[0], w[1])).sum();
        stats.collision_checks = checker.checks;
        stats.elapsed = run.started().elapsed();
        // The B-spline's control points are the reduced path's nodes.
        let mut staged = curve.into_staged(self.smoothing, tree.into_tree(), stats, raw, reduced);
        staged.plan.cost = cost;
        Ok(staged)
    }
}

sampling::impl_planner!(SafeRrtStar, "safe-rrt-star", optimizing: |planner| !planner.stop_at_first_solution, staged: Staged);
