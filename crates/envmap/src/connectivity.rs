//! Connectivity checks that prove "no path" before planning, and say why.
//!
//! A planner whose edges pass [`GridMap::segment_free_cells`] moves through cells that
//! touch: a segment crossing a cell corner touches all four cells around it, so two free
//! cells are joined by a free polyline exactly when they are joined by a chain of free
//! cells sharing sides (4-connected). Grid searches move along the same chains (8-connected
//! moves without corner cutting never need more), or along 8-connected chains when they
//! cut corners. So a flood fill over the passable cells decides, exactly and in time
//! linear in the cells it visits, whether any planner of the workspace can succeed.
//!
//! When start and goal are not connected, the cause is named ([`NoPathCause`]): the
//! obstacles themselves (a wall), or, for a planner that keeps out of the high-risk band,
//! the band, with the largest safety radius that would leave a passage: the bottleneck of
//! the widest path, over the exact distance transform of the obstacles, found by a
//! bucketed max-min search.
//!
//! ```
//! use envmap::{GridMap, connectivity::{self, Moves}};
//! use hyplan_core::{Goal, NoPathCause, Point2, Query};
//! let map = GridMap::from_ascii("
//!     ..#..
//!     ..#..
//!     ..#..
//! ")?;
//! let query = Query::new(Point2::new(0.5, 1.5), Goal::Point(Point2::new(4.5, 1.5)));
//! assert_eq!(connectivity::disconnection(&map, &query, Moves::Four), Some(NoPathCause::Wall));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use hyplan_core::{Goal, NoPathCause, Point2, Query, Zone};

use crate::{DistanceField, GridMap, Mask, distance_transform};

/// How a planner moves between cells.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Moves {
    /// Through shared sides only: planners checked by `segment_free` (the RRT family, the
    /// hybrids), and grid searches without corner cutting.
    #[default]
    Four,
    /// Also diagonally between cells that share only a corner: grid searches that cut
    /// corners.
    Eight,
}

/// Why no path can join the query's start to its goal on `map` for a planner that moves
/// through the cells passable under the map's [`blocked_from`](GridMap::blocked_from)
/// with `moves`; `None` when they are connected (or the start or goal lies outside the
/// map: the query's own validation reports that).
///
/// The goal counts as reached in any passable cell whose closed square meets the goal
/// disc (the goal point's cell for a point goal). The cause is
/// [`NoPathCause::Wall`] when even the high-risk band would not connect them, else (a map
/// that blocks the band too) [`NoPathCause::RiskBand`] with the band's radius and the
/// widest path's bottleneck.
#[must_use]
pub fn disconnection(map: &GridMap, query: &Query, moves: Moves) -> Option<NoPathCause> {
    let start = map.world_to_cell(query.start)?;
    let target = Target::new(map, &query.goal)?;
    let blocked = map.blocked_from;
    let zones = map.zones();
    if blocked == Zone::Free || flood(map, start, &target, moves, |k| zones[k] < blocked) {
        return None;
    }
    if blocked == Zone::Forbidden
        || !flood(map, start, &target, moves, |k| zones[k] < Zone::Forbidden)
    {
        return Some(NoPathCause::Wall);
    }
    Some(band_cause(map, start, &target, moves))
}

/// Why no path can join the query's start to its goal for a planner whose nodes stay in
/// the Free zone while its edges, at most `hop` world units long, may cross the high-risk
/// band (seed 003's safety-cost RRT*), on a map where only Forbidden blocks; `None` when
/// it cannot tell.
///
/// Every point of such a path lies within `hop / 2` of a node in a Free cell, so its cell
/// centre lies within `hop / 2` and a cell and a half (rounding) of a Free cell centre:
/// when no chain of non-Forbidden cells that close to the Free zone joins start and goal,
/// no such path exists, and the band is the cause (the obstacles alone leave a passage).
/// The band argument is used only when start and goal lie in the Free zone themselves.
/// The distance transform of the Free zone is computed only when the Free cells alone do
/// not join start and goal.
#[must_use]
pub fn disconnection_hopping(map: &GridMap, query: &Query, hop: f64) -> Option<NoPathCause> {
    let start = map.world_to_cell(query.start)?;
    let target = Target::new(map, &query.goal)?;
    let zones = map.zones();
    if !flood(map, start, &target, Moves::Four, |k| zones[k] < Zone::Forbidden) {
        return Some(NoPathCause::Wall);
    }
    let free = |p: Point2| map.zone_at(p) == Zone::Free;
    if !(free(query.start) && free(query.goal.center()))
        || flood(map, start, &target, Moves::Four, |k| zones[k] == Zone::Free)
    {
        return None;
    }
    let (w, h) = (map.width(), map.height());
    let free_mask = Mask::from_cells(w, h, zones.iter().map(|&z| z == Zone::Free).collect())?;
    let to_free = distance_transform(&free_mask);
    let reach = hop / (2.0 * map.resolution()) + 1.5;
    let reach_sq = reach * reach;
    let near_free = to_free.dist_sq();
    let connected = flood(map, start, &target, Moves::Four, |k| {
        zones[k] < Zone::Forbidden && f64::from(near_free[k]) <= reach_sq
    });
    (!connected).then(|| band_cause(map, start, &target, Moves::Four))
}

/// The cause on a map that blocks the band, once the obstacles are known to leave a
/// passage: the band's radius and the widest path's bottleneck.
fn band_cause(map: &GridMap, start: (usize, usize), target: &Target, moves: Moves) -> NoPathCause {
    let Some(field) = map.distance_from(Zone::Forbidden) else {
        return NoPathCause::Wall;
    };
    let cap = max_risk_dist_sq(map, field).saturating_add(1);
    let bottleneck = widest(map, field, start, target, moves, cap).unwrap_or(0);
    NoPathCause::RiskBand {
        band_radius: band_radius(map, field),
        max_radius: f64::from(bottleneck).sqrt() * map.resolution(),
    }
}

/// The largest squared distance of a high-risk cell to the obstacles (0 without one).
fn max_risk_dist_sq(map: &GridMap, field: &DistanceField) -> u32 {
    map.zones()
        .iter()
        .zip(field.dist_sq())
        .filter(|(z, _)| **z == Zone::Risk)
        .map(|(_, &d)| d)
        .max()
        .unwrap_or(0)
}

/// The band's radius in world units: the largest distance of a high-risk cell centre to
/// the nearest obstacle cell centre.
fn band_radius(map: &GridMap, field: &DistanceField) -> f64 {
    f64::from(max_risk_dist_sq(map, field)).sqrt() * map.resolution()
}

/// The cells that reach the goal: per row, the columns whose closed squares meet the goal
/// disc.
struct Target {
    /// Centre and radius in cell units.
    cu: f64,
    cv: f64,
    r: f64,
    width: usize,
    height: usize,
}

impl Target {
    fn new(map: &GridMap, goal: &Goal) -> Option<Self> {
        let c = goal.center();
        let o = map.origin();
        let res = map.resolution();
        let (cu, cv, r) = ((c.x - o.x) / res, (c.y - o.y) / res, goal.radius() / res);
        (cu.is_finite() && cv.is_finite() && r.is_finite() && r >= 0.0).then_some(Self {
            cu,
            cv,
            r,
            width: map.width(),
            height: map.height(),
        })
    }

    /// The columns `[lo, hi]` of row `j` that meet the disc, if any.
    fn row(&self, j: usize) -> Option<(usize, usize)> {
        let jf = j as f64;
        let dy = (jf - self.cv).max(self.cv - (jf + 1.0)).max(0.0);
        if dy > self.r {
            return None;
        }
        let half = (self.r * self.r - dy * dy).sqrt();
        let lo = (self.cu - half - 1.0).ceil().max(0.0);
        let hi = (self.cu + half).floor().min(self.width as f64 - 1.0);
        (lo <= hi && hi >= 0.0).then_some((lo as usize, hi as usize))
    }

    /// The rows that meet the disc.
    fn rows(&self) -> (usize, usize) {
        let lo = (self.cv - self.r - 1.0).ceil().max(0.0) as usize;
        let hi = (self.cv + self.r).floor().clamp(0.0, self.height as f64 - 1.0) as usize;
        (lo, hi)
    }

    fn contains(&self, i: usize, j: usize) -> bool {
        self.row(j).is_some_and(|(lo, hi)| (lo..=hi).contains(&i))
    }
}

/// Scan-line flood fill from `start` over the cells whose index passes `passable`; whether
/// it reaches a target cell. Stops as soon as it does.
fn flood(
    map: &GridMap,
    start: (usize, usize),
    target: &Target,
    moves: Moves,
    passable: impl Fn(usize) -> bool,
) -> bool {
    let (w, h) = (map.width(), map.height());
    if !passable(start.1 * w + start.0) {
        return false;
    }
    let (t_lo, t_hi) = target.rows();
    let reach = usize::from(moves == Moves::Eight);
    let mut seen = vec![false; w * h];
    let mut stack = vec![start];
    while let Some((x, y)) = stack.pop() {
        let row = y * w;
        if seen[row + x] {
            continue;
        }
        // The run of passable, unseen cells through x.
        let mut lo = x;
        while lo > 0 && !seen[row + lo - 1] && passable(row + lo - 1) {
            lo -= 1;
        }
        let mut hi = x;
        while hi + 1 < w && !seen[row + hi + 1] && passable(row + hi + 1) {
            hi += 1;
        }
        seen[row + lo..=row + hi].fill(true);
        if (t_lo..=t_hi).contains(&y)
            && let Some((a, b)) = target.row(y)
            && a <= hi
            && lo <= b
        {
            return true;
        }
        // Runs of the rows below and above that touch this one.
        let (from, to) = (lo.saturating_sub(reach), (hi + reach).min(w - 1));
        for ny in [y.wrapping_sub(1), y + 1] {
            if ny >= h {
                continue;
            }
            let nrow = ny * w;
            let mut inside = false;
            for nx in from..=to {
                let open = !seen[nrow + nx] && passable(nrow + nx);
                if open && !inside {
                    stack.push((nx, ny));
                }
                inside = open;
            }
        }
    }
    false
}

/// The widest path's bottleneck from `start` to a target cell through the non-Forbidden
/// cells: the largest `b` (a squared distance in cells^2, capped at `cap`) such that a
/// chain of cells each at squared distance >= `b` from the obstacles joins them; `None`
/// when none does. A max-min search with one bucket per squared distance below `cap`.
fn widest(
    map: &GridMap,
    field: &DistanceField,
    start: (usize, usize),
    target: &Target,
    moves: Moves,
    cap: u32,
) -> Option<u32> {
    let (w, h) = (map.width(), map.height());
    let zones = map.zones();
    let dist = field.dist_sq();
    let value = |k: usize| dist[k].min(cap) as usize;
    let mut buckets: Vec<Vec<u32>> = vec![Vec::new(); cap as usize + 1];
    let mut seen = vec![false; w * h];
    let k0 = start.1 * w + start.0;
    if zones[k0] == Zone::Forbidden {
        return None;
    }
    seen[k0] = true;
    buckets[value(k0)].push(k0 as u32);
    let mut top = value(k0);
    let mut level = top;
    let offsets: &[(isize, isize)] = match moves {
        Moves::Four => &[(1, 0), (-1, 0), (0, 1), (0, -1)],
        Moves::Eight => &[
            (1, 0),
            (-1, 0),
            (0, 1),
            (0, -1),
            (1, 1),
            (-1, 1),
            (1, -1),
            (-1, -1),
        ],
    };
    loop {
        while buckets[top].is_empty() {
            if top == 0 {
                return None;
            }
            top -= 1;
        }
        level = level.min(top);
        let k = buckets[top].pop()? as usize;
        let (i, j) = (k % w, k / w);
        if target.contains(i, j) {
            return Some(level as u32);
        }
        for &(di, dj) in offsets {
            let (ni, nj) = (i as isize + di, j as isize + dj);
            if ni < 0 || nj < 0 || ni as usize >= w || nj as usize >= h {
                continue;
            }
            let n = nj as usize * w + ni as usize;
            if seen[n] || zones[n] == Zone::Forbidden {
                continue;
            }
            seen[n] = true;
            let v = value(n);
            buckets[v].push(n as u32);
            top = top.max(v);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate::{narrow_passage, with_risk_band};
    use rand::SeedableRng;

    fn q(a: (f64, f64), b: (f64, f64)) -> Query {
        Query::new(Point2::new(a.0, a.1), Goal::Point(Point2::new(b.0, b.1)))
    }

    #[test]
    fn corner_touch_does_not_connect_four_but_does_eight() {
        let map = GridMap::from_ascii(
            "
            .#
            #.
        ",
        )
        .unwrap();
        let query = q((0.5, 1.5), (1.5, 0.5));
        assert_eq!(
            disconnection(&map, &query, Moves::Four),
            Some(NoPathCause::Wall)
        );
        assert_eq!(disconnection(&map, &query, Moves::Eight), None);
    }

    #[test]
    fn goal_disc_across_a_wall_counts() {
        let map = GridMap::from_ascii("..#..\n..#..").unwrap();
        let point = q((0.5, 0.5), (4.5, 0.5));
        assert!(disconnection(&map, &point, Moves::Four).is_some());
        let disc = Query::new(Point2::new(0.5, 0.5), Goal::disc(Point2::new(4.5, 0.5), 2.6));
        assert_eq!(disconnection(&map, &disc, Moves::Four), None);
    }

    #[test]
    fn band_cause_names_the_bottleneck() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        // A 6-cell tunnel: its middle cells are 3 cells from the walls... at most.
        let g = narrow_passage(60, 40, 6, 4, &mut rng);
        let query = Query::new(g.start, Goal::Point(g.goal));
        let banded = with_risk_band(&g.map, 5.0).avoiding_risk();
        let Some(NoPathCause::RiskBand {
            band_radius,
            max_radius,
        }) = disconnection(&banded, &query, Moves::Four)
        else {
            panic!("expected the band as the cause");
        };
        assert!(band_radius <= 5.0 && band_radius > 4.0, "{band_radius}");
        // The tunnel's widest cells are 3 cells from a wall (squared distance 9).
        assert_eq!(max_radius, 3.0);
        // A band just below the bottleneck connects, one at it does not.
        let ok = with_risk_band(&g.map, 2.99).avoiding_risk();
        assert_eq!(disconnection(&ok, &query, Moves::Four), None);
        let not = with_risk_band(&g.map, 3.0).avoiding_risk();
        assert!(disconnection(&not, &query, Moves::Four).is_some());
        // Only obstacles blocking: connected.
        assert_eq!(disconnection(&with_risk_band(&g.map, 5.0), &query, Moves::Four), None);
    }

    #[test]
    fn closed_wall_is_a_wall_even_for_safe_maps() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let g = narrow_passage(60, 40, 0, 4, &mut rng);
        let query = Query::new(g.start, Goal::Point(g.goal));
        let banded = with_risk_band(&g.map, 2.0).avoiding_risk();
        assert_eq!(
            disconnection(&banded, &query, Moves::Four),
            Some(NoPathCause::Wall)
        );
        assert_eq!(disconnection_hopping(&g.map, &query, 2.0), Some(NoPathCause::Wall));
    }

    #[test]
    fn hopping_crosses_thin_bands_only() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let g = narrow_passage(80, 40, 6, 20, &mut rng);
        let query = Query::new(g.start, Goal::Point(g.goal));
        let banded = with_risk_band(&g.map, 5.0);
        // A 20-cell tunnel entirely in the band: hops of 2 cannot cross it, hops of 60 might.
        assert!(matches!(
            disconnection_hopping(&banded, &query, 2.0),
            Some(NoPathCause::RiskBand { .. })
        ));
        assert_eq!(disconnection_hopping(&banded, &query, 60.0), None);
    }
}
