//! The four hybrid planners of seeds 000-003 on the 960 x 640 room of seed 000 (Table 2),
//! one seed per benchmark, so each measures one fixed planning problem.
//!
//! Run with `cargo bench -p hyplan-benches --bench hybrid`.
//!
//! The room and the planners are `crates/hybrid/tests/room.rs`'s, shared with the claim
//! test and `crates/hybrid/examples/room_timing.rs`: `rrt-astar-bt` uses the paper's pixel
//! defaults, the others room-scaled parameters (the median over 30 seeds is that example's
//! job; here criterion times one seed per planner).
//! Each plan is checked once outside the timed loop.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_main};
use hyplan_core::Workspace;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

#[path = "../../crates/hybrid/tests/room.rs"]
mod fixture;

fn room(c: &mut Criterion) {
    let room = fixture::room().unwrap();
    let planners = fixture::room_planners();
    let mut g = c.benchmark_group("hybrid_room");
    g.sample_size(20);
    for (_, planner, on_safe) in &planners {
        let ws = room.map_for(*on_safe);
        let name = planner.info().name;
        // Checked once: a valid path from start to goal.
        let plan = planner
            .plan(ws, &room.query, &mut ChaCha8Rng::seed_from_u64(1))
            .unwrap();
        assert_eq!(plan.path[0], room.start, "{name}");
        assert_eq!(*plan.path.last().unwrap(), room.goal, "{name}");
        assert!(
            plan.path.windows(2).all(|w| ws.segment_free(w[0], w[1])),
            "{name}"
        );
        g.bench_function(BenchmarkId::new(name, "960x640/seed1"), |b| {
            b.iter(|| {
                planner
                    .plan(
                        black_box(ws),
                        &room.query,
                        &mut ChaCha8Rng::seed_from_u64(1),
                    )
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
