//! Budgets honoured: a tiny time limit on a large map stops every planner within 10 ms of
//! the limit, the connectivity proof (built on the first call on a map, then cached in
//! it) and the grid's preparation included.

use std::time::{Duration, Instant};

use harness::PlannerConfig;
use hyplan_core::{Budget, Goal, Query};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;

#[test]
fn a_tiny_time_limit_stops_every_planner_within_10_ms() {
    // 2000 x 2000 cells of rooms and doors: no planner finishes in 20 ms. Every call gets
    // a fresh copy of the map, so it builds the connectivity proof inside its budget.
    let g = envmap::floor_plan(2000, 2000, 3, 4, &mut ChaCha8Rng::seed_from_u64(16));
    let query = Query::new(g.start, Goal::Point(g.goal));
    let limit = Duration::from_millis(20);
    let budget = Budget::iterations(u64::MAX).with_time(limit);
    let mut report = Vec::new();
    // Every planner of the registry: each one takes a budget.
    for config in PlannerConfig::all() {
        assert!(config.budget().is_some(), "{} has no budget", config.name());
        let name = config.name();
        let planner = config.with_step(10.0).with_budget(budget).build();
        // A planner that ignores its budget overshoots on every call. One that keeps it
        // can still return late when the machine is busy: its thread waits for a core
        // (on CI beside other jobs, A* returned 16 ms late three calls in a row at load 6
        // on 2 cores). So the call is repeated, up to 10 times, until one returns within
        // 10 ms; the least overshoot is reported.
        let mut best = Duration::MAX;
        let mut calls = 0;
        while calls < 10 && best > Duration::from_millis(10) {
            let map = g.map.clone();
            let mut rng = ChaCha8Rng::seed_from_u64(calls);
            let t = Instant::now();
            let _ = planner.plan(&map, &query, &mut rng);
            best = best.min(t.elapsed().saturating_sub(limit));
            calls += 1;
        }
        report.push(format!(
            "{name}: {:.1} ms over ({calls} calls)",
            best.as_secs_f64() * 1e3
        ));
        if best > Duration::from_millis(10) {
            panic!(
                "{name} overshot its 20 ms limit by {best:?} on each of {calls} calls: {report:?}"
            );
        }
    }
    eprintln!("{report:?}");
}
