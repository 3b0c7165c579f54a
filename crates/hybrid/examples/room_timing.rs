//! Times the four hybrid planners on the 960 x 640 room of seed 000 (Table 2): median
//! over 30 seeds per method, in a release build.
//!
//! ```text
//! cargo run --release -p hybrid --example room_timing [-- SEEDS [NAME]]
//! ```
//!
//! Two times: wall clock per plan (median, min, max), and the thread's CPU time from
//! `/proc/thread-self/schedstat` (Linux; the machine is often shared, and CPU time is what
//! a quiet machine would show as wall time). The kernel advances that CPU time once per
//! scheduler tick (4 ms here), so it is read around the whole run of seeds and reported
//! as the mean per plan; a per-plan median of it would be a multiple of the tick.
//!
//! The picture goes through `envmap::load_map` with `rectangles: true` and a 20-cell
//! safety radius (world units = pixels). Start and goal are the paper's (74, 1953) and
//! (5501, 1308) mm at 6.34 mm/px, in the picture frame (x = column, y = row from the top).
//! `rrt-astar-bt` uses the paper's pixel defaults on the safe map; the other three have
//! their papers' parameters scaled to the room's pixels (listed in the output), since
//! their papers' maps are 50-100 cells wide.

use std::path::Path;
use std::time::Duration;

use envmap::{LoadOptions, load_map};
use hybrid::{HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{Budget, Goal, Planner, Query, Workspace, Zone};
use rand::SeedableRng;

/// CPU time of this thread so far, if the kernel reports it.
fn cpu_time() -> Option<Duration> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: u64 = text.split_whitespace().next()?.parse().ok()?;
    Some(Duration::from_nanos(ns))
}

/// The median of sorted durations, in milliseconds.
fn median_ms(sorted: &[Duration]) -> f64 {
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let n = sorted.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        ms(sorted[n / 2])
    } else {
        0.5 * (ms(sorted[n / 2 - 1]) + ms(sorted[n / 2]))
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let seeds: u64 = std::env::args()
        .nth(1)
        .map(|s| s.parse())
        .transpose()?
        .unwrap_or(30);
    // Only the planners whose name contains this, if given.
    let only = std::env::args().nth(2).unwrap_or_default();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/maps/room_960x640.png");
    let loaded = load_map(
        &root,
        &LoadOptions {
            rectangles: true,
            safety_radius: Some(20.0),
            ..LoadOptions::default()
        },
    )?;
    let map = loaded.map;
    let safe = map.clone().avoiding_risk();
    let start = loaded.frame.to_world(74.0 / 6.34, 1953.0 / 6.34);
    let goal = loaded.frame.to_world(5501.0 / 6.34, 1308.0 / 6.34);
    let query = Query::new(start, Goal::Point(goal));
    println!(
        "room {}x{} px, start ({:.2}, {:.2}), goal ({:.2}, {:.2}) world px (y up), straight line {:.1} px",
        map.width(),
        map.height(),
        start.x,
        start.y,
        goal.x,
        goal.y,
        (goal - start).norm()
    );
    let planners: Vec<(&str, Box<dyn Planner>, bool)> = vec![
        (
            "rrt-astar-bt (paper defaults, safe map)",
            Box::new(RrtAstarBt::default()),
            true,
        ),
        (
            "rrt-astar-refine (step 20, near 30, safe map)",
            Box::new(RrtAstarRefine {
                step: 20.0,
                near_radius: 30.0,
                ..RrtAstarRefine::default()
            }),
            true,
        ),
        (
            "hybrid-rrt-astar (step 10, T 130, D 70, 1500 visited, safe map)",
            Box::new(HybridRrtAstar {
                step: 10.0,
                goal_threshold: 130.0,
                astar_spacing: 70.0,
                astar_max_visited: 1500,
                ..HybridRrtAstar::default()
            }),
            true,
        ),
        (
            "safe-rrt-star (step 40, goal 20, gamma 1000, r<=100, d_cp 50, three zones)",
            Box::new(SafeRrtStar {
                step: 40.0,
                goal_radius: 20.0,
                gamma: 1000.0,
                max_radius: 100.0,
                spline_max_spacing: 50.0,
                curve_spacing: 1.0,
                budget: Budget::iterations(3000),
                ..SafeRrtStar::default()
            }),
            false,
        ),
    ];
    println!(
        "| planner | median ms (wall) | min ms | max ms | mean CPU ms | solved | mean length px | mean nodes | mean expansions |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for (name, planner, on_safe) in &planners {
        if !name.contains(only.as_str()) {
            continue;
        }
        let ws: &dyn Workspace = if *on_safe { &safe } else { &map };
        let mut times: Vec<Duration> = Vec::new();
        let mut results = Vec::new();
        // The kernel updates the thread's CPU time only every scheduler tick (4 ms here),
        // so it is read around the whole run of seeds and reported per plan.
        let c0 = cpu_time();
        for seed in 0..seeds {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let t = std::time::Instant::now();
            let result = planner.plan(ws, &query, &mut rng);
            times.push(t.elapsed());
            results.push(result);
        }
        let cpu = c0.zip(cpu_time()).map(|(c0, c1)| c1.saturating_sub(c0));
        let (mut solved, mut length, mut nodes, mut expansions) = (0, 0.0, 0.0, 0.0);
        for plan in results.into_iter().flatten() {
            // Checked once, outside the timing.
            assert!(plan.path.windows(2).all(|w| ws.segment_free(w[0], w[1])));
            assert!(plan.path.iter().all(|&p| map.zone(p) != Zone::Forbidden));
            solved += 1;
            length += plan.length();
            nodes += plan.stats.nodes as f64;
            expansions += plan.stats.expansions as f64;
        }
        times.sort();
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        let median = median_ms(&times);
        let mean_cpu = cpu.map_or(f64::NAN, |c| ms(c) / seeds as f64);
        println!(
            "| {name} | {median:.2} | {:.2} | {:.2} | {mean_cpu:.2} | {solved}/{seeds} | {:.1} | {:.0} | {:.0} |",
            ms(times[0]),
            ms(times[times.len() - 1]),
            length / f64::from(solved.max(1)),
            nodes / f64::from(solved.max(1)),
            expansions / f64::from(solved.max(1)),
        );
    }
    Ok(())
}
