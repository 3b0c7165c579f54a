//! Lazy Theta* (or grid A*) alone on chosen suites: the fastest of `PASSES` passes over a
//! suite's queries, for comparing two builds on a noisy host (run their binaries
//! alternately), and for a profiler (`valgrind --tool=callgrind`, one pass).
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example any_angle_only -- PASSES lazy|astar SUITE...
//! ```
//!
//! Suites by name as in `any_angle_rounds` (`arena`, `maze`, and the generated ones such
//! as `game512`). Prints `suite planner best_ms pushes expansions` per suite (the counts of
//! one pass).

use std::time::Instant;

use hyplan_benches::grid::{generated, movingai};
use search::{GridOptions, GridSearch};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let passes: usize = args
        .first()
        .and_then(|a| a.parse().ok())
        .unwrap_or(10)
        .max(1);
    let lazy = args.get(1).is_none_or(|p| p != "astar");
    let names = args.get(2..).unwrap_or_default();
    let mut suites: Vec<_> = movingai().into_iter().collect();
    // The generated maps take seconds to make: only when asked for.
    if names.iter().any(|n| n != "arena" && n != "maze") {
        suites.extend(generated());
    }
    for name in names {
        let Some(s) = suites.iter().find(|s| s.name == name.as_str()) else {
            eprintln!("no suite named {name}");
            std::process::exit(2);
        };
        let mut search = GridSearch::new(&s.map, GridOptions::default()).expect("grid");
        let _ = s.map.blocked_strides();
        let (mut best, mut counts) = (f64::MAX, (0, 0));
        for _ in 0..passes {
            counts = (0, 0);
            let started = Instant::now();
            for &(a, b, _) in &s.queries {
                let path = if lazy {
                    search.lazy_theta_star(&s.map, a, b)
                } else {
                    search.astar(a, b)
                }
                .expect("a path");
                counts.0 += path.stats.pushes;
                counts.1 += path.stats.expansions;
            }
            best = best.min(started.elapsed().as_secs_f64() * 1e3);
        }
        let planner = if lazy { "lazy" } else { "astar" };
        println!("{name} {planner} {best:.3} {} {}", counts.0, counts.1);
    }
}
