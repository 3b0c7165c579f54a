//! Pieces every sampling planner shares: parameter checks, sampling, steering, the
//! collision-check counter and path extraction.

use std::ops::ControlFlow;
use std::time::Instant;

use hyplan_core::{Budget, Goal, PlanError, PlanStats, Point2, Progress, Query, Workspace};
use rand::Rng;

use crate::NearestIndex;

/// What an observer returns when it does not want to stop the run.
pub(crate) fn keep_going(_: &Progress) -> ControlFlow<()> {
    ControlFlow::Continue(())
}

/// How often (in iterations) `plan_with` calls its observer.
pub(crate) const OBSERVE_EVERY: u64 = 64;

/// Checks a step length: finite and > 0.
pub(crate) fn check_step(step: f64) -> Result<(), PlanError> {
    if step.is_finite() && step > 0.0 {
        Ok(())
    } else {
        Err(PlanError::InvalidParameter {
            name: "step",
            value: format!("{step}"),
            reason: "must be finite and > 0 (world units)",
        })
    }
}

/// Checks a goal bias: a probability in [0, 1].
pub(crate) fn check_goal_bias(goal_bias: f64) -> Result<(), PlanError> {
    if (0.0..=1.0).contains(&goal_bias) {
        Ok(())
    } else {
        Err(PlanError::InvalidParameter {
            name: "goal_bias",
            value: format!("{goal_bias}"),
            reason: "must be a probability in [0, 1]",
        })
    }
}

/// Validates the parts every planner has: step, budget and query.
pub(crate) fn validate<W: Workspace + ?Sized>(
    step: f64,
    budget: &Budget,
    ws: &W,
    query: &Query,
) -> Result<(), PlanError> {
    check_step(step)?;
    budget.validate()?;
    let b = ws.bounds();
    if !(b.width() > 0.0 && b.height() > 0.0 && b.width().is_finite() && b.height().is_finite()) {
        return Err(PlanError::InvalidParameter {
            name: "workspace.bounds",
            value: format!("{} x {}", b.width(), b.height()),
            reason: "the workspace must have a finite, positive area",
        });
    }
    query.validate(ws)
}

/// A uniform sample over the workspace bounds (not rejection-sampled: the edge check
/// rejects blocked extensions, as in the original RRT).
#[inline]
pub(crate) fn sample_uniform<W: Workspace + ?Sized, R: Rng + ?Sized>(
    ws: &W,
    rng: &mut R,
) -> Point2 {
    let b = ws.bounds();
    Point2::new(
        b.min.x + hyplan_core::uniform01(rng) * b.width(),
        b.min.y + hyplan_core::uniform01(rng) * b.height(),
    )
}

/// The point at most `step` from `from` on the segment towards `to` (`to` itself when it is
/// within `step`, bit for bit).
#[inline]
pub(crate) fn steer(from: Point2, to: Point2, step: f64) -> Point2 {
    let d = to - from;
    let len = d.norm();
    if len <= step {
        to
    } else {
        from + d * (step / len)
    }
}

/// The workspace plus a count of the collision queries made through it.
pub(crate) struct Checker<'a, W: ?Sized> {
    pub ws: &'a W,
    pub checks: u64,
}

impl<'a, W: Workspace + ?Sized> Checker<'a, W> {
    pub fn new(ws: &'a W) -> Self {
        Self { ws, checks: 0 }
    }

    /// Exact edge check, counted.
    #[inline]
    pub fn segment_free(&mut self, a: Point2, b: Point2) -> bool {
        self.checks += 1;
        self.ws.segment_free(a, b)
    }
}

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

/// The points from the root of a parent-linked tree down to `leaf`.
pub(crate) fn branch(points: &[Point2], parent: &[Option<u32>], leaf: usize) -> Vec<Point2> {
    let mut path = vec![points[leaf]];
    let mut i = leaf;
    while let Some(p) = parent[i] {
        i = p as usize;
        path.push(points[i]);
    }
    path.reverse();
    path
}

/// Removes consecutive exact duplicates (a joined bidirectional path can repeat the
/// meeting point).
pub(crate) fn dedup(path: &mut Vec<Point2>) {
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
        let mut index = NearestIndex::with_capacity(1024);
        index.insert(root);
        Self {
            index,
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

    /// The points in id order.
    pub fn points(&self) -> Vec<Point2> {
        (0..self.index.len()).map(|i| self.index.point(i)).collect()
    }

    /// Plain-data copy for [`hyplan_core::Plan::trees`].
    pub fn to_tree(&self) -> hyplan_core::Tree {
        hyplan_core::Tree {
            points: self.points(),
            parent: self.parent.clone(),
        }
    }
}

/// The path of two trees joined at `a` (a node of the start tree) and `b` (a node of the
/// goal tree): root of the start tree to `a`, then `b` back to the goal root.
pub(crate) fn joined_path(start: &GrowTree, a: usize, goal: &GrowTree, b: usize) -> Vec<Point2> {
    let mut path = branch(&start.points(), &start.parent, a);
    let mut back = branch(&goal.points(), &goal.parent, b);
    back.reverse();
    path.extend(back);
    dedup(&mut path);
    path
}
