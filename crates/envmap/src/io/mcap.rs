//! Maps from ROS 2 bags: the last `nav_msgs/msg/OccupancyGrid` on a topic of an MCAP
//! file, its cells classified by the ROS map rule of [`RosMapMeta::classify_occupancy`].

use std::path::Path;

#[cfg(feature = "mcap")]
use hyplan_core::Point2;
use hyplan_core::Zone;

use crate::{GridMap, MapError};
#[cfg(feature = "mcap")]
use crate::{RosCell, RosMapMeta, RosMode};

/// A map read from a bag: the grid (framed), and the yaw of its origin.
pub(crate) struct BagMap {
    pub(crate) map: GridMap,
    pub(crate) yaw: f64,
}

/// The thresholds of a bag's cells: map_saver's, so a grid reads as its saved PGM/YAML
/// pair does (0 free, 100 occupied, -1 unknown; graded values by the thresholds).
#[cfg(feature = "mcap")]
fn thresholds() -> RosMapMeta {
    RosMapMeta {
        image: std::path::PathBuf::new(),
        resolution: 1.0,
        origin: Point2::origin(),
        yaw: 0.0,
        negate: false,
        occupied_thresh: crate::ROS_OCCUPIED_THRESH,
        free_thresh: crate::ROS_FREE_THRESH,
        mode: RosMode::Trinary,
    }
}

/// Reads the last OccupancyGrid on `topic` of the bag at `path` as a three-zone map:
/// occupied cells `Forbidden`, free cells `Free`, unknown cells (-1, or a value between
/// the thresholds) `unknown`.
#[cfg(feature = "mcap")]
pub(crate) fn read_bag_map(
    path: &Path,
    topic: &str,
    max_cells: usize,
    unknown: Zone,
) -> Result<BagMap, MapError> {
    let grid = bag::read_occupancy_grid(path, topic, max_cells)?;
    let info = &grid.info;
    let q = info.origin.orientation;
    let norm = (q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w).sqrt();
    // A map lies in its frame's plane: only a turn about z is meaningful.
    if !((norm - 1.0).abs() < 1e-6 && q.x.abs() < 1e-6 && q.y.abs() < 1e-6) {
        return Err(bag::BagError::Field {
            path: path.to_path_buf(),
            topic: topic.to_string(),
            field: "info.origin.orientation",
            value: format!("({}, {}, {}, {})", q.x, q.y, q.z, q.w),
            reason: "must be a unit quaternion turning about z only".into(),
        }
        .into());
    }
    let rule = thresholds();
    // 256 possible values: classify each once.
    let zone_of: Vec<Zone> = (0..=255u8)
        .map(|b| {
            let v = b as i8;
            let cell = if (0..=100).contains(&v) {
                rule.classify_occupancy(f64::from(v) / 100.0)
            } else {
                RosCell::Unknown
            };
            match cell {
                RosCell::Free => Zone::Free,
                RosCell::Graded => Zone::Risk,
                RosCell::Occupied => Zone::Forbidden,
                RosCell::Unknown => unknown,
            }
        })
        .collect();
    let (w, h) = (info.width as usize, info.height as usize);
    let grid_err = |source| MapError::Grid {
        path: path.to_path_buf(),
        source,
    };
    let mut map = GridMap::filled(w, h, Zone::Free).map_err(grid_err)?;
    for (z, &v) in map.zones_mut().iter_mut().zip(&grid.data) {
        *z = zone_of[usize::from(v as u8)];
    }
    let origin = Point2::new(info.origin.position.x, info.origin.position.y);
    // The message holds a float32: its shortest decimal form is the resolution the
    // writer meant (0.05, not 0.0500000007), as in the YAML of the same map.
    let resolution = info
        .resolution
        .to_string()
        .parse::<f64>()
        .unwrap_or(f64::from(info.resolution));
    let map = map.with_frame(resolution, origin).map_err(grid_err)?;
    Ok(BagMap { map, yaw: q.yaw() })
}

/// Without the `mcap` feature: [`MapError::NoMcapSupport`].
#[cfg(not(feature = "mcap"))]
pub(crate) fn read_bag_map(
    path: &Path,
    _topic: &str,
    _max_cells: usize,
    _unknown: Zone,
) -> Result<BagMap, MapError> {
    Err(MapError::NoMcapSupport {
        path: path.to_path_buf(),
    })
}

#[cfg(all(test, feature = "mcap"))]
mod tests {
    use super::*;
    use crate::{InputFrame, LoadOptions, load_map, load_map_topic};

    fn write_bag(name: &str, grid: &bag::OccupancyGrid) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("envmap-mcap-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        let mut w = bag::BagWriter::create(&path).unwrap();
        w.write("/map", 0, grid).unwrap();
        w.finish().unwrap();
        path
    }

    fn grid(data: Vec<i8>, yaw: f64) -> bag::OccupancyGrid {
        bag::OccupancyGrid {
            header: bag::Header::at(0, "map"),
            info: bag::MapMetaData {
                resolution: 0.1,
                width: 3,
                height: 2,
                origin: bag::Pose::planar(1.0, -2.0, yaw),
                ..Default::default()
            },
            data,
        }
    }

    #[test]
    fn cells_read_by_the_ros_rule_with_the_grids_frame() {
        // Row 0 (bottom): free, occupied, unknown; row 1: 19 (free), 65 (between), 66.
        let path = write_bag("cells.mcap", &grid(vec![0, 100, -1, 19, 65, 66], 0.0));
        let loaded = load_map(&path, &LoadOptions::default()).unwrap();
        let m = &loaded.map;
        assert_eq!((m.width(), m.height(), m.resolution()), (3, 2, 0.1));
        assert_eq!((m.origin().x, m.origin().y), (1.0, -2.0));
        let zones: Vec<Zone> = (0..2)
            .flat_map(|j| (0..3).map(move |i| (i, j)))
            .map(|(i, j)| m.cell_zone(i, j))
            .collect();
        use Zone::{Forbidden as X, Free as F};
        assert_eq!(zones, [F, X, X, F, X, X]);
        assert_eq!(loaded.frame, InputFrame::World);
        let free = LoadOptions {
            unknown_free: true,
            ..LoadOptions::default()
        };
        let m = load_map(&path, &free).unwrap().map;
        assert_eq!((m.cell_zone(2, 0), m.cell_zone(1, 1)), (F, F));
    }

    #[test]
    fn a_yaw_is_kept_and_a_tilt_refused() {
        let path = write_bag("yaw.mcap", &grid(vec![0; 6], 0.5));
        let loaded = load_map(&path, &LoadOptions::default()).unwrap();
        let InputFrame::MapFrame { yaw, .. } = loaded.frame else {
            panic!("{:?}", loaded.frame)
        };
        assert!((yaw - 0.5).abs() < 1e-12);
        let mut tilted = grid(vec![0; 6], 0.0);
        tilted.info.origin.orientation = bag::Quaternion {
            x: 0.6,
            y: 0.0,
            z: 0.0,
            w: 0.8,
        };
        let path = write_bag("tilt.mcap", &tilted);
        let e = load_map(&path, &LoadOptions::default()).unwrap_err();
        assert!(
            e.to_string().contains("field `info.origin.orientation`"),
            "{e}"
        );
        let e = load_map_topic(&path, "/nope", &LoadOptions::default()).unwrap_err();
        assert!(e.to_string().contains("no message on topic `/nope`"), "{e}");
    }
}
