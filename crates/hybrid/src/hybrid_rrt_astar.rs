//! Hybrid RRT-A*: a goal-biased RRT that launches bounded A* sub-searches once it reaches
//! the goal area.
//!
//! Seed `002_6cddcbbe62b23f10.txt` (Al-Ansarry and Al-Darraji, 2021), section III,
//! Algorithms 1-2 and the flowchart of Fig. 2. The reading
//! (`docs/papers/002-hybrid-rrt-astar.md`, section 3.2): a sub-search starts from q_new
//! when q_new lies within the goal threshold (13) of the goal **and** at least the A*
//! threshold (7) away from every earlier sub-search start. Each sub-search is a fresh
//! 8-connected grid A* (octile costs, Euclidean heuristic, no corner cutting) from q_new's
//! cell to the goal's cell that gives up after 150 expanded ("visited") nodes. On success
//! the plan is the tree branch to q_new followed by the A* cells; on giving up, RRT growth
//! continues. The paper's "Cost (node)" is the tree size plus the nodes visited by the
//! sub-searches, reported as `stats.nodes`.

use envmap::GridMap;
use hyplan_core::{Budget, PlanError, Point2, Workspace};
use sampling::{CountingChecker, Extension, GrowTree, Run, Search};
use search::GridOptions;

use crate::Staged;
use crate::common;

/// Which earlier sub-search starts the A* threshold is measured against.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum SpacingRule {
    /// Every earlier start (default, our reading: a failed search is not relaunched from
    /// the same place when the goal bias drives the tree back and forth).
    #[default]
    All,
    /// Only the last start (the other reading of the text's "the last one").
    Last,
}

/// Hybrid RRT-A* (seed 002): goal-biased RRT with bounded grid A* sub-searches in the goal
/// area.
///
/// # Zones and workspace
///
/// The workspace must be an [`envmap::GridMap`] (found through [`Workspace::as_any`]),
/// since the sub-searches run on its cells. The map's
/// [`blocked_from`](GridMap::blocked_from) decides what blocks. Seed 002 pads its
/// obstacles by one cell (dilate the Forbidden cells before planning, e.g. with a 1-cell
/// safety radius) and has no risk band: pass the padded map as it is.
///
/// # Result
///
/// `path` is the tree branch to the node that launched the successful sub-search, then
/// the centres of the A* cells, ending at the goal centre (or the branch to a tree node
/// that reached the goal by itself). Every segment is checked with `segment_free`.
/// `stats.nodes` is the paper's "Cost (node)": tree nodes plus the nodes expanded by all
/// sub-searches; `stats.expansions` the sub-search part alone; `stats.iterations` the RRT
/// iterations. [`plan_detailed`](HybridRrtAstar::plan_detailed) also counts the
/// sub-searches launched and given up.
///
/// ```
/// use envmap::GridMap;
/// use hybrid::HybridRrtAstar;
/// use hyplan_core::{Goal, Point2, Query, Workspace};
/// use rand::SeedableRng;
/// let map = GridMap::from_ascii("
///     ....................
///     ....................
///     ......#######.......
///     ....................
///     ....................
/// ")?;
/// let query = Query::new(Point2::new(10.5, 4.5), Goal::Point(Point2::new(10.5, 0.5)));
/// let staged = HybridRrtAstar::default()
///     .plan_detailed(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(2))?;
/// assert!(staged.astar_runs >= 1);
/// assert_eq!(*staged.plan.path.last().unwrap(), Point2::new(10.5, 0.5));
/// assert!(staged.plan.path.windows(2).all(|w| map.segment_free(w[0], w[1])));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`plan_detailed`](Self::plan_detailed) (which also counts the sub-searches launched
/// and given up) and `plan` return [`PlanError::InvalidParameter`] for a bad parameter or
/// budget (through the [`Planner`](hyplan_core::Planner) trait also named `workspace` when
/// the workspace is not a grid map); [`PlanError::InvalidStart`] /
/// [`PlanError::InvalidGoal`] for a query outside the map or blocked;
/// [`PlanError::Disconnected`] when the map's passable cells do not join start and goal;
/// [`PlanError::BudgetExhausted`] when neither the tree nor a sub-search reached the goal
/// within the budget.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct HybridRrtAstar {
    /// RRT step size, world units, finite and > 0. Default 1 (the paper's).
    pub step: f64,
    /// Probability in [0, 1] of sampling the goal. Default 0.25 (the paper's).
    pub goal_bias: f64,
    /// T, the goal area radius within which sub-searches may start, world units, finite
    /// and >= 0. Default 13 (the paper's).
    pub goal_threshold: f64,
    /// D, the A* threshold: the least distance between two sub-search starts, world
    /// units, finite and >= 0. Default 7 (the paper's).
    pub astar_spacing: f64,
    /// Which earlier starts `astar_spacing` is measured against. Default
    /// [`SpacingRule::All`] (ours).
    pub spacing_rule: SpacingRule,
    /// Nodes a sub-search may expand before it gives up, >= 1. Default 150 (the paper's
    /// "Steps-threshold", Fig. 2).
    pub astar_max_visited: usize,
    /// The RRT's iteration and optional time limits. Default: unset, [`Budget::samples_for`](hyplan_core::Budget::samples_for) the map
    /// (100 000 iterations, or one per four cells of a grid map when that is more);
    /// the paper's 30 000 is in `scenarios/002-*.ron`.
    pub budget: Budget,
}

impl Default for HybridRrtAstar {
    fn default() -> Self {
        Self {
            step: 1.0,
            goal_bias: 0.25,
            goal_threshold: 13.0,
            astar_spacing: 7.0,
            spacing_rule: SpacingRule::All,
            astar_max_visited: 150,
            budget: Budget::default(),
        }
    }
}

impl HybridRrtAstar {
    fn validate_params(&self) -> Result<(), PlanError> {
        hyplan_core::check::positive("step", self.step)?;
        hyplan_core::check::probability("goal_bias", self.goal_bias)?;
        hyplan_core::check::non_negative("goal_threshold", self.goal_threshold)?;
        hyplan_core::check::non_negative("astar_spacing", self.astar_spacing)?;
        hyplan_core::check::count("astar_max_visited", self.astar_max_visited)
    }

    /// One call of [`plan_detailed`](Self::plan_detailed).
    fn staged(&self, search: Search<'_, GridMap>) -> Result<Staged, PlanError> {
        let map = search.ws;
        self.validate_params()?;
        let mut run = Run::start(self.step, &self.budget, map, search.query)?;
        run.check_connected(map, search.query)?;
        let goal = search.query.goal;
        let target = goal.center();
        let goal_cell = map.world_to_cell(target).ok_or(PlanError::InvalidGoal {
            point: target,
            reason: "outside the map",
        })?;
        let mut checker = CountingChecker::new(map);
        let mut tree = GrowTree::rooted_at(search.query.start);
        // The goal-biased samples draw the goal's centre again and again.
        tree.watch_goal(target);
        let mut starts: Vec<Point2> = Vec::new();
        let (mut visited_total, mut runs, mut failures) = (0_u64, 0_u32, 0_u32);
        // (leaf node, points after it to the goal)
        let mut done: Option<(usize, Vec<Point2>)> = None;
        if goal.contains(search.query.start) {
            done = Some((0, Vec::new()));
        }

        while done.is_none() && run.next_iteration() {
            // Phase 1 (Algorithm 1): goal-biased sample, nearest vertex, one step.
            let sample = sampling::sample_goal_biased(map, target, self.goal_bias, search.rng);
            let new = match tree.extend(sample, self.step, &mut checker) {
                Extension::Added { new, .. } => new,
                Extension::Refused => continue,
                Extension::NoNode => break,
            };
            let new_point = tree.point(new);
            // The tree reaches the goal by itself ("Is this node the goal?").
            let dist = (new_point - target).norm();
            if (dist <= self.step || goal.contains(new_point))
                && let Some(end) = common::finish_at_goal(&mut checker, &goal, new_point)
            {
                done = Some((new, end.into_iter().collect()));
                break;
            }
            // Condition 1: inside the goal area; condition 2: far enough from earlier
            // sub-search starts.
            if dist > self.goal_threshold || !self.spaced(&starts, new_point) {
                continue;
            }
            starts.push(new_point);
            // Phase 2 (Algorithm 2): a bounded A* sub-search to the goal.
            let Some(from) = map.world_to_cell(new_point) else {
                continue;
            };
            runs += 1;
            let (cells, visited) = common::grid_astar(
                map,
                from,
                goal_cell,
                GridOptions::default(),
                self.astar_max_visited,
            );
            visited_total += visited;
            match cells.and_then(|c| self.join(map, &mut checker, new_point, &c, target)) {
                Some(tail) => done = Some((new, tail)),
                None => failures += 1,
            }
        }

        let mut stats = run.stats(tree.len(), checker.checks);
        stats.nodes += visited_total;
        stats.expansions = visited_total;
        let Some((leaf, tail)) = done else {
            return Err(PlanError::BudgetExhausted { stats });
        };
        let path = common::branch_to_goal(&tree, leaf, tail);
        stats.elapsed = run.started().elapsed();
        Ok(Staged {
            plan: sampling::plan_of_path(path.clone(), vec![tree.into_tree()], stats),
            raw: path.clone(),
            reduced: path,
            astar_runs: runs,
            astar_failures: failures,
            ..Staged::default()
        })
    }

    /// Condition 2 of a sub-search start: at least `astar_spacing` from the earlier starts
    /// the spacing rule names.
    fn spaced(&self, starts: &[Point2], p: Point2) -> bool {
        match self.spacing_rule {
            SpacingRule::All => starts.iter().all(|s| (s - p).norm() >= self.astar_spacing),
            SpacingRule::Last => starts
                .last()
                .is_none_or(|s| (s - p).norm() >= self.astar_spacing),
        }
    }

    /// The points after `from` along the A* cells to `target`: cell centres, the last one
    /// replaced by the target; every segment checked, with the end cells' centres kept
    /// where a joint to a continuous point is not free. `None` if a segment fails.
    fn join<W: Workspace + ?Sized>(
        &self,
        map: &GridMap,
        checker: &mut CountingChecker<'_, W>,
        from: Point2,
        cells: &[(usize, usize)],
        target: Point2,
    ) -> Option<Vec<Point2>> {
        let centre = |c: (usize, usize)| map.cell_center(c.0, c.1);
        let mut out: Vec<Point2> = vec![from];
        out.extend(
            cells[1..cells.len().saturating_sub(1)]
                .iter()
                .map(|&c| centre(c)),
        );
        out.push(target);
        common::anchor_cell_path(map, checker, out, cells)
    }
}

sampling::impl_planner!(HybridRrtAstar, "hybrid-rrt-astar", grid_only, staged: Staged);
