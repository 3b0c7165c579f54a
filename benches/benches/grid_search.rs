//! Grid A*: ours (`search::GridSearch`, flat arrays, reused scratch) and our jump point
//! search (`search::JumpPointSearch`, map prepared once, not timed) against the
//! `pathfinding` crate's generic `astar` (the peer), in one criterion group.
//!
//! Run with `cargo bench -p hyplan-benches --bench grid_search`.
//!
//! Both run the same MovingAI scenarios (all 160 of `data/movingai/arena.map.scen`,
//! all 101 of `data/generated/maze.scen`) on the same grid with the same rules: 8
//! neighbours, costs 1 and sqrt 2, no corner cutting, octile heuristic. The peer is written
//! as the stand-alone `pathfinding-astar` peer writes it (`u32` cell ids, `OrderedFloat<f64>`
//! costs, successors in a fixed array). Before timing, every scenario is solved once by
//! all three and every cost is checked against the `.scen` optimum (`max(1e-3, 1e-5 len)`).
//! One iteration = every scenario of the file once; throughput is counted in scenarios.
//!
//! A second group, `grid_search_generated`, runs all three on 512 x 512 maps of the kinds of
//! the MovingAI benchmark sets, generated here from fixed seeds (mazes with corridors 1, 4
//! and 16 cells wide, random obstacles at 20% and 35%, 32-cell rooms with doors, city
//! streets, StarCraft-like open ground, Dragon-Age-like caverns), ten
//! queries each between random free cells at least 128 apart. There is no `.scen` file:
//! each query's optimum is our Dijkstra's cost, and all three are checked against it.
//! `cargo bench -p hyplan-benches --bench grid_search -- grid_search/` runs the first group
//! only, `-- generated` the second.

use criterion::{BenchmarkId, Criterion, Throughput, criterion_main};
use hyplan_benches::grid::{self, Suite, generated, movingai};
use search::{GridOptions, GridSearch, JumpPointSearch};

fn grid_search(c: &mut Criterion) {
    let suites = movingai();
    let mut group = c.benchmark_group("grid_search");
    for s in &suites {
        run_suite(&mut group, s);
    }
    group.finish();
}

/// Both A*s and JPS on one suite, after checking each returns the optimum on every query.
fn run_suite(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    s: &Suite,
) {
    // Checked once, outside the timed loop: each must return the optimal cost.
    let mut ours = GridSearch::new(&s.map, GridOptions::default()).unwrap();
    grid::check(s, &mut ours);
    let mut jps = JumpPointSearch::new(&s.map, GridOptions::default()).unwrap();
    grid::check_jps(s, &mut jps);
    group.throughput(Throughput::Elements(s.queries.len() as u64));
    let id = format!("{}/{}", s.name, s.queries.len());
    group.bench_function(BenchmarkId::new("hyplan_grid_astar", &id), |bench| {
        bench.iter(|| grid::run_ours(s, &mut ours));
    });
    group.bench_function(BenchmarkId::new("hyplan_jps", &id), |bench| {
        bench.iter(|| grid::run_jps(s, &mut jps));
    });
    group.bench_function(BenchmarkId::new("pathfinding_astar", &id), |bench| {
        bench.iter(|| grid::run_peer(s));
    });
}

/// The second group: both A*s and JPS on the generated maps.
fn grid_search_generated(c: &mut Criterion) {
    let mut group = c.benchmark_group("grid_search_generated");
    group.sample_size(10);
    for s in &generated() {
        run_suite(&mut group, s);
    }
    group.finish();
}

/// The group, configured from the command line.
fn benches() {
    let mut c = Criterion::default().configure_from_args();
    grid_search(&mut c);
    grid_search_generated(&mut c);
}

criterion_main!(benches);
