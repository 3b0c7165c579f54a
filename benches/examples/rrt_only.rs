//! RRT or RRT-Connect alone on a case of `bench-peers`: the median time of `RUNS`
//! seeded runs (seeds 1..=RUNS), and the runs' total nodes, iterations, edge checks and
//! path length, for comparing two builds on a noisy host (run their binaries alternately) or under
//! callgrind (no smoothing or metrics around the planner, as in `hyplan plan`).
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example rrt_only -- RUNS [rects100|maze101|room|arena] [rrt|rrt-connect]
//! ```

use std::time::Instant;

use hyplan_core::{Budget, Goal, Query};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use sampling::{Rrt, RrtConnect};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let runs: u64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(500);
    let case = args.get(1).map_or("rects100", String::as_str);
    let planner = args.get(2).map_or("rrt", String::as_str);
    // bench-peers' cases: map, start, goal, step, goal radius.
    let (file, start, goal, step, radius) = match case {
        "maze101" => (
            "data/generated/maze.pgm",
            (2.5, 2.5),
            (98.5, 98.5),
            3.0,
            0.0,
        ),
        "room" => (
            "scenarios/maps/room_960x640.pgm",
            (20.0, 320.0),
            (900.0, 520.0),
            40.0,
            20.0,
        ),
        "arena" => (
            "data/movingai/arena.map",
            (1.5, 45.5),
            (47.5, 9.5),
            3.0,
            0.0,
        ),
        _ => (
            "data/generated/rects100.pgm",
            (5.5, 5.5),
            (94.5, 94.5),
            5.0,
            0.0,
        ),
    };
    let loaded = hyplan_benches::load_as_peer(file);
    let map = loaded.map;
    // The one-time preparation bench-peers makes before its timed runs.
    let _ = map.blocked_strides();
    let center = loaded.frame.to_world(goal.0, goal.1);
    let goal = if radius > 0.0 {
        Goal::disc(center, radius)
    } else {
        Goal::Point(center)
    };
    let query = Query::new(loaded.frame.to_world(start.0, start.1), goal);
    let budget = Budget::iterations(2_000_000);
    let rrt = Rrt {
        step,
        goal_bias: 0.05,
        budget,
    };
    let connect = RrtConnect { step, budget };
    let mut times = Vec::new();
    let (mut nodes, mut iterations, mut checks, mut length) = (0, 0, 0, 0.0);
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
}
