//! [`Planner`] implementations of the grid searches.

use std::time::Instant;

use envmap::GridMap;
use hyplan_core::{
    Budget, Goal, Plan, PlanError, PlanStats, Planner, PlannerInfo, Point2, Query, Workspace, Zone,
};
use rand_core::RngCore;

use crate::{GridOptions, GridPath, GridSearch, GridSearchError, JpsError, JumpPointSearch};

/// Which grid search a planner runs.
#[derive(Clone, Copy)]
enum Algo {
    Astar,
    Dijkstra,
    ThetaStar,
    /// With the heuristic's weight.
    LazyThetaStar(f64),
    Jps,
}

/// The grid searches' default budget: unset, so they search to the end
/// ([`Budget::for_search`]).
const UNLIMITED: Budget = Budget {
    max_iterations: None,
    max_time: None,
};

/// A grid search as a planner: the parameter struct (its own fields, then the budget, with
/// their defaults), its inherent `plan` and its [`Planner`] implementation. The struct's
/// `algo()` names the search it runs.
macro_rules! grid_planner {
    (
        $(#[$doc:meta])*
        $ty:ident, $name:literal {
            $($(#[$field_doc:meta])* $field:ident: $field_ty:ty = $default:expr,)*
        }
    ) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq)]
        #[cfg_attr(
            feature = "serde",
            derive(serde::Serialize, serde::Deserialize),
            serde(default, deny_unknown_fields)
        )]
        pub struct $ty {
            $($(#[$field_doc])* pub $field: $field_ty,)*
            /// Expansions (`max_iterations`) and wall time the search may spend, the
            /// connectivity check and the grid's preparation included; unset by default
            /// (no expansion or time limit): the search ends with the path or when the grid is
            /// exhausted.
            pub budget: Budget,
        }

        impl Default for $ty {
            fn default() -> Self {
                Self {
                    $($field: $default,)*
                    budget: UNLIMITED,
                }
            }
        }

        impl $ty {
            /// Plans on `map`. The RNG is not used (the search is deterministic); it is
            /// there for the common planner shape. Through the [`Planner`] trait, a
            /// workspace that is not a grid map is refused with
            /// [`PlanError::InvalidParameter`] named `workspace` (and the planner).
            ///
            /// # Errors
            ///
            /// [`PlanError::InvalidStart`] / [`PlanError::InvalidGoal`] for points
            /// outside the map, not finite or blocked; [`PlanError::Disconnected`] (with
            /// the cause: a wall, or the risk band) when a flood fill of the passable
            /// cells, run first, does not join start and goal; [`PlanError::NoPath`]
            /// (with the expansion count) when every reachable cell was expanded;
            /// [`PlanError::BudgetExhausted`] when the budget ran out first.
            pub fn plan<R: RngCore + ?Sized>(
                &self,
                map: &GridMap,
                query: &Query,
                rng: &mut R,
            ) -> Result<Plan, PlanError> {
                let _ = rng;
                plan_on_grid(map, query, self.options, self.budget, self.algo())
            }
        }

        impl Planner for $ty {
            fn info(&self) -> PlannerInfo {
                PlannerInfo {
                    name: $name,
                    optimizing: false,
                    proves_no_path: true,
                    grid_only: true,
                }
            }

            fn plan(
                &self,
                ws: &dyn Workspace,
                query: &Query,
                rng: &mut dyn RngCore,
            ) -> Result<Plan, PlanError> {
                $ty::plan(self, GridMap::of_workspace(ws, $name)?, query, rng)
            }

            /// Prepares the grid search on the map and keeps it there ([`GridMap::keep`]):
            /// later plans on the map (until its zones change) skip the preparation.
            fn prepare(&self, ws: &dyn Workspace) -> Result<(), PlanError> {
                prepare_grid(GridMap::of_workspace(ws, $name)?, self.options, self.algo())
            }
        }
    };
}

impl GridAstar {
    fn algo(&self) -> Algo {
        Algo::Astar
    }
}

impl GridDijkstra {
    fn algo(&self) -> Algo {
        Algo::Dijkstra
    }
}

impl Jps {
    fn algo(&self) -> Algo {
        Algo::Jps
    }
}

impl LazyThetaStar {
    fn algo(&self) -> Algo {
        Algo::LazyThetaStar(self.weight)
    }
}

impl ThetaStar {
    fn algo(&self) -> Algo {
        if self.lazy {
            Algo::LazyThetaStar(1.0)
        } else {
            Algo::ThetaStar
        }
    }
}

grid_planner! {
    /// Grid A* as a planner: optimal 4- or 8-connected paths through cell centres.
    ///
    /// The workspace must be an [`envmap::GridMap`] (found through
    /// [`Workspace::as_any`]); its [`blocked_from`](GridMap::blocked_from) says which zones
    /// block. The returned path starts at the query's start point exactly, goes through the
    /// centres of the cells of the grid path and ends at the goal point. For a goal disc the
    /// search runs to the cell of the disc's centre and the path is cut at the first cell
    /// centre inside the disc (so it is valid but, for a large disc, not necessarily the
    /// shortest path into it). `cost` is the Euclidean length of the returned polyline, world
    /// units. `stats.expansions`, `stats.pushes` and `stats.nodes` (distinct cells reached)
    /// come from the search.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::{Goal, Point2, Query};
    /// use search::GridAstar;
    /// let map = GridMap::from_ascii("
    ///     ....
    ///     .##.
    ///     ....
    /// ")?;
    /// let query = Query::new(Point2::new(0.5, 1.5), Goal::Point(Point2::new(3.5, 1.5)));
    /// let plan = GridAstar::default().plan(&map, &query, &mut rand::rng())?;
    /// assert_eq!(plan.path.first(), Some(&query.start));
    /// assert_eq!(plan.path.last(), Some(&Point2::new(3.5, 1.5)));
    /// assert_eq!(plan.cost, 5.0);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    GridAstar, "astar" {
        /// Move rules (8-connected, no corner cutting by default).
        options: GridOptions = GridOptions::default(),
    }
}

grid_planner! {
    /// Grid Dijkstra as a planner: the same paths as [`GridAstar`] (equal costs), without a
    /// heuristic. Same conventions as [`GridAstar`].
    GridDijkstra, "dijkstra" {
        /// Move rules (8-connected, no corner cutting by default).
        options: GridOptions = GridOptions::default(),
    }
}

grid_planner! {
    /// Jump point search as a planner ([`JumpPointSearch`]): the optimal cost of
    /// [`GridAstar`] on 8-connected grids without corner cutting, expanding only jump
    /// points. Same conventions as [`GridAstar`]; `stats.expansions` counts jump points.
    ///
    /// The map's passable cells all cost the same (which zones block is the map's
    /// [`blocked_from`](GridMap::blocked_from)); other move rules (4-connected, corner
    /// cutting) are refused with [`PlanError::InvalidParameter`] named `options`, whose
    /// reason names `astar`, the planner that handles them.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::{Goal, Point2, Query};
    /// use search::{GridAstar, Jps};
    /// let map = GridMap::from_ascii("
    ///     ........
    ///     .######.
    ///     ........
    /// ")?;
    /// let query = Query::new(Point2::new(0.5, 1.5), Goal::Point(Point2::new(7.5, 1.5)));
    /// let plan = Jps::default().plan(&map, &query, &mut rand::rng())?;
    /// let astar = GridAstar::default().plan(&map, &query, &mut rand::rng())?;
    /// assert_eq!(plan.cost, astar.cost);
    /// assert!(plan.stats.expansions < astar.stats.expansions);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    Jps, "jps" {
        /// Move rules: only the default (8-connected, no corner cutting) is accepted.
        options: GridOptions = GridOptions::default(),
    }
}

grid_planner! {
    /// Theta* as a planner: any-angle paths between cell centres, each segment free under the
    /// map's exact `segment_free`. Same conventions as [`GridAstar`]. By default the lazy
    /// variant ([`GridSearch::lazy_theta_star`]: one line-of-sight test per expansion);
    /// `lazy: false` is the original ([`GridSearch::theta_star`]).
    ThetaStar, "theta-star" {
        /// Connectivity of the underlying grid moves (corner cutting is never used).
        options: GridOptions = GridOptions::default(),
        /// Lazy Theta* (Nash, Koenig and Tovey 2010; default `true`): a cell's line of sight
        /// to its parent is tested once, when it is expanded. `false`: Theta* (Nash et al.
        /// 2007), which tests it for every neighbour of every expanded cell, several times
        /// slower on open maps (60 s against 4 s on a 2000 x 2000 floor plan).
        lazy: bool = true,
    }
}

grid_planner! {
    /// Lazy Theta* (Nash, Koenig and Tovey 2010) as a planner under its own name: the
    /// search of [`ThetaStar`] with `lazy: true` ([`GridSearch::lazy_theta_star`]), so the
    /// same paths as `ThetaStar::default()`; `ThetaStar { lazy: false, .. }` is the eager
    /// original to compare it with. Same conventions as [`GridAstar`].
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::{Goal, Point2, Query};
    /// use search::{LazyThetaStar, ThetaStar};
    /// let map = GridMap::from_ascii("
    ///     ........
    ///     ..##....
    ///     ........
    /// ")?;
    /// let query = Query::new(Point2::new(0.5, 1.5), Goal::Point(Point2::new(7.5, 1.5)));
    /// let lazy = LazyThetaStar::default().plan(&map, &query, &mut rand::rng())?;
    /// let theta = ThetaStar { lazy: true, ..ThetaStar::default() };
    /// assert_eq!(lazy.path, theta.plan(&map, &query, &mut rand::rng())?.path);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    LazyThetaStar, "lazy-theta-star" {
        /// Connectivity of the underlying grid moves (corner cutting is never used).
        options: GridOptions = GridOptions::default(),
        /// The heuristic's weight, at least 1 (default 1: Lazy Theta*). Above 1, Lazy
        /// Theta* with Optimizations from the same paper: the straight-line distance to the
        /// goal times `weight`, as weighted A*, so fewer cells are expanded and paths may
        /// be longer ([`GridSearch::lazy_theta_star_weighted`]).
        weight: f64 = 1.0,
    }
}

fn plan_on_grid(
    map: &GridMap,
    query: &Query,
    options: GridOptions,
    budget: Budget,
    algo: Algo,
) -> Result<Plan, PlanError> {
    let started = Instant::now();
    budget.validate()?;
    if let Algo::LazyThetaStar(weight) = algo
        && !(weight.is_finite() && weight >= 1.0)
    {
        return Err(PlanError::InvalidParameter {
            name: "weight",
            value: weight.to_string(),
            reason: "the heuristic's weight must be a number of at least 1 (1: Lazy Theta*)",
        });
    }
    query.validate(map)?;
    // A flood fill proves "no path", with its cause, faster than exhausting the search.
    if let Some(cause) = envmap::disconnection(map, query, moves(algo, options)) {
        return Err(PlanError::Disconnected {
            cause,
            stats: PlanStats {
                elapsed: started.elapsed(),
                ..PlanStats::default()
            },
        });
    }
    let cell_of = |p: Point2| map.world_to_cell(p);
    let start_cell = cell_of(query.start).ok_or(PlanError::InvalidStart {
        point: query.start,
        reason: "outside the map",
    })?;
    let goal_point = query.goal.center();
    let goal_cell = cell_of(goal_point).ok_or(PlanError::InvalidGoal {
        point: goal_point,
        reason: "outside the map",
    })?;
    // The clock runs from the call: the check and the grid's preparation count.
    let deadline = budget.max_time.map(|t| started + t);
    let spent = |stats: PlanStats| PlanError::BudgetExhausted {
        stats: PlanStats {
            elapsed: started.elapsed(),
            ..stats
        },
    };
    let max_expansions = budget.max_iterations.unwrap_or(u64::MAX);
    let found = match search_cells(
        map,
        options,
        algo,
        (deadline, max_expansions),
        start_cell,
        goal_cell,
    ) {
        Ok(found) => found,
        Err(JpsError::Grid(GridSearchError::LimitReached { .. })) => {
            return Err(spent(PlanStats::default()));
        }
        Err(JpsError::NotApplicable { .. }) => {
            return Err(PlanError::InvalidParameter {
                name: "options",
                value: format!("{options:?}"),
                reason: "jump point search needs uniform-cost 8-connected moves without corner cutting; use astar",
            });
        }
        Err(e) => {
            return Err(PlanError::InvalidParameter {
                name: "workspace",
                value: e.to_string(),
                reason: "map too large for the grid search",
            });
        }
    };
    let mut stats = PlanStats::default();
    let found = match found {
        Ok(found) => found,
        Err(GridSearchError::NoPath { stats: s }) => {
            stats.expansions = s.expansions;
            stats.pushes = s.pushes;
            stats.nodes = s.reached;
            stats.elapsed = started.elapsed();
            return Err(PlanError::NoPath { stats });
        }
        Err(GridSearchError::LimitReached { stats: s }) => {
            stats.expansions = s.expansions;
            stats.pushes = s.pushes;
            stats.nodes = s.reached;
            stats.iterations = s.expansions;
            return Err(spent(stats));
        }
        // validate() accepted the points, so the cells are inside and free; anything else
        // is reported as what it is.
        Err(GridSearchError::StartBlocked { .. } | GridSearchError::StartOutside { .. }) => {
            return Err(PlanError::InvalidStart {
                point: query.start,
                reason: "its cell is blocked",
            });
        }
        Err(_) => {
            return Err(PlanError::InvalidGoal {
                point: goal_point,
                reason: "its cell is blocked",
            });
        }
    };
    stats.expansions = found.stats.expansions;
    stats.pushes = found.stats.pushes;
    stats.nodes = found.stats.reached;

    // Start point, the centres of the cells, then the goal.
    let mut path = Vec::with_capacity(found.cells.len() + 2);
    path.push(query.start);
    for &(i, j) in &found.cells {
        let c = map.cell_center(i, j);
        if path.last() != Some(&c) {
            path.push(c);
        }
        if let Goal::Disc { .. } = query.goal
            && query.goal.contains(c)
        {
            break;
        }
    }
    let last = *path.last().unwrap_or(&query.start);
    if !query.goal.contains(last) {
        path.push(goal_point);
    }
    stats.elapsed = started.elapsed();
    Ok(Plan {
        cost: hyplan_core::path_length(&path),
        path,
        trees: Vec::new(),
        waypoints: Vec::new(),
        stats,
    })
}

/// The moves of `algo` under `options`, for the connectivity check.
fn moves(algo: Algo, options: GridOptions) -> envmap::Moves {
    match (algo, options.connectivity, options.corner_cutting) {
        (Algo::Astar | Algo::Dijkstra, crate::Connectivity::Eight, true) => envmap::Moves::Eight,
        _ => envmap::Moves::Four,
    }
}

/// A search prepared from a map's cells, kept with the map between planner calls
/// ([`GridMap::keep`]): it fits the map while the map keeps it (the map drops it when
/// its zones change) for the same `blocked_from` and options.
struct Kept<S> {
    blocked_from: Zone,
    options: GridOptions,
    search: S,
}

/// The search kept with `map` for `options`, or a new one from `make`; handed to `run`,
/// then kept with the map for the next call (also when `run` found no path).
fn with_kept<S: Send + 'static, T>(
    map: &GridMap,
    options: GridOptions,
    make: impl FnOnce() -> Result<S, JpsError>,
    run: impl FnOnce(&mut S) -> T,
) -> Result<T, JpsError> {
    let blocked_from = map.blocked_from;
    let fits = |k: &Kept<S>| k.blocked_from == blocked_from && k.options == options;
    let mut search = match map.take_kept(fits) {
        Some(kept) => kept.search,
        None => make()?,
    };
    let found = run(&mut search);
    map.keep(Kept {
        blocked_from,
        options,
        search,
    });
    Ok(found)
}

/// Runs the grid search `algo` on `map` with `limit` (deadline, expansions) from `start`
/// to `goal` (the inner result), on the search kept with the map from an earlier call or
/// on one prepared now. The outer error is the preparation's: the move rules rule jump
/// point search out, the map is too large, or the deadline passed.
fn search_cells(
    map: &GridMap,
    options: GridOptions,
    algo: Algo,
    (deadline, max_expansions): (Option<Instant>, u64),
    start: (usize, usize),
    goal: (usize, usize),
) -> Result<Result<GridPath, GridSearchError>, JpsError> {
    if let Algo::Jps = algo {
        return with_kept(
            map,
            options,
            || JumpPointSearch::new_until(map, options, deadline),
            |search: &mut JumpPointSearch| {
                search.set_limit(max_expansions, deadline);
                search.search(start, goal)
            },
        );
    }
    with_kept(
        map,
        options,
        || Ok(GridSearch::new_until(map, options, deadline)?),
        |search: &mut GridSearch| {
            search.set_limit(max_expansions, deadline);
            match algo {
                Algo::Astar => search.astar(start, goal),
                Algo::Dijkstra => search.dijkstra(start, goal),
                Algo::ThetaStar => search.theta_star(map, start, goal),
                Algo::LazyThetaStar(weight) => {
                    search.lazy_theta_star_weighted(map, start, goal, weight)
                }
                // (Jump point search has its own search, run above.)
                Algo::Jps => search.lazy_theta_star(map, start, goal),
            }
        },
    )
}

/// Prepares what a plan of `algo` on `map` reads first: the connectivity check's
/// components (cached in the map) and the grid search (kept with the map,
/// [`GridMap::keep`]), so that the next plan on it does not.
fn prepare_grid(map: &GridMap, options: GridOptions, algo: Algo) -> Result<(), PlanError> {
    envmap::prepare_disconnection(map, moves(algo, options));
    let kept = match algo {
        Algo::Jps => with_kept(map, options, || JumpPointSearch::new(map, options), |_| ()),
        _ => with_kept(
            map,
            options,
            || Ok(GridSearch::new(map, options)?),
            |search: &mut GridSearch| {
                // What Theta*'s lines of sight read, made here so that its first plan
                // costs what it expands (a plan with a deadline would not make the map's
                // stride table: `GridSearch::sight`).
                if matches!(algo, Algo::ThetaStar | Algo::LazyThetaStar(_)) {
                    search.prepare_lines_of_sight(map);
                }
            },
        ),
    };
    kept.map_err(|e| PlanError::InvalidParameter {
        name: "workspace",
        value: e.to_string(),
        reason: "the grid search could not be prepared on this map",
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Connectivity;

    #[test]
    fn connectivity_default_is_eight() {
        assert_eq!(GridOptions::default().connectivity, Connectivity::Eight);
        assert!(!GridOptions::default().corner_cutting);
    }
}
