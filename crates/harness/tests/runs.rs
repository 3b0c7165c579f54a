//! Monte-Carlo runs: parallel equals serial, seeds depend on the run index only.

use std::path::Path;

use harness::{Scenario, Summary, run_planner};

fn scenario() -> (Scenario, harness::World) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/001-grid100.ron");
    Scenario::load(&path).unwrap()
}

#[test]
fn parallel_runs_equal_serial_runs() {
    let (s, w) = scenario();
    let spec = &s.planners[0];
    let serial = run_planner(&s, &w, spec, 12, false, &|| {}).unwrap();
    let parallel = run_planner(&s, &w, spec, 12, true, &|| {}).unwrap();
    assert_eq!(serial.len(), 12);
    for (a, b) in serial.iter().zip(&parallel) {
        assert_eq!((a.run, a.seed, a.success), (b.run, b.seed, b.success));
        assert_eq!(a.path, b.path, "run {}", a.run);
        assert_eq!(a.length.to_bits(), b.length.to_bits());
        assert_eq!(a.explored.to_bits(), b.explored.to_bits());
    }
}

/// Every planner, and every smoothing method on one of them: the runs spread over threads
/// give the serial runs' bits (paths, lengths, counts), only the times differ.
#[test]
fn every_planner_gives_the_same_bits_on_threads() {
    let (s, w) = scenario();
    let names = harness::PlannerConfig::names();
    let smoothings = ["none", "prune", "pchip", "bspline", "bspline-interp"];
    let specs = names
        .iter()
        .map(|n| (n, "none"))
        .chain(smoothings.iter().map(|m| (&"rrt-connect", *m)));
    for (name, smoothing) in specs {
        let spec = harness::PlannerSpec {
            smoothing: Some(smoothing.to_string()),
            ..harness::PlannerSpec::new(harness::PlannerConfig::by_name(name).unwrap())
        };
        let serial = run_planner(&s, &w, &spec, 4, false, &|| {}).unwrap();
        let parallel = run_planner(&s, &w, &spec, 4, true, &|| {}).unwrap();
        for (a, b) in serial.iter().zip(&parallel) {
            let what = format!("{name} / {smoothing}, run {}", a.run);
            assert_eq!(
                (a.run, a.seed, a.success),
                (b.run, b.seed, b.success),
                "{what}"
            );
            assert_eq!(a.path, b.path, "{what}");
            for (x, y) in [
                (a.length, b.length),
                (a.nodes, b.nodes),
                (a.turns, b.turns),
                (a.explored, b.explored),
                (a.min_clearance, b.min_clearance),
            ] {
                assert_eq!(x.to_bits(), y.to_bits(), "{what}");
            }
        }
    }
}

#[test]
fn runs_are_scored_and_summarised() {
    let (s, w) = scenario();
    let runs = run_planner(&s, &w, &s.planners[0], 8, true, &|| {}).unwrap();
    let summary = Summary::of(&runs);
    assert_eq!(summary.runs, 8);
    let length = summary.get("length").unwrap();
    // The straight line is the lower bound of any path from (5, 5) to the goal disc.
    let straight = (90f64 * 90.0 * 2.0).sqrt() - 3.0;
    assert!(length.min >= straight, "{length:?}");
    for r in runs.iter().filter(|r| r.success) {
        assert!(
            r.path
                .windows(2)
                .all(|p| hyplan_core::Workspace::segment_free(&w.map, p[0], p[1]))
        );
        // Turns can only happen at inner nodes, and the path keeps the query's ends.
        assert!(
            r.turns <= r.inner_nodes,
            "{} turns at {} inner nodes",
            r.turns,
            r.inner_nodes
        );
        assert_eq!(r.path.first(), Some(&w.query.start));
        assert!(w.query.goal.contains(*r.path.last().unwrap()));
    }
}
