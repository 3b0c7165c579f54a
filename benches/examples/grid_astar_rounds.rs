//! Our grid A* against the `pathfinding` peer, timed alternately over several rounds (the
//! fastest round of each counts), with expansions and pushes per expansion: a quicker,
//! noise-robust view next to the criterion group.
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example grid_astar_rounds [-- ROUNDS [--generated]]
//! ```
//!
//! Without `--generated`: the bench's MovingAI suites (the arena pair of `data/movingai` and
//! the peers' maze of `data/generated`); with it, the generated 512 x 512 maps as well.

use std::hint::black_box;
use std::time::Instant;

use hyplan_benches::grid::{self, Suite, generated, movingai};
use search::{GridOptions, GridSearch};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let rounds: usize = args
        .iter()
        .find_map(|a| a.parse().ok())
        .unwrap_or(15)
        .max(1);
    let mut suites: Vec<Suite> = movingai().into_iter().collect();
    if args.iter().any(|a| a == "--generated") {
        suites.extend(generated());
    }
    println!(
        "suite,queries,expansions,pushes_per_expansion,ours_ms,peer_ms,ours_ns_per_expansion,peer_ns_per_expansion,ratio"
    );
    let (mut ours_total, mut peer_total) = (0.0, 0.0);
    for s in &suites {
        let mut search = GridSearch::new(&s.map, GridOptions::default()).expect("grid");
        let counts = grid::check(s, &mut search);
        let (expansions, pushes) = (counts.expansions, counts.pushes);
        let (mut ours, mut peer) = (f64::MAX, f64::MAX);
        for _ in 0..rounds {
            let t = Instant::now();
            black_box(grid::run_ours(s, &mut search));
            ours = ours.min(t.elapsed().as_secs_f64());
            let t = Instant::now();
            black_box(grid::run_peer(s));
            peer = peer.min(t.elapsed().as_secs_f64());
        }
        ours_total += ours;
        peer_total += peer;
        let per = |t: f64| t * 1e9 / expansions as f64;
        println!(
            "{},{},{expansions},{:.2},{:.3},{:.3},{:.1},{:.1},{:.2}",
            s.name,
            s.queries.len(),
            pushes as f64 / expansions as f64,
            ours * 1e3,
            peer * 1e3,
            per(ours),
            per(peer),
            peer / ours
        );
    }
    println!(
        "total,,,,{:.3},{:.3},,,{:.2}",
        ours_total * 1e3,
        peer_total * 1e3,
        peer_total / ours_total
    );
}
