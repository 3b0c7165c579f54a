//! Bad input gives typed errors naming the file and the field or line, never a panic.

use std::path::{Path, PathBuf};

use envmap::{LoadOptions, MapError, load_map, parse_movingai, parse_ros_yaml};

fn tmp_file(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("envmap_errors");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

const GOOD_YAML: &str = "image: map.pgm\nresolution: 0.05\norigin: [-10.0, -10.0, 0.0]\n\
                         negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";

fn yaml_error(yaml: &str) -> MapError {
    parse_ros_yaml(yaml.as_bytes(), Path::new("bad.yaml")).unwrap_err()
}

fn field_of(e: &MapError) -> &'static str {
    match e {
        MapError::Field { field, .. } => field,
        other => panic!("expected a field error, got {other:?}"),
    }
}

#[test]
#[cfg(feature = "image")]
fn missing_file_names_the_file() {
    let e = load_map(Path::new("/no/such/file.png"), &LoadOptions::default()).unwrap_err();
    assert!(matches!(e, MapError::Read { .. }), "{e:?}");
    assert!(e.to_string().contains("/no/such/file.png"));
    let e = load_map(Path::new("/no/such/file.map"), &LoadOptions::default()).unwrap_err();
    assert!(matches!(e, MapError::Read { .. }));
    let e = load_map(Path::new("/no/such/file.yaml"), &LoadOptions::default()).unwrap_err();
    assert!(matches!(e, MapError::Read { .. }));
}

#[test]
#[cfg(feature = "image")]
fn not_an_image() {
    let p = tmp_file("text.png", b"this is not a picture");
    let e = envmap::read_picture(&p).unwrap_err();
    assert!(matches!(e, MapError::Decode { .. }), "{e:?}");
    assert!(e.to_string().contains("text.png"));
}

#[test]
#[cfg(feature = "image")]
fn zero_size_image() {
    let p = tmp_file("empty.pgm", b"P5\n0 0\n255\n");
    let e = envmap::read_picture(&p).unwrap_err();
    assert!(
        matches!(e, MapError::EmptyImage { .. } | MapError::Decode { .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("empty.pgm"));
}

#[test]
fn yaml_missing_and_out_of_range_fields() {
    assert!(parse_ros_yaml(GOOD_YAML.as_bytes(), Path::new("ok.yaml")).is_ok());
    let drop = |key: &str| {
        GOOD_YAML
            .lines()
            .filter(|l| !l.starts_with(key))
            .collect::<Vec<_>>()
            .join("\n")
    };
    for key in [
        "image",
        "resolution",
        "origin",
        "occupied_thresh",
        "free_thresh",
    ] {
        let e = yaml_error(&drop(key));
        assert_eq!(field_of(&e), key);
        assert!(e.to_string().contains("missing"), "{e}");
        assert!(e.to_string().contains("bad.yaml"), "{e}");
    }
    let e = yaml_error(&GOOD_YAML.replace("resolution: 0.05", "resolution: -0.05"));
    assert_eq!(field_of(&e), "resolution");
    assert!(e.to_string().contains("-0.05"), "{e}");
    let e = yaml_error(&GOOD_YAML.replace("occupied_thresh: 0.65", "occupied_thresh: 1.5"));
    assert_eq!(field_of(&e), "occupied_thresh");
    let e = yaml_error(&GOOD_YAML.replace("free_thresh: 0.196", "free_thresh: -0.1"));
    assert_eq!(field_of(&e), "free_thresh");
    // A yaw is accepted (issue 16); a wrong origin is quoted on one line.
    let meta = parse_ros_yaml(
        GOOD_YAML.replace("0.0]", "0.5]").as_bytes(),
        Path::new("y.yaml"),
    );
    assert_eq!(meta.unwrap().yaw, 0.5);
    let e = yaml_error(&GOOD_YAML.replace("-10.0, -10.0, 0.0]", "1.5, 2]"));
    assert_eq!(field_of(&e), "origin");
    assert!(
        e.to_string().contains("= [1.5, 2]: expected [x, y, yaw]"),
        "{e}"
    );
    assert!(!e.to_string().contains('\n'), "{e}");
    let e = yaml_error(&GOOD_YAML.replace("negate: 0", "negate: 2"));
    assert_eq!(field_of(&e), "negate");
    let e = yaml_error(&format!("{GOOD_YAML}mode: fancy\n"));
    assert_eq!(field_of(&e), "mode");
    let e = yaml_error("image: [unclosed");
    assert!(matches!(e, MapError::Yaml { .. }), "{e:?}");
    let e = yaml_error("- just\n- a list\n");
    assert!(matches!(e, MapError::Field { .. }), "{e:?}");
}

#[test]
#[cfg(feature = "image")]
fn yaml_with_a_missing_image_names_the_image() {
    let p = tmp_file(
        "noimage.yaml",
        GOOD_YAML.replace("map.pgm", "nowhere.pgm").as_bytes(),
    );
    let e = load_map(&p, &LoadOptions::default()).unwrap_err();
    assert!(matches!(e, MapError::Read { .. }), "{e:?}");
    assert!(e.to_string().contains("nowhere.pgm"), "{e}");
}

fn map_error(text: &str) -> (usize, String) {
    match parse_movingai(text.as_bytes(), Path::new("bad.map")).unwrap_err() {
        MapError::Line { line, reason, path } => {
            assert_eq!(path, Path::new("bad.map"));
            (line, reason)
        }
        other => panic!("expected a line error, got {other:?}"),
    }
}

#[test]
fn movingai_malformed_files() {
    let (line, reason) = map_error("type octile\nheight 2\nwidth 3\n...\n...\n");
    assert!(
        reason.contains("unexpected header line"),
        "{line}: {reason}"
    );
    assert_eq!(line, 4);
    let (_, reason) = map_error("type octile\nheight 2\nwidth 3\n");
    assert!(reason.contains("no `map` line"), "{reason}");
    let (line, reason) = map_error("type octile\nheight 2\nwidth 3\nmap\n...\n..\n");
    assert_eq!(line, 6);
    assert!(reason.contains("width 3"), "{reason}");
    let (_, reason) = map_error("type octile\nheight 3\nwidth 3\nmap\n...\n...\n");
    assert!(
        reason.contains("2 rows") && reason.contains("height 3"),
        "{reason}"
    );
    let (line, reason) = map_error("type octile\nheight 1\nwidth 3\nmap\n...\n...\n");
    assert_eq!(line, 6);
    assert!(reason.contains("more than"), "{reason}");
    let (line, reason) = map_error("type octile\nheight x\nwidth 3\nmap\n");
    assert_eq!(line, 2);
    assert!(reason.contains("\"x\""), "{reason}");
    let (_, reason) = map_error("type octile\nwidth 3\nmap\n...\n");
    assert!(reason.contains("height"), "{reason}");
    // Large header, tiny file: an error, not an allocation.
    let (_, reason) = map_error("type octile\nheight 10000\nwidth 10000\nmap\n...\n");
    assert!(reason.contains("width"), "{reason}");
    // Above the memory limit: refused from the header, naming the size and the limit.
    let e = parse_movingai(
        b"type octile\nheight 100000000\nwidth 100000000\nmap\n...\n",
        Path::new("bad.map"),
    )
    .unwrap_err();
    assert!(matches!(e, MapError::TooLarge { .. }), "{e:?}");
    assert!(e.to_string().contains("100000000 x 100000000"), "{e}");
}

#[test]
fn movingai_tolerates_crlf_and_trailing_blank_lines() {
    let map = parse_movingai(
        b"type octile\r\nheight 1\r\nwidth 2\r\nmap\r\n.@\r\n\r\n",
        Path::new("ok.map"),
    )
    .unwrap();
    assert_eq!(map.zone_counts(), [1, 0, 1]);
}

#[test]
fn negative_safety_radius_is_rejected() {
    let p = tmp_file("tiny.map", b"type octile\nheight 1\nwidth 1\nmap\n.\n");
    let e = load_map(
        &p,
        &LoadOptions {
            safety_radius: Some(-1.0),
            ..LoadOptions::default()
        },
    )
    .unwrap_err();
    assert!(
        matches!(
            e,
            MapError::InvalidParameter {
                name: "safety_radius",
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn yaml_accepts_integers_booleans_and_modes() {
    let yaml = "image: /abs/map.png\nresolution: 1\norigin: [0, -3, 0]\nnegate: true\n\
                occupied_thresh: 1\nfree_thresh: 0\nmode: raw\n";
    let meta = parse_ros_yaml(yaml.as_bytes(), Path::new("dir/int.yaml")).unwrap();
    assert_eq!(meta.resolution, 1.0);
    assert_eq!(meta.origin, hyplan_core::Point2::new(0.0, -3.0));
    assert!(meta.negate);
    assert_eq!(meta.mode, envmap::RosMode::Raw);
    assert_eq!(meta.image, Path::new("/abs/map.png"));
    // Raw mode: the value is a percentage.
    assert_eq!(meta.classify(0.0), envmap::RosCell::Free);
    assert_eq!(meta.classify(100.0), envmap::RosCell::Occupied);
    assert_eq!(meta.classify(50.0), envmap::RosCell::Graded);
    assert_eq!(meta.classify(255.0), envmap::RosCell::Unknown);
}
