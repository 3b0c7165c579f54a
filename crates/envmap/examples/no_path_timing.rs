//! Times the connectivity proof on disconnected 2000 x 2000 maps: a closed wall, and a
//! tunnel closed by a 5-cell risk band (safe map). Prints the median and maximum wall time
//! of 20 calls, each on a fresh copy of the map (no cached distance field), and, on Linux,
//! the mean CPU time of the process per call (from `/proc/self/stat`, 10 ms ticks): on a
//! loaded machine wall time measures the queue, CPU time the work.
//!
//! ```text
//! cargo run --release -p envmap --example no_path_timing
//! ```

use std::time::Instant;

use envmap::connectivity::{self, Moves};
use envmap::generate;
use hyplan_core::{Goal, Query};
use rand::SeedableRng;

fn main() {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    let walled = generate::narrow_passage(2000, 2000, 0, 8, &mut rng);
    let tunnel = generate::narrow_passage(2000, 2000, 6, 8, &mut rng);
    let cases = [
        ("wall", generate::with_risk_band(&walled.map, 2.0), &walled),
        (
            "band",
            generate::with_risk_band(&tunnel.map, 5.0).avoiding_risk(),
            &tunnel,
        ),
    ];
    for (name, map, g) in &cases {
        let query = Query::new(g.start, Goal::disc(g.goal, 2.0));
        let cpu0 = cpu_ms();
        let mut ms: Vec<f64> = (0..20)
            .map(|_| {
                let map = map.clone();
                let t = Instant::now();
                let cause = connectivity::disconnection(&map, &query, Moves::Four);
                let e = t.elapsed().as_secs_f64() * 1e3;
                assert!(cause.is_some());
                e
            })
            .collect();
        let cpu = cpu_ms().zip(cpu0).map(|(b, a)| (b - a) / 20.0);
        ms.sort_by(f64::total_cmp);
        println!(
            "{name}: wall median {:.1} ms, max {:.1} ms; CPU {} ms per call",
            ms[10],
            ms[19],
            cpu.map_or("?".into(), |c| format!("{c:.1}"))
        );
    }
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
