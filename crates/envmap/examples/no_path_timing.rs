//! Times the connectivity proof on disconnected 2000 x 2000 maps: a closed wall, and a
//! tunnel closed by a 5-cell risk band (safe map). For each: the first check on a fresh
//! map (it builds the cached components), a check on the same map again (cached), and
//! the slow reference (`disconnection_reference`: floods over every cell, the full
//! distance transform, a max-min search) in the same run. Prints the median and maximum
//! wall time of 20 calls, and, on Linux, the mean CPU time of the process per call (from
//! `/proc/self/stat`, 10 ms ticks): on a loaded machine wall time measures the queue, CPU
//! time the work.
//!
//! ```text
//! cargo run --release -p envmap --example no_path_timing
//! ```

use std::time::Instant;

use envmap::GridMap;
use envmap::Moves;
use hyplan_core::{Goal, NoPathCause, Query};
use rand::SeedableRng;

const CALLS: usize = 20;

fn main() {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    let walled = envmap::narrow_passage(2000, 2000, 0, 8, &mut rng);
    let tunnel = envmap::narrow_passage(2000, 2000, 6, 8, &mut rng);
    let cases = [
        ("wall", envmap::with_risk_band(&walled.map, 2.0), &walled),
        (
            "band",
            envmap::with_risk_band(&tunnel.map, 5.0).avoiding_risk(),
            &tunnel,
        ),
    ];
    for (name, map, g) in &cases {
        let query = Query::new(g.start, Goal::disc(g.goal, 2.0));
        let fast = |m: &GridMap| envmap::disconnection(m, &query, Moves::Four);
        let slow = |m: &GridMap| envmap::disconnection_reference(m, &query, Moves::Four);
        // A fresh copy per call: nothing cached yet (the maps above were never checked).
        let (first, cause) = time(|| map.clone(), fast);
        let warm = map.clone();
        let _ = fast(&warm);
        let (cached, _) = time(|| warm.clone(), fast);
        let (refr, ref_cause) = time(|| map.clone(), slow);
        assert_eq!(cause, ref_cause, "{name}: fast and reference disagree");
        println!(
            "{name}: {}",
            cause.map_or("connected?".into(), |c| c.to_string())
        );
        println!("  first check on a fresh map: {first}");
        println!("  cached (same map again):    {cached}");
        println!("  reference (per cell, EDT):  {refr}");
    }
}

/// Median and max wall ms and mean CPU ms of `CALLS` calls of `check` on `fresh()`.
fn time(
    fresh: impl Fn() -> GridMap,
    check: impl Fn(&GridMap) -> Option<NoPathCause>,
) -> (String, Option<NoPathCause>) {
    let mut ms = Vec::with_capacity(CALLS);
    let mut cpu = 0.0;
    let mut cause = None;
    for _ in 0..CALLS {
        let map = fresh();
        let c0 = cpu_ms();
        let t = Instant::now();
        cause = check(&map);
        ms.push(t.elapsed().as_secs_f64() * 1e3);
        cpu += cpu_ms().zip(c0).map_or(f64::NAN, |(b, a)| b - a);
        assert!(cause.is_some());
    }
    ms.sort_by(f64::total_cmp);
    let text = format!(
        "wall median {:.2} ms, max {:.2} ms; CPU {:.1} ms per call",
        ms[CALLS / 2],
        ms[CALLS - 1],
        cpu / CALLS as f64
    );
    (text, cause)
}

/// User + system CPU time of this process so far, ms (Linux only).
fn cpu_ms() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command name (which ends with ')'): utime is the 12th, stime the 13th.
    let rest = stat.rsplit_once(')')?.1;
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks * 10.0)
}
