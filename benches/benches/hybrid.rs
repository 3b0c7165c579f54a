//! The four hybrid planners of seeds 000-003 on the 960 x 640 room of seed 000 (Table 2),
//! one seed per benchmark, so each measures one fixed planning problem.
//!
//! Run with `cargo bench -p hyplan-benches --bench hybrid`.
//!
//! The picture goes through `envmap::load_map` with `rectangles: true` and a 20-cell band;
//! start and goal are the paper's. `rrt-astar-bt` uses the paper's pixel defaults, the
//! others the room-scaled parameters of `crates/hybrid/examples/room_timing.rs` (the
//! median over 30 seeds is that example's job; here criterion times one seed per planner).
//! Each plan is checked once outside the timed loop.

use std::hint::black_box;
use std::path::Path;

use criterion::{BenchmarkId, Criterion, criterion_main};
use envmap::{LoadOptions, load_map};
use hybrid::{HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{Goal, Planner, Query, Workspace};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn room(c: &mut Criterion) {
    let png = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenarios/maps/room_960x640.png");
    let loaded = load_map(
        &png,
        &LoadOptions {
            rectangles: true,
            safety_radius: Some(20.0),
            ..LoadOptions::default()
        },
    )
    .unwrap();
    let map = loaded.map;
    let safe = map.clone().avoiding_risk();
    let start = loaded.frame.to_world(74.0 / 6.34, 1953.0 / 6.34);
    let goal = loaded.frame.to_world(5501.0 / 6.34, 1308.0 / 6.34);
    let query = Query::new(start, Goal::Point(goal));
    let planners: Vec<(Box<dyn Planner>, bool)> = vec![
        (Box::new(RrtAstarBt::default()), true),
        (
            Box::new(RrtAstarRefine {
                step: 20.0,
                near_radius: 30.0,
                ..RrtAstarRefine::default()
            }),
            true,
        ),
        (
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
            Box::new(SafeRrtStar {
                step: 40.0,
                goal_radius: 20.0,
                gamma: 1000.0,
                max_radius: 100.0,
                spline_max_spacing: 50.0,
                curve_spacing: 1.0,
                ..SafeRrtStar::default()
            }),
            false,
        ),
    ];
    let mut g = c.benchmark_group("hybrid_room");
    g.sample_size(20);
    for (planner, on_safe) in &planners {
        let ws: &dyn Workspace = if *on_safe { &safe } else { &map };
        let name = planner.info().name;
        // Checked once: a valid path from start to goal.
        let plan = planner
            .plan(ws, &query, &mut ChaCha8Rng::seed_from_u64(1))
            .unwrap();
        assert_eq!(plan.path[0], start, "{name}");
        assert_eq!(*plan.path.last().unwrap(), goal, "{name}");
        assert!(
            plan.path.windows(2).all(|w| ws.segment_free(w[0], w[1])),
            "{name}"
        );
        g.bench_function(BenchmarkId::new(name, "960x640/seed1"), |b| {
            b.iter(|| {
                planner
                    .plan(black_box(ws), &query, &mut ChaCha8Rng::seed_from_u64(1))
                    .unwrap()
            })
        });
    }
    g.finish();
}

/// The criterion entry points (the macro's generated function carries no doc).
#[allow(missing_docs)]
mod entry {
    criterion::criterion_group!(benches, super::room);
}
criterion_main!(entry::benches);
