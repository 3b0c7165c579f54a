//! Total search time of our jump point search, our grid A* and the `pathfinding` crate's A*
//! on the same queries, each suite's maps prepared once and not timed (as the criterion
//! group `grid_search` does), the fastest of a few rounds counting.
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example grid_jps_rounds [-- ROUNDS [--generated] [--bucketed] [--only SUITE]]
//! cargo run --release -p hyplan-benches --example grid_jps_rounds -- ROUNDS --random-family
//! ```
//!
//! Without `--generated`: the MovingAI suites (the arena pair of `data/movingai` and the
//! peers' maze of `data/generated`); with it, the generated 512 x 512 maps as well. With
//! `--bucketed`, the generated maps' queries are drawn as MovingAI spreads a benchmark
//! set's over their lengths (`grid::bucketed_queries`) instead of their ten long ones.
//! Every cost is checked against the optimum before timing.
//!
//! `--random-family` runs, instead, the densities of MovingAI's random-obstacle family
//! (`random512-10` to `random512-40`: 10 to 40 % of the cells blocked, in steps of 5), one
//! generated 512 x 512 map each ([`grid::random_family`]) with bucketed queries, and adds a
//! line of the family's totals, the sums over its maps, as the benchmark's family columns
//! are reported.

use std::hint::black_box;
use std::time::Instant;

use hyplan_benches::grid::{self, Suite, generated, movingai};
use search::{GridOptions, GridSearch, JumpPointSearch};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let rounds: usize = args.iter().find_map(|a| a.parse().ok()).unwrap_or(5).max(1);
    let family = args.iter().any(|a| a == "--random-family");
    let mut suites: Vec<Suite> = if family {
        grid::random_family()
    } else {
        movingai().into_iter().collect()
    };
    if !family && args.iter().any(|a| a == "--generated") {
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
    let mut totals = Row::default();
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
        let row = Row {
            queries: s.queries.len(),
            astar_expansions: a.expansions,
            jps_expansions: j.expansions,
            jps: tj,
            astar: ta,
            peer: tp,
        };
        row.print(s.name);
        totals.add(&row);
    }
    if family {
        totals.print("family");
    }
}

/// One line of the table: a suite's (or the family's summed) queries, expansions and
/// seconds.
#[derive(Default)]
struct Row {
    queries: usize,
    astar_expansions: u64,
    jps_expansions: u64,
    jps: f64,
    astar: f64,
    peer: f64,
}

impl Row {
    fn add(&mut self, other: &Row) {
        self.queries += other.queries;
        self.astar_expansions += other.astar_expansions;
        self.jps_expansions += other.jps_expansions;
        self.jps += other.jps;
        self.astar += other.astar;
        self.peer += other.peer;
    }

    fn print(&self, name: &str) {
        println!(
            "{name},{},{},{},{:.3},{:.3},{:.3},{:.4},{:.4},{:.3}",
            self.queries,
            self.astar_expansions,
            self.jps_expansions,
            self.jps * 1e3,
            self.astar * 1e3,
            self.peer * 1e3,
            self.jps / self.peer,
            self.astar / self.peer,
            self.jps / self.astar
        );
    }
}
