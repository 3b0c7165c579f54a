//! What a short jump point search query costs after the map's one-time preparation, on a
//! 512 x 512 and a 4096 x 4096 open map: the preparation is paid once per map, a query
//! what it touches.
//!
//! ```sh
//! cargo run --release -p search --example jps_query_cost
//! ```

use std::time::Instant;

use envmap::GridMap;
use hyplan_core::Zone;
use search::{GridOptions, JumpPointSearch};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("map,prepare_ms,first_query_us,best_query_us,expansions,cost");
    for n in [512, 4096] {
        // Rooms: walls every 64 cells with a door in each, so the query turns a corner.
        let mut map = GridMap::filled(n, n, Zone::Free)?;
        for k in (64..n).step_by(64) {
            for i in 0..n {
                if i % 64 != 32 {
                    map.set_cell_zone(i, k, Zone::Forbidden);
                    map.set_cell_zone(k, i, Zone::Forbidden);
                }
            }
        }
        let t = Instant::now();
        let mut jps = JumpPointSearch::new(&map, GridOptions::default())?;
        let prepare = t.elapsed();
        let (start, goal) = ((10, 11), (13, 12));
        let t = Instant::now();
        let first = jps.search(start, goal)?;
        let first_us = t.elapsed().as_secs_f64() * 1e6;
        let mut best = f64::MAX;
        for _ in 0..1000 {
            let t = Instant::now();
            std::hint::black_box(jps.search(start, goal)?);
            best = best.min(t.elapsed().as_secs_f64() * 1e6);
        }
        println!(
            "{n}x{n},{:.1},{first_us:.1},{best:.2},{},{:.4}",
            prepare.as_secs_f64() * 1e3,
            first.stats.expansions,
            first.cost
        );
    }
    Ok(())
}
