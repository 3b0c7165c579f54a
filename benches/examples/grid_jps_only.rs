//! Jump point search alone on chosen suites: microseconds per query, the fastest of 20
//! rounds of about `SECONDS / 20` each, for comparing two builds on a noisy host (run
//! their binaries alternately; the fastest round is the least disturbed one).
//!
//! ```sh
//! cargo run --release -p hyplan-benches --example grid_jps_only -- SECONDS SUITE...
//! ```
//!
//! Suites by name as in `grid_jps_rounds` (`arena`, `maze`, and the generated ones such as
//! `streets512`; the random-obstacle family's maps of `--random-family` with a `family:`
//! prefix, `family:random512-25`). Prints `suite us_per_query expansions pushes` per suite.

use std::time::Instant;

use hyplan_benches::grid::{self, generated, movingai};
use search::{GridOptions, JumpPointSearch};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let secs: f64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(1.0);
    let names = args.get(1..).unwrap_or_default();
    let mut suites: Vec<_> = movingai().into_iter().collect();
    // The generated maps take seconds to make: only when asked for.
    if names.iter().any(|n| n != "arena" && n != "maze") {
        suites.extend(generated());
    }
    // The random-obstacle family's maps are named as the generated ones: asked for with a
    // `family:` prefix (`family:random512-20`).
    let family = if names.iter().any(|n| n.starts_with("family:")) {
        grid::random_family()
    } else {
        Vec::new()
    };
    for name in names {
        let found = match name.strip_prefix("family:") {
            Some(name) => family.iter().find(|s| s.name == name),
            None => suites.iter().find(|s| s.name == name),
        };
        let Some(s) = found else {
            eprintln!("no suite {name}");
            continue;
        };
        let mut jps = JumpPointSearch::new(&s.map, GridOptions::default()).expect("jps");
        let stats = grid::check_jps(s, &mut jps);
        let t = Instant::now();
        let mut sum = grid::run_jps(s, &mut jps);
        let reps = ((secs / 20.0 / t.elapsed().as_secs_f64()) as usize).max(1);
        let mut best = f64::MAX;
        for _ in 0..20 {
            let t = Instant::now();
            for _ in 0..reps {
                sum += grid::run_jps(s, &mut jps);
            }
            best = best.min(t.elapsed().as_secs_f64());
        }
        std::hint::black_box(sum);
        let per_query = best * 1e6 / (reps * s.queries.len()) as f64;
        println!(
            "{name} {per_query:.3} {} {}",
            stats.expansions, stats.pushes
        );
    }
}
