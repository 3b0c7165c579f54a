//! `hyplan bench` through the built binary: bad input exits 2 before any run, results do
//! not depend on the thread count, the OMPL log loads into OMPL's database with our values.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::common::{Scratch, hyplan, repo_file, stderr};

const SCRATCH: Scratch = Scratch("hyplan_bench");

fn arena() -> String {
    repo_file("data/movingai/arena.map")
}

/// A fresh output directory of this name (tests run in parallel: one name per test).
fn out_dir(name: &str) -> PathBuf {
    let p = SCRATCH.path(name);
    let _ = std::fs::remove_dir_all(&p);
    p
}

/// `hyplan bench --experiment FILE --out OUT`.
fn bench_experiment(file: &str, out: &Path) -> Output {
    hyplan(&[
        "bench",
        "--experiment",
        file,
        "--out",
        out.to_str().unwrap(),
    ])
}

fn bench(out: &Path, extra: &[&str]) -> Output {
    let arena = arena();
    let mut args = vec![
        "bench",
        "--map",
        &arena,
        "--query",
        "1.5,11.5",
        "46.5,46.5",
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    hyplan(&args)
}

#[test]
fn bad_input_exits_2_before_any_run() {
    let malformed = SCRATCH.file(
        "bad-ron/malformed.ron",
        "(problems: [ (map: \"a.map\", queries: [] ) ], planners: [\"rrt\"]",
    );
    let unknown_field = SCRATCH.file(
        "bad-ron/unknown.ron",
        "(problems: [], planners: [\"rrt\"], rusn: 3)",
    );
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["--planner", "rrt-connect", "--planner", "rrt-conect"],
            "rrt-conect",
        ),
        (vec!["--planner", "rrt:stpe=3"], "stpe"),
        (vec!["--planner", "rrt:step=three"], "three"),
        (
            vec!["--planner", "astar", "--query", "60.5,1.5", "46.5,46.5"],
            "60.5,1.5 46.5,46.5",
        ),
        (
            vec!["--planner", "astar", "--query", "1.5,11.5", "0.5,0.5"],
            "inside an obstacle",
        ),
        (vec!["--planner", "astar", "--runs", "0"], "runs"),
        (vec!["--planner", "astar", "--smooth", "spline"], "spline"),
    ];
    for (k, (extra, needle)) in cases.into_iter().enumerate() {
        let out = out_dir(&format!("bad-{k}"));
        let o = bench(&out, &extra);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{extra:?}: {err}");
        assert!(
            err.contains(needle),
            "{extra:?}: message should name {needle:?}: {err}"
        );
        assert!(
            !out.exists(),
            "{extra:?}: nothing is written before the runs"
        );
    }
    for (file, needle) in [(&malformed, "malformed.ron:1"), (&unknown_field, "rusn")] {
        let out = out_dir("bad-ron-out");
        let o = bench_experiment(file, &out);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(needle), "should name {needle:?}: {err}");
        assert!(!out.exists());
    }
}

fn runs_json(out: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(out.join("runs.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// Every field of every run but the clocks.
fn without_times(runs: &serde_json::Value) -> Vec<serde_json::Value> {
    runs.as_array()
        .unwrap()
        .iter()
        .map(|r| {
            let mut r = r.clone();
            let m = r.as_object_mut().unwrap();
            for key in ["time_s", "cpu_time_s", "planning_time_s"] {
                assert!(m.remove(key).is_some(), "runs.json has {key}");
            }
            // An anytime run's progress: the same iterations and costs, other clocks.
            if let Some(points) = m.get_mut("progress").and_then(|p| p.as_array_mut()) {
                for p in points {
                    p.as_object_mut().unwrap().remove("time_s");
                }
            }
            r
        })
        .collect()
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let planners = [
        "--planner",
        "rrt-connect",
        "--planner",
        "rrt-star:max_iterations=300,stop_at_first_solution=false",
        "--planner",
        "theta-star",
        "--smooth",
        "prune",
        "--runs",
        "6",
    ];
    let one = out_dir("threads-1");
    let two = out_dir("threads-3");
    let o = bench(&one, &[&planners[..], &["--threads", "1"]].concat());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = bench(&two, &[&planners[..], &["--threads", "3"]].concat());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let (a, b) = (runs_json(&one), runs_json(&two));
    assert_eq!(a["runs"].as_array().unwrap().len(), 18);
    // RRT* to its whole budget reports its progress (every 64 iterations and at the end).
    assert_eq!(
        a["runs"][6]["progress"].as_array().unwrap().len(),
        300 / 64 + 1
    );
    assert_eq!(without_times(&a["runs"]), without_times(&b["runs"]));
    assert_eq!(a["threads"], 1);
    assert_eq!(b["threads"], 3);
    // With `--smooth`, the summary gives the smoothing's cost beside the planning call's.
    let md = std::fs::read_to_string(one.join("summary.md")).unwrap();
    assert!(
        md.contains("| time median (ms) | time IQR (ms) | with smoothing median (ms) |"),
        "{md}"
    );
}

#[test]
fn experiment_file_runs_several_problems() {
    let file = SCRATCH.file(
        "ron/exp.ron",
        format!(
            "(name: \"arena\", problems: [(map: {:?}, queries: [((1.5, 11.5), (46.5, 46.5)), \
             ((4.5, 4.5), (40.5, 30.5))])], planners: [\"astar\", \"rrt-connect:step=4\"], \
             runs: 3, seed: 9, limits: Some((1.0, 1.0, 2.0)))",
            arena()
        ),
    );
    let out = out_dir("ron/out");
    let o = bench_experiment(&file, &out);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let j = runs_json(&out);
    assert_eq!(j["runs"].as_array().unwrap().len(), 12);
    assert_eq!(j["summary"].as_array().unwrap().len(), 4);
    assert_eq!(j["comparisons"].as_array().unwrap().len(), 2);
    // Limits give every solved run a transfer time.
    assert!(j["runs"][0]["transfer_time_s"].as_f64().unwrap() > 0.0);
    for name in ["arena-arena-q0", "arena-arena-q1"] {
        for suffix in [".log", "-time.svg", "-length.svg", "-success.svg"] {
            assert!(
                out.join(format!("{name}{suffix}")).exists(),
                "{name}{suffix}"
            );
        }
    }
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert!(md.contains("| astar | 3 | 100% |"), "{md}");
    assert!(!md.contains("with smoothing"), "{md}");
    let csv = std::fs::read_to_string(out.join("runs.csv")).unwrap();
    assert_eq!(csv.lines().count(), 13);
}

/// The database OMPL's script makes of our log holds every run with the values of
/// runs.json. Skipped in one printed line without `ompl_benchmark_statistics` (package
/// ompl-demos), unless `HYPLAN_REQUIRE_TOOLS` is set (as `.ci/run` sets it).
#[test]
fn ompl_database_holds_every_run() {
    let script = "ompl_benchmark_statistics";
    if !crate::common::ompl_statistics_available() {
        return;
    }
    let out = out_dir("ompl");
    let o = bench(
        &out,
        &[
            "--planner",
            "rrt-connect",
            "--planner",
            "rrt:max_iterations=30",
            "--planner",
            "astar",
            "--runs",
            "8",
            "--limits",
            "1,1,1",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let log = out.join("hyplan-arena-q0.log");
    let db = out.join("bench.db");
    let s = Command::new(script)
        .arg("-d")
        .arg(&db)
        .arg(&log)
        .output()
        .unwrap();
    assert!(s.status.success(), "{}", String::from_utf8_lossy(&s.stderr));
    let dump = Command::new("python3")
        .arg("-c")
        .arg(
            "import sqlite3, json, sys\n\
             c = sqlite3.connect(sys.argv[1]); c.row_factory = sqlite3.Row\n\
             print(json.dumps([dict(r) for r in c.execute('SELECT runs.*, plannerConfigs.name \
             AS planner FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id \
             ORDER BY runs.id')]))",
        )
        .arg(&db)
        .output()
        .unwrap();
    assert!(dump.status.success(), "{}", stderr(&dump));
    let rows: serde_json::Value = serde_json::from_slice(&dump.stdout).unwrap();
    let rows = rows.as_array().unwrap();
    let j = runs_json(&out);
    let runs = j["runs"].as_array().unwrap();
    assert_eq!(rows.len(), runs.len(), "every run is in the database");
    assert!(
        runs.iter().any(|r| r["success"] == false),
        "a failed run is checked too"
    );
    let close = |a: &serde_json::Value, b: &serde_json::Value| match (a.as_f64(), b.as_f64()) {
        (Some(x), Some(y)) => (x - y).abs() <= 4.0 * f64::EPSILON * x.abs(),
        _ => a.is_null() && b.is_null(),
    };
    for (run, row) in runs.iter().zip(rows) {
        let what = format!("{run} / {row}");
        assert_eq!(row["planner"], run["planner"], "{what}");
        assert_eq!(row["run_index"], run["run"], "{what}");
        assert_eq!(row["solved"], u8::from(run["success"] == true), "{what}");
        for (col, key) in [
            ("time", "planning_time_s"),
            ("total_time", "time_s"),
            ("solution_length", "raw_length"),
            ("path_length", "length"),
            ("transfer_time", "transfer_time_s"),
            ("minimum_clearance", "min_clearance"),
            ("max_curvature", "max_curvature"),
            ("graph_states", "explored"),
            ("path_nodes", "nodes"),
            ("turns", "turns"),
            ("collision_checks", "collision_checks"),
            ("iterations", "iterations"),
        ] {
            assert!(close(&run[key], &row[col]), "{col} vs {key}: {what}");
        }
    }
}
