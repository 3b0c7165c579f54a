//! The hard-map suite (issue 13) under criterion: the four hybrids on one generated map of
//! each kind (`envmap::generate`, seed 1, a 2-cell risk band, goal disc of radius 2, step
//! 10; step 40 on the 2000 x 2000 floor plan), one fixed planning problem per benchmark;
//! and the connectivity proof ("no path" with its cause) on disconnected 2000 x 2000 maps,
//! on a fresh map and cached.
//!
//! Run with `cargo bench -p hyplan-benches --bench hard_maps`. Success rates over seeds are
//! the job of the ignored test `hard_map_success_rates` in `crates/hybrid/tests/hard_maps.rs`.
//! Each plan is checked once outside the timed loop.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BatchSize, BenchmarkId, Criterion, criterion_main};
use envmap::GridMap;
use envmap::HardMap;
use hyplan_core::{Budget, Goal, Planner, Query, Workspace};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The four hybrids as `hyplan plan --step STEP --goal-radius 2` builds them, 10 s each.
fn hybrids(step: f64) -> Vec<Box<dyn Planner>> {
    let budget = Budget::iterations(u64::MAX).with_time(Duration::from_secs(10));
    hybrid::four_hybrids(step, envmap::SUITE_GOAL_RADIUS, budget)
}

fn hard_maps(c: &mut Criterion) {
    let mut g = c.benchmark_group("hard_maps");
    g.sample_size(10);
    for kind in HardMap::ALL {
        let step = kind.suite_step(10.0);
        let (map, query) = kind.suite_problem(step, &mut ChaCha8Rng::seed_from_u64(1));
        for planner in hybrids(step) {
            let name = planner.info().name;
            let plan = planner
                .plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(1))
                .unwrap_or_else(|e| panic!("{name} on {}: {e}", kind.name()));
            assert!(
                plan.path.windows(2).all(|w| map.segment_free(w[0], w[1])),
                "{name}"
            );
            g.bench_function(BenchmarkId::new(name, kind.name()), |b| {
                b.iter(|| {
                    planner
                        .plan(black_box(&map), &query, &mut ChaCha8Rng::seed_from_u64(1))
                        .unwrap()
                })
            });
        }
    }
    g.finish();

    // "No path" with its cause on 2000 x 2000 maps: walled in two, and a tunnel the
    // 5-cell band closes (safe map). "fresh": each call on a new copy of the map (the
    // first check on a map builds the components it caches); "cached": the same map again.
    let mut rng = ChaCha8Rng::seed_from_u64(1);
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
    let mut g = c.benchmark_group("no_path_2000");
    g.sample_size(20);
    for (what, map, generated) in &cases {
        let query = Query::new(generated.start, Goal::disc(generated.goal, 2.0));
        for planner in hybrids(40.0) {
            let name = planner.info().name;
            let plan = |m: &GridMap| {
                planner
                    .plan(black_box(m), &query, &mut ChaCha8Rng::seed_from_u64(1))
                    .unwrap_err()
            };
            g.bench_function(BenchmarkId::new(name, format!("{what} fresh")), |b| {
                b.iter_batched(|| map.clone(), |m| plan(&m), BatchSize::LargeInput)
            });
            let warm = map.clone();
            let err = plan(&warm);
            assert!(err.cause().is_some(), "{name}: {err}");
            g.bench_function(BenchmarkId::new(name, format!("{what} cached")), |b| {
                b.iter(|| plan(&warm))
            });
        }
    }
    g.finish();
}

/// The criterion entry points (the macro's generated function carries no doc).
#[allow(missing_docs)]
mod entry {
    criterion::criterion_group!(benches, super::hard_maps);
}
criterion_main!(entry::benches);
