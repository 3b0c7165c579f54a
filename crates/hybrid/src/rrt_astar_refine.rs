//! RRT + A* refinement: a plain RRT path whose stretches near obstacles are re-planned by
//! grid A*, then shortcut greedily.
//!
//! Seed `001_7c0427b868de6fdd.txt` (Yin), section 2.3: "leverages the exploration
//! capability of RRT to generate an initial path", then "for each path node, it checks
//! whether the node is near an obstacle (i.e., whether there is an obstacle within a
//! certain radius). For regions near obstacles, the algorithm replans the path between
//! these nodes using the A-Star algorithm", and finally connects nodes directly where the
//! line is free. The reading (`docs/papers/001-rrt-astar-refine.md`, section 3.1): every
//! maximal run of path nodes whose clearance is below `near_radius` is re-planned by
//! 8-connected grid A* (`search::GridSearch`: octile costs and heuristic, no corner
//! cutting, whole map) between the last node
//! before the run and the first node after it; the result is shortcut greedily from the
//! start. The paper gives no parameter values: every default is ours.

use std::time::Instant;

use envmap::GridMap;
use hyplan_core::{Budget, Plan, PlanError, PlanStats, Point2, Workspace};
use sampling::{CountingChecker, Rrt, Search};
use search::{GridOptions, GridSearch};

use crate::Staged;
use crate::common;

/// RRT + A* near-obstacle refinement (seed 001).
///
/// # Zones and workspace
///
/// The workspace must be an [`envmap::GridMap`] (found through
/// [`Workspace::as_any`]), since the refinement runs grid A*. The map's
/// [`blocked_from`](GridMap::blocked_from) decides what blocks, for the RRT, the A* and
/// the clearance test alike: seed 001 has no risk band, so pass the map as it is (only
/// Forbidden blocks), or `avoiding_risk()` to keep out of a band.
///
/// # Result
///
/// `path` is the shortcut polyline: it starts at the query's start and ends at the goal
/// (the RRT joins an exact goal point from within one step, or stops inside a goal disc).
/// `trees` holds the RRT tree; `stats.nodes` its size, `stats.iterations` the RRT's,
/// `stats.expansions` the sum over the A* searches, and
/// `stats.collision_checks` all checks made. [`plan_detailed`](RrtAstarRefine::plan_detailed)
/// also returns the raw RRT path and the refined path before the shortcut.
///
/// ```
/// use envmap::GridMap;
/// use hybrid::RrtAstarRefine;
/// use hyplan_core::{Goal, Point2, Query, Workspace};
/// use rand::SeedableRng;
/// let map = GridMap::from_ascii("
///     ....................
///     ........#...........
///     ........#...........
///     ........#...........
///     ....................
/// ")?;
/// let query = Query::new(Point2::new(0.5, 2.5), Goal::Point(Point2::new(19.5, 2.5)));
/// let staged = RrtAstarRefine { step: 2.0, near_radius: 2.0, ..RrtAstarRefine::default() }
///     .plan_detailed(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(5))?;
/// let path = &staged.plan.path;
/// assert!(path.windows(2).all(|w| map.segment_free(w[0], w[1])));
/// assert!(staged.plan.length() <= hyplan_core::path_length(&staged.raw) + 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`plan_detailed`](Self::plan_detailed) (which also returns the raw RRT path and the
/// refined path before the shortcut) and `plan` return [`PlanError::InvalidParameter`] for
/// a bad parameter or budget (through the [`Planner`](hyplan_core::Planner) trait also
/// named `workspace` when the workspace is not a grid map); [`PlanError::InvalidStart`] /
/// [`PlanError::InvalidGoal`] for a query outside the map or blocked;
/// [`PlanError::Disconnected`] when the map's passable cells do not join start and goal
/// (checked by the RRT before sampling); [`PlanError::BudgetExhausted`] when the RRT does
/// not reach the goal within its budget.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct RrtAstarRefine {
    /// RRT step, world units, finite and > 0. Default 3 (ours: 3 % of the paper's 100-cell
    /// map side).
    pub step: f64,
    /// Probability in [0, 1] of sampling the goal centre. Default 0.05 (ours; the paper
    /// has none).
    pub goal_bias: f64,
    /// A path node is "near an obstacle" when a blocked cell lies closer than this, world
    /// units, finite and >= 0 (0 turns the refinement off). Default 5 (ours: 5 % of the
    /// map side).
    pub near_radius: f64,
    /// Move rules of the refinement A*. Default 8-connected, no corner cutting.
    pub grid: GridOptions,
    /// Shortcut the refined path greedily (the paper's last step). Default `true`.
    pub shortcut: bool,
    /// The RRT's iteration and optional time limits. Default: unset, [`Budget::samples_for`](hyplan_core::Budget::samples_for) the map
    /// (100 000 iterations, or one per four cells of a grid map when that is more).
    pub budget: Budget,
}

impl Default for RrtAstarRefine {
    fn default() -> Self {
        Self {
            step: 3.0,
            goal_bias: 0.05,
            near_radius: 5.0,
            grid: GridOptions::default(),
            shortcut: true,
            budget: Budget::default(),
        }
    }
}

impl RrtAstarRefine {
    /// One call of [`plan_detailed`](Self::plan_detailed).
    fn staged(&self, search: Search<'_, GridMap>) -> Result<Staged, PlanError> {
        let map = search.ws;
        let started = Instant::now();
        hyplan_core::check::non_negative("near_radius", self.near_radius)?;
        // 1. RRT (2.1): the initial path.
        let rrt = Rrt {
            step: self.step,
            goal_bias: self.goal_bias,
            budget: self.budget,
        };
        let rrt_plan = rrt
            .plan(map, search.query, search.rng)
            .map_err(|e| match e {
                PlanError::BudgetExhausted { mut stats } => {
                    stats.elapsed = started.elapsed();
                    PlanError::BudgetExhausted { stats }
                }
                other => other,
            })?;
        let raw = rrt_plan.path;
        let mut checker = CountingChecker::new(map);
        let mut stats = PlanStats {
            iterations: rrt_plan.stats.iterations,
            nodes: rrt_plan.stats.nodes,
            ..PlanStats::default()
        };
        // 2. Near-obstacle test for each node (the end points are anchors).
        let m = raw.len() - 1;
        let near: Vec<bool> = raw
            .iter()
            .enumerate()
            .map(|(k, &p)| k != 0 && k != m && map.blocked_within(p, self.near_radius).is_some())
            .collect();
        // 3. Each run of near nodes re-planned by grid A* between its anchors.
        let (mut runs, mut failures) = (0_u32, 0_u32);
        let mut search: Option<GridSearch> = None;
        let mut refined = vec![raw[0]];
        let mut i = 0;
        while i < m {
            if !near[i + 1] {
                refined.push(raw[i + 1]);
                i += 1;
                continue;
            }
            let mut j = i + 1;
            while near[j] {
                j += 1;
            }
            runs += 1;
            let stretch =
                self.astar_stretch(map, &mut search, &mut checker, &mut stats, raw[i], raw[j]);
            match stretch {
                Some(s) => refined.extend(s),
                None => {
                    failures += 1;
                    refined.extend_from_slice(&raw[i + 1..=j]);
                }
            }
            i = j;
        }
        common::dedup(&mut refined);
        // 4. Greedy shortcut (the paper's "path smoothing").
        let path = if self.shortcut {
            postproc::shortcut_greedy(&refined, |a, b| checker.segment_free(a, b))
        } else {
            refined.clone()
        };
        stats.collision_checks = rrt_plan.stats.collision_checks + checker.checks;
        stats.elapsed = started.elapsed();
        Ok(Staged {
            plan: Plan {
                cost: hyplan_core::path_length(&path),
                path,
                trees: rrt_plan.trees,
                waypoints: Vec::new(),
                stats,
            },
            raw,
            reduced: refined,
            astar_runs: runs,
            astar_failures: failures,
            ..Staged::default()
        })
    }

    /// The A* replacement of the stretch between anchors `a` and `b`: the points after `a`
    /// up to `b` included, every segment checked; `None` when A* or a check fails.
    fn astar_stretch<W: Workspace + ?Sized>(
        &self,
        map: &GridMap,
        search: &mut Option<GridSearch>,
        checker: &mut CountingChecker<'_, W>,
        stats: &mut PlanStats,
        a: Point2,
        b: Point2,
    ) -> Option<Vec<Point2>> {
        let (ca, cb) = (map.world_to_cell(a)?, map.world_to_cell(b)?);
        if search.is_none() {
            *search = GridSearch::new(map, self.grid).ok();
        }
        let cells = match search.as_mut()?.astar(ca, cb) {
            Ok(found) => {
                stats.expansions += found.stats.expansions;
                found.cells
            }
            Err(e) => {
                if let search::GridSearchError::NoPath { stats: s } = e {
                    stats.expansions += s.expansions;
                }
                return None;
            }
        };
        let centre = |c: (usize, usize)| map.cell_center(c.0, c.1);
        let cells = &cells;
        let mut out: Vec<Point2> = vec![a];
        // Interior cells, keeping only those where the move direction changes (the same
        // polyline with its collinear points dropped).
        let n = cells.len();
        let step = |p: (usize, usize), q: (usize, usize)| {
            (q.0 as isize - p.0 as isize, q.1 as isize - p.1 as isize)
        };
        for k in 1..n.saturating_sub(1) {
            let turns = step(cells[k - 1], cells[k]) != step(cells[k], cells[k + 1]);
            if k == 1 || k == n - 2 || turns {
                out.push(centre(cells[k]));
            }
        }
        out.push(b);
        // Joints to the continuous anchors: fall back on the anchors' own cell centres.
        common::anchor_cell_path(map, checker, out, cells)
    }
}

sampling::impl_planner!(RrtAstarRefine, "rrt-astar-refine", grid_only, staged: Staged);
