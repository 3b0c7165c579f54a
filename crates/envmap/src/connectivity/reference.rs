//! The slow exact reference of [`super::disconnection`] and
//! [`super::disconnection_hopping`]: flood fills over every cell, the full distance
//! transform of the obstacles, and a bucketed max-min (widest path) search. Kept to test
//! the fast run-based version against and to time it (`examples/no_path_timing.rs`);
//! planners do not call it. Which question is asked when (walls first, then the band) is
//! the fast version's own decision, shared; how each question is answered is the
//! reference's.

use hyplan_core::{NoPathCause, Query, Zone};

use super::{Moves, Target, decide, decide_hopping};
use crate::{DistanceField, GridMap, Mask, distance_transform};

/// [`super::disconnection`] by floods over every cell: the same contract.
#[must_use]
pub fn disconnection(map: &GridMap, query: &Query, moves: Moves) -> Option<NoPathCause> {
    let zones = map.zones();
    decide(
        map,
        query,
        moves,
        |s, t, zone, moves| flood(map, s, t, moves, |k| zones[k] < zone),
        |s, t, moves| band_cause(map, s, t, moves),
    )
}

/// [`super::disconnection_hopping`] by floods over every cell and the full distance
/// transform of the Free zone: the same contract.
#[must_use]
pub fn disconnection_hopping(map: &GridMap, query: &Query, hop: f64) -> Option<NoPathCause> {
    let (w, h, zones) = (map.width(), map.height(), map.zones());
    let near_free = |s, t: &Target, reach: f64| {
        let free = Mask::from_cells(w, h, zones.iter().map(|&z| z == Zone::Free).collect())?;
        let to_free = distance_transform(&free);
        let (near, reach_sq) = (to_free.dist_sq(), reach * reach);
        Some(flood(map, s, t, Moves::Four, |k| {
            zones[k] < Zone::Forbidden && f64::from(near[k]) <= reach_sq
        }))
    };
    decide_hopping(
        map,
        query,
        hop,
        |s, t, zone| flood(map, s, t, Moves::Four, |k| zones[k] < zone),
        near_free,
        |s, t| band_cause(map, s, t, Moves::Four),
    )
}

/// The cause on a map that blocks the band, once the obstacles are known to leave a
/// passage: the band's radius and the widest path's bottleneck.
fn band_cause(map: &GridMap, start: (usize, usize), target: &Target, moves: Moves) -> NoPathCause {
    let Some(field) = map.distance_from(Zone::Forbidden) else {
        return NoPathCause::Wall;
    };
    if map.zone_counts()[Zone::Forbidden as usize] == 0 {
        // No obstacle to measure the band by (see the fast version).
        return NoPathCause::RiskBand {
            band_radius: f64::INFINITY,
            max_radius: f64::INFINITY,
        };
    }
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
