//! `hyplan scen`: MovingAI scenario files through the built binary.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn hyplan(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hyplan"))
        .args(args)
        .output()
        .expect("the hyplan binary runs")
}

/// A file of the repository's `data` folder; a missing one fails the test with its path.
fn data(rel: &str) -> String {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../data")
        .join(rel);
    assert!(p.exists(), "test data missing: {}", p.display());
    p.display().to_string()
}

fn tmp_file(name: &str, text: &str) -> String {
    // Each test writes under its own names: tests run in parallel.
    let p = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("hyplan_scen")
        .join(name);
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

const TINY_MAP: &str = "type octile\nheight 4\nwidth 4\nmap\n.@..\n....\n..@.\n....\n";

#[test]
fn arena_all_scenarios_match() {
    let arena = data("movingai/arena.map");
    let scen = data("movingai/arena.map.scen");
    for algo in ["astar", "dijkstra"] {
        let o = hyplan(&["scen", "--map", &arena, "--scen", &scen, "--algo", algo]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let out = String::from_utf8_lossy(&o.stdout).into_owned();
        let mut lines = out.lines();
        assert_eq!(lines.next(), Some("id,expected,cost,time_us,expanded"));
        let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
        assert_eq!(rows.len(), 160);
        for (k, r) in rows.iter().enumerate() {
            assert_eq!(r.len(), 5);
            assert_eq!(r[0], k.to_string());
            let (expected, cost): (f64, f64) = (r[1].parse().unwrap(), r[2].parse().unwrap());
            assert!(
                (expected - cost).abs() <= f64::max(1e-3, 1e-5 * expected),
                "{r:?}"
            );
            assert!(r[3].parse::<f64>().unwrap() >= 0.0);
            r[4].parse::<u64>().unwrap();
        }
        assert!(
            stderr(&o).contains("scenarios 160, mismatches 0"),
            "{}",
            stderr(&o)
        );
    }
}

#[test]
fn limit_takes_the_first_scenarios() {
    let o = hyplan(&[
        "scen",
        "--map",
        &data("generated/tiny.map"),
        "--scen",
        &data("generated/tiny.scen"),
        "--limit",
        "2",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 3, "{out}");
    assert_eq!(lines[0], "id,expected,cost,time_us,expanded");
    // (0,0)->(1,1) costs 2: the diagonal would cut the blocked cell beside it.
    assert!(lines[1].starts_with("0,2,2.00000000,"), "{out}");
    assert!(lines[2].starts_with("1,4.41421356,4.41421356,"), "{out}");
}

/// Runs `hyplan scen` on the tiny map with one scenario line; returns (exit code, stderr).
fn bad(line: &str) -> (Option<i32>, String, String) {
    let map = tmp_file("tiny.map", TINY_MAP);
    let scen = tmp_file("bad.scen", &format!("version 1\n{line}\n"));
    let o = hyplan(&["scen", "--map", &map, "--scen", &scen]);
    assert!(o.stdout.is_empty(), "no CSV on bad input");
    (o.status.code(), stderr(&o), scen)
}

#[test]
fn bad_input_names_file_and_line_and_exits_2() {
    let cases = [
        (
            "0\ttiny.map\t4\t4\t0\t0\t1",
            "expected 9 tab-separated fields, found 7",
        ),
        (
            "0\ttiny.map\t4\t4\tx\t0\t1\t1\t2",
            "field start x is not a valid",
        ),
        ("0\ttiny.map\t4\t4\t0\t0\t1\t1\tfar", "field optimal length"),
        ("0\tother.map\t4\t4\t0\t0\t1\t1\t2", "does not match --map"),
        (
            "0\ttiny.map\t4\t4\t4\t0\t1\t1\t2",
            "start (4, 0) is outside the 4 x 4 map",
        ),
        ("0\ttiny.map\t4\t4\t0\t0\t1\t9\t2", "goal (1, 9) is outside"),
        (
            "0\ttiny.map\t4\t4\t1\t0\t0\t0\t2",
            "start (1, 0) is on a blocked cell",
        ),
        (
            "0\ttiny.map\t4\t4\t0\t0\t2\t2\t2",
            "goal (2, 2) is on a blocked cell",
        ),
        ("0\ttiny.map\t5\t4\t0\t0\t1\t1\t2", "declares a 5 x 4 map"),
    ];
    for (line, want) in cases {
        let (code, err, scen) = bad(line);
        assert_eq!(code, Some(2), "{line}: {err}");
        assert!(err.starts_with("error: "), "{err}");
        assert!(err.contains(&format!("{scen}:2")), "{line}: {err}");
        assert!(err.contains(want), "{line}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn dir_prefix_in_map_column_is_ignored_and_missing_files_are_errors() {
    let map = tmp_file("dir/tiny.map", TINY_MAP);
    let scen = tmp_file(
        "dir/dir.scen",
        "version 1\n0\tmaps/dao/tiny.map\t4\t4\t0\t0\t1\t1\t2\n",
    );
    let o = hyplan(&["scen", "--map", &map, "--scen", &scen]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = hyplan(&["scen", "--map", &map, "--scen", "/nonexistent/x.scen"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("/nonexistent/x.scen"));
    let o = hyplan(&["scen", "--map", "/nonexistent/m.map", "--scen", &scen]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("/nonexistent/m.map"));
}
