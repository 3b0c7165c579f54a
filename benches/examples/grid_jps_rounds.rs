//! Total search time of our jump point search, our grid A* and the `pathfinding` crate's A*
//! on the same queries, each suite's maps prepared once and not timed (as the criterion
//! group `grid_search` does), the fastest of a few rounds counting.
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example grid_jps_rounds [-- ROUNDS [--generated] [--bucketed] [--only SUITE]]
//! ```
//!
//! Without `--generated`: the MovingAI suites (the arena pair of `data/movingai` and the
//! peers' maze of `data/generated`); with it, the generated 512 x 512 maps as well. With
//! `--bucketed`, the generated maps' queries are drawn as MovingAI spreads a benchmark
//! set's over their lengths (`grid::bucketed_queries`) instead of their ten long ones.
//! Every cost is checked against the optimum before timing.

use std::hint::black_box;
use std::time::Instant;

use hyplan_benches::grid::{self, Suite, generated, movingai};
use search::{GridOptions, GridSearch, JumpPointSearch};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let rounds: usize = args.iter().find_map(|a| a.parse().ok()).unwrap_or(5).max(1);
    let mut suites: Vec<Suite> = movingai().into_iter().collect();
    if args.iter().any(|a| a == "--generated") {
        let bucketed = args.iter().any(|a| a == "--bucketed");
        suites.extend(generated().into_iter().map(|mut s| {
            if bucketed {
                s.queries = grid::bucketed_queries(&s.map);
            }
            s
        }));
    }
    // `--only NAME`: that suite alone.
    if let Some(k) = args.iter().position(|a| a == "--only") {
        let name = args.get(k + 1).cloned().unwrap_or_default();
        suites.retain(|s| s.name == name);
    }
    println!(
        "suite,queries,astar_expansions,jps_expansions,jps_ms,astar_ms,peer_ms,jps/peer,astar/peer,jps/astar"
    );
    for s in &suites {
        let mut astar = GridSearch::new(&s.map, GridOptions::default()).expect("grid");
        let mut jps = JumpPointSearch::new(&s.map, GridOptions::default()).expect("jps");
        let a = grid::check(s, &mut astar);
        let j = grid::check_jps(s, &mut jps);
        let (mut tj, mut ta, mut tp) = (f64::MAX, f64::MAX, f64::MAX);
        let time = |f: &mut dyn FnMut() -> f64| {
            let t = Instant::now();
            black_box(f());
            t.elapsed().as_secs_f64()
        };
        // Each planner's rounds back to back, as a criterion group times them (each
        // with its own data in the caches).
        for _ in 0..rounds {
            tj = tj.min(time(&mut || grid::run_jps(s, &mut jps)));
        }
        for _ in 0..rounds {
            ta = ta.min(time(&mut || grid::run_ours(s, &mut astar)));
        }
        for _ in 0..rounds {
            tp = tp.min(time(&mut || grid::run_peer(s)));
        }
        println!(
            "{},{},{},{},{:.3},{:.3},{:.3},{:.4},{:.4},{:.3}",
            s.name,
            s.queries.len(),
            a.expansions,
            j.expansions,
            tj * 1e3,
            ta * 1e3,
            tp * 1e3,
            tj / tp,
            ta / tp,
            tj / ta
        );
    }
}
