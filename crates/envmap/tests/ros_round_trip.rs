//! Writing a ROS map and loading it back gives the same map.

use envmap::{GridMap, LoadOptions, MapKind, load_map, write_ros};
use hyplan_core::{Point2, Zone};
use proptest::prelude::*;

fn tmp(name: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("envmap_ros");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
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
        prop_assert_eq!(back.map, map);
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
    assert!(text.contains("mode: scale"), "{text}");
    assert!(path.with_extension("pgm").exists());
    let meta = envmap::read_ros_yaml(&path).unwrap();
    assert_eq!(meta.image, path.with_extension("pgm"));
}
