//! RRT-A*-BT: an RRT whose every extension is chosen the A* way, with back-tracking out of
//! dead ends, then one pass of node reduction and PCHIP smoothing.
//!
//! Seed `000_9b224721fe327833.txt`, sections 4.2 (RRT, N_max = 50), 4.3 (A*, f = g + h),
//! 4.4 (back-tracking out of U-shaped obstacles), 4.5 (node reduction) and 4.6 (PCHIP).
//! The reading implemented here, and why, is `docs/papers/000-rrt-astar-bt.md`, section
//! 3.2: RRT extensions chosen **in A* order**. The node being expanded (the "current
//! node", first the start) is steered one step towards each of N_max = 50 collision-free
//! random samples; these candidates, with f = g + h (g the tree path length through their
//! parent, h the straight distance to the goal), join an open list. Each iteration takes
//! the open candidate with the lowest f that is still admissible (free edge, not within
//! `closed_radius` of a tree node: A*'s closed list), adds it to the tree and expands it.
//! Back-tracking (4.4) is the open list keeping the options of earlier nodes: when the
//! current branch is trapped (its candidates are blocked or worse), the search resumes
//! from the earlier node whose option has the best f. Without back-tracking only the
//! current node's own candidates count, and a trapped node ends the run.
//!
//! # Cost
//!
//! On the room of issue 6 a plan draws ~95 000 random points (~830 rounds of 50
//! collision-free samples, by rejection), pushes ~41 000 candidates and pops nearly all of
//! them, three in four already closed, and most of the rest blocked. So the work is kept
//! per draw and per candidate: a sample on a [`envmap::GridMap`] is one cell lookup
//! (`GridMap::is_free`'s point test), an edge whose new end lies inside a blocked cell is
//! refused without the segment sweep (`GridMap::segment_free`), the closed list is a bucket grid over the tree's nodes
//! (`ClosedList`: the 3 x 3 cells around a point, checked exactly) instead of a k-d tree
//! query, a candidate already closed when drawn never enters the open list (it could never
//! be taken: nodes are never removed, and the closed test comes before the counted edge
//! check), and heap entries carry no g (recomputed, identically, for the one taken).
//! Same seed, same plan, trees and counts (collision checks included), bit for bit, as
//! the plain version (k-d tree `nearest` at every pop, `sample_uniform` and
//! `segment_free` through the workspace): about 41 million instructions per plan on the
//! room instead of 144 million, ~8 ms instead of ~21 ms.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use hyplan_core::{Budget, PlanError, Point2, Workspace};
use sampling::{CountingChecker, GrowTree, Run, Search};

use crate::Staged;
use crate::common;
use crate::smooth;

/// RRT-A*-BT (seed 000): RRT extensions taken in A* order with back-tracking, one-pass
/// node reduction and PCHIP.
///
/// # Zones
///
/// The planner avoids whatever the workspace's `segment_free` and `is_free` reject. Seed
/// 000 plans on its "binary safe map", where the high-risk band blocks as well as the
/// obstacles: pass `map.avoiding_risk()` for an [`envmap::GridMap`] with three zones. The
/// PCHIP curve is checked against the same workspace, so the returned path stays in the
/// safe zone too. Works on any [`Workspace`].
///
/// # Completeness
///
/// Before sampling, the planner asks the workspace for a proof that start and goal are
/// not connected ([`Workspace::disconnection`]; a grid map checks its passable cells) and
/// returns [`PlanError::Disconnected`] with the cause at once when there is one. Otherwise
/// only a path or the budget ends the run: when the open list runs dry (every candidate
/// closed or blocked), the search goes on from the tree node nearest to a fresh random
/// sample (RRT's rule, 4.2), whose new round of candidates refills the open list
/// ([`Staged::restarts`] counts these). The paper's back-tracking (4.4, the open list
/// keeping earlier nodes' options, best f first) is unchanged wherever the list is not
/// empty; the paper does not say what happens when it is.
///
/// # Units
///
/// Lengths are world units. The defaults are the paper's pixel values, so they fit a
/// picture loaded at one world unit per pixel (as [`envmap::load_map`] loads pictures);
/// on a map in millimetres multiply them by the millimetres per pixel (6.34 in the paper).
///
/// # Result
///
/// `path` is the PCHIP curve through the reduced nodes, sampled every `curve_spacing`,
/// every sample pair checked with `segment_free` (colliding pieces are repaired by
/// inserting chord midpoints, then straightened). It starts at the query's start and ends
/// at the goal centre when the last segment to it is free (else inside the goal region).
/// `trees` holds every node ever grown; `stats.nodes` is that count ("nodes explored"),
/// `stats.iterations` the expansions (one round of N_max candidates each),
/// `stats.expansions` the nodes added. [`plan_detailed`](RrtAstarBt::plan_detailed) also returns the raw branch and
/// the reduced nodes (the paper's "nodes" and "segments").
///
/// ```
/// use envmap::GridMap;
/// use hybrid::RrtAstarBt;
/// use hyplan_core::{Goal, Point2, Query, Workspace};
/// use rand::SeedableRng;
/// let map = GridMap::from_ascii("
///     ....................
///     ....................
///     ........#...........
///     ........#...........
///     ........#...........
///     ....................
/// ")?;
/// let planner = RrtAstarBt { step: 2.0, goal_radius: 1.0, closed_radius: Some(0.5), ..RrtAstarBt::default() };
/// let query = Query::new(Point2::new(1.5, 3.5), Goal::Point(Point2::new(18.5, 3.5)));
/// let plan = planner.plan(&map, &query, &mut rand_chacha::ChaCha8Rng::seed_from_u64(1))?;
/// assert_eq!(plan.path[0], query.start);
/// assert_eq!(*plan.path.last().unwrap(), Point2::new(18.5, 3.5));
/// assert!(plan.path.windows(2).all(|w| map.segment_free(w[0], w[1])));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`plan_detailed`](Self::plan_detailed) (which also returns the raw branch, the reduced
/// nodes and the smoothing repairs) and `plan` return [`PlanError::InvalidParameter`] for a
/// bad parameter or budget; [`PlanError::InvalidStart`] / [`PlanError::InvalidGoal`] for a
/// query outside the workspace or blocked; [`PlanError::Disconnected`] (with the cause)
/// when the workspace proves start and goal unconnected ([`Workspace::disconnection`],
/// before any sampling); without back-tracking, [`PlanError::NoPath`] at the first node
/// with no admissible candidate (the paper's "premature end", kept as the ablation: not a
/// proof); [`PlanError::BudgetExhausted`] when the iterations or time ran out. With
/// back-tracking an empty open list does not end the run (see above).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(default, deny_unknown_fields)
)]
pub struct RrtAstarBt {
    /// delta, the maximum length of an edge, world units, finite and > 0. Default 40 (the
    /// paper's 40 px).
    pub step: f64,
    /// r, radius of the goal region that ends the search, world units, finite and >= 0.
    /// Default 20 (the paper's 20 px). A node within it finishes the path at the goal
    /// centre when that segment is free, or where it is when it lies in the query's goal
    /// disc. A node within one `step` of the goal centre also finishes the path when the
    /// segment to the centre is free (RRT's goal connection, 4.2: "reaches q_goal (in best
    /// case)"), so a goal region smaller than the step is still reached.
    pub goal_radius: f64,
    /// N_max, candidate extensions drawn per iteration, >= 1. Default 50 (the paper's
    /// value; our reading of what it counts).
    pub candidates: usize,
    /// Rejection draws allowed for one collision-free sample, >= 1. Default 1000 (ours).
    pub sample_tries: usize,
    /// A candidate closer than this to an existing node is rejected (A*'s closed list),
    /// world units, finite and >= 0; `None` (default) follows the step: `step / 4` (ours;
    /// 10 px for the paper's 40 px step; with step / 2 the candidates through the room's
    /// narrow passages are too often all closed: 31 failures in 100 seeds, against 0 with
    /// step / 4).
    pub closed_radius: Option<f64>,
    /// Passes of the pairwise node reduction (4.5): 1 (default, the paper's one pass), or
    /// 0 to repeat until nothing changes.
    pub reduction_passes: usize,
    /// Keep earlier nodes' options on the open list (default `true`, back-tracking);
    /// `false` keeps only the current node's candidates and ends the run with
    /// [`PlanError::NoPath`] at the first node with none admissible (the paper's RRT-A*
    /// without BT, and its "premature end").
    pub backtracking: bool,
    /// Smooth the reduced path with PCHIP (default `true`); `false` returns the reduced
    /// polyline.
    pub smoothing: bool,
    /// Spacing of the curve samples, world units, finite and > 0. Default 1 (one pixel).
    pub curve_spacing: f64,
    /// K_max: the iteration (rounds of candidates) and optional time limits. Default: unset, [`Budget::samples_for`](hyplan_core::Budget::samples_for) the map
    /// (100 000 iterations, or one per four cells of a grid map when that is more);
    /// the paper's 10 000 is in `scenarios/000-*.ron`.
    pub budget: Budget,
}

impl Default for RrtAstarBt {
    fn default() -> Self {
        Self {
            step: 40.0,
            goal_radius: 20.0,
            candidates: 50,
            sample_tries: 1000,
            closed_radius: None,
            reduction_passes: 1,
            backtracking: true,
            smoothing: true,
            curve_spacing: 1.0,
            budget: Budget::default(),
        }
    }
}

impl RrtAstarBt {
    /// The closed-list radius in use: [`closed_radius`](Self::closed_radius), or a quarter
    /// step.
    #[must_use]
    pub fn closed_radius(&self) -> f64 {
        self.closed_radius.unwrap_or(self.step / 4.0)
    }

    fn validate_params(&self) -> Result<(), PlanError> {
        hyplan_core::check::positive("step", self.step)?;
        hyplan_core::check::non_negative("goal_radius", self.goal_radius)?;
        hyplan_core::check::count("candidates", self.candidates)?;
        hyplan_core::check::count("sample_tries", self.sample_tries)?;
        if let Some(r) = self.closed_radius {
            hyplan_core::check::non_negative("closed_radius", r)?;
        }
        hyplan_core::check::positive("curve_spacing", self.curve_spacing)
    }

    /// One call of [`plan_detailed`](Self::plan_detailed).
    fn staged<W: Workspace + ?Sized>(&self, search: Search<'_, W>) -> Result<Staged, PlanError> {
        self.validate_params()?;
        let mut run = Run::start(self.step, &self.budget, search.ws, search.query)?;
        run.check_connected(search.ws, search.query)?;
        let goal = search.query.goal;
        let target = goal.center();
        let mut checker = CountingChecker::new(search.ws);
        let bounds = search.ws.bounds();
        // The tree: every node ever grown, with its parent and g (path length from start,
        // its cost-to-come), and the same nodes bucketed for the closed-list test.
        let mut tree = GrowTree::with_costs(search.query.start);
        let mut closed = ClosedList::new(bounds, self.closed_radius(), search.query.start);
        // The open list: candidate extensions not yet taken, lowest f first.
        let mut open: BinaryHeap<Candidate> = BinaryHeap::with_capacity(4096);
        let mut seq = 0_u64;
        let mut head = 0_usize;
        let mut grown = 0_u64;
        let mut backtracks = 0_u32;
        let mut restarts = 0_u32;
        let mut reached: Option<(usize, Option<Point2>)> = None;
        let mut failure = false;

        let reach = self.goal_radius.max(self.step);
        if (search.query.start - target).norm() <= reach || goal.contains(search.query.start) {
            reached =
                common::finish_at_goal(&mut checker, &goal, search.query.start).map(|e| (0, e));
        }
        while reached.is_none() && run.next_iteration() {
            // Without back-tracking only the head's own options count (RRT-A* alone).
            if !self.backtracking {
                open.clear();
            }
            // Candidates: the head steered towards N_max collision-free random samples,
            // each with A*'s f = g + h, onto the open list. A candidate already on the
            // closed list stays off it: nodes are never removed, so it could never be
            // taken (this saves the heap work, not a collision check).
            let hp = tree.point(head);
            for _ in 0..self.candidates {
                let sample =
                    sampling::sample_accepted(&bounds, self.sample_tries, search.rng, |p| {
                        checker.is_free(p)
                    });
                let Some(sample) = sample else { continue };
                let c = sampling::steer(hp, sample, self.step);
                if c == hp {
                    continue;
                }
                seq += 1;
                if closed.is_closed(tree.points(), c) {
                    continue;
                }
                let g_c = tree.cost(head) + (c - hp).norm();
                let h = (target - c).norm();
                open.push(Candidate {
                    f: g_c + h,
                    h,
                    seq,
                    parent: head as u32,
                    point: c,
                });
            }
            // Select: the open candidate with the lowest f that is still admissible (not
            // on the closed list, free edge). When it hangs from an earlier node than the
            // head, the search has backed out of a dead end (4.4).
            let mut chosen = None;
            while let Some(c) = open.pop() {
                if !closed.is_closed(tree.points(), c.point)
                    && checker.segment_free(tree.point(c.parent as usize), c.point)
                {
                    chosen = Some(c);
                    break;
                }
            }
            let Some(c) = chosen else {
                if !self.backtracking {
                    // RRT-A* alone: the paper's premature end.
                    failure = true;
                    break;
                }
                // No option left on the open list. Back-tracking goes on from the tree node
                // nearest to a fresh collision-free sample (RRT's own choice of the node
                // to extend, 4.2), whose new round of candidates refills the list. Every
                // node keeps a chance of being extended again in any direction, so the
                // search is probabilistically complete, as RRT is; only the budget or a
                // path ends it.
                let sample =
                    sampling::sample_accepted(&bounds, self.sample_tries, search.rng, |p| {
                        checker.is_free(p)
                    });
                if let Some((n, _)) = sample.and_then(|p| tree.nearest(p)) {
                    head = n;
                }
                restarts += 1;
                continue;
            };
            let from = c.parent as usize;
            if from != head {
                backtracks += 1;
            }
            // Grow: the chosen candidate becomes the new head (g as computed when it was
            // drawn).
            let id = tree.add(c.point, from);
            closed.insert(c.point);
            head = id;
            grown += 1;
            // Goal test: within r of the goal (4.2), then join the goal itself if free.
            if (c.point - target).norm() <= reach || goal.contains(c.point) {
                reached = common::finish_at_goal(&mut checker, &goal, c.point).map(|e| (id, e));
            }
        }

        let mut stats = run.stats(tree.len(), checker.checks);
        stats.expansions = grown;
        let Some((leaf, end)) = reached else {
            return Err(if failure {
                PlanError::NoPath { stats }
            } else {
                PlanError::BudgetExhausted { stats }
            });
        };
        let raw = common::branch_to_goal(&tree, leaf, end);
        // Node reduction (4.5): pairwise, one pass by default.
        // 0 passes means "to stability".
        let passes = match self.reduction_passes {
            0 => usize::MAX,
            n => n,
        };
        let reduced =
            postproc::prune_pairwise_passes(&raw, passes, |a, b| checker.segment_free(a, b));
        // PCHIP (4.6), sampled and checked against the same zones.
        let curve = smooth::fit_if(self.smoothing, &reduced, |nodes| {
            smooth::fit_checked(nodes, postproc::Fit::Pchip, self.curve_spacing, |a, b| {
                checker.segment_free(a, b)
            })
        });
        stats.collision_checks = checker.checks;
        stats.elapsed = run.started().elapsed();
        Ok(Staged {
            backtracks,
            restarts,
            ..curve.into_staged(self.smoothing, tree.into_tree(), stats, raw, reduced)
        })
    }
}

/// A candidate extension on the open list, ordered so that `BinaryHeap` pops the lowest
/// f first (ties: lower h, then earlier draw). Its g is recomputed when it is taken.
struct Candidate {
    f: f64,
    h: f64,
    seq: u64,
    parent: u32,
    point: Point2,
}

/// A*'s closed list over the tree's nodes: is a point closer than `radius` to a node? The
/// nodes (their ids, added in id order as the tree grows) are bucketed in a grid of square
/// cells a little wider than `radius` (and at most 256 per side), so such a node lies in
/// the point's cell or one of its eight neighbours; those are checked exactly, with the
/// distance computed as the k-d tree computed it (square root of dx * dx + dy * dy).
struct ClosedList {
    radius: f64,
    /// radius^2 with a relative margin below and above: a squared distance under `below`
    /// is closer than `radius`, one over `above` is not.
    below: f64,
    above: f64,
    origin: Point2,
    /// 1 / cell side.
    inv: f64,
    nx: usize,
    ny: usize,
    /// Per cell, the last node added to it (`NONE` if empty); row-major, `nx + 2` wide,
    /// with an empty ring of cells around the grid so every cell has eight neighbours.
    last: Vec<u32>,
    /// Per node, the node added to its cell before it (`NONE` if first).
    prev: Vec<u32>,
}

const NONE: u32 = u32::MAX;

impl ClosedList {
    /// The list holding `root` (node 0) over `bounds`.
    fn new(bounds: hyplan_core::Bounds, radius: f64, root: Point2) -> Self {
        let (w, h) = (bounds.width(), bounds.height());
        // A margin over `radius` keeps rounding from pushing a close node two cells away.
        let side = (radius * (1.0 + 1e-6)).max(w.max(h) / 256.0);
        let cells = |len: f64| {
            if side > 0.0 && (len / side).is_finite() {
                (len / side) as usize + 1
            } else {
                1
            }
        };
        let (nx, ny) = (cells(w).clamp(1, 257), cells(h).clamp(1, 257));
        let mut list = Self {
            radius,
            below: radius * radius * (1.0 - 1e-9),
            above: radius * radius * (1.0 + 1e-9),
            origin: bounds.min,
            inv: if side > 0.0 { 1.0 / side } else { 0.0 },
            nx,
            ny,
            last: vec![NONE; (nx + 2) * (ny + 2)],
            prev: Vec::with_capacity(1024),
        };
        list.insert(root);
        list
    }

    /// The index in `last` of the cell of `p`, clamped to the grid (clamping keeps
    /// neighbours neighbours).
    #[inline]
    fn cell(&self, p: Point2) -> usize {
        // `as i32` saturates, and the grid is at most 257 cells a side.
        let i = ((p.x - self.origin.x) * self.inv) as i32;
        let j = ((p.y - self.origin.y) * self.inv) as i32;
        let i = i.clamp(0, self.nx as i32 - 1) as usize + 1;
        let j = j.clamp(0, self.ny as i32 - 1) as usize + 1;
        j * (self.nx + 2) + i
    }

    /// Adds the next node, at `p`.
    fn insert(&mut self, p: Point2) {
        let k = self.cell(p);
        self.prev.push(self.last[k]);
        self.last[k] = (self.prev.len() - 1) as u32;
    }

    /// Whether a node lies closer than `radius` to `p`; `points` are the nodes by id.
    fn is_closed(&self, points: &[Point2], p: Point2) -> bool {
        if self.radius <= 0.0 {
            return false;
        }
        let c = self.cell(p);
        let w = self.nx + 2;
        // The cell first, then its neighbours.
        [
            c,
            c - 1,
            c + 1,
            c - w,
            c + w,
            c - w - 1,
            c - w + 1,
            c + w - 1,
            c + w + 1,
        ]
        .into_iter()
        .any(|cell| {
            let mut k = self.last[cell];
            while k != NONE {
                let q = points[k as usize];
                let (dx, dy) = (p.x - q.x, p.y - q.y);
                let d2 = dx * dx + dy * dy;
                // Squared distances settle all but the near-ties without a root.
                if d2 < self.below || (d2 <= self.above && d2.sqrt() < self.radius) {
                    return true;
                }
                k = self.prev[k as usize];
            }
            false
        })
    }
}

impl PartialEq for Candidate {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Candidate {}

impl PartialOrd for Candidate {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Candidate {
    fn cmp(&self, other: &Self) -> Ordering {
        other
            .f
            .total_cmp(&self.f)
            .then(other.h.total_cmp(&self.h))
            .then(other.seq.cmp(&self.seq))
    }
}

sampling::impl_planner!(RrtAstarBt, "rrt-astar-bt", optimizing: |_bt| false, staged: Staged);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_pass_merges_pairs() {
        let p: Vec<Point2> = (0..6).map(|i| Point2::new(f64::from(i), 0.0)).collect();
        let once = |p: &[Point2], free: bool| postproc::prune_pairwise_passes(p, 1, |_, _| free);
        assert_eq!(once(&p, true), vec![p[0], p[2], p[4], p[5]]);
        assert_eq!(once(&p, false), p);
    }
}
