//! The roll-out's local costmap (a rolling window of the remembered hits, inflated) and
//! its two breadth-first distance grids (the package's `MapGrid`).

use envmap::{CellFrame, Connectivity, DistanceField, Inflation, Mask, steps_from_cells};
use hyplan_core::Point2;

use super::Rollout;
use crate::control::FollowInput;

/// The local costmap and its two distance grids, rebuilt every control step.
#[derive(Debug, Default)]
pub(super) struct LocalGrids {
    pub(super) frame: Option<CellFrame>,
    /// Squared distance to the nearest lethal cell, cells^2.
    pub(super) dist_sq: Vec<u32>,
    /// Nav2 cost per cell.
    pub(super) costs: Vec<u8>,
    /// Steps to the nearest path cell (4-connected, crossing no illegal cell; `u32::MAX`
    /// where none is reached).
    pub(super) path: Vec<u32>,
    /// Steps to the local goal cell, likewise.
    pub(super) goal: Vec<u32>,
}

impl LocalGrids {
    /// Rebuilds the window around the robot from the memory's hits at `i.tick`, and the
    /// distance grids from the path's point `from` = (segment, point) on: cells within
    /// `clear` of a lethal cell are obstacles, their costs `inflation`'s (whose inscribed
    /// radius is `clear`); cells within `footprint` of the robot are crossed anyway.
    pub(super) fn rebuild(
        &mut self,
        p: &Rollout,
        footprint: f64,
        inflation: Inflation,
        i: &FollowInput<'_>,
        (k, q): (usize, Point2),
    ) {
        let g = self;
        let res = p.resolution;
        let here = Point2::new(i.pose.x, i.pose.y);
        let n = (p.window / res).ceil().max(1.0) as usize;
        // A rolling window snapped to the resolution, as costmap_2d's.
        let half = n as f64 * res / 2.0;
        let origin = Point2::new(
            ((here.x - half) / res).floor() * res,
            ((here.y - half) / res).floor() * res,
        );
        let frame = CellFrame::new(origin, res, n, n);
        g.frame = Some(frame);
        let mut lethal = Mask::new(n, n);
        for h in i.memory.points(i.tick) {
            if let Some((a, b)) = frame.cell_of(h) {
                lethal.set(a, b, true);
            }
        }
        let field = envmap::distance_transform(&lethal);
        let clear = inflation.inscribed_radius;
        g.costs = inflation
            .costs(&field, res)
            .expect("the scenario's inflation was validated");
        g.dist_sq.clear();
        g.dist_sq.extend_from_slice(field.dist_sq());
        // Cells the distance grids cross: legal cells, and those under the robot now (the
        // package's `within_robot`).
        let clear_sq = (clear / res).powi(2);
        let body_sq = (footprint / res).powi(2);
        let open = (0..n * n)
            .map(|c| {
                let d = g.dist_sq[c];
                let centre = frame.cell_center(c % n, c / n);
                let under = ((centre - here).norm() / res).powi(2) <= body_sq;
                d == DistanceField::NONE || f64::from(d) > clear_sq || under
            })
            .collect();
        let open = Mask::from_cells(n, n, open).expect("n x n cells");
        // The path from the robot's projection on, densified to the resolution.
        let mut seeds = Vec::new();
        let mut local_goal = None;
        let mut a = q;
        let mut started = false;
        'walk: for &b in &i.path[k + 1..] {
            let steps = ((b - a).norm() / res).ceil().max(1.0) as usize;
            for s in 0..=steps {
                let pt = a + (b - a) * (s as f64 / steps as f64);
                match frame.index_of(pt) {
                    Some(c) => {
                        seeds.push(c);
                        local_goal = Some(c);
                        started = true;
                    }
                    None if started => break 'walk,
                    None => {}
                }
            }
            a = b;
        }
        let cell = |c: usize| (c % n, c / n);
        g.path = steps_from_cells(&open, seeds.iter().map(|&c| cell(c)), Connectivity::Four);
        g.goal = steps_from_cells(&open, local_goal.map(cell), Connectivity::Four);
    }
}
