//! Scenario files: every shipped scenario loads; bad files stop with a message naming the
//! file and the problem.

use std::path::{Path, PathBuf};

use harness::{Scenario, ScenarioError};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Writes `text` as a scenario file next to the shipped ones' maps folder, so relative map
/// paths resolve, and loads it.
fn load_text(name: &str, text: &str) -> Result<(), ScenarioError> {
    let dir = std::env::temp_dir().join(format!("hyplan-harness-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{name}.ron"));
    std::fs::write(&path, text).unwrap();
    Scenario::load(&path).map(|_| ())
}

const GOOD: &str = r#"Scenario(
    name: "t",
    source: Source(seed_file: "x.txt", experiment: "Table 1"),
    map: Grid(width: 20, height: 10, obstacles: [Rect(x: 8.0, y: 0.0, w: 2.0, h: 7.0)]),
    units: "cells",
    start: (1.5, 1.5),
    goal: (18.5, 1.5),
    goal_radius: 1.0,
    runs: 4,
    base_seed: 1,
    planners: [PlannerSpec(planner: Rrt(step: 1.0))],
)"#;

#[test]
fn every_shipped_scenario_loads() {
    let dir = repo().join("scenarios");
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "ron") {
            let (s, w) = Scenario::load(&path).unwrap_or_else(|e| panic!("{e}"));
            assert!(w.map.bounds().contains(w.query.start), "{}", s.name);
            n += 1;
        }
    }
    assert!(n >= 17, "expected the seed 000-003 scenarios, found {n}");
}

#[test]
fn a_good_scenario_loads() {
    load_text("good", GOOD).unwrap();
}

fn message(name: &str, text: &str) -> String {
    load_text(name, text).unwrap_err().to_string()
}

#[test]
fn unknown_planner_is_named() {
    let m = message("planner", &GOOD.replace("Rrt(", "RrtTurbo("));
    assert!(
        m.contains("planner.ron") && m.contains("RrtTurbo") && m.contains("RrtConnect"),
        "{m}"
    );
}

#[test]
fn unknown_parameter_is_named() {
    let m = message("param", &GOOD.replace("step:", "stride:"));
    assert!(
        m.contains("param.ron:") && m.contains("stride") && m.contains("step"),
        "{m}"
    );
}

#[test]
fn missing_field_gives_file_and_line() {
    let m = message("missing", &GOOD.replace("    units: \"cells\",\n", ""));
    assert!(m.contains("missing.ron:") && m.contains("units"), "{m}");
}

#[test]
fn start_inside_an_obstacle_is_refused() {
    let m = message(
        "start",
        &GOOD.replace("start: (1.5, 1.5)", "start: (8.5, 1.5)"),
    );
    assert!(
        m.contains("start") && m.contains("inside an obstacle"),
        "{m}"
    );
}

#[test]
fn missing_map_file_is_named() {
    let text = GOOD.replace(
        "Grid(width: 20, height: 10, obstacles: [Rect(x: 8.0, y: 0.0, w: 2.0, h: 7.0)])",
        "File(path: \"no-such-map.map\")",
    );
    let m = message("nofile", &text);
    assert!(m.contains("no-such-map.map"), "{m}");
}

#[test]
fn zero_runs_is_refused() {
    let m = message("runs", &GOOD.replace("runs: 4", "runs: 0"));
    assert!(m.contains("`runs`"), "{m}");
}

#[test]
fn a_claim_across_scenarios_names_one_planner() {
    let text = GOOD.replace(
        "    runs: 4,",
        "    runs: 4,\n    claims: [Claim(text: \"t\", metric: \"length\", order: [\"rrt\", \"rrt\"], across: [\"a\", \"b\"])],",
    );
    let m = message("across", &text);
    assert!(
        m.contains("claims.order") && m.contains("exactly one planner"),
        "{m}"
    );
}
