//! The hard-map suite (issue 13) under criterion: the four hybrids on one generated map of
//! each kind (`envmap::generate`, seed 1, a 2-cell risk band, goal disc of radius 2, step
//! 10; step 40 on the 2000 x 2000 floor plan), one fixed planning problem per benchmark;
//! and the connectivity proof ("no path" with its cause) on a disconnected 2000 x 2000 map.
//!
//! Run with `cargo bench -p hyplan-benches --bench hard_maps`. Success rates over seeds are
//! the job of the ignored test `hard_map_success_rates` in `crates/hybrid/tests/hard_maps.rs`.
//! Each plan is checked once outside the timed loop.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, criterion_main};
use envmap::generate::{self, HardMap};
use hybrid::{HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{Budget, Goal, Planner, Query, Workspace};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The four hybrids as `hyplan plan --step STEP --goal-radius 2` builds them, 10 s each.
fn hybrids(step: f64) -> Vec<Box<dyn Planner>> {
    let budget = Budget::iterations(u64::MAX).with_time(Duration::from_secs(10));
    vec![
        Box::new(RrtAstarBt {
            step,
            goal_radius: 2.0,
            budget,
            ..RrtAstarBt::default()
        }),
        Box::new(RrtAstarRefine {
            step,
            budget,
            ..RrtAstarRefine::default()
        }),
        Box::new(HybridRrtAstar {
            step,
            budget,
            ..HybridRrtAstar::default()
        }),
        Box::new(SafeRrtStar {
            step,
            goal_radius: 2.0,
            budget,
            ..SafeRrtStar::default()
        }),
    ]
}

fn hard_maps(c: &mut Criterion) {
    let mut g = c.benchmark_group("hard_maps");
    g.sample_size(10);
    for kind in HardMap::ALL {
        let step = if kind == HardMap::FloorPlan {
            40.0
        } else {
            10.0
        };
        let generated = kind.generate(step, &mut ChaCha8Rng::seed_from_u64(1));
        let map = generate::with_risk_band(&generated.map, 2.0);
        let query = Query::new(generated.start, Goal::disc(generated.goal, 2.0));
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

    // "No path" with its cause on a 2000 x 2000 map walled in two: the flood fill alone.
    let walled = generate::narrow_passage(2000, 2000, 0, 8, &mut ChaCha8Rng::seed_from_u64(1));
    let map = generate::with_risk_band(&walled.map, 2.0);
    let query = Query::new(walled.start, Goal::disc(walled.goal, 2.0));
    let mut g = c.benchmark_group("no_path_2000");
    g.sample_size(20);
    for planner in hybrids(40.0) {
        let name = planner.info().name;
        let err = planner
            .plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(1))
            .unwrap_err();
        assert!(err.cause().is_some(), "{name}: {err}");
        g.bench_function(BenchmarkId::new(name, "wall"), |b| {
            b.iter(|| {
                planner
                    .plan(black_box(&map), &query, &mut ChaCha8Rng::seed_from_u64(1))
                    .unwrap_err()
            })
        });
    }
    g.finish();
}

/// The criterion entry points (the macro's generated function carries no doc).
#[allow(missing_docs)]
mod entry {
    criterion::criterion_group!(benches, super::hard_maps);
}
criterion_main!(entry::benches);
