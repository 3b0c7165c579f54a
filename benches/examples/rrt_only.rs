//! RRT or RRT-Connect alone on a case of `bench-peers`: the median time of `RUNS`
//! seeded runs (seeds 1..=RUNS), the runs' total nodes, iterations, edge checks and path
//! length, and how many of the trees' full-step edges come out longer than the step by
//! rounding; for comparing two builds on a noisy host (run their binaries alternately) or under
//! callgrind (no smoothing or metrics around the planner, as in `hyplan plan`).
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example rrt_only -- RUNS [rects100|maze101|room|arena] [rrt|rrt-connect]
//! ```

use std::time::Instant;

use hyplan_core::Budget;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use sampling::{Rrt, RrtConnect};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let runs: u64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(500);
    let case = args.get(1).map_or("rects100", String::as_str);
    let planner = args.get(2).map_or("rrt", String::as_str);
    // bench-peers' case (by the start of its name), read and prepared as bench-peers does
    // before its timed runs.
    let Some(peer) = hyplan_benches::PEER_CASES
        .iter()
        .find(|c| c.name.starts_with(case))
    else {
        eprintln!("no bench-peers case named {case}");
        std::process::exit(2);
    };
    let loaded = hyplan_benches::load_as_peer(peer.map);
    let map = loaded.map;
    let _ = map.blocked_strides();
    let query = peer.query(&loaded.frame);
    let step = peer.step;
    let budget = Budget::iterations(2_000_000);
    let rrt = Rrt {
        step,
        goal_bias: peer.goal_bias,
        budget,
    };
    let connect = RrtConnect { step, budget };
    let mut times = Vec::new();
    let (mut nodes, mut iterations, mut checks, mut length) = (0, 0, 0, 0.0);
    let (mut full_steps, mut rounded_over) = (0u64, 0u64);
    for seed in 1..=runs {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let t = Instant::now();
        let plan = if planner == "rrt-connect" {
            connect.plan(&map, &query, &mut rng)
        } else {
            rrt.plan(&map, &query, &mut rng)
        }
        .expect("a path");
        times.push(t.elapsed().as_secs_f64() * 1e3);
        // The full steps among the trees' edges, and those whose squared length comes out
        // above the step's square by rounding (the edge checks' bound for short segments
        // must allow for them).
        for tree in &plan.trees {
            for (&child, parent) in tree.points.iter().zip(&tree.parent) {
                let Some(parent) = parent else { continue };
                let len_sq = (child - tree.points[*parent as usize]).norm_squared();
                if len_sq >= step * step * (1.0 - 1e-12) {
                    full_steps += 1;
                    rounded_over += u64::from(len_sq > step * step);
                }
            }
        }
        nodes += plan.stats.nodes;
        iterations += plan.stats.iterations;
        checks += plan.stats.collision_checks;
        length += plan.cost;
    }
    times.sort_by(f64::total_cmp);
    println!(
        "{case} {planner}: median {:.4} ms over {runs} runs; nodes {nodes} iterations {iterations} edge checks {checks} length {length:.9}",
        times[times.len() / 2]
    );
    println!(
        "tree edges of a full step: {full_steps}, of which {rounded_over} longer than the step by rounding"
    );
}
