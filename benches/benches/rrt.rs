//! One full RRT (and RRT-Connect) run on the OMPL peer's `rects100` map, the path checked
//! once outside the timed loop.

use std::hint::black_box;

use criterion::{Criterion, criterion_main};
use hyplan_core::{Budget, Goal, Plan, PlanError, Query, Workspace};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use sampling::{Rrt, RrtConnect};

fn bench_rrt(c: &mut Criterion) {
    let loaded = hyplan_benches::load_as_peer("data/generated/rects100.pgm");
    let map = loaded.map;
    let query = Query::new(
        loaded.frame.to_world(5.5, 5.5),
        Goal::Point(loaded.frame.to_world(94.5, 94.5)),
    );
    let rrt = Rrt {
        step: 5.0,
        goal_bias: 0.05,
        budget: Budget::iterations(1_000_000),
    };
    let connect = RrtConnect {
        step: 5.0,
        budget: Budget::iterations(1_000_000),
    };
    // Each planner's run with a fresh RNG.
    type PlanFn<'a> = &'a dyn Fn(&mut ChaCha8Rng) -> Result<Plan, PlanError>;
    let planners: [(&str, PlanFn<'_>); 2] = [
        ("rrt", &|rng| rrt.plan(&map, &query, rng)),
        ("rrt_connect", &|rng| connect.plan(&map, &query, rng)),
    ];
    // Checked once, outside the timed loop: a valid path.
    for (_, plan) in planners {
        let plan = plan(&mut ChaCha8Rng::seed_from_u64(1)).unwrap();
        assert_eq!(plan.path[0], query.start);
        assert!(query.goal.contains(*plan.path.last().unwrap()));
        assert!(plan.path.windows(2).all(|w| map.segment_free(w[0], w[1])));
    }

    let mut group = c.benchmark_group("rrt_rects100_step5");
    // Each iteration plans with the next seed, so the time is an average over many trees.
    for (name, plan) in planners {
        group.bench_function(name, |b| {
            let mut seed = 0;
            b.iter(|| {
                seed += 1;
                let mut rng = ChaCha8Rng::seed_from_u64(seed);
                black_box(plan(&mut rng).unwrap().path.len())
            });
        });
    }
    group.finish();
}

/// The criterion entry points (the macro's generated function carries no doc).
#[allow(missing_docs)]
mod entry {
    criterion::criterion_group!(benches, super::bench_rrt);
}
criterion_main!(entry::benches);
