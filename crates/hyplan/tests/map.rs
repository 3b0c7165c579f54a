//! `hyplan map`: runs the built binary and checks exit codes, stdout and stderr.

use std::path::Path;

use envmap::{GridMap, Picture};
use hyplan_core::Point2;

use crate::common::{
    Scratch, assert_error, assert_exit, hyplan, json, nav2_counts, repo_file, stderr,
};

const SCRATCH: Scratch = Scratch("hyplan_map");

/// `hyplan map FILE --json EXTRA`, which must succeed: its record.
fn map_json(file: &str, extra: &[&str]) -> serde_json::Value {
    let o = hyplan(&[&["map", file, "--json"], extra].concat());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    json(&o)
}

/// A 50 x 40 white picture with two dark boxes, as PNG.
fn picture() -> String {
    let mut pic = Picture::filled_rgb(50, 40, [240, 240, 240]);
    for y in 5..10 {
        for x in 5..15 {
            pic.set_rgb(x, y, [10, 10, 10]);
        }
    }
    for y in 20..30 {
        for x in 30..33 {
            pic.set_rgb(x, y, [50, 60, 70]);
        }
    }
    // One file per call: tests run in parallel, and one rewriting the file while the
    // binary of another reads it made that read fail.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let p = SCRATCH.path(&format!("two_boxes_{n}.png"));
    envmap::write_picture(&pic, &p).unwrap();
    p.display().to_string()
}

#[test]
fn picture_json_counts_zones_and_obstacles() {
    let pic = picture();
    let o = hyplan(&["map", &pic, "--safety-radius", "2", "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v = json(&o);
    assert_eq!(v["width"], 50);
    assert_eq!(v["height"], 40);
    assert_eq!(v["forbidden"], 50 + 30);
    let total = v["free"].as_u64().unwrap() + v["risk"].as_u64().unwrap() + 80;
    assert_eq!(total, 2000);
    assert!(v["risk"].as_u64().unwrap() > 0);
    assert_eq!(v["obstacles"].as_array().unwrap().len(), 2);
    // The first box in the input frame (y down): x in [5, 15), y in [5, 10).
    let boxes: Vec<_> = v["obstacles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|o| (&o["min"], &o["max"]))
        .collect();
    assert!(
        boxes
            .iter()
            .any(|(a, b)| **a == serde_json::json!([5.0, 5.0])
                && **b == serde_json::json!([15.0, 10.0])),
        "{boxes:?}"
    );
    assert_eq!(v["resolution"], 1.0);
    assert_eq!(v["origin"], serde_json::json!([0.0, 0.0]));
}

#[test]
fn picture_defaults_follow_the_seed_and_summary_is_human() {
    let pic = picture();
    let o = hyplan(&["map", &pic]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("50 x 40 cells"), "{out}");
    assert!(out.contains("obstacles: 2"), "{out}");
    // Default radius 20 cells: the 50 x 40 picture is mostly high-risk.
    let v = map_json(&pic, &[]);
    let with_default = v["risk"].as_u64().unwrap();
    let v20 = map_json(&pic, &["--safety-radius", "20"]);
    assert_eq!(with_default, v20["risk"].as_u64().unwrap());
    // --invert makes the background the obstacle.
    let inv = map_json(&pic, &["--invert", "--safety-radius", "0"]);
    assert_eq!(inv["forbidden"], 2000 - 80);
}

/// `hyplan map` on `pic` with a 3-cell band, writing the zone picture to `out` and the ROS
/// pair to `yaml`, with or without `--rectangles`: its record.
fn write_zones(pic: &str, out: &Path, yaml: &Path, rectangles: bool) -> serde_json::Value {
    let mut extra = vec![
        "--safety-radius",
        "3",
        "--out",
        out.to_str().unwrap(),
        "--yaml",
        yaml.to_str().unwrap(),
    ];
    if rectangles {
        extra.push("--rectangles");
    }
    map_json(pic, &extra)
}

#[test]
fn rectangles_and_writers() {
    let pic = picture();
    let out = SCRATCH.path("zones.png");
    let yaml = SCRATCH.path("zones.yaml");
    let v = write_zones(&pic, &out, &yaml, true);
    assert_eq!(v["obstacle_shape"], "rectangles");
    let zones = envmap::read_picture(&out).unwrap();
    assert_eq!((zones.width(), zones.height()), (50, 40));
    assert_eq!(zones.pixel(5, 5), &envmap::RECTANGLE_COLOUR);
    // The ROS pair loads back to the same counts.
    let back = map_json(yaml.to_str().unwrap(), &[]);
    for key in ["free", "risk", "forbidden", "width", "height"] {
        assert_eq!(back[key], v[key], "{key}");
    }
    assert_eq!(back["frame"], "world_y_up");
}

#[test]
fn repository_data_maps() {
    let arena = repo_file("data/movingai/arena.map");
    let ros = repo_file("data/ros_maps/turtlebot3_world/map.yaml");
    let v = map_json(&arena, &[]);
    assert_eq!(
        (v["width"].as_u64(), v["height"].as_u64()),
        (Some(49), Some(49))
    );
    assert_eq!(v["free"], 2054);
    assert_eq!(v["risk"], 0);
    assert_eq!(v["frame"], "cells_y_down");
    let v = map_json(&ros, &[]);
    assert_eq!(v["free"], 7939);
    assert_eq!(v["forbidden"], 795 + 138722);
    assert_eq!(v["resolution"], 0.05);
    assert_eq!(v["origin"], serde_json::json!([-10.0, -10.0]));
    let v = map_json(&ros, &["--unknown-free"]);
    assert_eq!(v["forbidden"], 795);
    // 0.1 m = 2 cells of band around the 795 occupied cells.
    let v = map_json(&ros, &["--unknown-free", "--safety-radius", "0.1"]);
    assert!(v["risk"].as_u64().unwrap() > 795);
}

#[test]
fn errors_name_the_file_and_exit_2() {
    assert_error(&hyplan(&["map", "/no/such/map.png"]), &["/no/such/map.png"]);
    assert_error(
        &hyplan(&["map", "/no/such/map.yaml"]),
        &["/no/such/map.yaml"],
    );
    let text = SCRATCH.file("not_an_image.png", b"hello");
    assert_error(
        &hyplan(&["map", &text]),
        &["not_an_image.png", "not a readable image"],
    );
    let empty = SCRATCH.file("empty.pgm", b"P5\n0 0\n255\n");
    assert_error(&hyplan(&["map", &empty]), &["empty.pgm"]);
    let map = SCRATCH.file(
        "short.map",
        b"type octile\nheight 3\nwidth 2\nmap\n..\n..\n",
    );
    assert_error(
        &hyplan(&["map", &map]),
        &["short.map", "2 rows", "height 3"],
    );
    let map = SCRATCH.file(
        "ragged.map",
        b"type octile\nheight 2\nwidth 2\nmap\n..\n...\n",
    );
    assert_error(&hyplan(&["map", &map]), &["ragged.map:6", "width 2"]);
    let map = SCRATCH.file("nomap.map", b"type octile\nheight 2\nwidth 2\n");
    assert_error(&hyplan(&["map", &map]), &["nomap.map", "no `map` line"]);
    let good = "image: x.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n\
                occupied_thresh: 0.65\nfree_thresh: 0.196\n";
    let y = SCRATCH.file(
        "nores.yaml",
        good.replace("resolution: 0.05\n", "").as_bytes(),
    );
    assert_error(
        &hyplan(&["map", &y]),
        &["nores.yaml", "`resolution`", "missing"],
    );
    let y = SCRATCH.file("negres.yaml", good.replace("0.05", "-0.05").as_bytes());
    assert_error(
        &hyplan(&["map", &y]),
        &["negres.yaml", "`resolution`", "-0.05"],
    );
    let y = SCRATCH.file("thresh.yaml", good.replace("0.65", "1.65").as_bytes());
    assert_error(
        &hyplan(&["map", &y]),
        &["thresh.yaml", "`occupied_thresh`", "1.65"],
    );
    let y = SCRATCH.file("noimg.yaml", good.as_bytes());
    assert_error(&hyplan(&["map", &y]), &["x.pgm"]);
    let pic = picture();
    assert_error(
        &hyplan(&["map", &pic, "--safety-radius", "-1"]),
        &["safety_radius", "-1"],
    );
    let bad_out = "/no/such/dir/zones.png";
    assert_error(&hyplan(&["map", &pic, "--out", bad_out]), &[bad_out]);
}

#[test]
fn yaml_out_round_trips_through_the_library() {
    let map = GridMap::from_ascii("#~..\n....")
        .unwrap()
        .with_frame(0.5, Point2::new(1.0, -2.0))
        .unwrap();
    let yaml = SCRATCH.path("lib.yaml");
    envmap::write_ros(&map, &yaml).unwrap();
    let v = map_json(yaml.to_str().unwrap(), &[]);
    assert_eq!(
        (
            v["free"].as_u64(),
            v["risk"].as_u64(),
            v["forbidden"].as_u64()
        ),
        (Some(6), Some(1), Some(1))
    );
    assert_eq!(v["origin"], serde_json::json!([1.0, -2.0]));
}

/// A map above the memory limit is refused with exit 2, its size, the limit and the flag
/// that raises it, whatever its format; `hyplan plan` says the same.
#[test]
fn maps_above_the_memory_limit_name_size_limit_and_flag() {
    let n = 30_000;
    let pgm = SCRATCH.file("huge.pgm", format!("P5\n{n} {n}\n255\n").as_bytes());
    let map = SCRATCH.file(
        "huge.map",
        format!("type octile\nheight {n}\nwidth {n}\nmap\n").as_bytes(),
    );
    SCRATCH.file("huge_img.pgm", format!("P5\n{n} {n}\n255\n").as_bytes());
    let yaml = SCRATCH.file(
        "huge.yaml",
        b"image: huge_img.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n\
          occupied_thresh: 0.65\nfree_thresh: 0.196\n",
    );
    for file in [&pgm, &map, &yaml] {
        for args in [
            vec!["map", file.as_str()],
            vec![
                "plan",
                "--map",
                file.as_str(),
                "--start",
                "1,1",
                "--goal",
                "5,5",
            ],
        ] {
            let o = hyplan(&args);
            let e = stderr(&o);
            assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
            assert!(e.contains("30000 x 30000"), "{e}");
            assert!(e.contains("limit of 100000000 cells"), "{e}");
            assert!(e.contains("--max-cells 900000000"), "{e}");
            assert_eq!(e.trim().lines().count(), 1, "{e}");
        }
    }
    // The flag lowers the limit too.
    let o = hyplan(&["map", &picture(), "--max-cells", "100"]);
    assert_exit(&o, 2, &["50 x 40 = 2000 cells"]);
}

/// `--out X.pgm` and `--yaml` write binary PGM (`P5`, what Pillow and map_server read),
/// and Nav2's trinary rule on their grey levels gives back the zones `--json` counts:
/// safe free, forbidden occupied, high-risk unknown (for `--yaml`: between the thresholds,
/// a graded cost in its scale mode). With `--rectangles`, the blue outlines lie on
/// forbidden cells and read as occupied too.
#[test]
fn pgm_outputs_are_p5_and_read_back_by_nav2s_rule() {
    let pic = picture();
    for rectangles in [false, true] {
        let out = SCRATCH.path(&format!("zones_{rectangles}.pgm"));
        let yaml = SCRATCH.path(&format!("zones_ros_{rectangles}.yaml"));
        let v = write_zones(&pic, &out, &yaml, rectangles);
        let want = [&v["free"], &v["forbidden"], &v["risk"]].map(|x| x.as_u64().unwrap() as usize);
        assert!(want.iter().all(|&n| n > 0), "{want:?}");
        let yaml_text = std::fs::read_to_string(&yaml).unwrap();
        assert!(yaml_text.lines().any(|l| l == "mode: scale"), "{yaml_text}");
        for file in [out.clone(), yaml.with_extension("pgm")] {
            let bytes = std::fs::read(&file).unwrap();
            assert!(bytes.starts_with(b"P5\n"), "{}: not P5", file.display());
            let grey = envmap::read_picture(&file).unwrap();
            assert_eq!((grey.width(), grey.height(), grey.channels()), (50, 40, 1));
            let n = nav2_counts(grey.data());
            assert_eq!(n, want, "{}: [free, occupied, unknown]", file.display());
        }
    }
}

/// A ROS map whose origin has a yaw (the MIT Stata basement's, 3.14 rad) comes back out
/// turned as it went in: `hyplan map --yaml` writes the yaw again and `hyplan plan --mcap`
/// writes the map's origin pose with it, so a query in the input's map frame plans the
/// same path on the input and on either output. Written with yaw 0, the same query lay
/// off both outputs' maps.
#[test]
fn a_turned_ros_map_stays_turned() {
    let input = repo_file("data/ros_maps/mit_stata_basement/stata_basement.yaml");
    let yaml = SCRATCH.path("stata_again.yaml");
    let mcap = SCRATCH.path("stata_plan.mcap");
    let o = hyplan(&["map", &input, "--yaml", yaml.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&yaml).unwrap();
    assert!(text.contains("origin: [25.9, 48.5, 3.14]"), "{text}");
    let plan = |map: &str, extra: &[&str]| {
        let q = [
            "plan",
            "--map",
            map,
            "--start",
            "-55.494,34.24",
            "--goal",
            "25.291,-1.622",
            "--planner",
            "jps",
            "--json",
        ];
        let o = hyplan(&[&q[..], extra].concat());
        assert_eq!(o.status.code(), Some(0), "{map}: {}", stderr(&o));
        json(&o)["length"].as_f64().unwrap()
    };
    let length = plan(&input, &["--mcap", mcap.to_str().unwrap()]);
    assert!((length - 113.446).abs() < 1e-3, "{length}");
    assert_eq!(plan(yaml.to_str().unwrap(), &[]), length);
    assert_eq!(plan(mcap.to_str().unwrap(), &[]), length);
}
