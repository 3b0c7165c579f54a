//! The roll-out's local costmap (a rolling window of the remembered hits, inflated) and
//! its two breadth-first distance grids (the package's `MapGrid`).

use envmap::{CellFrame, DistanceField, Inflation, Mask};
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
    /// Steps to the nearest path cell.
    pub(super) path: Vec<u32>,
    /// Steps to the local goal cell.
    pub(super) goal: Vec<u32>,
    blocked: Vec<bool>,
    queue: Vec<usize>,
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
        // Obstacle cells for the distance grids: illegal cells, except those under the
        // robot now (the package's `within_robot`).
        let clear_sq = (clear / res).powi(2);
        let body_sq = (footprint / res).powi(2);
        g.blocked.clear();
        g.blocked.extend((0..n * n).map(|c| {
            let d = g.dist_sq[c];
            let centre = frame.cell_center(c % n, c / n);
            let under = ((centre - here).norm() / res).powi(2) <= body_sq;
            d != DistanceField::NONE && f64::from(d) <= clear_sq && !under
        }));
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
        let mut queue = std::mem::take(&mut g.queue);
        let mut out = std::mem::take(&mut g.path);
        wave(&frame, &g.blocked, &seeds, &mut out, &mut queue);
        g.path = out;
        let mut out = std::mem::take(&mut g.goal);
        wave(
            &frame,
            &g.blocked,
            local_goal.as_slice(),
            &mut out,
            &mut queue,
        );
        g.goal = out;
        g.queue = queue;
    }
}

/// Breadth-first steps (4-connected) from `seeds` over `frame`'s cells into `out`: a
/// `blocked` cell met gets the obstacle value (the cell count) and is not crossed, an
/// unreached one the cell count plus one (the package's `MapGrid` values).
fn wave(
    frame: &CellFrame,
    blocked: &[bool],
    seeds: &[usize],
    out: &mut Vec<u32>,
    queue: &mut Vec<usize>,
) {
    let (w, h) = (frame.width, frame.height);
    let n = w * h;
    out.clear();
    out.resize(n, n as u32 + 1);
    queue.clear();
    // `out` below `n + 1` marks a visited cell.
    for &s in seeds {
        if out[s] != 0 {
            out[s] = 0;
            queue.push(s);
        }
    }
    let mut head = 0;
    while head < queue.len() {
        let c = queue[head];
        head += 1;
        let next = out[c] + 1;
        let (i, j) = (c % w, c / w);
        let around = [
            (i > 0).then(|| c - 1),
            (i + 1 < w).then(|| c + 1),
            (j > 0).then(|| c - w),
            (j + 1 < h).then(|| c + w),
        ];
        for nb in around.into_iter().flatten() {
            if out[nb] != n as u32 + 1 {
                continue;
            }
            if blocked[nb] {
                out[nb] = n as u32;
            } else {
                out[nb] = next;
                queue.push(nb);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wave_counts_steps_round_obstacles() {
        let frame = CellFrame::new(Point2::origin(), 1.0, 3, 3);
        // A wall in the middle column but its top cell.
        let blocked = [false, true, false, false, true, false, false, false, false];
        let (mut out, mut queue) = (Vec::new(), Vec::new());
        wave(&frame, &blocked, &[0], &mut out, &mut queue);
        assert_eq!(out, vec![0, 9, 6, 1, 9, 5, 2, 3, 4]);
    }
}
