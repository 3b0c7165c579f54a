//! `hyplan sim`: scenario files through the built binary.

use std::path::Path;

use crate::common::{Scratch, assert_exit, hyplan, nav2_counts, repo_file, stderr, stdout};

const SCRATCH: Scratch = Scratch("hyplan_sim");

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
    let f = SCRATCH.file("ok.ron", hall("", "", "(0.5, 1.5)"));
    let out = SCRATCH.path("out");
    let o = hyplan(&["sim", &f, "--seed", "3", "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
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
    let [free, occupied, unknown] = trinary_counts(&out.join("map.yaml"));
    assert_eq!(free + occupied + unknown, 120 * 60);
    assert!(
        free > 0 && occupied > 0 && unknown > 0,
        "{free} {occupied} {unknown}"
    );
    assert!(
        std::fs::read_to_string(out.join("animation.svg"))
            .unwrap()
            .contains("<animate")
    );
}

#[test]
fn other_planners_by_name() {
    let f = SCRATCH.file("astar.ron", hall("", "", "(0.5, 1.5)"));
    let o = hyplan(&["sim", &f, "--planner", "astar"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("planner astar"));
    let o = hyplan(&["sim", &f, "--planner", "rrt-connect", "--seed", "1"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = hyplan(&["sim", &f, "--planner", "no-such-planner"]);
    assert_exit(&o, 2, &["no-such-planner"]);
}

/// The collision monitor from the file (`Some(())`: its defaults) and from the flag.
#[test]
fn the_collision_monitor_from_the_file_and_the_flag() {
    let on = SCRATCH.file(
        "monitor_on.ron",
        hall(
            "",
            "\n    navigation: (collision_monitor: Some(())),",
            "(0.5, 1.5)",
        ),
    );
    let plain = SCRATCH.file("monitor_plain.ron", hall("", "", "(0.5, 1.5)"));
    for args in [
        vec!["sim", &on],
        vec!["sim", &on, "--collision-monitor", "off"],
        vec!["sim", &plain, "--collision-monitor", "on"],
    ] {
        let o = hyplan(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        assert!(stdout(&o).contains("0 at fault"), "{args:?}");
    }
    let o = hyplan(&["sim", &plain, "--collision-monitor", "maybe"]);
    assert_exit(&o, 2, &["maybe"]);
}

#[test]
fn unreachable_goal_exits_1() {
    // A wall across the hall: no way through.
    let f = SCRATCH.file(
        "walled.ron",
        hall(
            ", Wall(from: (2.0, 0.0), to: (2.0, 3.0), thickness: 0.2)",
            "\n    navigation: (max_failures: 2, retry_period: 0.5),",
            "(0.5, 1.5)",
        ),
    );
    let o = hyplan(&["sim", &f]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stdout(&o).contains("not reached"));
}

/// Each bad scenario, and what the message must name (file, field, value).
#[test]
fn bad_scenarios_exit_2_naming_field_and_value() {
    let cases: [(&str, String, &[&str]); 9] = [
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
            "monitor.ron",
            hall(
                "",
                "\n    navigation: (collision_monitor: Some((person_speed: -1.0))),",
                "(0.5, 1.5)",
            ),
            &[
                "monitor.ron",
                "navigation.collision_monitor.person_speed",
                "-1",
            ],
        ),
        (
            "path.ron",
            hall("", "", "(0.5, 1.5)").replace("[(4.5, 2.8), (4.5, 0.2)]", "[(4.5, 2.8)]"),
            &["path.ron", "people[0].path", "at least 2 points"],
        ),
    ];
    for (name, text, needles) in cases {
        let f = SCRATCH.file(name, text);
        let o = hyplan(&["sim", &f]);
        assert_eq!(o.status.code(), Some(2), "{name}: {}", stderr(&o));
        let err = stderr(&o);
        for n in needles {
            assert!(err.contains(n), "{name}: {n:?} not in {err}");
        }
    }
    let o = hyplan(&["sim", "/no/such/file.ron"]);
    assert_exit(&o, 2, &["/no/such/file.ron"]);
}

/// A 6 m x 4 m room with a box, small enough to explore in a few seconds, with `extra`
/// fields. The Python tests of the written maps explore the same room.
fn room(extra: &str) -> String {
    let text = include_str!("data/room.ron");
    let body = text.trim_end().strip_suffix(')').unwrap().trim_end();
    format!("{body}{extra}\n)")
}

#[test]
fn explore_writes_coverage_map_and_figures() {
    let f = SCRATCH.file("room.ron", room(""));
    let out = SCRATCH.path("explore");
    for detector in ["both", "frontier"] {
        let o = hyplan(&[
            "explore",
            &f,
            "--detector",
            detector,
            "--eta",
            "2",
            "--seed",
            "4",
            "--out",
            out.to_str().unwrap(),
        ]);
        let stdout = stdout(&o);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{detector}: {stdout}{}",
            stderr(&o)
        );
        assert!(stdout.contains("explored, no frontier left"), "{stdout}");
        assert!(stderr(&o).contains("coverage"), "progress lines on stderr");
        let csv = std::fs::read_to_string(out.join("coverage.csv")).unwrap();
        let last: f64 = csv
            .lines()
            .last()
            .unwrap()
            .rsplit(',')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert!(last >= 0.95, "{detector}: final coverage {last}");
        for name in ["track.csv", "map.yaml", "map.pgm", "animation.png"] {
            assert!(out.join(name).is_file(), "{name}");
        }
        // The map file, read by Nav2's trinary rule, has the cells the summary counts.
        let counts = trinary_counts(&out.join("map.yaml"));
        let [f, o, u] = counts;
        let line =
            format!("built map: 120 x 80 cells of 0.05 m: {f} free, {o} occupied, {u} unknown");
        assert!(
            stdout.lines().any(|l| l == line),
            "{line:?} not in {stdout}"
        );
        check_animation(&out.join("animation.png"));
        let svgs = std::fs::read_dir(&out)
            .unwrap()
            .filter(|e| {
                e.as_ref()
                    .is_ok_and(|e| e.file_name().to_string_lossy().ends_with(".svg"))
            })
            .count();
        assert!(svgs >= 1);
    }
}

/// The animation decodes frame by frame (palette expanded to RGB, as a viewer shows it)
/// into the five colours of the figure: the last frame has free, occupied and unknown
/// cells, the track and the robot.
fn check_animation(file: &Path) {
    let mut decoder =
        png::Decoder::new(std::io::BufReader::new(std::fs::File::open(file).unwrap()));
    decoder.set_transformations(png::Transformations::EXPAND);
    let mut reader = decoder.read_info().unwrap();
    let frames = reader.info().animation_control().unwrap().num_frames;
    assert!(frames >= 2, "{frames} frames");
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let palette: [[u8; 3]; 5] = [
        [255, 255, 255],
        [0, 0, 0],
        [160, 160, 160],
        [30, 60, 200],
        [220, 0, 0],
    ];
    let mut seen = [false; 5];
    for _ in 0..frames {
        seen = [false; 5];
        let info = reader.next_frame(&mut buf).unwrap();
        assert_eq!(info.color_type, png::ColorType::Rgb);
        for px in buf[..info.buffer_size()].chunks_exact(3) {
            let k = palette.iter().position(|c| c == px);
            assert!(k.is_some(), "colour {px:?} is not the figure's");
            seen[k.unwrap()] = true;
        }
    }
    assert_eq!(
        seen, [true; 5],
        "last frame: white, black, grey, track, robot"
    );
}

/// A ROS map given in place of a scenario is explored with the defaults, from a start
/// chosen on the map (said on stderr) or from `--start`; a start in a wall names the flag.
#[test]
fn explore_takes_a_ros_map() {
    let map = repo_file("data/ros_maps/turtlebot3_world/map.yaml");
    let o = hyplan(&["explore", &map]);
    let out = stdout(&o);
    assert_eq!(o.status.code(), Some(0), "{out}{}", stderr(&o));
    assert!(
        stderr(&o).contains("on map.yaml (--start X,Y to choose)"),
        "{}",
        stderr(&o)
    );
    assert!(
        out.contains("explore-map: explored, no frontier left"),
        "{out}"
    );
    let coverage: f64 = out
        .split("coverage ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .and_then(|c| c.parse().ok())
        .unwrap_or_else(|| panic!("no coverage in {out}"));
    assert!(coverage >= 99.9, "{out}");
    let o = hyplan(&["explore", &map, "--start", "0.5,0.5", "--time-limit", "5"]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "stopped by the time limit: {}",
        stderr(&o)
    );
    let o = hyplan(&["explore", &map, "--start", "-1.1,-1.1"]);
    assert_exit(&o, 2, &["--start (-1.1, -1.1): inside an obstacle"]);
}

/// A ROS map given in place of a scenario is driven across, known in advance, from
/// `--start` to `--goal`, which it requires; a goal in a wall names the flag.
#[test]
fn sim_takes_a_ros_map() {
    let map = repo_file("data/ros_maps/turtlebot3_world/map.yaml");
    let o = hyplan(&["sim", &map, "--start", "-0.5,-0.5", "--goal", "0.5,0.5"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stdout(&o).starts_with("nav-map: goal reached in"),
        "{}",
        stdout(&o)
    );
    let o = hyplan(&["sim", &map, "--start", "-0.5,-0.5"]);
    assert_exit(&o, 2, &["a map needs --start X,Y and --goal X,Y"]);
    let o = hyplan(&["sim", &map, "--start", "-0.5,-0.5", "--goal", "-1.1,-1.1"]);
    assert_exit(&o, 2, &["--goal (-1.1, -1.1): inside an obstacle"]);
    let o = hyplan(&[
        "sim",
        &map,
        "--start=-0.5,-0.5",
        "--goal",
        "0.5,0.5",
        "--time-limit",
        "0",
    ]);
    assert_exit(&o, 2, &["--time-limit = 0: must be finite and > 0"]);
}

/// `--crowd D` places people on the map's floor (who react, under social forces unless
/// `--people-model` says otherwise) and reports the crowd's figures; a bad density or a
/// scenario without a map is refused, naming the flag.
#[test]
fn sim_places_a_crowd_on_a_map() {
    let map = repo_file("data/ros_maps/aws_small_house/map.yaml");
    let run = |extra: &[&str]| {
        let mut args = vec!["sim", &map, "--start=-5.02,-2.72", "--goal", "8.775,2.475"];
        args.extend_from_slice(extra);
        hyplan(&args)
    };
    let o = run(&["--crowd", "4", "--seed", "2"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.starts_with("crowd: 4 people on 108 m^2"), "{text}");
    assert!(text.contains("among people:"), "{text}");
    assert!(text.contains("0 at fault"), "{text}");
    assert!(
        text.contains(
            "crowd robot: collision monitor on, waits up to 30 s for people, 270-degree scanner"
        ),
        "{text}"
    );
    // The same seed, the same run.
    assert_eq!(stdout(&run(&["--crowd", "4", "--seed", "2"])), text);
    // The robot's line says what the run does.
    let off = stdout(&run(&[
        "--crowd",
        "4",
        "--seed",
        "2",
        "--collision-monitor",
        "off",
    ]));
    assert!(off.contains("crowd robot: collision monitor off,"), "{off}");
    let o = run(&["--crowd", "-1"]);
    assert_exit(&o, 2, &["--crowd -1", "must be finite and >= 0"]);
    let f = SCRATCH.file("no-map.ron", hall("", "", "(0.5, 1.5)"));
    let o = hyplan(&["sim", &f, "--crowd", "1"]);
    assert_exit(&o, 2, &["--crowd", "has no map"]);
}

/// On a ROS map whose origin has a yaw (the MIT Stata basement's, 3.14 rad) `--start` and
/// `--goal` are metres in the map frame, as for `hyplan plan`, and explore's default
/// start is that frame's origin. Taken as the grid's own frame, these points lay outside
/// the map.
#[test]
fn sim_and_explore_take_map_frame_points_on_a_turned_map() {
    let map = repo_file("data/ros_maps/mit_stata_basement/stata_basement.yaml");
    let o = hyplan(&["sim", &map, "--start=-55.494,34.24", "--goal=-52.5,34.2"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("goal reached"), "{}", stdout(&o));
    let o = hyplan(&["explore", &map, "--time-limit", "2"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("starting at (0.00, 0.00)"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn explore_bad_input_exits_2_naming_the_field() {
    let f = SCRATCH.file("room2.ron", room(""));
    let cases: [(&[&str], &str); 6] = [
        (&["--eta", "-1"], "--eta"),
        (&["--eta", "inf"], "--eta"),
        (&["--fov", "0"], "--fov"),
        (&["--fov", "400"], "--fov"),
        (&["--detector", "sideways"], "--detector"),
        (&["--eta", "NaN"], "--eta"),
    ];
    for (extra, needle) in cases {
        let mut args = vec!["explore", f.as_str()];
        args.extend_from_slice(extra);
        let o = hyplan(&args);
        assert_eq!(o.status.code(), Some(2), "{extra:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(needle), "{extra:?}: {}", stderr(&o));
    }
    let bad = SCRATCH.file(
        "region.ron",
        room("\n    exploration: (region: [(2.0, 0.0), (6.0, 0.0), (6.0, 4.0), (2.0, 4.0)]),"),
    );
    let o = hyplan(&["explore", &bad]);
    assert_exit(&o, 2, &["exploration.region"]);
    let bad = SCRATCH.file(
        "radius.ron",
        room("\n    exploration: (info_radius: -1.0),"),
    );
    let o = hyplan(&["explore", &bad]);
    assert_exit(&o, 2, &["exploration.info_radius"]);
}

/// The cells of a ROS map written by `hyplan sim` / `hyplan explore` as Nav2's trinary
/// rule reads them: `[free, occupied, unknown]`. Checks on the way that the files are what
/// map_saver writes: a YAML in trinary mode with its thresholds, and a binary PGM (`P5`)
/// of 254 / 0 / 205.
fn trinary_counts(yaml: &Path) -> [usize; 3] {
    let text = std::fs::read_to_string(yaml).unwrap();
    for line in [
        "image: map.pgm",
        "mode: trinary",
        "negate: 0",
        "occupied_thresh: 0.65",
        "free_thresh: 0.196",
    ] {
        assert!(text.lines().any(|l| l == line), "{line:?} not in {text}");
    }
    let bytes = std::fs::read(yaml.with_extension("pgm")).unwrap();
    assert!(bytes.starts_with(b"P5\n# CREATOR: hyplan"), "a binary PGM");
    let pic = envmap::read_picture(&yaml.with_extension("pgm")).unwrap();
    assert_eq!(pic.channels(), 1);
    for &v in pic.data() {
        assert!([254, 0, 205].contains(&v), "grey {v} is not map_saver's");
    }
    nav2_counts(pic.data())
}

/// A world whose grids (or map file) exceed the memory limit: exit 2 before anything is
/// allocated, naming the file, the field, its value and the flag that raises the limit;
/// `--max-cells` raises it.
#[test]
fn grids_above_the_memory_limit_exit_2_naming_the_flag() {
    let huge_img = SCRATCH.file("huge_img.pgm", "P5\n30000 30000\n255\n");
    SCRATCH.file(
        "huge.yaml",
        format!(
            "image: {}\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n\
             occupied_thresh: 0.65\nfree_thresh: 0.196\n",
            Path::new(&huge_img).file_name().unwrap().to_string_lossy()
        ),
    );
    let cases: [(&str, String, &[&str]); 5] = [
        (
            "huge_laser.ron",
            hall("", "\n    laser: (beams: 1000000000000),", "(0.5, 1.5)"),
            &[
                "huge_laser.ron",
                "`laser.beams` = 1000000000000",
                "--max-cells 1000000000000",
            ],
        ),
        (
            "huge_world.ron",
            hall("", "", "(0.5, 1.5)").replace("size: (6.0, 3.0)", "size: (1e6, 3.0)"),
            &[
                "huge_world.ron",
                "`world.size` = (1000000, 3)",
                "--max-cells 1200000000",
            ],
        ),
        (
            "tiny_map_res.ron",
            hall("", "\n    mapping: (resolution: 0.0001),", "(0.5, 1.5)"),
            &[
                "tiny_map_res.ron",
                "`mapping.resolution` = 0.0001",
                "60000 x 30000",
                "--max-cells 1800000000",
            ],
        ),
        (
            "tiny_cost_res.ron",
            hall("", "\n    costmap: (resolution: 0.0002),", "(0.5, 1.5)"),
            &[
                "tiny_cost_res.ron",
                "`costmap.resolution` = 0.0002",
                "--max-cells 450000000",
            ],
        ),
        (
            "huge_map.ron",
            hall("", "", "(0.5, 1.5)").replace(
                "world: (size: (6.0, 3.0),",
                "world: (map: Some(Ros(\"huge.yaml\")), size: (6.0, 3.0),",
            ),
            &[
                "huge_map.ron",
                "world.map",
                "huge_img.pgm",
                "30000 x 30000",
                "--max-cells 900000000",
            ],
        ),
    ];
    for (name, text, needles) in cases {
        let f = SCRATCH.file(name, text);
        for cmd in ["sim", "explore"] {
            let o = hyplan(&[cmd, &f]);
            let err = stderr(&o);
            assert_eq!(o.status.code(), Some(2), "{cmd} {name}: {err}");
            for n in needles {
                assert!(err.contains(n), "{cmd} {name}: {n:?} not in {err}");
            }
        }
    }
    // The hall's largest grids are 120 x 60 cells: a limit one below refuses it, naming
    // the value that is enough; that value runs.
    let f = SCRATCH.file("limit.ron", hall("", "", "(0.5, 1.5)"));
    let o = hyplan(&["sim", &f, "--max-cells", "7199"]);
    assert_exit(&o, 2, &["--max-cells 7200"]);
    let o = hyplan(&["sim", &f, "--max-cells", "7200"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let f = SCRATCH.file("limit_room.ron", room(""));
    let o = hyplan(&["explore", &f, "--max-cells", "9599"]);
    assert_exit(&o, 2, &["--max-cells 9600"]);
}
