//! Lazy Theta* against grid A* and eager Theta* on the same queries: total search time
//! (the fastest of a few rounds) and path lengths, on the MovingAI suites, the generated
//! 512 x 512 maps and seed 000's room (its risk band blocking).
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example any_angle_rounds [-- ROUNDS [WEIGHT]]
//! ```
//!
//! `WEIGHT` (default 1) runs Lazy Theta* with Optimizations, its heuristic weighted
//! ([`GridSearch::lazy_theta_star_weighted`]), in place of plain Lazy Theta*.
//!
//! The cells each search expanded over the suite are printed too (A* and Lazy Theta*).
//!
//! Each map's one-time preparation (the grid search's cells and the map's stride table,
//! `GridMap::blocked_strides`) is timed apart and printed. Every lazy and eager Theta*
//! path segment is checked with the map's `segment_free` before timing.

use std::hint::black_box;
use std::time::Instant;

use envmap::{GridMap, LoadOptions, load_map};
use harness::stats::median;
use hyplan_benches::grid::{self, Suite, generated, movingai};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use search::{GridOptions, GridPath, GridSearch};

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(5)
        .max(1);
    let weight: f64 = std::env::args()
        .nth(2)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1.0);
    let mut suites: Vec<Suite> = movingai().into_iter().collect();
    suites.extend(generated());
    suites.push(room());
    println!(
        "suite,queries,prep_ms,astar_ms,lazy_ms,theta_ms,lazy/astar,theta/astar,lazy/theta_length_median,astar_expanded,lazy_expanded"
    );
    let (mut time_ratios, mut length_ratios) = (Vec::new(), Vec::new());
    for s in &suites {
        let prepared = Instant::now();
        let mut search = GridSearch::new(&s.map, GridOptions::default()).expect("grid");
        let _ = s.map.blocked_strides();
        let prep_ms = prepared.elapsed().as_secs_f64() * 1e3;
        // Lengths, and every segment checked, outside the timed rounds.
        let (mut lengths, mut expanded) = (Vec::new(), (0, 0));
        for &(a, b, _) in &s.queries {
            let lazy = search
                .lazy_theta_star_weighted(&s.map, a, b, weight)
                .expect("lazy Theta*");
            expanded.0 += search.astar(a, b).map_or(0, |p| p.stats.expansions);
            expanded.1 += lazy.stats.expansions;
            let eager = search.theta_star(&s.map, a, b).expect("Theta*");
            check(&s.map, &lazy);
            check(&s.map, &eager);
            lengths.push(lazy.cost / eager.cost);
        }
        // The three searches' rounds alternate (A*, lazy, eager, then again), so that a
        // slow stretch of the host falls on all three alike, not on one planner's rounds.
        let mut best = [f64::MAX; 3];
        for _ in 0..rounds {
            for (k, t) in best.iter_mut().enumerate() {
                let started = Instant::now();
                for &(a, b, _) in &s.queries {
                    let cost = match k {
                        0 => search.astar(a, b).map_or(0.0, |p| p.cost),
                        1 => search
                            .lazy_theta_star_weighted(&s.map, a, b, weight)
                            .map_or(0.0, |p| p.cost),
                        _ => search.theta_star(&s.map, a, b).map_or(0.0, |p| p.cost),
                    };
                    black_box(cost);
                }
                *t = t.min(started.elapsed().as_secs_f64() * 1e3);
            }
        }
        let [astar, lazy, theta] = best;
        let length = median(lengths).unwrap_or(f64::NAN);
        println!(
            "{},{},{:.2},{:.3},{:.3},{:.3},{:.3},{:.3},{:.5},{},{}",
            s.name,
            s.queries.len(),
            prep_ms,
            astar,
            lazy,
            theta,
            lazy / astar,
            theta / astar,
            length,
            expanded.0,
            expanded.1
        );
        time_ratios.push(lazy / astar);
        length_ratios.push(length);
    }
    println!(
        "median over {} maps: lazy Theta* / A* time {:.3}; lazy / eager Theta* length {:.5}",
        suites.len(),
        median(time_ratios).unwrap_or(f64::NAN),
        median(length_ratios).unwrap_or(f64::NAN)
    );
}

/// Seed 000's room (`scenarios/maps/room_960x640.png`, default loading, the risk band
/// blocking as with `--avoid-risk`) and ten random queries.
fn room() -> Suite {
    let path = grid::data().join("../scenarios/maps/room_960x640.png");
    let loaded = load_map(&path, &LoadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let map: GridMap = loaded.map.avoiding_risk();
    let queries = grid::queries(&map, &mut ChaCha8Rng::seed_from_u64(0));
    Suite {
        name: "room960x640",
        map,
        queries,
    }
}

/// Panics unless every segment of `path` between cell centres passes `segment_free`.
fn check(map: &GridMap, path: &GridPath) {
    for w in path.cells.windows(2) {
        let (p, q) = (
            map.cell_center(w[0].0, w[0].1),
            map.cell_center(w[1].0, w[1].1),
        );
        assert!(map.segment_free_cells(p, q), "{w:?}");
    }
}
