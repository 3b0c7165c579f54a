//! The OMPL log of a benchmark, read back by OMPL's own `ompl_benchmark_statistics`
//! (Debian package `ompl-demos`): every run lands in the database with our values.
//!
//! Skipped, in one printed line, when the script or python3 is not installed; with
//! `HYPLAN_REQUIRE_TOOLS` set (as `.ci/run` sets it) a missing script fails the test.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

use harness::bench::{self, BenchRun, ExperimentInfo};
use harness::{PlannerConfig, Scenario, Scoring, run_seed};

/// `ompl_benchmark_statistics` when installed.
fn ompl_script() -> Option<&'static str> {
    let script = "ompl_benchmark_statistics";
    let found = Command::new(script)
        .arg("--help")
        .output()
        .is_ok_and(|o| o.status.success());
    if found {
        Some(script)
    } else {
        assert!(
            std::env::var_os("HYPLAN_REQUIRE_TOOLS").is_none(),
            "`{script}` not found (apt-get install ompl-demos) and HYPLAN_REQUIRE_TOOLS is set"
        );
        eprintln!(
            "SKIPPED: `{script}` not found (apt-get install ompl-demos); the OMPL log was not \
             checked against OMPL's reader"
        );
        None
    }
}

/// Runs of a few planners on scenario 001's map, one of them smoothed with limits.
fn runs() -> Vec<BenchRun> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/001-grid100.ron");
    let (_, world) = Scenario::load(&path).unwrap();
    let mut obstacles = world.map.clone();
    obstacles.blocked_from = hyplan_core::Zone::Forbidden;
    let mut out = Vec::new();
    for (label, spec, smoothing) in [
        ("rrt-connect", "rrt-connect:step=5.0", "none"),
        ("rrt:budget", "rrt:budget.max_iterations=40", "none"),
        ("astar", "astar", "pchip"),
        (
            "rrt-star:anytime",
            "rrt-star:budget.max_iterations=400,stop_at_first_solution=false,step=5.0",
            "none",
        ),
    ] {
        let config: PlannerConfig = spec.parse().unwrap();
        let name = config.name();
        let planner = config.build();
        // RRT* to its whole budget, observed: the progress properties.
        let anytime = match config {
            PlannerConfig::RrtStar(p) => Some(p),
            _ => None,
        };
        let call = match &anytime {
            Some(rrt_star) => bench::PlanCall::RrtStar(rrt_star),
            None => bench::PlanCall::Planner(planner.as_ref()),
        };
        let scoring = Scoring {
            ws: &world.map,
            obstacles: &obstacles,
            explored_by_expansions: name == "astar",
            smoothing: smoothing.parse().unwrap(),
            limits: Some(postproc::Limits::new(1.0, 1.0, 1.0).unwrap()),
            spacing: 0.25 * world.map.resolution(),
        };
        for k in 0..6 {
            out.push(bench::run_once(
                call,
                &scoring,
                &world.query,
                0,
                label,
                k,
                run_seed(3, u64::from(k)),
            ));
        }
    }
    out
}

/// Equal up to the last bits lost by the JSON reader (serde_json's float parsing is
/// not always correctly rounded without its `float_roundtrip` feature).
fn same(ours: f64, theirs: &serde_json::Value) -> bool {
    match theirs.as_f64() {
        None => !ours.is_finite() && theirs.is_null(),
        Some(t) => (ours - t).abs() <= 4.0 * f64::EPSILON * ours.abs(),
    }
}

#[test]
fn ompl_script_reads_every_run_with_our_values() {
    let Some(script) = ompl_script() else { return };
    let runs = runs();
    // Some runs fail (RRT with 40 iterations): NULLs must round-trip too.
    assert!(runs.iter().any(|r| !r.metrics.success));
    assert!(runs.iter().any(|r| r.metrics.success));
    let info = ExperimentInfo {
        name: "grid100".into(),
        host: "test".into(),
        start: "2026-12-02 01:00:00".into(),
        setup: "map scenarios/001-grid100.ron\n|>>> not the end".into(),
        seed: 3,
        max_time: 0.0,
        run_count: 6,
        total_duration: 1.5,
    };
    let mut settings = BTreeMap::new();
    settings.insert(
        "rrt-connect".to_string(),
        [("step".to_string(), "5".to_string())].into(),
    );
    let refs: Vec<&BenchRun> = runs.iter().collect();
    let log = bench::experiment_log(&info, &refs, &settings)
        .to_log()
        .unwrap();
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("ompl-log");
    std::fs::create_dir_all(&dir).unwrap();
    let log_path = dir.join("grid100.log");
    let db = dir.join("grid100.db");
    std::fs::write(&log_path, &log).unwrap();
    let _ = std::fs::remove_file(&db);
    let status = Command::new(script)
        .arg("-d")
        .arg(&db)
        .arg(&log_path)
        .status()
        .unwrap();
    assert!(
        status.success(),
        "{script} failed on {}",
        log_path.display()
    );

    let dump = Command::new("python3")
        .arg("-c")
        .arg(
            "import sqlite3, json, sys\n\
             c = sqlite3.connect(sys.argv[1]); c.row_factory = sqlite3.Row\n\
             q = lambda s: [dict(r) for r in c.execute(s)]\n\
             print(json.dumps({'runs': q('SELECT runs.*, plannerConfigs.name AS planner, \
             plannerConfigs.settings AS settings FROM runs JOIN plannerConfigs \
             ON runs.plannerid = plannerConfigs.id ORDER BY runs.id'), \
             'experiments': q('SELECT * FROM experiments'), \
             'progress': q('SELECT * FROM progress ORDER BY runid, time'), \
             'enums': q('SELECT * FROM enums ORDER BY value')}))",
        )
        .arg(&db)
        .output()
        .unwrap();
    assert!(
        dump.status.success(),
        "{}",
        String::from_utf8_lossy(&dump.stderr)
    );
    let db: serde_json::Value = serde_json::from_slice(&dump.stdout).unwrap();

    let exp = &db["experiments"][0];
    assert_eq!(exp["name"], "grid100");
    assert_eq!(
        exp["version"],
        format!("hyplan {}", env!("CARGO_PKG_VERSION"))
    );
    assert_eq!(exp["seed"], "3");
    assert_eq!(exp["runcount"], 6);
    assert_eq!(exp["totaltime"], 1.5);
    assert!(exp["setup"].as_str().unwrap().contains("not the end"));
    assert_eq!(db["enums"][6]["description"], "Exact solution");

    let rows = db["runs"].as_array().unwrap();
    assert_eq!(rows.len(), runs.len(), "every run is in the database");
    for (r, row) in runs.iter().zip(rows) {
        let what = format!("{} run {}: {row}", r.planner, r.metrics.run);
        assert_eq!(row["planner"], r.planner.as_str(), "{what}");
        assert_eq!(row["run_index"], r.metrics.run, "{what}");
        assert_eq!(row["solved"], u8::from(r.metrics.success), "{what}");
        assert_eq!(row["approximate_solution"], 0, "{what}");
        assert_eq!(row["status"], r.ompl_status() as i64, "{what}");
        assert_eq!(row["iterations"], r.iterations, "{what}");
        assert_eq!(row["collision_checks"], r.collision_checks, "{what}");
        if r.exact {
            assert_eq!(
                row["correct_solution"],
                u8::from(r.metrics.success),
                "{what}"
            );
        } else {
            assert!(row["correct_solution"].is_null(), "{what}");
        }
        for (col, ours) in [
            ("time", r.planning_time_s),
            ("total_time", r.metrics.time_s),
            ("cpu_time", r.metrics.cpu_time_s),
            ("solution_length", r.raw_length),
            ("path_length", r.metrics.length),
            ("max_curvature", r.max_curvature),
            ("minimum_clearance", r.metrics.min_clearance),
            ("transfer_time", r.metrics.transfer_time_s),
            ("graph_states", r.metrics.explored),
            ("path_nodes", r.metrics.nodes),
            ("turns", r.metrics.turns),
        ] {
            assert!(
                same(ours, &row[col]),
                "{col}: ours {ours}, database {}; {what}",
                row[col]
            );
        }
    }
    let settings = rows[0]["settings"].as_str().unwrap();
    assert_eq!(settings, "step = 5\n;");

    // The progress table: every sample of every anytime run, under the run's id.
    let progress = db["progress"].as_array().unwrap();
    let expected: usize = runs.iter().map(|r| r.progress.len()).sum();
    assert!(expected > runs.len() / 4, "RRT* reported progress");
    assert_eq!(
        progress.len(),
        expected,
        "every progress sample is in the database"
    );
    let mut k = 0;
    for (r, row) in runs.iter().zip(rows) {
        for p in &r.progress {
            let got = &progress[k];
            k += 1;
            assert_eq!(got["runid"], row["id"], "{}", r.planner);
            assert_eq!(got["iterations"], p.iterations);
            assert!(same(p.time_s, &got["time"]), "{got}");
            assert!(same(p.best_cost, &got["best_cost"]), "{got}");
        }
    }
}
