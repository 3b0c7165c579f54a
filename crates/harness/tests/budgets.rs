//! Budgets honoured: a tiny time limit on a large map stops every budgeted planner within
//! 10 ms of the limit.

use std::time::{Duration, Instant};

use envmap::generate;
use harness::PlannerConfig;
use hyplan_core::{Budget, Goal, Query};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;

#[test]
#[ignore = "known defect (issue 16): rrt overshoots a 20 ms limit by about 50 ms on this \
            map; work before the sampling loop is not budgeted. Run with --ignored"]
fn a_tiny_time_limit_stops_every_planner_within_10_ms() {
    // 2000 x 2000 cells of rooms and doors: no planner finishes in 20 ms.
    let g = generate::floor_plan(2000, 2000, 3, 4, &mut ChaCha8Rng::seed_from_u64(16));
    let query = Query::new(g.start, Goal::Point(g.goal));
    let limit = Duration::from_millis(20);
    let mut report = Vec::new();
    // Every planner with a budget (see docs/reliability.md for those without).
    for config in PlannerConfig::all().filter(|c| c.budget().is_some()) {
        let name = config.name();
        let planner = config
            .with_step(10.0)
            .with_budget(Budget::iterations(u64::MAX).with_time(limit))
            .build();
        // The least overshoot of three calls: a machine busy with other work can delay
        // one call's return; a planner that ignores its budget overshoots every time.
        let overshoot = (0..3)
            .map(|k| {
                let mut rng = ChaCha8Rng::seed_from_u64(k);
                let t = Instant::now();
                let _ = planner.plan(&g.map, &query, &mut rng);
                t.elapsed().saturating_sub(limit)
            })
            .min()
            .unwrap();
        report.push(format!(
            "{name}: {:.1} ms over",
            overshoot.as_secs_f64() * 1e3
        ));
        if overshoot > Duration::from_millis(10) {
            panic!("{name} overshot its 20 ms limit by {overshoot:?}: {report:?}");
        }
    }
    eprintln!("{report:?}");
}
