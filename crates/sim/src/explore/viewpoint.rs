//! View points: where to stand to see a frontier, instead of on it.
//!
//! A frontier point lies at the edge of unknown space, often in a gap the costmap's
//! inflation closes (between pillars, in a pillar's shadow) or inside unknown space, so
//! that a robot sent onto it cannot plan there or stands still; yet the robot only needs
//! to *see* it. A view point of a target is a costmap cell the robot's centre can reach
//! (breadth-first from the robot over cells below the inscribed cost, [`costmap_steps`])
//! whose cost is at most a threshold, between `min_range` and `range` from the target, and from whose centre
//! the segment to the target meets no occupied cell of the built map before it reaches
//! the target or unknown space ([`edge_check`]). The view point chosen is the one fewest
//! costmap steps away (ties to the nearer one to the target, then row-major order), as
//! frontier exploration systems with view-point sampling do.
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
        let b = self.costmap.map.bounds();
        let res = self.costmap.map.resolution();
        Point2::new(
            b.min.x + (u as f64 + 0.5) * res,
            b.min.y + (v as f64 + 0.5) * res,
        )
    }

    fn usable(&self, c: usize) -> bool {
        self.steps[c] != u32::MAX && ros_cost(self.costmap.costs[c]) <= self.max_cost
    }

    /// The view point of `target` fewest steps away, with its steps; `None` when no
    /// usable cell within `range` sees it.
    #[must_use]
    pub fn best(&self, map: &OccupancyGrid, target: Point2) -> Option<(u32, Point2)> {
        let b = self.costmap.map.bounds();
        let res = self.costmap.map.resolution();
        let (w, h) = (self.costmap.map.width(), self.costmap.map.height());
        let lo = |x: f64, o: f64| ((x - self.range - o) / res).floor().max(0.0) as usize;
        let hi = |x: f64, o: f64, n: usize| {
            (((x + self.range - o) / res).floor().max(-1.0) + 1.0).min(n as f64) as usize
        };
        let mut best: Option<(u32, f64, Point2)> = None;
        for v in lo(target.y, b.min.y)..hi(target.y, b.min.y, h) {
            for u in lo(target.x, b.min.x)..hi(target.x, b.min.x, w) {
                let c = v * w + u;
                if !self.usable(c) {
                    continue;
                }
                let p = self.centre(u, v);
                let d = (p - target).norm();
                let s = self.steps[c];
                if d > self.range || d < self.min_range || best.is_some_and(|(bs, bd, _)| (s, d) >= (bs, bd)) {
                    continue;
                }
                if sees(map, p, target, self.slack) {
                    best = Some((s, d, p));
                }
            }
        }
        best.map(|(s, _, p)| (s, p))
    }

    /// Of `targets` (skipping those for which `skip` holds), the one whose view point is
    /// fewest steps away (ties to the nearer target from the view point, then the first),
    /// as `(target, view point)`. Reachable cells are visited in order of steps, so the
    /// search stops at the first cell that sees a target.
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
        let mut order: Vec<usize> = (0..self.steps.len()).filter(|&c| self.usable(c)).collect();
        order.sort_by_key(|&c| (self.steps[c], c));
        let r2 = self.range * self.range;
        let min2 = self.min_range * self.min_range;
        for c in order {
            let p = self.centre(c % w, c / w);
            let mut found: Option<(f64, Point2)> = None;
            for &t in &targets {
                let d2 = (t - p).norm_squared();
                if d2 <= r2 && d2 >= min2 && found.is_none_or(|(fd, _)| d2 < fd) && sees(map, p, t, self.slack) {
                    found = Some((d2, t));
                }
            }
            if let Some((_, t)) = found {
                return Some((t, p));
            }
        }
        None
    }
}
