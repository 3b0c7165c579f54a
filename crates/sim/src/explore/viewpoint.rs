//! View points: where to stand to see a frontier, instead of on it.
//!
//! A frontier point lies at the edge of unknown space, often in a gap the costmap's
//! inflation closes (between pillars, in a pillar's shadow) or inside unknown space, so
//! that a robot sent onto it cannot plan there or stands still; yet the robot only needs
//! to *see* it. A view point of a target is a costmap cell the robot's centre can reach
//! (breadth-first from the robot over cells below the inscribed cost, [`costmap_steps`])
//! whose cost is at most a threshold, between `min_range` and `range` from the target,
//! and from whose centre the segment to the target crosses only free cells of the built
//! map before it reaches the target or the unknown space next to it ([`sees`]). The view
//! point chosen is the one with the least travel to the target through it (costmap steps
//! to it, then the straight line on): the nearest place to the frontier on the robot's
//! way there that sees it, so that the robot still drives towards what it explores.
//!
//! [`costmap_steps`]: crate::explore::frontier::costmap_steps

use hyplan_core::Point2;

use crate::costmap::{Costmap, ros_cost};
use crate::explore::detector::{Edge, edge_check};
use crate::mapping::OccupancyGrid;

/// Whether `target` can be seen from `from` on the built map: the segment between them
/// crosses only free cells until it reaches the target's cell, or an unknown cell
/// within `slack` of the target (the unknown space the target stands for); an occupied
/// cell first, or an unknown cell farther from the target, hides it.
#[must_use]
pub fn sees(map: &OccupancyGrid, from: Point2, target: Point2, slack: f64) -> bool {
    if map.occupied_at(from) {
        return false;
    }
    match edge_check(map, from, target) {
        Edge::Occupied => false,
        Edge::Unknown(p) => (p - target).norm() <= slack,
        Edge::Free => true,
    }
}

/// Where the robot can look from: the costmap, the breadth-first steps from the robot
/// over it, and the greatest cost (ROS 0-100) a view point may have.
#[derive(Debug)]
pub struct ViewPoints<'a> {
    /// The costmap of the built map.
    pub costmap: &'a Costmap,
    /// Costmap steps from the robot (`u32::MAX`: unreachable).
    pub steps: &'a [u32],
    /// Greatest cost of a view point.
    pub max_cost: i8,
    /// Greatest distance from a view point to its target, m.
    pub range: f64,
    /// Least distance from a view point to its target, m: nearer, the target may lie
    /// under the body or inside the laser's minimum range.
    pub min_range: f64,
    /// How far from the target the first unknown cell on the line of sight may be, m
    /// ([`sees`]).
    pub slack: f64,
}

impl ViewPoints<'_> {
    fn centre(&self, u: usize, v: usize) -> Point2 {
        self.costmap.map.cell_center(u, v)
    }

    fn usable(&self, c: usize) -> bool {
        self.steps[c] != u32::MAX && ros_cost(self.costmap.costs[c]) <= self.max_cost
    }

    /// Travel to `target` through the view point in cell `c`, m: the costmap steps to it
    /// times the cell side, plus the straight line on to the target.
    fn key(&self, c: usize, p: Point2, target: Point2) -> f64 {
        f64::from(self.steps[c]) * self.costmap.map.resolution() + (p - target).norm()
    }

    /// The view point of `target` with the least travel to the target through it (steps
    /// to the view point times the cell side, plus the straight line on to the target;
    /// ties to the first cell in row-major order), with that travel, m; `None` when no
    /// usable cell within range sees it.
    #[must_use]
    pub fn best(&self, map: &OccupancyGrid, target: Point2) -> Option<(f64, Point2)> {
        let frame = self.costmap.map.frame();
        let w = frame.width;
        let mut best: Option<(f64, Point2)> = None;
        for v in frame.rows(target.y - self.range, target.y + self.range) {
            for u in frame.columns(target.x - self.range, target.x + self.range) {
                let c = v * w + u;
                if !self.usable(c) {
                    continue;
                }
                let p = self.centre(u, v);
                let d = (p - target).norm();
                let k = self.key(c, p, target);
                if d > self.range || d < self.min_range || best.is_some_and(|(bk, _)| k >= bk) {
                    continue;
                }
                if sees(map, p, target, self.slack) {
                    best = Some((k, p));
                }
            }
        }
        best
    }

    /// Of `targets` (skipping those for which `skip` holds), the one with the least
    /// travel through a view point (as [`ViewPoints::best`]; ties to the cell fewer steps
    /// away, then the first target), as `(target, view point)`. Reachable cells are
    /// visited in order of steps, and the search stops once the steps alone exceed the
    /// best travel found.
    #[must_use]
    pub fn nearest(
        &self,
        map: &OccupancyGrid,
        targets: &[Point2],
        skip: impl Fn(Point2) -> bool,
    ) -> Option<(Point2, Point2)> {
        let targets: Vec<Point2> = targets.iter().copied().filter(|&t| !skip(t)).collect();
        if targets.is_empty() {
            return None;
        }
        let w = self.costmap.map.width();
        let res = self.costmap.map.resolution();
        // By steps, then by cell: counted per step, then placed in cell order (a
        // flood's steps are dense, from 0 to the farthest cell's).
        let usable: Vec<u32> = (0..self.steps.len())
            .filter(|&c| self.usable(c))
            .map(|c| c as u32)
            .collect();
        let most = usable.iter().map(|&c| self.steps[c as usize]).max();
        let mut starts = vec![0usize; most.map_or(0, |m| m as usize + 2)];
        for &c in &usable {
            starts[self.steps[c as usize] as usize + 1] += 1;
        }
        for k in 1..starts.len() {
            starts[k] += starts[k - 1];
        }
        let mut order = vec![0u32; usable.len()];
        for &c in &usable {
            let at = &mut starts[self.steps[c as usize] as usize];
            order[*at] = c;
            *at += 1;
        }
        let mut best: Option<(f64, Point2, Point2)> = None;
        for c in order.into_iter().map(|c| c as usize) {
            if best.is_some_and(|(bk, _, _)| f64::from(self.steps[c]) * res + self.min_range >= bk)
            {
                break;
            }
            let p = self.centre(c % w, c / w);
            for &t in &targets {
                let d = (t - p).norm();
                if d > self.range || d < self.min_range {
                    continue;
                }
                let k = self.key(c, p, t);
                if best.is_none_or(|(bk, _, _)| k < bk) && sees(map, p, t, self.slack) {
                    best = Some((k, t, p));
                }
            }
        }
        best.map(|(_, t, p)| (t, p))
    }

    /// The usable cell fewest steps from the robot, at least `away` (m) from `robot`,
    /// whose cost is zero (out of every obstacle's inflation): where a robot its
    /// navigator could not move may step back into the open.
    #[must_use]
    pub fn open_cell(&self, robot: Point2, away: f64) -> Option<Point2> {
        let w = self.costmap.map.width();
        (0..self.steps.len())
            .filter(|&c| self.usable(c) && self.costmap.costs[c] == 0)
            .map(|c| (self.steps[c], c, self.centre(c % w, c / w)))
            .filter(|(_, _, p)| (p - robot).norm() >= away)
            .min_by_key(|&(s, c, _)| (s, c))
            .map(|(_, _, p)| p)
    }
}
