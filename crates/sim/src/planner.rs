//! Global planning on the costmap: Dijkstra (the paper's Algorithm 3) through `search`'s
//! grid Dijkstra, or any [`Planner`] of the workspace in its place.
//!
//! Both plan first in the cells away from obstacles (the costmap's `Free` zone) and, when
//! that fails, through the inflation band too (`Free` and `Risk`): a plain Dijkstra on a
//! two-level costmap, where NavFn weighs every cell by its cost. A robot whose own cell
//! is blocked (it stopped close to a person) plans from the nearest passable cell.
//! Grid paths are shortened with `postproc`'s greedy shortcut under the map's exact
//! `segment_free`, so straight stretches come out straight.

use envmap::GridMap;
use hyplan_core::{Goal, Planner, Point2, Query, Workspace, Zone};
use rand_chacha::ChaCha8Rng;
use search::{GridOptions, GridSearch, GridSearchError, JumpPointSearch};

use crate::costmap::changed_window;

/// Which planner the navigator calls.
pub enum GlobalPlanner {
    /// Dijkstra on the costmap cells (Algorithm 3), 8-connected, no corner cutting.
    Dijkstra,
    /// Any planner of the workspace, run on the costmap as a [`GridMap`] workspace with
    /// the goal as a disc of the goal tolerance.
    Other(Box<dyn Planner>),
}

impl std::fmt::Debug for GlobalPlanner {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name())
    }
}

impl GlobalPlanner {
    /// The planner's name ("dijkstra" for Algorithm 3).
    #[must_use]
    pub fn name(&self) -> String {
        match self {
            Self::Dijkstra => "dijkstra".into(),
            Self::Other(p) => p.info().name.to_string(),
        }
    }

    /// A path from `start` to within `tolerance` of `goal` on `map` (the costmap's zones),
    /// start first, ending at the goal; `None` when neither zone level has one.
    pub fn plan(
        &self,
        map: &GridMap,
        start: Point2,
        goal: Point2,
        tolerance: f64,
        rng: &mut ChaCha8Rng,
    ) -> Option<Vec<Point2>> {
        self.plan_with(
            &mut PlanScratch::default(),
            map,
            start,
            goal,
            tolerance,
            rng,
        )
    }

    /// [`plan`](Self::plan) with the buffers of earlier plans (a navigator keeps one
    /// [`PlanScratch`]): the same path, without allocating a search grid per plan.
    pub fn plan_with(
        &self,
        scratch: &mut PlanScratch,
        map: &GridMap,
        start: Point2,
        goal: Point2,
        tolerance: f64,
        rng: &mut ChaCha8Rng,
    ) -> Option<Vec<Point2>> {
        let mut m = map.clone();
        for (level, blocked) in [Zone::Risk, Zone::Forbidden].into_iter().enumerate() {
            m.blocked_from = blocked;
            let found = match self {
                Self::Dijkstra => dijkstra(&mut scratch.levels[level], &m, start, goal),
                Self::Other(p) => other(p.as_ref(), &m, start, goal, tolerance, rng),
            };
            if let Some(path) = found {
                return Some(path);
            }
        }
        None
    }
}

/// What plans keep between them: a grid search per zone level, built for the first
/// costmap and brought up to date with the next ones where their zones changed.
///
/// ```
/// use envmap::GridMap;
/// use hyplan_core::Point2;
/// use rand::SeedableRng;
/// use sim::{GlobalPlanner, PlanScratch};
/// let map = GridMap::from_ascii("......\n.####.\n......")?;
/// let (s, g) = (Point2::new(0.5, 0.5), Point2::new(5.5, 0.5));
/// let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0);
/// let mut scratch = PlanScratch::default();
/// let first = GlobalPlanner::Dijkstra.plan_with(&mut scratch, &map, s, g, 0.1, &mut rng);
/// let again = GlobalPlanner::Dijkstra.plan_with(&mut scratch, &map, s, g, 0.1, &mut rng);
/// assert!(first.is_some());
/// assert_eq!(first, again);
/// assert_eq!(first, GlobalPlanner::Dijkstra.plan(&map, s, g, 0.1, &mut rng));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Default)]
pub struct PlanScratch {
    levels: [Option<Prepared>; 2],
}

/// A grid search and the zones it was last brought up to date with.
struct Prepared {
    search: GridSearch,
    /// Finds the optimal cost first, which bounds Dijkstra's search (`None`: the map is
    /// too large for it).
    jps: Option<JumpPointSearch>,
    zones: Vec<Zone>,
    /// The last query on these zones and its answer: a robot held where it stands (a
    /// path blocked at once, a retry after a failure) asks the same again, and a plan is
    /// a function of the zones, the start cell and the goal.
    last: Option<Answer>,
}

/// A plan's query and its shortened path from the start cell's centre (`None`: no path).
struct Answer {
    start: (usize, usize),
    goal: [u64; 2],
    path: Option<Vec<Point2>>,
}

impl std::fmt::Debug for PlanScratch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let built = self.levels.iter().filter(|l| l.is_some()).count();
        f.debug_struct("PlanScratch")
            .field("levels_built", &built)
            .finish()
    }
}

/// The search of `slot` brought up to date with `map` (built on the first call, or when
/// the size changed).
fn prepared<'s>(slot: &'s mut Option<Prepared>, map: &GridMap) -> Option<&'s mut Prepared> {
    let fits = slot
        .as_ref()
        .is_some_and(|p| p.zones.len() == map.zones().len());
    if !fits {
        let search = GridSearch::new(map, GridOptions::default()).ok()?;
        let jps = JumpPointSearch::new(map, GridOptions::default()).ok();
        let zones = map.zones().to_vec();
        return Some(slot.insert(Prepared {
            search,
            jps,
            zones,
            last: None,
        }));
    }
    let p = slot.as_mut()?;
    if let Some((columns, rows)) = changed_window(&p.zones, map.zones(), map.width()) {
        p.last = None;
        p.search
            .update_window(map, columns.clone(), rows.clone())
            .ok()?;
        if let Some(jps) = &mut p.jps {
            jps.update_window(map, columns.clone(), rows.clone()).ok()?;
        }
        for j in rows {
            let at = j * map.width();
            p.zones[at + columns.start..at + columns.end]
                .copy_from_slice(&map.zones()[at + columns.start..at + columns.end]);
        }
    }
    Some(p)
}

/// How far a plan's start may move to the nearest passable cell, m: a robot whose centre
/// is a little too near an obstacle on the costmap (it stopped close to a wall it had not
/// yet mapped) starts from there.
const START_SLACK: f64 = 0.5;

/// [`START_SLACK`] in rings of cells of side `resolution`.
pub(crate) fn start_rings(resolution: f64) -> usize {
    (START_SLACK / resolution).ceil() as usize
}

/// The passable cell nearest `cell` within [`START_SLACK`].
fn nearest_passable(map: &GridMap, cell: (usize, usize)) -> Option<(usize, usize)> {
    let size = (map.width(), map.height());
    let rings = start_rings(map.resolution());
    envmap::nearest_passable(size, cell, rings, |i, j| map.cell_free(i, j))
}

fn dijkstra(
    slot: &mut Option<Prepared>,
    map: &GridMap,
    start: Point2,
    goal: Point2,
) -> Option<Vec<Point2>> {
    let s = nearest_passable(map, map.world_to_cell(start)?)?;
    let g = map.world_to_cell(goal)?;
    if !map.cell_free(g.0, g.1) {
        return None;
    }
    let prepared = prepared(slot, map)?;
    let goal_bits = [goal.x.to_bits(), goal.y.to_bits()];
    let pruned = match &prepared.last {
        Some(a) if a.start == s && a.goal == goal_bits => a.path.clone(),
        _ => {
            let path = shortest(&mut prepared.search, prepared.jps.as_mut(), map, s, g, goal);
            prepared.last = Some(Answer {
                start: s,
                goal: goal_bits,
                path: path.clone(),
            });
            path
        }
    }?;
    let mut path = Vec::with_capacity(pruned.len() + 1);
    path.push(start);
    path.extend(pruned.into_iter().filter(|&p| p != start));
    Some(path)
}

/// Algorithm 3's path from cell `s` to cell `g` (ending at `goal`, in that cell),
/// shortened.
fn shortest(
    search: &mut GridSearch,
    jps: Option<&mut JumpPointSearch>,
    map: &GridMap,
    s: (usize, usize),
    g: (usize, usize),
    goal: Point2,
) -> Option<Vec<Point2>> {
    // A plan that fails floods every cell the start reaches, and a navigator retries
    // failed plans: the two-sided test costs at most the smaller region, and no costs.
    if !search.connected(s, g).ok()? {
        return None;
    }
    // Dijkstra's path, among the cells that can lie on a path of the optimal cost: jump
    // point search finds that cost in a fraction of the time, but not Dijkstra's path
    // (its ties go another way, and the runs would change). Should the bound fall below
    // Dijkstra's optimum (the two searches reading the map differently), the unbounded
    // search still finds the path.
    let optimal = jps.and_then(|jps| jps.search(s, g).ok()).map(|p| p.cost);
    let found = match optimal {
        Some(cost) => search
            .dijkstra_within(s, g, cost)
            .or_else(|_| search.dijkstra(s, g)),
        None => search.dijkstra(s, g),
    };
    let found = match found {
        Ok(p) => p,
        Err(GridSearchError::NoPath { .. }) => return None,
        Err(_) => return None,
    };
    let mut cells: Vec<Point2> = found
        .cells
        .iter()
        .map(|&(i, j)| map.cell_center(i, j))
        .collect();
    // The goal replaces the goal cell's centre (same cell, so the segment is free).
    if let Some(last) = cells.last_mut() {
        *last = goal;
    }
    // On a straight run of the grid path away from the anchor, the segment to the next
    // cell is the one just found free and one move of the path (free: no move cuts a
    // corner), so it is free without a sweep. A corridor costs a sweep per anchor, not
    // one per cell it runs along.
    let centre_cell = |p: Point2| {
        map.world_to_cell(p)
            .filter(|&(i, j)| map.cell_center(i, j) == p)
            .map(|(i, j)| (i as i64, j as i64))
    };
    let mut last_free: Option<(Point2, Point2)> = None;
    Some(postproc::shortcut_greedy(&cells, |a, c| {
        let straight_on = last_free
            .filter(|&(from, _)| from == a)
            .and_then(|(_, b)| {
                let (a, b, c) = (centre_cell(a)?, centre_cell(b)?, centre_cell(c)?);
                let (run, step) = ((b.0 - a.0, b.1 - a.1), (c.0 - b.0, c.1 - b.1));
                let one_move = step != (0, 0) && step.0.abs() <= 1 && step.1.abs() <= 1;
                let onward =
                    run.0 * step.1 == run.1 * step.0 && run.0 * step.0 + run.1 * step.1 > 0;
                Some(one_move && onward)
            })
            .unwrap_or(false);
        let free = straight_on || map.segment_free(a, c);
        last_free = free.then_some((a, c));
        free
    }))
}

fn other(
    planner: &dyn Planner,
    map: &GridMap,
    start: Point2,
    goal: Point2,
    tolerance: f64,
    rng: &mut ChaCha8Rng,
) -> Option<Vec<Point2>> {
    let s = nearest_passable(map, map.world_to_cell(start)?)?;
    let s_pt = if s == map.world_to_cell(start)? {
        start
    } else {
        map.cell_center(s.0, s.1)
    };
    let query = Query::new(s_pt, Goal::disc(goal, tolerance.max(0.0)));
    let plan = planner.plan(map, &query, rng).ok()?;
    let mut path = Vec::with_capacity(plan.path.len() + 2);
    path.push(start);
    path.extend(plan.path.into_iter().filter(|&p| p != start));
    if path.last().is_some_and(|&p| p != goal) && map.segment_free(*path.last()?, goal) {
        path.push(goal);
    }
    Some(path)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        /// The navigator's plan with jump point search's bound is its plan without:
        /// the same shortened path, on maps of free, risk and forbidden cells, at both
        /// zone levels. Fails when the bound leaves out a cell of Dijkstra's path (with
        /// the octile distance doubled, say).
        #[test]
        fn the_bound_keeps_the_navigators_plans(
            (w, h) in (2usize..40, 2usize..40),
            zones in proptest::collection::vec(0u8..10, 1600),
            (si, sj, gi, gj) in (0usize..40, 0usize..40, 0usize..40, 0usize..40),
            risk_blocks in any::<bool>(),
        ) {
            let zones = zones[..w * h]
                .iter()
                .map(|&z| match z {
                    0..=5 => Zone::Free,
                    6..=7 => Zone::Risk,
                    _ => Zone::Forbidden,
                })
                .collect();
            let mut map = GridMap::from_zones(w, h, 0.05, Point2::origin(), zones).unwrap();
            map.blocked_from = if risk_blocks { Zone::Risk } else { Zone::Forbidden };
            let (s, g) = ((si % w, sj % h), (gi % w, gj % h));
            map.set_cell_zone(s.0, s.1, Zone::Free);
            map.set_cell_zone(g.0, g.1, Zone::Free);
            let goal = map.cell_center(g.0, g.1);
            let mut bounded = GridSearch::new(&map, GridOptions::default()).unwrap();
            let mut jps = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
            let mut plain = GridSearch::new(&map, GridOptions::default()).unwrap();
            prop_assert_eq!(
                shortest(&mut bounded, Some(&mut jps), &map, s, g, goal),
                shortest(&mut plain, None, &map, s, g, goal)
            );
            // Without the fallback: the two searches read the zones alike, so the bound
            // is the optimum itself and finds Dijkstra's cells.
            if let Ok(optimum) = jps.search(s, g) {
                let within = bounded.dijkstra_within(s, g, optimum.cost).map(|p| p.cells);
                prop_assert_eq!(within.ok(), plain.dijkstra(s, g).ok().map(|p| p.cells));
            }
        }
    }
}
