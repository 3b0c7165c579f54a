//! `hyplan plan`: runs the built binary on small MovingAI maps and checks exit codes and
//! the CSV / JSON / SVG outputs.

use std::process::{Command, Output};

use crate::common::{Scratch, assert_error, flags, hyplan, json, repo_file, stderr, stdout};

const SCRATCH: Scratch = Scratch("hyplan_plan");

/// `hyplan plan ARGS`.
fn plan(args: &[&str]) -> Output {
    hyplan(&[&["plan"], args].concat())
}

/// The query of the tests: `--map MAP` from (2.5, 2.5) to (17.5, 2.5), across the wall of
/// [`walled`].
fn across(map: &str) -> Vec<&str> {
    vec!["--map", map, "--start", "2.5,2.5", "--goal", "17.5,2.5"]
}

/// `hyplan plan` on [`across`] with the flags of `line`.
fn plan_across(map: &str, line: &str) -> Output {
    plan(&[across(map), flags(line)].concat())
}

/// [`plan_across`] a fresh [`walled`] map named `tag`, which must succeed.
fn plan_walled(tag: &str, line: &str) -> Output {
    let o = plan_across(&walled(tag), line);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    o
}

/// A MovingAI `.map` from rows drawn top row first (`.` free, `@` blocked).
fn movingai(name: &str, rows: &[String]) -> String {
    let mut text = format!(
        "type octile\nheight {}\nwidth {}\nmap\n",
        rows.len(),
        rows[0].len()
    );
    for r in rows {
        text.push_str(r);
        text.push('\n');
    }
    SCRATCH.file(name, text)
}

/// 20 x 10 with a wall at x = 10 over the top `wall_rows` rows. Row 0 is the top.
fn wall_map(name: &str, wall_rows: usize) -> String {
    let rows: Vec<String> = (0..10)
        .map(|y| {
            (0..20)
                .map(|x| if x == 10 && y < wall_rows { '@' } else { '.' })
                .collect()
        })
        .collect();
    movingai(name, &rows)
}

/// The wall leaves a gap in the bottom three rows. `tag` names the file: tests run in
/// parallel, each writes its own.
fn walled(tag: &str) -> String {
    wall_map(&format!("walled_{tag}.map"), 7)
}

/// The same with the gap closed: the right half is unreachable from the left.
fn closed(tag: &str) -> String {
    wall_map(&format!("closed_{tag}.map"), 10)
}

/// A JSON array of `[x, y]` points.
fn points(v: &serde_json::Value) -> Vec<(f64, f64)> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect()
}

/// The lengths of the segments between consecutive points.
fn segments(points: &[(f64, f64)]) -> impl Iterator<Item = f64> + '_ {
    points
        .windows(2)
        .map(|w| (w[0].0 - w[1].0).hypot(w[0].1 - w[1].1))
}

const PLANNERS: [&str; 9] = [
    "rrt",
    "rrt-star",
    "bi-rrt",
    "rrt-connect",
    "astar",
    "jps",
    "dijkstra",
    "theta-star",
    "lazy-theta-star",
];

#[test]
fn every_planner_finds_a_path_and_prints_json() {
    let map = walled("every_planner_finds_a_path_and_prints_json");
    for planner in PLANNERS {
        let line = format!("--planner {planner} --step 1.5 --seed 3 --json");
        let o = plan_across(&map, &line);
        assert_eq!(o.status.code(), Some(0), "{planner}: {}", stderr(&o));
        let v = json(&o);
        assert_eq!(v["planner"], planner);
        assert_eq!(v["run"], 0);
        assert_eq!(v["solved"], true);
        assert!(v["seed"].is_u64() && v["time_s"].is_f64() && v["nodes"].is_u64());
        let path = points(&v["path"]);
        // The input frame: y counted from the top row; the path starts and ends exactly.
        assert_eq!(path[0], (2.5, 2.5));
        assert_eq!(path[path.len() - 1], (17.5, 2.5));
        // It must go through the gap (rows 7..10 from the top) to cross x = 10.
        assert!(path.iter().any(|p| p.1 > 7.0));
        let length: f64 = segments(&path).sum();
        assert!((length - v["length"].as_f64().unwrap()).abs() < 1e-9);
        // Same seed, same path.
        let again = json(&plan_across(&map, &line));
        assert_eq!(v["path"], again["path"], "{planner}: same seed, same path");
    }
}

/// `hyplan plan --json` on the walled map with `--planner planner`: the JSON output.
fn walled_json(tag: &str, planner: &str) -> serde_json::Value {
    json(&plan_walled(tag, &format!("--planner {planner} --json")))
}

/// `jps` finds A*'s length through the gap; `lazy-theta-star` is `theta-star`'s default
/// (lazy) search by name, and the eager original is still there to compare with.
#[test]
fn jps_has_astars_length_and_lazy_theta_star_is_theta_stars_default() {
    let tag = "jps_has_astars_length_and_lazy_theta_star_is_theta_stars_default";
    let astar = walled_json(tag, "astar");
    let jps = walled_json(tag, "jps");
    assert_eq!(jps["planner"], "jps");
    let (a, j) = (
        astar["length"].as_f64().unwrap(),
        jps["length"].as_f64().unwrap(),
    );
    assert!((a - j).abs() < 1e-9, "astar {a}, jps {j}");
    assert!(
        jps["nodes"].as_u64().unwrap() < astar["nodes"].as_u64().unwrap(),
        "jps reaches fewer cells: {} vs {}",
        jps["nodes"],
        astar["nodes"]
    );
    let lazy = walled_json(tag, "lazy-theta-star");
    assert_eq!(lazy["planner"], "lazy-theta-star");
    assert_eq!(lazy["path"], walled_json(tag, "theta-star")["path"]);
    assert_eq!(
        lazy["path"],
        walled_json(tag, "theta-star:lazy=true")["path"]
    );
    let eager = walled_json(tag, "theta-star:lazy=false");
    assert_eq!(eager["solved"], true);
    // `lazy` is theta-star's field only: the lazy planner's name already says it.
    let o = plan_across(&walled(tag), "--planner lazy-theta-star:lazy=false");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

#[test]
fn csv_has_the_ompl_peer_columns_and_one_row_per_run() {
    let o = plan_walled(
        "csv_has_the_ompl_peer_columns_and_one_row_per_run",
        "--planner rrt-connect --step 2 --goal-radius 1 --runs 4 --csv",
    );
    let out = stdout(&o);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines[0],
        "planner,run,solved,exact,time_s,length,states_in_path,graph_vertices"
    );
    assert_eq!(lines.len(), 5);
    for (k, line) in lines[1..].iter().enumerate() {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f.len(), 8, "{line}");
        assert_eq!(f[0], "rrt-connect");
        assert_eq!(f[1], k.to_string());
        assert_eq!((f[2], f[3]), ("1", "1"));
        assert!(f[5].parse::<f64>().unwrap() >= 15.0);
        assert!(f[6].parse::<usize>().unwrap() >= 2);
    }
}

#[test]
fn runs_get_distinct_derived_seeds() {
    let o = plan_walled(
        "runs_get_distinct_derived_seeds",
        "--runs 3 --seed 9 --json",
    );
    let seeds: Vec<u64> = stdout(&o)
        .lines()
        .map(|l| {
            serde_json::from_str::<serde_json::Value>(l).unwrap()["seed"]
                .as_u64()
                .unwrap()
        })
        .collect();
    assert_eq!(seeds.len(), 3);
    assert!(seeds[0] != seeds[1] && seeds[1] != seeds[2] && seeds[0] != seeds[2]);
}

/// [`plan_across`] a fresh [`walled`] map named `tag`, with `line`'s flags and `--svg`,
/// which must succeed: its output and the SVG's text.
fn plan_svg(tag: &str, line: &str) -> (Output, String) {
    let map = walled(tag);
    let svg = SCRATCH.path(&format!("{tag}.svg"));
    let mut args = [across(&map), flags(line)].concat();
    args.extend(["--svg", svg.to_str().unwrap()]);
    let o = plan(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap();
    (o, text)
}

#[test]
fn svg_draws_map_tree_and_path() {
    let (o, text) = plan_svg("svg_draws_map_tree_and_path", "--planner bi-rrt");
    assert!(text.contains("<svg"));
    assert!(text.matches("<path").count() >= 3, "two trees and the path");
    assert!(text.contains("data:image/png;base64,"), "the zone layer");
    assert!(stdout(&o).contains("path of length"));
}

/// The zones are one picture (`envmap::render_zones`, no seams between rows), and a
/// smoothed curve is drawn and reported with its transfer time.
#[test]
fn svg_zones_are_seamless_and_the_curve_is_drawn() {
    let (o, text) = plan_svg(
        "svg_zones_are_seamless",
        "--planner rrt-connect --smooth pchip --vmax 1 --wmax 1 --amax 1",
    );
    // One raster for the zones, no cell rectangles.
    assert_eq!(text.matches("<image").count(), 1, "{text}");
    assert_eq!(text.matches("<rect").count(), 0, "{text}");
    let hex = |c: [u8; 4]| format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
    assert!(
        text.contains(&hex(harness::CURVE_COLOUR)),
        "the smoothed curve"
    );
    let out = stdout(&o);
    assert!(
        out.contains("pchip curve") && out.contains("transfer time"),
        "{out}"
    );
}

/// `--planner NAME:key=value` sets any field of the planner; an unknown key is named.
#[test]
fn planner_pairs_set_fields_and_bad_keys_are_named() {
    let map = walled("planner_pairs");
    let o = plan_across(
        &map,
        "--json --planner rrt:step=2.5,budget.max_iterations=50000",
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let line: serde_json::Value = serde_json::from_str(stdout(&o).lines().next().unwrap()).unwrap();
    assert_eq!(line["planner"], "rrt");
    // Steps of 2.5 cells: no path segment is longer.
    for d in segments(&points(&line["path"])) {
        assert!(d <= 2.5 + 1e-9, "segment {d}");
    }
    let o = plan_across(&map, "--json --planner rrt:stepp=2");
    assert_error(&o, &["--planner", "stepp", "goal_bias"]);
    let o = plan_across(&map, "--json --planner rrt-turbo");
    assert_error(&o, &["rrt-turbo", "ga-pchip"]);
}

#[test]
fn unreachable_goal_is_no_path_with_exit_1() {
    let map = closed("unreachable_goal_is_no_path_with_exit_1");
    let started = std::time::Instant::now();
    let o = plan_across(&map, "--max-iter 20000");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("no path: an obstacle wall separates start and goal"),
        "{}",
        stdout(&o)
    );
    let csv = plan_across(&map, "--planner rrt-connect --time-limit 0.2 --csv");
    assert_eq!(csv.status.code(), Some(1));
    let out = stdout(&csv);
    let row: Vec<&str> = out.lines().nth(1).unwrap().split(',').collect();
    assert_eq!((row[2], row[3], row[5]), ("0", "0", ""));
    let t: f64 = row[4].parse().unwrap();
    // Proved before sampling (issue 13): well before the 0.2 s limit.
    assert!(t < 0.2, "time {t}: the wall should be proved at once");
    assert!(started.elapsed().as_secs_f64() < 20.0);
}

#[test]
fn bad_input_is_exit_2_with_a_message() {
    let map = walled("bad_input_is_exit_2_with_a_message");
    // Flags given later replace the defaults (clap rejects repeated flags).
    let base = |extra: &[&str]| {
        let mut args = vec!["--map", map.as_str()];
        if !extra.contains(&"--start") {
            args.extend(["--start", "2.5,2.5"]);
        }
        if !extra.contains(&"--goal") {
            args.extend(["--goal", "17.5,2.5"]);
        }
        args.extend_from_slice(extra);
        plan(&args)
    };
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (
            vec!["--start", "-3,2.5"],
            vec![
                "--start",
                "outside the map",
                "x from 0 to 20 and y from 0 to 10, in cells",
            ],
        ),
        (vec!["--start", "25,2.5"], vec!["outside the map"]),
        (vec!["--start", "10.5,2.5"], vec!["--start", "obstacle"]),
        (vec!["--goal", "10.5,0.5"], vec!["--goal", "obstacle"]),
        (vec!["--goal", "nan,1"], vec!["--goal", "finite"]),
        (vec!["--goal-radius", "-1"], vec!["radius"]),
        (vec!["--step", "0"], vec!["step"]),
        (vec!["--step", "-1"], vec!["step"]),
        (vec!["--step", "NaN"], vec!["step"]),
        (vec!["--goal-bias", "1.5"], vec!["goal_bias"]),
        (vec!["--goal-bias", "-0.1"], vec!["goal_bias"]),
        (
            vec!["--goal-bias", "2", "--planner", "rrt-connect"],
            vec!["goal_bias"],
        ),
        (vec!["--max-iter", "0"], vec!["max_iterations"]),
        (vec!["--time-limit", "0"], vec!["--time-limit"]),
        (vec!["--time-limit", "-1"], vec!["--time-limit"]),
        (vec!["--runs", "0"], vec!["--runs"]),
        (
            vec!["--planner", "rrt-sharp"],
            vec!["unknown planner", "rrt-connect"],
        ),
        (vec!["--start", "1;2"], vec!["X,Y"]),
    ];
    for (extra, needles) in cases {
        let o = base(&extra);
        assert_error(&o, &needles);
    }
    let missing = plan(&[
        "--map",
        "/nonexistent/room.png",
        "--start",
        "1,1",
        "--goal",
        "2,2",
    ]);
    assert_error(&missing, &["room.png"]);
}

#[test]
fn the_papers_hybrids_plan_from_the_command_line() {
    let map = walled("the_papers_hybrids_plan_from_the_command_line");
    for planner in [
        "rrt-astar-bt",
        "rrt-astar-refine",
        "hybrid-rrt-astar",
        "safe-rrt-star",
    ] {
        let o = plan_across(
            &map,
            &format!("--goal-radius 1 --planner {planner} --step 1.5 --json"),
        );
        assert_eq!(o.status.code(), Some(0), "{planner}: {}", stderr(&o));
        let v = json(&o);
        assert_eq!(v["planner"], planner);
        let path = points(&v["path"]);
        assert_eq!(path[0], (2.5, 2.5), "{planner}");
        let (x, y) = path[path.len() - 1];
        assert!(
            (x - 17.5).hypot(y - 2.5) <= 1.0 + 1e-9,
            "{planner} ends at {x},{y}"
        );
    }
}

#[test]
fn smoothing_adds_the_checked_curve_turns_and_transfer_time() {
    let map = walled("smoothing_adds_the_checked_curve_turns_and_transfer_time");
    let run = |smooth: &str| {
        let o = plan_across(
            &map,
            &format!("--planner astar --smooth {smooth} --vmax 1 --wmax 1 --amax 0.5 --json"),
        );
        assert_eq!(o.status.code(), Some(0), "{smooth}: {}", stderr(&o));
        json(&o)
    };
    let raw = run("none");
    assert!(raw.get("smoothed").is_none());
    let raw_time = raw["transfer_time_s"].as_f64().unwrap();
    // Never faster than the length at full speed.
    assert!(raw_time >= raw["length"].as_f64().unwrap());
    for smooth in ["prune", "pchip", "bspline"] {
        let v = run(smooth);
        let curve = points(&v["smoothed"]);
        assert_eq!(curve[0], (2.5, 2.5), "{smooth}");
        assert_eq!(curve[curve.len() - 1], (17.5, 2.5), "{smooth}");
        // At most a quarter cell apart, and never inside the wall (x = 10, rows 0..7).
        assert!(segments(&curve).all(|d| d <= 0.25 + 1e-9), "{smooth}");
        for &(x, y) in &curve {
            assert!(
                !((10.0..11.0).contains(&x) && y < 7.0),
                "{smooth}: ({x}, {y}) in the wall"
            );
        }
        assert!(
            v["turns"].as_u64().unwrap() <= raw["turns"].as_u64().unwrap(),
            "{smooth}"
        );
        assert!(
            v["transfer_time_s"].as_f64().unwrap() < raw_time,
            "{smooth}: shortcuts save time"
        );
    }
    // Limits come as a set of three.
    let o = plan_across(&map, "--vmax 1");
    assert_eq!(o.status.code(), Some(2));
    let o = plan_across(&map, "--smooth wiggly");
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn a_closed_pipe_ends_quietly() {
    use std::process::Stdio;
    let map = walled("a_closed_pipe_ends_quietly");
    let mut child = Command::new(env!("CARGO_BIN_EXE_hyplan"))
        .arg("plan")
        .args(across(&map))
        .args(["--runs", "2000", "--csv"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Read one line, then hang up, like `| head -1`.
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 16];
    std::io::Read::read_exact(&mut stdout, &mut first).unwrap();
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(out.status.code(), Some(0), "{err}");
}

/// A generated floor plan (rooms, corridors, 60-cell doors) written as a PNG picture, with
/// its start and goal in the picture's frame (column, row from the top).
fn floor_plan_picture(name: &str, side: usize) -> (String, String, String) {
    use rand_chacha::rand_core::SeedableRng;
    let g = envmap::floor_plan(
        side,
        side,
        60,
        4,
        &mut rand_chacha::ChaCha8Rng::seed_from_u64(1),
    );
    let (w, h) = (g.map.width(), g.map.height());
    let mut data = vec![255_u8; w * h];
    for j in 0..h {
        for i in 0..w {
            if g.map.cell_zone(i, j) == hyplan_core::Zone::Forbidden {
                data[(h - 1 - j) * w + i] = 0;
            }
        }
    }
    let path = SCRATCH.path(name);
    envmap::write_picture(&envmap::Picture::grey(w, h, data).unwrap(), &path).unwrap();
    let xy = |p: hyplan_core::Point2| format!("{},{}", p.x, h as f64 - p.y);
    (path.display().to_string(), xy(g.start), xy(g.goal))
}

/// No planner gives up by default: with no budget flag, every planner of the registry
/// solves a generated floor plan, seed 000's Table 2 room with `--avoid-risk` and a
/// building map in metres that nobody here drew (the AWS small house of `data/ros_maps`),
/// except GA-PCHIP on the floor plan, whose six via-points cannot thread its doors (its
/// budget is generations; the message then names that budget and the flags that raise
/// it). RRT-A*-BT's own defaults are seed 000's pixels (a 40-unit step, a 20-unit goal
/// radius): taken as metres in the 25 m house they left its tree at one or two nodes until
/// its budget ran out, before the command line scaled them to the map. The release
/// binary's times on the 2000 x 2000 plan are in docs/measurements/.
#[test]
fn every_registry_planner_solves_a_floor_plan_the_room_and_a_house_at_its_defaults() {
    let (plan_map, start, goal) = floor_plan_picture("floor_plan_1000.png", 1000);
    let room = repo_file("scenarios/maps/room_960x640.png");
    let house = repo_file("data/ros_maps/aws_small_house/map.yaml");
    for name in harness::PlannerConfig::names() {
        let o = plan(&[
            "--map",
            &plan_map,
            "--start",
            &start,
            "--goal",
            &goal,
            "--planner",
            name,
        ]);
        if name == "ga-pchip" {
            assert_eq!(o.status.code(), Some(1), "{name}: {}", stderr(&o));
            let out = stdout(&o);
            assert!(
                out.contains("the budget was 200 iterations") && out.contains("--max-iter N"),
                "{out}"
            );
        } else {
            assert_eq!(
                o.status.code(),
                Some(0),
                "{name} on the floor plan: {}{}",
                stdout(&o),
                stderr(&o)
            );
        }
        let o = plan(&[
            "--map",
            &room,
            "--start",
            "12,308",
            "--goal",
            "868,206",
            "--avoid-risk",
            "--planner",
            name,
        ]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{name} in the room: {}{}",
            stdout(&o),
            stderr(&o)
        );
        let o = plan(&[
            "--map",
            &house,
            "--start",
            "8.475,2.075",
            "--goal",
            "-8.675,-4.475",
            "--planner",
            name,
        ]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{name} in the house: {}{}",
            stdout(&o),
            stderr(&o)
        );
    }
}

/// A spent budget says which budget it was and how to raise it.
#[test]
fn a_spent_budget_names_itself_and_the_flag() {
    let map = walled("a_spent_budget_names_itself_and_the_flag");
    let o = plan_across(&map, "--planner astar --max-iter 3 --json");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let v = json(&o);
    assert_eq!(v["no_path"]["kind"], "budget");
    assert_eq!(v["no_path"]["max_iterations"], 3);
    let msg = v["no_path"]["message"].as_str().unwrap();
    assert!(
        msg.contains("the budget was 3 iterations") && msg.contains("--max-iter"),
        "{msg}"
    );
}
