//! Private pieces the planners of this crate share: the observer plumbing, statistics,
//! the exact-goal join, the plain growing tree, the loop of the two-tree planners and the
//! ends of one- and two-tree runs (the plan built from the tree or trees). The public building blocks (checks,
//! sampling, steering, the counted checker, branches) are in [`crate::toolkit`].

use std::ops::ControlFlow;
use std::time::Instant;

use hyplan_core::{
    Budget, Goal, Plan, PlanError, PlanStats, Point2, Progress, Query, Tree, Workspace,
};
use rand::Rng;

use crate::toolkit::CountingChecker;
use crate::{NearestIndex, toolkit};

/// What an observer returns when it does not want to stop the run.
pub(crate) fn keep_going(_: &Progress) -> ControlFlow<()> {
    ControlFlow::Continue(())
}

/// How often (in iterations) `plan_with` calls its observer.
pub(crate) const OBSERVE_EVERY: u64 = 64;

/// The per-run counters, filled in at the end.
pub(crate) fn stats(iterations: u64, nodes: usize, checks: u64, started: Instant) -> PlanStats {
    PlanStats {
        iterations,
        nodes: nodes as u64,
        collision_checks: checks,
        elapsed: started.elapsed(),
        ..PlanStats::default()
    }
}

/// Whether a new node may be joined to an exact goal point: the goal is a point (or a disc
/// of radius 0) and lies within `step` of the node.
#[inline]
pub(crate) fn exact_goal_within(goal: &Goal, p: Point2, step: f64) -> Option<Point2> {
    if goal.radius() > 0.0 {
        return None;
    }
    let g = goal.center();
    ((g - p).norm_squared() <= step * step && g != p).then_some(g)
}

/// Removes consecutive exact duplicates (a joined bidirectional path can repeat the
/// meeting point).
fn dedup(path: &mut Vec<Point2>) {
    path.dedup_by(|a, b| a == b);
}

/// A plain growing tree: a nearest-neighbour index plus parent links.
pub(crate) struct GrowTree {
    pub index: NearestIndex,
    pub parent: Vec<Option<u32>>,
}

impl GrowTree {
    /// A tree holding only its root.
    pub fn rooted_at(root: Point2) -> Self {
        Self {
            index: NearestIndex::rooted_at(root),
            parent: vec![None],
        }
    }

    /// Adds `p` under `parent` and returns its id.
    pub fn add(&mut self, p: Point2, parent: usize) -> usize {
        self.parent.push(Some(parent as u32));
        self.index.insert(p)
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// Plain-data copy for [`hyplan_core::Plan::trees`].
    pub fn to_tree(&self) -> hyplan_core::Tree {
        hyplan_core::Tree {
            points: self.index.points().to_vec(),
            parent: self.parent.clone(),
        }
    }
}

/// The path of two trees joined at `a` (a node of the start tree) and `b` (a node of the
/// goal tree): root of the start tree to `a`, then `b` back to the goal root.
fn joined_path(start: &GrowTree, a: usize, goal: &GrowTree, b: usize) -> Vec<Point2> {
    let mut path = toolkit::branch(start.index.points(), &start.parent, a);
    let mut back = toolkit::branch(goal.index.points(), &goal.parent, b);
    back.reverse();
    path.extend(back);
    dedup(&mut path);
    path
}

/// The end of a one-tree run: the branch from the root to `leaf` as the plan, with the
/// tree and the statistics; without a leaf, [`PlanError::BudgetExhausted`] with the
/// statistics.
pub(crate) fn tree_plan(
    tree: Tree,
    leaf: Option<usize>,
    stats: PlanStats,
) -> Result<Plan, PlanError> {
    let Some(leaf) = leaf else {
        return Err(PlanError::BudgetExhausted { stats });
    };
    let path = toolkit::branch(&tree.points, &tree.parent, leaf);
    Ok(Plan {
        cost: hyplan_core::path_length(&path),
        path,
        trees: vec![tree],
        waypoints: Vec::new(),
        stats,
    })
}

/// Where two trees met: a start-tree node and the goal-tree node it met (`None` for the
/// goal node when the start tree reached the goal region by itself).
pub(crate) type Join = (usize, Option<usize>);

/// The loop of the two-tree planners (Bi-RRT, RRT-Connect): one tree from the start, one
/// from the goal centre, grown in turn until they meet or the budget runs out, with the
/// observer called every [`OBSERVE_EVERY`] iterations.
///
/// Each iteration draws one uniform sample and hands it to `grow` with the trees and the
/// index of the one to grow (`active`); `grow` returns where the trees met, if they did.
/// The other tree grows next.
pub(crate) fn grow_two_trees<W, R, F, G>(
    step: f64,
    budget: &Budget,
    ws: &W,
    query: &Query,
    rng: &mut R,
    observer: &mut F,
    mut grow: G,
) -> Result<Plan, PlanError>
where
    W: Workspace + ?Sized,
    R: Rng + ?Sized,
    F: FnMut(&Progress) -> ControlFlow<()>,
    G: FnMut(&mut [GrowTree; 2], usize, Point2, &mut CountingChecker<'_, W>) -> Option<Join>,
{
    let started = Instant::now();
    let budget = &budget.for_sampling(ws.cells());
    toolkit::validate_step_and_budget(step, budget, ws, query)?;
    toolkit::check_connected(ws, query, started)?;
    let mut checker = CountingChecker::new(ws);
    // trees[0] grows from the start, trees[1] from the goal centre.
    let mut trees = [
        GrowTree::rooted_at(query.start),
        GrowTree::rooted_at(query.goal.center()),
    ];
    let mut iterations = 0_u64;
    let mut joined = query.goal.contains(query.start).then_some((0, None));
    let mut active = 0_usize;
    while joined.is_none() && !budget.exhausted(iterations, started) {
        iterations += 1;
        if iterations.is_multiple_of(OBSERVE_EVERY) {
            let progress = Progress {
                iterations,
                nodes: (trees[0].len() + trees[1].len()) as u64,
                best_cost: None,
            };
            if observer(&progress).is_break() {
                break;
            }
        }
        // Sample: uniform in the bounds.
        let sample = toolkit::sample_uniform(ws, rng);
        joined = grow(&mut trees, active, sample, &mut checker);
        // Swap: the other tree grows next.
        active = 1 - active;
    }
    let nodes = trees[0].len() + trees[1].len();
    let stats = stats(iterations, nodes, checker.checks, started);
    two_tree_plan(&trees, joined, stats)
}

/// The end of a two-tree run (start tree first): the trees joined at `joined` (a start-tree
/// node and the goal-tree node it met; `None` for the goal node when the start tree reached
/// the goal region by itself) as the plan, with both trees and the statistics; without a
/// join, [`PlanError::BudgetExhausted`] with the statistics.
pub(crate) fn two_tree_plan(
    trees: &[GrowTree; 2],
    joined: Option<Join>,
    stats: PlanStats,
) -> Result<Plan, PlanError> {
    let Some((a, b)) = joined else {
        return Err(PlanError::BudgetExhausted { stats });
    };
    let path = match b {
        Some(b) => joined_path(&trees[0], a, &trees[1], b),
        None => toolkit::branch(trees[0].index.points(), &trees[0].parent, a),
    };
    Ok(Plan {
        cost: hyplan_core::path_length(&path),
        path,
        trees: vec![trees[0].to_tree(), trees[1].to_tree()],
        waypoints: Vec::new(),
        stats,
    })
}
