//! `hyplan sim`: scenario files through the built binary.

use std::path::Path;
use std::process::{Command, Output};

fn hyplan(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hyplan"))
        .args(args)
        .output()
        .expect("the hyplan binary runs")
}

fn tmp_file(name: &str, text: &str) -> String {
    let p = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("hyplan_sim")
        .join(name);
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A 6 m x 3 m hall with a box in the middle and a person crossing.
fn hall(extra_world: &str, extra: &str, start: &str) -> String {
    format!(
        r#"SimScenario(
    name: "hall",
    world: (size: (6.0, 3.0), shapes: [Box(center: (3.0, 0.6), size: (0.6, 1.2)){extra_world}]),
    people: [(path: [(4.5, 2.8), (4.5, 0.2)], speed: 0.3, start: 4.0)],
    start: {start}, goal: (5.5, 1.5),
    time_limit: 60.0,{extra}
)"#
    )
}

#[test]
fn reaches_the_goal_and_writes_outputs() {
    let f = tmp_file("ok.ron", &hall("", "", "(0.5, 1.5)"));
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("hyplan_sim/out");
    let o = hyplan(&["sim", &f, "--seed", "3", "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("goal reached"), "{text}");
    assert!(text.contains("0 at fault"), "{text}");
    for f in [
        "trace.csv",
        "trace.json",
        "map.yaml",
        "map.pgm",
        "trajectory.svg",
        "velocity.svg",
        "animation.svg",
    ] {
        assert!(out.join(f).exists(), "{f} missing");
    }
    let csv = std::fs::read_to_string(out.join("trace.csv")).unwrap();
    assert!(csv.starts_with("t,x,y,phi,v,omega,wheel_right,wheel_left,d_obstacle,d_person,events"));
    assert!(
        std::fs::read_to_string(out.join("animation.svg"))
            .unwrap()
            .contains("<animate")
    );
}

#[test]
fn other_planners_by_name() {
    let f = tmp_file("astar.ron", &hall("", "", "(0.5, 1.5)"));
    let o = hyplan(&["sim", &f, "--planner", "astar"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("planner astar"));
    let o = hyplan(&["sim", &f, "--planner", "rrt-connect", "--seed", "1"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = hyplan(&["sim", &f, "--planner", "no-such-planner"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("no-such-planner"), "{}", stderr(&o));
}

#[test]
fn unreachable_goal_exits_1() {
    // A wall across the hall: no way through.
    let f = tmp_file(
        "walled.ron",
        &hall(
            ", Wall(from: (2.0, 0.0), to: (2.0, 3.0), thickness: 0.2)",
            "\n    navigation: (max_failures: 2, retry_period: 0.5),",
            "(0.5, 1.5)",
        ),
    );
    let o = hyplan(&["sim", &f]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("not reached"));
}

/// Each bad scenario, and what the message must name (file, field, value).
#[test]
fn bad_scenarios_exit_2_naming_field_and_value() {
    let cases: [(&str, String, &[&str]); 8] = [
        (
            "unknown.ron",
            hall("", "\n    colour: 3,", "(0.5, 1.5)"),
            &["unknown.ron", "colour"],
        ),
        (
            "radius.ron",
            hall(", Disc(center: (1.0, 2.5), radius: -0.2)", "", "(0.5, 1.5)"),
            &["radius.ron", "world.shapes[1].radius", "-0.2"],
        ),
        (
            "speed.ron",
            hall("", "", "(0.5, 1.5)").replace("speed: 0.3", "speed: -1.0"),
            &["speed.ron", "people[0].speed", "-1"],
        ),
        (
            "inside.ron",
            hall("", "", "(3.0, 0.6)"),
            &["inside.ron", "start", "(3, 0.6)", "inside an obstacle"],
        ),
        (
            "outside.ron",
            hall("", "", "(7.0, 1.5)"),
            &["outside.ron", "start", "(7, 1.5)", "outside the world"],
        ),
        (
            "goal_inside.ron",
            hall("", "", "(0.5, 1.5)").replace("goal: (5.5, 1.5)", "goal: (3.0, 0.6)"),
            &["goal_inside.ron", "goal", "(3, 0.6)", "inside an obstacle"],
        ),
        (
            "goal_outside.ron",
            hall("", "", "(0.5, 1.5)").replace("goal: (5.5, 1.5)", "goal: (5.5, 4.0)"),
            &["goal_outside.ron", "goal", "(5.5, 4)", "outside the world"],
        ),
        (
            "path.ron",
            hall("", "", "(0.5, 1.5)").replace("[(4.5, 2.8), (4.5, 0.2)]", "[(4.5, 2.8)]"),
            &["path.ron", "people[0].path", "at least 2 points"],
        ),
    ];
    for (name, text, needles) in cases {
        let f = tmp_file(name, &text);
        let o = hyplan(&["sim", &f]);
        assert_eq!(o.status.code(), Some(2), "{name}: {}", stderr(&o));
        let err = stderr(&o);
        for n in needles {
            assert!(err.contains(n), "{name}: {n:?} not in {err}");
        }
    }
    let o = hyplan(&["sim", "/no/such/file.ron"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("/no/such/file.ron"));
}
