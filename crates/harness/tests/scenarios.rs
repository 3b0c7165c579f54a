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

/// Each bad file: its name, the text of [`GOOD`] replaced and by what, and what the
/// message must name.
#[test]
fn bad_files_are_refused_naming_file_and_problem() {
    let cases: [(&str, &str, &str, &[&str]); 8] = [
        // An unknown planner is named, with the known ones.
        (
            "planner",
            "Rrt(",
            "RrtTurbo(",
            &["planner.ron", "RrtTurbo", "RrtConnect"],
        ),
        (
            "param",
            "step:",
            "stride:",
            &["param.ron:", "stride", "step"],
        ),
        // A missing field: file and line.
        (
            "missing",
            "    units: \"cells\",\n",
            "",
            &["missing.ron:", "units"],
        ),
        (
            "start",
            "start: (1.5, 1.5)",
            "start: (8.5, 1.5)",
            &["start", "inside an obstacle"],
        ),
        (
            "nofile",
            "Grid(width: 20, height: 10, obstacles: [Rect(x: 8.0, y: 0.0, w: 2.0, h: 7.0)])",
            "File(path: \"no-such-map.map\")",
            &["no-such-map.map"],
        ),
        ("runs", "runs: 4", "runs: 0", &["`runs`"]),
        // Every run's record is kept in memory: a run count the input controls is capped.
        (
            "manyruns",
            "runs: 4",
            "runs: 4000000000",
            &["`runs`", "4000000000", "MAX_RUNS"],
        ),
        (
            "across",
            "    runs: 4,",
            "    runs: 4,\n    claims: [Claim(text: \"t\", metric: \"length\", order: [\"rrt\", \"rrt\"], across: [\"a\", \"b\"])],",
            &["claims.order", "exactly one planner"],
        ),
    ];
    for (name, from, to, needles) in cases {
        assert!(GOOD.contains(from), "{name}: {from:?} not in GOOD");
        let m = load_text(name, &GOOD.replace(from, to))
            .expect_err(name)
            .to_string();
        for n in needles {
            assert!(m.contains(n), "{name}: {n:?} not in {m}");
        }
    }
}

/// A grid, a room or a map file above the memory limit is refused before it is drawn or
/// decoded, naming the file, the field, its value and the counts.
#[test]
fn maps_above_the_memory_limit_are_refused() {
    let grid = "Grid(width: 20, height: 10, obstacles: [Rect(x: 8.0, y: 0.0, w: 2.0, h: 7.0)])";
    let limit = envmap::DEFAULT_MAX_CELLS;
    for (name, map, needles) in [
        (
            "huge_grid",
            "Grid(width: 100000, height: 100000, obstacles: [])".to_string(),
            vec![
                "huge_grid.ron",
                "`map.width x map.height` = 100000 x 100000",
                "10000000000 cells",
            ],
        ),
        (
            "overflow_grid",
            format!("Grid(width: {0}, height: {0}, obstacles: [])", usize::MAX),
            vec!["overflow_grid.ron", "`map.width x map.height`"],
        ),
        (
            "huge_room",
            "Room(width: 200000, height: 1000, furniture: [])".to_string(),
            vec!["huge_room.ron", "= 200000 x 1000", "200000000 cells"],
        ),
    ] {
        let m = message(name, &GOOD.replace(grid, &map));
        for n in needles {
            assert!(m.contains(n), "{n:?} not in {m}");
        }
        assert!(m.contains(&format!("limit of {limit} cells")), "{m}");
    }
    // A map file: the loader's limit, named as the scenario's `map.path`.
    let dir = std::env::temp_dir().join(format!("hyplan-harness-{}-limit", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("small.pgm"),
        [&b"P5\n20 10\n255\n"[..], &[255; 200]].concat(),
    )
    .unwrap();
    let path = dir.join("file.ron");
    std::fs::write(
        &path,
        GOOD.replace(grid, "File(path: \"small.pgm\", safety_radius: Some(0.0))"),
    )
    .unwrap();
    let e = Scenario::load_limited(&path, 199).unwrap_err();
    let m = e.to_string();
    assert!(
        matches!(
            e,
            ScenarioError::TooLarge {
                width: 20,
                height: 10,
                limit: 199,
                ..
            }
        ),
        "{m}"
    );
    assert!(
        m.contains("file.ron") && m.contains("`map.path` = small.pgm"),
        "{m}"
    );
    Scenario::load_limited(&path, 200).unwrap();
    // The grid's own limit, at the edge.
    let text = GOOD.to_string();
    let good = dir.join("good.ron");
    std::fs::write(&good, text).unwrap();
    Scenario::load_limited(&good, 200).unwrap();
    let e = Scenario::load_limited(&good, 199).unwrap_err();
    assert!(matches!(e, ScenarioError::TooLarge { .. }), "{e}");
}
