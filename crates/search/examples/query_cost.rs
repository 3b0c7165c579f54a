//! What a short grid query costs after the map's one-time preparation, on a 512 x 512 and a
//! 4096 x 4096 map of rooms: the preparation is paid once per map, a query what it touches
//! (issue 31: a query that expands k nodes costs O(k), not O(map)). Jump point search, A*,
//! Dijkstra and Lazy Theta*, each on its own prepared search (Lazy Theta*'s preparation
//! adds what its lines of sight read: `GridSearch::prepare_lines_of_sight`); then the same
//! four through the `Planner` trait (as `hyplan plan`, the registry and Python call them),
//! after `Planner::prepare` has left the search with the map: the query from world point
//! (10.5, 11.5) to (13.5, 12.5), its time the whole `plan` call (checks, search and path).
//!
//! ```sh
//! cargo run --release -p search --example query_cost
//! ```

use std::time::Instant;

use envmap::GridMap;
use hyplan_core::{Goal, Planner, Point2, Query, Zone};
use search::{
    GridAstar, GridDijkstra, GridOptions, GridSearch, Jps, JumpPointSearch, LazyThetaStar,
};

/// The first call's time and the fastest of 1,000 more, microseconds, and the first
/// answer.
fn time<T, E>(mut query: impl FnMut() -> Result<T, E>) -> Result<(f64, f64, T), E> {
    let t = Instant::now();
    let first = query()?;
    let first_us = t.elapsed().as_secs_f64() * 1e6;
    let mut best = f64::MAX;
    for _ in 0..1000 {
        let t = Instant::now();
        std::hint::black_box(query()?);
        best = best.min(t.elapsed().as_secs_f64() * 1e6);
    }
    Ok((first_us, best, first))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("map,planner,prepare_ms,first_query_us,best_query_us,expansions,cost");
    for n in [512, 4096] {
        // Rooms: walls every 64 cells with a door in each.
        let mut map = GridMap::filled(n, n, Zone::Free)?;
        for k in (64..n).step_by(64) {
            for i in 0..n {
                if i % 64 != 32 {
                    map.set_cell_zone(i, k, Zone::Forbidden);
                    map.set_cell_zone(k, i, Zone::Forbidden);
                }
            }
        }
        // The issue's query: a few cells apart in open space.
        let (start, goal) = ((10, 11), (13, 12));
        let t = Instant::now();
        let mut jps = JumpPointSearch::new(&map, GridOptions::default())?;
        let jps_prepare = t.elapsed();
        let t = Instant::now();
        let mut grid = GridSearch::new(&map, GridOptions::default())?;
        let grid_prepare = t.elapsed();
        let mut sight = GridSearch::new(&map, GridOptions::default())?;
        let t = Instant::now();
        sight.prepare_lines_of_sight(&map);
        let sight_prepare = grid_prepare + t.elapsed();
        let rows = [
            ("jps", jps_prepare, time(|| jps.search(start, goal))?),
            ("astar", grid_prepare, time(|| grid.astar(start, goal))?),
            (
                "dijkstra",
                grid_prepare,
                time(|| grid.dijkstra(start, goal))?,
            ),
            (
                "lazy-theta-star",
                sight_prepare,
                time(|| sight.lazy_theta_star(&map, start, goal))?,
            ),
        ];
        for (name, prepare, (first_us, best, path)) in rows {
            println!(
                "{n}x{n},{name},{:.1},{first_us:.1},{best:.2},{},{:.4}",
                prepare.as_secs_f64() * 1e3,
                path.stats.expansions,
                path.cost
            );
        }
        let query = Query::new(
            Point2::new(10.5, 11.5),
            Goal::Point(Point2::new(13.5, 12.5)),
        );
        let planners: [(&str, &dyn Planner); 4] = [
            ("jps (Planner)", &Jps::default()),
            ("astar (Planner)", &GridAstar::default()),
            ("dijkstra (Planner)", &GridDijkstra::default()),
            ("lazy-theta-star (Planner)", &LazyThetaStar::default()),
        ];
        let mut rng = rand::rng();
        for (name, planner) in planners {
            let t = Instant::now();
            planner.prepare(&map)?;
            let prepare = t.elapsed();
            let (first_us, best, plan) = time(|| planner.plan(&map, &query, &mut rng))?;
            println!(
                "{n}x{n},{name},{:.1},{first_us:.1},{best:.2},{},{:.4}",
                prepare.as_secs_f64() * 1e3,
                plan.stats.expansions,
                plan.cost
            );
        }
    }
    Ok(())
}
