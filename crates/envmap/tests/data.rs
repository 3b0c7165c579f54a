//! The repository's data maps load with the sizes and counts `data/README.md` gives.

use std::path::{Path, PathBuf};

use envmap::{
    InputFrame, LoadOptions, MapKind, load_map, read_movingai, read_picture, read_ros_yaml,
    ros_cell_counts,
};
use hyplan_core::{Point2, Zone};

/// The repository's `data` folder (public maps with their licences).
fn data(rel: &str) -> PathBuf {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../data")
        .join(rel);
    // Missing data fails the test, naming the path: a test never passes without its input.
    assert!(p.exists(), "test data missing: {}", p.display());
    p
}

#[test]
fn arena_has_2054_passable_cells() {
    let path = data("movingai/arena.map");
    let map = read_movingai(&path).unwrap();
    assert_eq!((map.width(), map.height()), (49, 49));
    assert_eq!(map.zone_counts(), [2054, 0, 49 * 49 - 2054]);
    // Row 0 of the file is the top row of the map.
    let text = std::fs::read_to_string(&path).unwrap();
    let first_row = text.lines().skip_while(|l| *l != "map").nth(1).unwrap();
    for (i, c) in first_row.chars().enumerate() {
        assert_eq!(map.cell_zone(i, 48) == Zone::Free, c == '.', "column {i}");
    }
}

#[test]
fn arena_through_load_map_uses_the_cell_frame() {
    let path = data("movingai/arena.map");
    let loaded = load_map(&path, &LoadOptions::default()).unwrap();
    assert_eq!(loaded.kind, MapKind::MovingAi);
    assert_eq!(loaded.map.zone_counts(), [2054, 0, 49 * 49 - 2054]);
    assert_eq!(
        loaded.frame,
        InputFrame::Cells {
            height: 49,
            resolution: 1.0,
            origin: Point2::origin()
        }
    );
    // Input cell (x, y) = (3, 0) is the top row: map cell (3, 48).
    let p = loaded.frame.to_world(3.5, 0.5);
    assert_eq!(loaded.map.world_to_cell(p), Some((3, 48)));
}

#[test]
fn turtlebot3_world_counts_match_map_server() {
    let path = data("ros_maps/turtlebot3_world/map.yaml");
    let meta = read_ros_yaml(&path).unwrap();
    assert_eq!(meta.resolution, 0.05);
    assert_eq!(meta.origin, Point2::new(-10.0, -10.0));
    let pic = read_picture(&meta.image).unwrap();
    assert_eq!((pic.width(), pic.height()), (384, 384));
    // [free, graded, occupied, unknown]
    assert_eq!(ros_cell_counts(&meta, &pic), [7939, 0, 795, 138722]);

    let loaded = load_map(&path, &LoadOptions::default()).unwrap();
    assert_eq!(loaded.frame, InputFrame::World);
    assert_eq!(loaded.map.zone_counts(), [7939, 0, 795 + 138722]);
    assert_eq!(loaded.map.origin(), Point2::new(-10.0, -10.0));
    assert_eq!(loaded.map.resolution(), 0.05);
    let free = load_unknown_as(&path, true);
    assert_eq!(free.map.zone_counts(), [7939 + 138722, 0, 795]);
}

#[test]
fn turtlebot3_pixel_rows_are_flipped() {
    let path = data("ros_maps/turtlebot3_world/map.yaml");
    let meta = read_ros_yaml(&path).unwrap();
    let pic = read_picture(&meta.image).unwrap();
    let loaded = load_unknown_as(&path, false);
    // Map cell (i, j) is image pixel (i, 383 - j).
    for (x, y) in [(0, 0), (200, 150), (383, 383), (190, 200)] {
        let occupied = pic.pixel(x, y)[0] == 0;
        assert_eq!(
            loaded.map.cell_zone(x, 383 - y) == Zone::Forbidden && pic.pixel(x, y)[0] != 205,
            occupied,
            "pixel ({x}, {y})"
        );
    }
    assert!(Path::new(&meta.image).ends_with("map.pgm"));
}

/// The bounded inflation equals the full transform's costs on maps we did not draw: the
/// TurtleBot3 world's walls and pillars (occupied pixels only, and with the unknown
/// outside as obstacles too) and the MovingAI arena, with Nav2's default radii and
/// sim's costmap parameters.
#[test]
fn inflate_equals_the_full_costs_on_the_shared_maps() {
    use envmap::{Inflation, Mask, distance_transform};
    let mut masks: Vec<(Mask, f64)> = Vec::new();
    let path = data("ros_maps/turtlebot3_world/map.yaml");
    let meta = read_ros_yaml(&path).unwrap();
    let pic = read_picture(&meta.image).unwrap();
    // Occupied pixels only (dark ones), as the seed-000 pipeline binarizes.
    masks.push((envmap::binarize(&pic, 50, false), meta.resolution));
    let loaded = load_map(&path, &LoadOptions::default()).unwrap();
    masks.push((
        Mask::from_zones_at_least(&loaded.map, Zone::Forbidden),
        meta.resolution,
    ));
    let map = read_movingai(&data("movingai/arena.map")).unwrap();
    masks.push((Mask::from_zones_at_least(&map, Zone::Forbidden), 0.2));
    for (k, (mask, res)) in masks.iter().enumerate() {
        assert!(mask.cells().iter().any(|&c| c) && mask.cells().iter().any(|&c| !c));
        for inf in [
            Inflation::default(),
            Inflation {
                inscribed_radius: 0.3,
                inflation_radius: 0.55,
                cost_scaling_factor: 10.0,
            },
            Inflation {
                inscribed_radius: 0.1,
                inflation_radius: 1.5,
                cost_scaling_factor: 3.0,
            },
        ] {
            let full = inf.costs(&distance_transform(mask), *res).unwrap();
            assert_eq!(inf.inflate(mask, *res).unwrap(), full, "map {k}, {inf:?}");
        }
    }
}

/// `path` loaded with unknown cells free (`true`) or blocked.
fn load_unknown_as(path: &std::path::Path, unknown_free: bool) -> envmap::LoadedMap {
    let options = LoadOptions {
        unknown_free,
        ..LoadOptions::default()
    };
    load_map(path, &options).unwrap()
}
