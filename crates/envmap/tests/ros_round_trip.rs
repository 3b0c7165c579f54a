//! Writing a ROS map and loading it back gives the same map; the files are what ROS tools
//! read: a binary PGM (`P5`) that a hand-written netpbm reader decodes, and cells that
//! Nav2's rules classify as written.

use envmap::{
    GridMap, LoadOptions, MapKind, Occupancy, Picture, RosMode, load_map, write_picture, write_ros,
    write_ros_occupancy,
};
use hyplan_core::{Point2, Zone};
use proptest::prelude::*;

fn tmp(name: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("envmap_ros");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// A netpbm reader written from the format's definition (netpbm's `pgm(5)` / `ppm(5)`),
/// independent of the `image` crate: magic, then width, height and maxval separated by
/// whitespace with `#` comments to the end of a line, one whitespace byte, the samples.
/// Returns (magic, width, height, samples).
fn read_pnm(bytes: &[u8]) -> (String, usize, usize, Vec<u8>) {
    let magic = String::from_utf8(bytes[..2].to_vec()).unwrap();
    let mut k = 2;
    let mut fields = Vec::new();
    while fields.len() < 3 {
        match bytes[k] {
            b'#' => {
                while bytes[k] != b'\n' {
                    k += 1;
                }
            }
            b if b.is_ascii_whitespace() => k += 1,
            _ => {
                let start = k;
                while bytes[k].is_ascii_digit() {
                    k += 1;
                }
                let s = std::str::from_utf8(&bytes[start..k]).unwrap();
                fields.push(s.parse::<usize>().unwrap());
            }
        }
    }
    assert!(
        bytes[k].is_ascii_whitespace(),
        "one whitespace byte after maxval"
    );
    let (w, h, maxval) = (fields[0], fields[1], fields[2]);
    assert_eq!(maxval, 255);
    (magic, w, h, bytes[k + 1..].to_vec())
}

/// Nav2's `loadMapFromFile` for one grey value: `occ = (255 - v) / 255`; `Some(100)`
/// occupied when `occ > occupied`, `Some(0)` free when `occ < free`, else `None` (unknown
/// in trinary mode, a graded cost in scale mode).
fn nav2(v: u8, occupied: f64, free: f64) -> Option<u8> {
    let occ = (255.0 - f64::from(v)) / 255.0;
    if occ > occupied {
        Some(100)
    } else if occ < free {
        Some(0)
    } else {
        None
    }
}

/// The PGM of `yaml` (same stem), decoded by [`read_pnm`]: (width, height, rows top first).
fn pgm_of(yaml: &std::path::Path) -> (usize, usize, Vec<u8>) {
    let bytes = std::fs::read(yaml.with_extension("pgm")).unwrap();
    assert!(bytes.starts_with(b"P5\n# CREATOR: hyplan"), "P5 header");
    let (magic, w, h, data) = read_pnm(&bytes);
    assert_eq!(magic, "P5");
    assert_eq!(data.len(), w * h, "one byte per pixel, nothing after");
    (w, h, data)
}

fn occupancy() -> impl Strategy<Value = Occupancy> {
    prop_oneof![
        Just(Occupancy::Free),
        Just(Occupancy::Occupied),
        Just(Occupancy::Unknown)
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn ros_yaml_pgm_round_trip(
        (w, h, zones, res, ox, oy) in (1usize..30, 1usize..30).prop_flat_map(|(w, h)| (
            Just(w), Just(h),
            proptest::collection::vec(prop_oneof![Just(Zone::Free), Just(Zone::Risk), Just(Zone::Forbidden)], w * h),
            0.001..10.0f64, -100.0..100.0f64, -100.0..100.0f64,
        ))
    ) {
        let map = GridMap::from_zones(w, h, res, Point2::new(ox, oy), zones).unwrap();
        let path = tmp(&format!("rt_{w}_{h}.yaml"));
        write_ros(&map, &path).unwrap();
        let back = load_map(&path, &LoadOptions::default()).unwrap();
        prop_assert_eq!(back.kind, MapKind::Ros);
        prop_assert_eq!(back.map.resolution(), res);
        prop_assert_eq!(back.map.origin(), Point2::new(ox, oy));
        prop_assert_eq!(&back.map, &map);
        // Nav2's rule on the bytes: safe free, forbidden occupied, high-risk between the
        // thresholds (a graded cost in scale mode, unknown in trinary mode).
        let (pw, ph, data) = pgm_of(&path);
        prop_assert_eq!((pw, ph), (w, h));
        for j in 0..h {
            for i in 0..w {
                let want = match map.cell_zone(i, j) {
                    Zone::Free => Some(0),
                    Zone::Forbidden => Some(100),
                    Zone::Risk => None,
                };
                prop_assert_eq!(nav2(data[(h - 1 - j) * w + i], 0.65, 0.196), want);
            }
        }
    }

    /// An occupancy grid (the simulator's built map) comes back cell for cell under
    /// Nav2's trinary rule, and through `load_map` with unknown cells forbidden (the
    /// default) or free (`unknown_free`).
    #[test]
    fn occupancy_round_trip(
        (w, h, cells, res, ox, oy) in (1usize..30, 1usize..30).prop_flat_map(|(w, h)| (
            Just(w), Just(h),
            proptest::collection::vec(occupancy(), w * h),
            0.001..10.0f64, -100.0..100.0f64, -100.0..100.0f64,
        ))
    ) {
        let path = tmp(&format!("occ_{w}_{h}.yaml"));
        write_ros_occupancy(&cells, w, h, res, Point2::new(ox, oy), &path).unwrap();
        let meta = envmap::read_ros_yaml(&path).unwrap();
        prop_assert_eq!(meta.mode, RosMode::Trinary);
        prop_assert_eq!((meta.occupied_thresh, meta.free_thresh), (0.65, 0.196));
        prop_assert!(!meta.negate);
        prop_assert_eq!(meta.resolution, res);
        prop_assert_eq!(meta.origin, Point2::new(ox, oy));
        let (pw, ph, data) = pgm_of(&path);
        prop_assert_eq!((pw, ph), (w, h));
        for j in 0..h {
            for i in 0..w {
                let (v, want) = match cells[j * w + i] {
                    Occupancy::Free => (254, Some(0)),
                    Occupancy::Occupied => (0, Some(100)),
                    Occupancy::Unknown => (205, None),
                };
                let px = data[(h - 1 - j) * w + i];
                prop_assert_eq!(px, v);
                prop_assert_eq!(nav2(px, meta.occupied_thresh, meta.free_thresh), want);
            }
        }
        for unknown_free in [false, true] {
            let opts = LoadOptions { unknown_free, ..LoadOptions::default() };
            let back = load_map(&path, &opts).unwrap().map;
            prop_assert_eq!((back.width(), back.height()), (w, h));
            prop_assert_eq!(back.resolution(), res);
            prop_assert_eq!(back.origin(), Point2::new(ox, oy));
            for j in 0..h {
                for i in 0..w {
                    let want = match cells[j * w + i] {
                        Occupancy::Free => Zone::Free,
                        Occupancy::Occupied => Zone::Forbidden,
                        Occupancy::Unknown if unknown_free => Zone::Free,
                        Occupancy::Unknown => Zone::Forbidden,
                    };
                    prop_assert_eq!(back.cell_zone(i, j), want);
                }
            }
        }
    }
}

#[test]
fn written_yaml_names_its_pgm_and_scale_mode() {
    let map = GridMap::from_ascii("#~.")
        .unwrap()
        .with_frame(0.05, Point2::new(-1.0, 2.5))
        .unwrap();
    let path = tmp("named map.yaml");
    write_ros(&map, &path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    for line in [
        "mode: scale",
        "negate: 0",
        "occupied_thresh: 0.65",
        "free_thresh: 0.196",
        "resolution: 0.05",
        "origin: [-1.0, 2.5, 0.0]",
    ] {
        assert!(text.lines().any(|l| l == line), "{line:?} not in {text}");
    }
    let meta = envmap::read_ros_yaml(&path).unwrap();
    assert_eq!(meta.image, path.with_extension("pgm"));
    // map_saver's header layout; rows top (highest y) first.
    let bytes = std::fs::read(path.with_extension("pgm")).unwrap();
    let mut want = format!(
        "P5\n# CREATOR: hyplan {} 0.05 m/pix\n3 1\n255\n",
        env!("CARGO_PKG_VERSION")
    )
    .into_bytes();
    want.extend_from_slice(&[0, 128, 254]);
    assert_eq!(bytes, want);
}

#[test]
fn occupancy_writer_rows_top_first_and_refuses_bad_sizes() {
    let (f, o, u) = (Occupancy::Free, Occupancy::Occupied, Occupancy::Unknown);
    // Bottom row first: [f, o], then the top row [u, u].
    let path = tmp("occ_rows.yaml");
    write_ros_occupancy(&[f, o, u, u], 2, 2, 0.5, Point2::new(1.0, 2.0), &path).unwrap();
    let (_, _, data) = pgm_of(&path);
    assert_eq!(data, [205, 205, 254, 0]);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.lines().any(|l| l == "mode: trinary"), "{text}");
    assert!(
        text.lines().any(|l| l == "origin: [1.0, 2.0, 0.0]"),
        "{text}"
    );
    for (cells, w, h, res) in [
        (&[f, o, u][..], 2, 2, 0.5),
        (&[][..], 0, 0, 0.5),
        (&[f][..], 1, 1, 0.0),
        (&[f][..], 1, 1, f64::NAN),
    ] {
        let e = write_ros_occupancy(cells, w, h, res, Point2::origin(), &tmp("bad.yaml"));
        assert!(
            matches!(e, Err(envmap::MapError::InvalidParameter { .. })),
            "{e:?}"
        );
    }
}

/// `write_picture` writes netpbm itself (the `image` crate's encoder writes PAM): `.pgm`
/// is `P5` (an RGB picture as its rounded channel means), `.ppm` is `P6`, and our reader
/// loads both back.
#[test]
fn pictures_as_pgm_and_ppm() {
    let mut rgb = Picture::filled_rgb(3, 2, [255, 255, 255]);
    rgb.set_rgb(0, 0, [0, 0, 255]);
    rgb.set_rgb(1, 0, [160, 160, 160]);
    rgb.set_rgb(2, 1, [1, 1, 2]);
    let pgm = tmp("picture.pgm");
    write_picture(&rgb, &pgm).unwrap();
    let (magic, w, h, data) = read_pnm(&std::fs::read(&pgm).unwrap());
    assert_eq!((magic.as_str(), w, h), ("P5", 3, 2));
    assert_eq!(data, [85, 160, 255, 255, 255, 1]);
    let back = envmap::read_picture(&pgm).unwrap();
    assert_eq!((back.channels(), back.data()), (1, data.as_slice()));

    let ppm = tmp("picture.PPM");
    write_picture(&rgb, &ppm).unwrap();
    let (magic, w, h, data) = read_pnm(&std::fs::read(&ppm).unwrap());
    assert_eq!((magic.as_str(), w, h), ("P6", 3, 2));
    assert_eq!(data, rgb.data());
    assert_eq!(envmap::read_picture(&ppm).unwrap().data(), rgb.data());

    let grey = Picture::grey(2, 1, vec![7, 200]).unwrap();
    let ppm = tmp("grey.ppm");
    write_picture(&grey, &ppm).unwrap();
    let (magic, _, _, data) = read_pnm(&std::fs::read(&ppm).unwrap());
    assert_eq!((magic.as_str(), data), ("P6", vec![7, 7, 7, 200, 200, 200]));
}
