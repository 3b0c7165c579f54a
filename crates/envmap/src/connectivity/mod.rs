//! Connectivity checks that prove "no path" before planning, and say why.
//!
//! A planner whose edges pass [`GridMap::segment_free_cells`] moves through cells that
//! touch: a segment crossing a cell corner touches all four cells around it, so two free
//! cells are joined by a free polyline exactly when they are joined by a chain of free
//! cells sharing sides (4-connected). Grid searches move along the same chains (8-connected
//! moves without corner cutting never need more), or along 8-connected chains when they
//! cut corners. So the connected components of the passable cells decide, exactly,
//! whether any planner of the workspace can succeed.
//!
//! # Cost: once per map, on runs
//!
//! The components are labelled on horizontal runs of passable cells (union-find over the
//! runs of consecutive rows), computed on the first check and cached in the map for each
//! set of passable zones and each kind of move; a later check is two binary searches plus
//! one per row of the goal disc. A 2000 x 2000 map has a few thousand to a hundred
//! thousand runs, so even the first check costs a pass over the zone bytes and not a flood
//! over every cell (`cargo run --release -p envmap --example no_path_timing`).
//!
//! # The cause
//!
//! When start and goal are not connected, the cause is named ([`NoPathCause`]): the
//! obstacles themselves (a wall), or, for a planner that keeps out of the high-risk band,
//! the band, with the largest safety radius that would leave a passage: the bottleneck of
//! the widest path over the exact Euclidean distance between cell centres and obstacle
//! cell centres. It is found without a distance transform: the cells within squared
//! distance `t` of an obstacle are the exact dilation of the obstacle runs by a disc
//! (each run widened by `floor(sqrt(t - dy^2))` in the rows `dy` away), so "start and goal
//! stay connected once the cells within `t` are removed" is a run-based test, monotone in
//! `t`. The band's radius (the largest squared distance `R` of a high-risk cell to the
//! obstacles) is the least `t` whose dilation covers the band, found by doubling then
//! bisection; the bottleneck lies in `[1, R + 1]` (a path beyond `R` everywhere would run
//! in the Free zone), and bisection over that integer range finds it exactly. Each test
//! costs the runs near changes between rows times the disc's diameter (rows repeated in a
//! block are widened once), so the searches touch the map's shapes a few dozen times and
//! never its cells one by one: a few milliseconds on 2000 x 2000 cells. [`disconnection_reference`](crate::disconnection_reference)
//! keeps the slow cell-by-cell version the tests compare against.
//!
//! ```
//! use envmap::{GridMap, Moves, disconnection};
//! use hyplan_core::{Goal, NoPathCause, Point2, Query};
//! let map = GridMap::from_ascii("
//!     ..#..
//!     ..#..
//!     ..#..
//! ")?;
//! let query = Query::new(Point2::new(0.5, 1.5), Goal::Point(Point2::new(4.5, 1.5)));
//! assert_eq!(disconnection(&map, &query, Moves::Four), Some(NoPathCause::Wall));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::sync::{Arc, Mutex, OnceLock};

use hyplan_core::{Goal, NoPathCause, Point2, Query, Zone};

use crate::GridMap;

mod reference;

pub use reference::{
    disconnection as disconnection_reference,
    disconnection_hopping as disconnection_hopping_reference,
};
mod runs;

use runs::{Components, Runs};

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
///
/// The components are cached in the map (see the module docs); the band's cause is
/// computed per call, only when the band is the cause.
#[must_use]
pub fn disconnection(map: &GridMap, query: &Query, moves: Moves) -> Option<NoPathCause> {
    let cache = map.connectivity_cache();
    decide(
        map,
        query,
        moves,
        |s, t, zone, moves| cache.below(map, zone, moves).joins(s, t),
        |s, t, moves| band_cause(map, s, t, moves),
    )
}

/// Computes the components that [`disconnection`] reads first for `moves` on `map` (the
/// passable cells under its `blocked_from`) and caches them in the map, as its first call
/// would: a caller that times queries prepares them apart.
///
/// ```
/// use envmap::{GridMap, Moves, disconnection, prepare_disconnection};
/// use hyplan_core::{Goal, Point2, Query};
/// let map = GridMap::from_ascii("..#..")?;
/// prepare_disconnection(&map, Moves::Four);
/// let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(4.5, 0.5)));
/// assert!(disconnection(&map, &query, Moves::Four).is_some());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn prepare_disconnection(map: &GridMap, moves: Moves) {
    if map.blocked_from != Zone::Free {
        let _ = map.connectivity_cache().below(map, map.blocked_from, moves);
    }
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
/// The cells near the Free zone (the Free runs dilated by the reach) are computed only
/// when the Free cells alone do not join start and goal, and cached in the map for the
/// last few reaches.
#[must_use]
pub fn disconnection_hopping(map: &GridMap, query: &Query, hop: f64) -> Option<NoPathCause> {
    let cache = map.connectivity_cache();
    let near_free = |s, t: &Target, reach: f64| {
        // Squared distances are integers: d^2 <= reach^2 exactly when d^2 <= floor(reach^2).
        // Beyond the map's diagonal every cell is near.
        let diag = (map.width() * map.width() + map.height() * map.height()) as f64;
        let limit = (reach * reach).min(diag).floor() as u64;
        Some(cache.near_free(map, limit).joins(s, t))
    };
    decide_hopping(
        map,
        query,
        hop,
        |s, t, zone| cache.below(map, zone, Moves::Four).joins(s, t),
        near_free,
        |s, t| band_cause(map, s, t, Moves::Four),
    )
}

/// A cell of the grid, (column, row).
type Cell = (usize, usize);

/// [`disconnection`]'s decision, shared with the reference, which answers the same
/// questions by plain floods: `below(start, target, zone, moves)`, whether the cells
/// with a zone below `zone` join start to target; `band(start, target, moves)`, the
/// band's cause once the obstacles are known to leave a passage.
fn decide(
    map: &GridMap,
    query: &Query,
    moves: Moves,
    below: impl Fn(Cell, &Target, Zone, Moves) -> bool,
    band: impl FnOnce(Cell, &Target, Moves) -> NoPathCause,
) -> Option<NoPathCause> {
    let start = map.world_to_cell(query.start)?;
    let target = Target::new(map, &query.goal)?;
    let blocked = map.blocked_from;
    if blocked == Zone::Free || below(start, &target, blocked, moves) {
        return None;
    }
    if blocked == Zone::Forbidden || !below(start, &target, Zone::Forbidden, moves) {
        return Some(NoPathCause::Wall);
    }
    Some(band(start, &target, moves))
}

/// [`disconnection_hopping`]'s decision, shared with the reference: `below` as in
/// [`decide`] (4-connected); `near_free(start, target, reach)`, whether the non-Forbidden
/// cells whose centres lie within `reach` cells of a Free cell centre join them (`None`
/// when it cannot tell); `band` the band's cause.
fn decide_hopping(
    map: &GridMap,
    query: &Query,
    hop: f64,
    below: impl Fn(Cell, &Target, Zone) -> bool,
    near_free: impl FnOnce(Cell, &Target, f64) -> Option<bool>,
    band: impl FnOnce(Cell, &Target) -> NoPathCause,
) -> Option<NoPathCause> {
    let start = map.world_to_cell(query.start)?;
    let target = Target::new(map, &query.goal)?;
    if !below(start, &target, Zone::Forbidden) {
        return Some(NoPathCause::Wall);
    }
    let free = |p: Point2| map.zone_at(p) == Zone::Free;
    if !(free(query.start) && free(query.goal.center())) || below(start, &target, Zone::Risk) {
        return None;
    }
    let reach = hop / (2.0 * map.resolution()) + 1.5;
    (!near_free(start, &target, reach)?).then(|| band(start, &target))
}

/// The cause on a map that blocks the band, once the obstacles are known to leave a
/// passage: the band's radius and the widest path's bottleneck, both exact (see the
/// module docs for the search). The band's radius and every thresholded component set
/// the search builds are cached in the map, so a second query on the same map costs a
/// few binary searches.
fn band_cause(map: &GridMap, start: (usize, usize), target: &Target, moves: Moves) -> NoPathCause {
    let cache = map.connectivity_cache();
    let Some(max_risk) = cache.max_risk(map) else {
        // High-risk cells drawn on a map without obstacles: no distance to measure them
        // by, and any band recomputed from the (absent) obstacles would be empty.
        return NoPathCause::RiskBand {
            band_radius: f64::INFINITY,
            max_radius: f64::INFINITY,
        };
    };
    // The bottleneck b: start and goal stay joined once the cells with d^2 <= t are gone
    // exactly for t < b. Joined at t = 0 (the obstacles leave a passage); capped at the
    // band's radius + 1 like the reference's distances.
    let cap = max_risk + 1;
    let cut = bisect(0, cap, |t| {
        !cache.beyond(map, t, moves).joins(start, target)
    });
    let res = map.resolution();
    NoPathCause::RiskBand {
        band_radius: (max_risk as f64).sqrt() * res,
        max_radius: (cut.min(cap) as f64).sqrt() * res,
    }
}

/// The least `t >= 0` with `holds(t)`, for a predicate that is monotone (false, then true
/// for ever) and true somewhere: doubling, then bisection.
fn least(mut holds: impl FnMut(u64) -> bool) -> u64 {
    if holds(0) {
        return 0;
    }
    let (mut lo, mut hi) = (0, 1);
    while !holds(hi) {
        lo = hi;
        hi *= 2;
    }
    bisect(lo, hi, holds)
}

/// The least `t` in `(lo, hi]` with `holds(t)`, for a monotone predicate known (not
/// asked) to be false at `lo` and true at `hi`.
fn bisect(mut lo: u64, mut hi: u64, mut holds: impl FnMut(u64) -> bool) -> u64 {
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if holds(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// How many values a [`Memo`] keeps (the oldest goes first).
const MEMO_KEPT: usize = 64;

/// A small map-keyed store behind a mutex: values computed outside the lock (two threads
/// may compute the same one; both get a correct value).
struct Memo<K, V>(Mutex<Vec<(K, Arc<V>)>>);

impl<K: PartialEq + Copy, V> Memo<K, V> {
    fn get_or(&self, key: K, make: impl FnOnce() -> V) -> Arc<V> {
        let lock = || {
            self.0
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner)
        };
        if let Some((_, v)) = lock().iter().find(|(k, _)| *k == key) {
            return Arc::clone(v);
        }
        let v = Arc::new(make());
        let mut kept = lock();
        if kept.len() >= MEMO_KEPT {
            kept.remove(0);
        }
        kept.push((key, Arc::clone(&v)));
        v
    }
}

impl<K, V> Default for Memo<K, V> {
    fn default() -> Self {
        Self(Mutex::new(Vec::new()))
    }
}

impl<K: Clone, V> Clone for Memo<K, V> {
    fn clone(&self) -> Self {
        Self(Mutex::new(
            self.0
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner)
                .clone(),
        ))
    }
}

/// What a [`GridMap`] remembers of its connectivity between checks: the zone runs, the
/// components of its passable cells per set of passable zones and kind of move, and what
/// the band's cause needs (the band's radius, dilations of the obstacles, components of
/// the cells beyond a distance, cells near the Free zone). Emptied whenever the zones
/// change. A few dozen run sets at most: each test of the searches is one set.
#[derive(Default, Clone)]
pub(crate) struct Cache {
    zones: OnceLock<runs::ZoneRuns>,
    /// Indexed by [`Cache::slot`]: cells below Risk / below Forbidden, Four / Eight.
    below: [OnceLock<Components>; 4],
    /// The largest squared distance of a high-risk cell to the obstacles (`None` without
    /// obstacles).
    max_risk: OnceLock<Option<u64>>,
    /// The cells within squared distance `t` of an obstacle, by `t`.
    dilated: Memo<u64, Runs>,
    /// The components of the non-Forbidden cells beyond squared distance `t`, by `(t,
    /// moves)`.
    beyond: Memo<(u64, Moves), Components>,
    /// The components (Four) of the non-Forbidden cells within squared distance `t` of
    /// a Free cell, by `t`.
    near_free: Memo<u64, Components>,
}

impl Cache {
    fn slot(zone: Zone, moves: Moves) -> usize {
        usize::from(zone == Zone::Forbidden) * 2 + usize::from(moves == Moves::Eight)
    }

    fn zones(&self, map: &GridMap) -> &runs::ZoneRuns {
        self.zones.get_or_init(|| runs::ZoneRuns::of(map))
    }

    /// The components of the cells whose zone is below `zone` (Risk or Forbidden).
    fn below(&self, map: &GridMap, zone: Zone, moves: Moves) -> &Components {
        self.below[Self::slot(zone, moves)].get_or_init(|| {
            let z = self.zones(map);
            let set = if zone == Zone::Forbidden {
                z.passable.clone()
            } else {
                z.free.clone()
            };
            Components::of(set, moves)
        })
    }

    fn dilated(&self, map: &GridMap, t: u64) -> Arc<Runs> {
        self.dilated
            .get_or(t, || self.zones(map).obstacles.dilate(t))
    }

    fn max_risk(&self, map: &GridMap) -> Option<u64> {
        *self.max_risk.get_or_init(|| {
            let z = self.zones(map);
            if z.obstacles.is_empty() {
                None
            } else if z.risk.is_empty() {
                Some(0)
            } else {
                // The least t whose dilation covers every high-risk cell.
                Some(least(|t| z.risk.within(&self.dilated(map, t))))
            }
        })
    }

    fn beyond(&self, map: &GridMap, t: u64, moves: Moves) -> Arc<Components> {
        self.beyond.get_or((t, moves), || {
            let passable = &self.zones(map).passable;
            Components::of(passable.minus(&self.dilated(map, t)), moves)
        })
    }

    fn near_free(&self, map: &GridMap, t: u64) -> Arc<Components> {
        self.near_free.get_or(t, || {
            let z = self.zones(map);
            Components::of(z.free.dilate(t).and(&z.passable), Moves::Four)
        })
    }
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
        let hi = (self.cv + self.r)
            .floor()
            .clamp(0.0, self.height as f64 - 1.0) as usize;
        (lo, hi)
    }

    fn contains(&self, i: usize, j: usize) -> bool {
        self.row(j).is_some_and(|(lo, hi)| (lo..=hi).contains(&i))
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
        let disc = Query::new(
            Point2::new(0.5, 0.5),
            Goal::disc(Point2::new(4.5, 0.5), 2.6),
        );
        assert_eq!(disconnection(&map, &disc, Moves::Four), None);
    }

    /// A 60 x 40 map split by a wall with a `gap`-cell tunnel, and its query.
    fn passage(gap: usize) -> (crate::Generated, Query) {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let g = narrow_passage(60, 40, gap, 4, &mut rng);
        let query = Query::new(g.start, Goal::Point(g.goal));
        (g, query)
    }

    #[test]
    fn band_cause_names_the_bottleneck() {
        // A 6-cell tunnel: its middle cells are 3 cells from the walls... at most.
        let (g, query) = passage(6);
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
        assert_eq!(
            disconnection(&with_risk_band(&g.map, 5.0), &query, Moves::Four),
            None
        );
    }

    #[test]
    fn closed_wall_is_a_wall_even_for_safe_maps() {
        let (g, query) = passage(0);
        let banded = with_risk_band(&g.map, 2.0).avoiding_risk();
        assert_eq!(
            disconnection(&banded, &query, Moves::Four),
            Some(NoPathCause::Wall)
        );
        assert_eq!(
            disconnection_hopping(&g.map, &query, 2.0),
            Some(NoPathCause::Wall)
        );
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
