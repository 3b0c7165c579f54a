//! Private pieces of the two-tree planners (Bi-RRT, RRT-Connect): their loop and the plan
//! of two joined trees. The public building blocks are in [`crate::toolkit`],
//! [`crate::GrowTree`] and [`crate::Run`].

use hyplan_core::{Budget, Goal, Plan, PlanError, PlanStats, Point2, Workspace};

use crate::toolkit::{self, CountingChecker};
use crate::{GrowTree, Run, Search};

/// The path of two trees joined at `a` (a node of the start tree) and `b` (a node of the
/// goal tree): root of the start tree to `a`, then `b` back to the goal root, without
/// the repeated meeting point.
fn joined_path(start: &GrowTree, a: usize, goal: &GrowTree, b: usize) -> Vec<Point2> {
    // In one vector of the joined length: `a` up to the start, turned round, then `b` up
    // to the goal.
    let mut path = Vec::with_capacity(start.climb(a).count() + goal.climb(b).count());
    path.extend(start.climb(a));
    path.reverse();
    path.extend(goal.climb(b));
    path.dedup_by(|a, b| a == b);
    path
}

/// Where two trees met: a start-tree node and the goal-tree node it met (`None` for the
/// goal node when the start tree reached the goal region by itself).
pub(crate) type Join = (usize, Option<usize>);

/// One turn of a two-tree run, handed to the planner's growth step: the trees (`trees[0]`
/// from the start, `trees[1]` from the goal centre), the one to grow (`active`) and the
/// other, the turn's sample, the goal and the counted checker.
pub(crate) struct Turn<'a, 'w, W: ?Sized> {
    pub trees: &'a mut [GrowTree; 2],
    pub active: usize,
    pub other: usize,
    pub sample: Point2,
    pub goal: Goal,
    pub checker: &'a mut CountingChecker<'w, W>,
}

impl<W: ?Sized> Turn<'_, '_, W> {
    /// Where the trees met: node `grown` of the active tree and node `met` of the other,
    /// start tree first.
    pub fn joined(&self, grown: usize, met: usize) -> Join {
        if self.active == 0 {
            (grown, Some(met))
        } else {
            (met, Some(grown))
        }
    }

    /// Whether `p`, a new node of `trees[tree]`, ends the search by itself: the start tree
    /// inside a goal disc.
    pub fn ends_in_goal(&self, tree: usize, p: Point2) -> bool {
        tree == 0 && self.goal.radius() > 0.0 && self.goal.contains(p)
    }
}

/// The loop of the two-tree planners (Bi-RRT, RRT-Connect): one tree from the start, one
/// from the goal centre, grown in turn until they meet or the budget runs out, with the
/// observer called every [`OBSERVE_EVERY`](crate::OBSERVE_EVERY) iterations.
///
/// Each iteration draws one uniform sample and hands it to `grow` as a [`Turn`]; `grow`
/// returns where the trees met, if they did. The other tree grows next.
pub(crate) fn grow_two_trees<W, G>(
    step: f64,
    budget: &Budget,
    search: Search<'_, W>,
    mut grow: G,
) -> Result<Plan, PlanError>
where
    W: Workspace + ?Sized,
    G: FnMut(Turn<'_, '_, W>) -> Option<Join>,
{
    let mut run = Run::start(step, budget, search.ws, search.query)?;
    run.check_connected(search.ws, search.query)?;
    let mut checker = CountingChecker::new(search.ws);
    // trees[0] grows from the start, trees[1] from the goal centre.
    let mut trees = [
        GrowTree::rooted_at(search.query.start),
        GrowTree::rooted_at(search.query.goal.center()),
    ];
    let mut joined = search
        .query
        .goal
        .contains(search.query.start)
        .then_some((0, None));
    let mut active = 0_usize;
    while joined.is_none() && run.next_iteration() {
        let nodes = || (trees[0].len() + trees[1].len(), None);
        if run.observe(search.observer, nodes).is_break() {
            break;
        }
        // Sample: uniform in the bounds.
        let sample = toolkit::sample_uniform(search.ws, search.rng);
        joined = grow(Turn {
            trees: &mut trees,
            active,
            other: 1 - active,
            sample,
            goal: search.query.goal,
            checker: &mut checker,
        });
        // Swap: the other tree grows next.
        active = 1 - active;
    }
    let stats = run.stats(trees[0].len() + trees[1].len(), checker.checks);
    two_tree_plan(trees, joined, stats)
}

/// The end of a two-tree run (start tree first): the trees joined at `joined` as the
/// plan, with both trees and the statistics; without a join,
/// [`PlanError::BudgetExhausted`] with the statistics.
fn two_tree_plan(
    trees: [GrowTree; 2],
    joined: Option<Join>,
    stats: PlanStats,
) -> Result<Plan, PlanError> {
    let Some((a, b)) = joined else {
        return Err(PlanError::BudgetExhausted { stats });
    };
    let path = match b {
        Some(b) => joined_path(&trees[0], a, &trees[1], b),
        None => trees[0].branch(a),
    };
    let [start, goal] = trees;
    Ok(toolkit::plan_of_path(
        path,
        vec![start.into_tree(), goal.into_tree()],
        stats,
    ))
}
