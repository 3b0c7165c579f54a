//! `hyplan scen`: MovingAI scenario files through the built binary.

use std::process::Output;

use crate::common::{Scratch, assert_exit, hyplan, repo_file, stderr, stdout};

const SCRATCH: Scratch = Scratch("hyplan_scen");

/// `hyplan scen --map MAP --scen SCEN EXTRA`.
fn scen(map: &str, scen: &str, extra: &[&str]) -> Output {
    hyplan(&[&["scen", "--map", map, "--scen", scen], extra].concat())
}

const TINY_MAP: &str = "type octile\nheight 4\nwidth 4\nmap\n.@..\n....\n..@.\n....\n";

#[test]
fn arena_all_scenarios_match() {
    let arena = repo_file("data/movingai/arena.map");
    let arena_scen = repo_file("data/movingai/arena.map.scen");
    for (flag, planner) in [
        ("--algo", "astar"),
        ("--planner", "dijkstra"),
        ("--planner", "jps"),
    ] {
        let o = scen(&arena, &arena_scen, &[flag, planner]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let out = stdout(&o);
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

/// The `.scen` alone, as an argument: the map it names is found beside it (the MovingAI
/// downloads' layout); a map found nowhere is an error that names the paths tried.
#[test]
fn the_map_is_found_beside_the_scen() {
    let o = hyplan(&[
        "scen",
        &repo_file("data/movingai/arena.map.scen"),
        "--limit",
        "5",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("scenarios 5, mismatches 0"),
        "{}",
        stderr(&o)
    );
    let scen_text = std::fs::read(repo_file("data/movingai/arena.map.scen")).unwrap();
    let lonely = SCRATCH.file("lonely.scen", scen_text);
    let o = hyplan(&["scen", &lonely]);
    assert_exit(&o, 2, &["maps/dao/arena.map", "give --map"]);
}

/// The `cost` column of `hyplan scen` on the arena with `--planner planner`.
fn arena_costs(planner: &str) -> Vec<f64> {
    let o = scen(
        &repo_file("data/movingai/arena.map"),
        &repo_file("data/movingai/arena.map.scen"),
        &["--planner", planner],
    );
    assert_eq!(o.status.code(), Some(0), "{planner}: {}", stderr(&o));
    stdout(&o)
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(2).unwrap().parse().unwrap())
        .collect()
}

/// Jump point search gives A*'s length on every arena query (up to the order in which
/// the moves' lengths were added), and `--help` says when to pick which.
#[test]
fn jps_gives_astars_lengths_and_help_says_which_to_use() {
    let (astar, jps) = (arena_costs("astar"), arena_costs("jps"));
    assert_eq!(astar.len(), 160);
    assert_eq!(jps.len(), astar.len());
    for (k, (a, j)) in astar.iter().zip(&jps).enumerate() {
        assert!((a - j).abs() <= 1e-6, "scenario {k}: astar {a}, jps {j}");
    }
    let o = hyplan(&["scen", "--help"]);
    let help = stdout(&o);
    // Which planner where: jps, and where astar is as fast (cells blocked at random).
    assert!(
        help.contains("Use jps") && help.contains("blocked at random the two take the same"),
        "{help}"
    );
}

#[test]
fn limit_takes_the_first_scenarios() {
    let o = scen(
        &repo_file("data/generated/tiny.map"),
        &repo_file("data/generated/tiny.scen"),
        &["--limit", "2"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 3, "{out}");
    assert_eq!(lines[0], "id,expected,cost,time_us,expanded");
    // (0,0)->(1,1) costs 2: the diagonal would cut the blocked cell beside it.
    assert!(lines[1].starts_with("0,2,2.00000000,"), "{out}");
    assert!(lines[2].starts_with("1,4.41421356,4.41421356,"), "{out}");
}

/// Runs `hyplan scen` on the tiny map with one scenario line; returns (exit code, stderr).
fn bad(line: &str) -> (Option<i32>, String, String) {
    let map = SCRATCH.file("tiny.map", TINY_MAP);
    let file = SCRATCH.file("bad.scen", format!("version 1\n{line}\n"));
    let o = scen(&map, &file, &[]);
    assert!(o.stdout.is_empty(), "no CSV on bad input");
    (o.status.code(), stderr(&o), file)
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
    let map = SCRATCH.file("dir/tiny.map", TINY_MAP);
    let file = SCRATCH.file(
        "dir/dir.scen",
        "version 1\n0\tmaps/dao/tiny.map\t4\t4\t0\t0\t1\t1\t2\n",
    );
    let o = scen(&map, &file, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = scen(&map, "/nonexistent/x.scen", &[]);
    assert_exit(&o, 2, &["/nonexistent/x.scen"]);
    let o = scen("/nonexistent/m.map", &file, &[]);
    assert_exit(&o, 2, &["/nonexistent/m.map"]);
}
