//! Grid A*: ours (`search::GridSearch`, flat arrays, reused scratch) against the
//! `pathfinding` crate's generic `astar` (the peer), in one criterion group.
//!
//! Run with `cargo bench -p hyplan-benches --bench grid_search`.
//!
//! Both run the same MovingAI scenarios (all 160 of `shared/data/movingai/arena.map.scen`,
//! all 101 of `shared/peers/maps/maze.scen`) on the same grid with the same rules: 8
//! neighbours, costs 1 and sqrt 2, no corner cutting, octile heuristic. The peer is written
//! as `shared/peers/pathfinding-astar` writes it (`u32` cell ids, `OrderedFloat<f64>`
//! costs, successors in a fixed array). Before timing, every scenario is solved once by
//! both and both costs are checked against the `.scen` optimum (`max(1e-3, 1e-5 len)`).
//! One iteration = every scenario of the file once; throughput is counted in scenarios.

use std::hint::black_box;
use std::path::{Path, PathBuf};

use criterion::{BenchmarkId, Criterion, Throughput, criterion_main};
use envmap::GridMap;
use ordered_float::OrderedFloat;
use search::{GridOptions, GridSearch, ScenEntry, read_scen};

const SQRT2: f64 = std::f64::consts::SQRT_2;

/// One scenario: start cell, goal cell `(i, j)` (row from the bottom), optimal length.
type Scenario = ((usize, usize), (usize, usize), f64);

/// A scenario file and its map.
struct Suite {
    name: &'static str,
    map: GridMap,
    queries: Vec<Scenario>,
}

fn shared() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared")
}

fn suite(name: &'static str, map: &Path, scen: &Path) -> Suite {
    let map = envmap::read_movingai(map).unwrap_or_else(|e| panic!("{e}"));
    let h = map.height();
    let queries = read_scen(scen)
        .unwrap_or_else(|e| panic!("{e}"))
        .iter()
        .map(|s| {
            let cell = |p| ScenEntry::to_cell(p, h).expect("scenario inside the map");
            (cell(s.start), cell(s.goal), s.optimal)
        })
        .collect();
    Suite { name, map, queries }
}

/// The peer: `pathfinding::directed::astar::astar` on the same grid and rules, as the
/// stand-alone peer in `shared/peers/pathfinding-astar` runs it.
fn peer_astar(map: &GridMap, start: (usize, usize), goal: (usize, usize)) -> Option<f64> {
    let (w, h) = (map.width() as i64, map.height() as i64);
    let free = |x: i64, y: i64| {
        x >= 0 && y >= 0 && x < w && y < h && map.cell_free(x as usize, y as usize)
    };
    let id = |x: i64, y: i64| (y * w + x) as u32;
    let (gx, gy) = (goal.0 as i64, goal.1 as i64);
    let goal_id = id(gx, gy);
    let octile = |x: i64, y: i64| {
        let (dx, dy) = ((x - gx).abs() as f64, (y - gy).abs() as f64);
        let (lo, hi) = if dx < dy { (dx, dy) } else { (dy, dx) };
        (hi - lo) + SQRT2 * lo
    };
    pathfinding::directed::astar::astar(
        &id(start.0 as i64, start.1 as i64),
        |&n| {
            let (x, y) = (i64::from(n) % w, i64::from(n) / w);
            let mut out = [(0u32, OrderedFloat(0.0)); 8];
            let mut k = 0;
            let (e, wst, nth, s) = (
                free(x + 1, y),
                free(x - 1, y),
                free(x, y + 1),
                free(x, y - 1),
            );
            let mut push = |nx: i64, ny: i64, c: f64| {
                out[k] = (id(nx, ny), OrderedFloat(c));
                k += 1;
            };
            if e {
                push(x + 1, y, 1.0);
            }
            if wst {
                push(x - 1, y, 1.0);
            }
            if nth {
                push(x, y + 1, 1.0);
            }
            if s {
                push(x, y - 1, 1.0);
            }
            if e && nth && free(x + 1, y + 1) {
                push(x + 1, y + 1, SQRT2);
            }
            if e && s && free(x + 1, y - 1) {
                push(x + 1, y - 1, SQRT2);
            }
            if wst && nth && free(x - 1, y + 1) {
                push(x - 1, y + 1, SQRT2);
            }
            if wst && s && free(x - 1, y - 1) {
                push(x - 1, y - 1, SQRT2);
            }
            out.into_iter().take(k)
        },
        |&n| OrderedFloat(octile(i64::from(n) % w, i64::from(n) / w)),
        |&n| n == goal_id,
    )
    .map(|(_, c)| c.0)
}

fn grid_search(c: &mut Criterion) {
    let suites = [
        suite(
            "arena",
            &shared().join("data/movingai/arena.map"),
            &shared().join("data/movingai/arena.map.scen"),
        ),
        suite(
            "maze",
            &shared().join("peers/maps/maze.map"),
            &shared().join("peers/maps/maze.scen"),
        ),
    ];
    let mut group = c.benchmark_group("grid_search");
    for s in &suites {
        // Checked once, outside the timed loop: both must return the optimal cost.
        let mut ours = GridSearch::new(&s.map, GridOptions::default()).unwrap();
        for (k, &(a, b, opt)) in s.queries.iter().enumerate() {
            let tol = f64::max(1e-3, 1e-5 * opt);
            let mine = ours.astar(a, b).map(|p| p.cost).ok();
            let peer = peer_astar(&s.map, a, b);
            assert!(
                mine.is_some_and(|c| (c - opt).abs() <= tol),
                "{} #{k}: ours {mine:?} vs {opt}",
                s.name
            );
            assert!(
                peer.is_some_and(|c| (c - opt).abs() <= tol),
                "{} #{k}: peer {peer:?} vs {opt}",
                s.name
            );
        }
        group.throughput(Throughput::Elements(s.queries.len() as u64));
        let id = format!("{}/{}", s.name, s.queries.len());
        group.bench_function(BenchmarkId::new("hyplan_grid_astar", &id), |bench| {
            bench.iter(|| {
                let mut total = 0.0;
                for &(a, b, _) in &s.queries {
                    total += ours
                        .astar(black_box(a), black_box(b))
                        .map_or(0.0, |p| p.cost);
                }
                total
            });
        });
        group.bench_function(BenchmarkId::new("pathfinding_astar", &id), |bench| {
            bench.iter(|| {
                let mut total = 0.0;
                for &(a, b, _) in &s.queries {
                    total += peer_astar(&s.map, black_box(a), black_box(b)).unwrap_or(0.0);
                }
                total
            });
        });
    }
    group.finish();
}

/// The group, configured from the command line.
fn benches() {
    let mut c = Criterion::default().configure_from_args();
    grid_search(&mut c);
}

criterion_main!(benches);
