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
//! The room and the planners' parameters are `tests/room.rs`'s (shared with the claim
//! test and the `hybrid` bench): `rrt-astar-bt` uses the paper's pixel defaults on the
//! safe map; the other three have their papers' parameters scaled to the room's pixels
//! (listed in the output), since their papers' maps are 50-100 cells wide.

use std::time::Duration;

use hyplan_core::{Workspace, Zone};
use rand::SeedableRng;

#[path = "../tests/room.rs"]
mod room;

use room::{room, room_planners};

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
    let room = room()?;
    println!(
        "room {}x{} px, start ({:.2}, {:.2}), goal ({:.2}, {:.2}) world px (y up), straight line {:.1} px",
        room.map.width(),
        room.map.height(),
        room.start.x,
        room.start.y,
        room.goal.x,
        room.goal.y,
        (room.goal - room.start).norm()
    );
    let planners = room_planners();
    println!(
        "| planner | median ms (wall) | min ms | max ms | mean CPU ms | solved | mean length px | mean nodes | mean expansions |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for (name, planner, on_safe) in &planners {
        if !name.contains(only.as_str()) {
            continue;
        }
        let ws = room.map_for(*on_safe);
        let mut times: Vec<Duration> = Vec::new();
        let mut results = Vec::new();
        // The kernel updates the thread's CPU time only every scheduler tick (4 ms here),
        // so it is read around the whole run of seeds and reported per plan.
        let c0 = cpu_time();
        for seed in 0..seeds {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let t = std::time::Instant::now();
            let result = planner.plan(ws, &room.query, &mut rng);
            times.push(t.elapsed());
            results.push(result);
        }
        let cpu = c0.zip(cpu_time()).map(|(c0, c1)| c1.saturating_sub(c0));
        let (mut solved, mut length, mut nodes, mut expansions) = (0, 0.0, 0.0, 0.0);
        for plan in results.into_iter().flatten() {
            // Checked once, outside the timing.
            assert!(plan.path.windows(2).all(|w| ws.segment_free(w[0], w[1])));
            assert!(
                plan.path
                    .iter()
                    .all(|&p| room.map.zone(p) != Zone::Forbidden)
            );
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
