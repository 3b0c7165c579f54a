//! Round trips through a file, and every refusal of the map reader.

use std::path::{Path, PathBuf};

use bag::{
    BagError, BagWriter, Header, LaserScan, MapMetaData, Marker, MarkerArray, OccupancyGrid,
    Odometry, Point, Pose, PoseStamped, RosMessage, TFMessage, TransformStamped, Twist,
    read_occupancy_grid,
};

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bag-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn grid(w: u32, h: u32, data: Vec<i8>) -> OccupancyGrid {
    OccupancyGrid {
        header: Header::at(3_000_000_000, "map"),
        info: MapMetaData {
            resolution: 0.05,
            width: w,
            height: h,
            origin: Pose::planar(-2.0, 1.5, 0.0),
            ..MapMetaData::default()
        },
        data,
    }
}

fn write_maps(path: &Path, maps: &[(&str, u64, OccupancyGrid)]) {
    let mut bag = BagWriter::create(path).unwrap();
    bag.write("/cmd_vel", 0, &Twist::default()).unwrap();
    for (topic, t, m) in maps {
        bag.write(topic, *t, m).unwrap();
    }
    bag.finish().unwrap();
}

fn round_trip<M: RosMessage + PartialEq + std::fmt::Debug>(m: &M) {
    let back: M = bag::decode(&bag::encode(m).unwrap()).unwrap();
    assert_eq!(&back, m, "{}", M::NAME);
}

#[test]
fn every_message_round_trips_through_cdr() {
    round_trip(&grid(3, 2, vec![-1, 0, 100, 50, 0, -1]));
    round_trip(&LaserScan {
        header: Header::at(5, "laser"),
        angle_min: -1.5,
        angle_max: 1.5,
        angle_increment: 0.01,
        range_max: 10.0,
        ranges: vec![1.0, f32::INFINITY, 2.5],
        ..LaserScan::default()
    });
    let mut odom = Odometry {
        header: Header::at(7, "odom"),
        child_frame_id: "base_link".into(),
        ..Odometry::default()
    };
    odom.pose.pose = Pose::planar(1.0, 2.0, 0.3);
    odom.pose.covariance[5][5] = 0.25;
    odom.twist.twist.linear.x = 0.4;
    round_trip(&odom);
    round_trip(&TFMessage {
        transforms: vec![TransformStamped {
            header: Header::at(1, "map"),
            child_frame_id: "odom".into(),
            ..TransformStamped::default()
        }],
    });
    round_trip(&bag::Path {
        header: Header::at(2, "map"),
        poses: vec![PoseStamped {
            header: Header::at(2, "map"),
            pose: Pose::planar(0.5, 0.5, 0.0),
        }],
    });
    round_trip(&MarkerArray {
        markers: vec![Marker {
            header: Header::at(9, "map"),
            ns: "tree".into(),
            kind: Marker::LINE_LIST,
            points: vec![
                Point::default(),
                Point {
                    x: 1.0,
                    y: 0.0,
                    z: 0.0,
                },
            ],
            ..Marker::default()
        }],
    });
}

#[test]
fn odometry_has_its_fixed_size_covariances_on_the_wire() {
    // header (4 + 4 + 4 + "odom\0" = 17, padded to 20) + "base_link\0" (4 + 10 = 34,
    // padded to 40) + pose 7 * 8 + 36 * 8 + twist 6 * 8 + 36 * 8.
    let bytes = bag::encode(&Odometry {
        header: Header::at(0, "odom"),
        child_frame_id: "base_link".into(),
        ..Odometry::default()
    })
    .unwrap();
    assert_eq!(bytes.len(), 4 + 40 + 56 + 288 + 48 + 288);
}

#[test]
fn the_last_map_of_the_topic_is_read_back() {
    let path = temp("maps.mcap");
    let first = grid(2, 2, vec![0, 0, 0, 0]);
    let last = grid(3, 1, vec![100, -1, 0]);
    let other = grid(1, 1, vec![100]);
    write_maps(
        &path,
        &[
            ("/map", 1, first),
            ("/map", 2, last.clone()),
            ("/other", 3, other.clone()),
        ],
    );
    assert_eq!(read_occupancy_grid(&path, "/map", 100).unwrap(), last);
    assert_eq!(read_occupancy_grid(&path, "/other", 100).unwrap(), other);
}

#[test]
fn a_truncated_file_is_refused_naming_it() {
    let path = temp("truncated.mcap");
    write_maps(&path, &[("/map", 1, grid(40, 40, vec![0; 1600]))]);
    let bytes = std::fs::read(&path).unwrap();
    for cut in [bytes.len() - 9, bytes.len() / 2, 12, 3] {
        let short = temp(&format!("cut-{cut}.mcap"));
        std::fs::write(&short, &bytes[..cut]).unwrap();
        let e = read_occupancy_grid(&short, "/map", 10_000).unwrap_err();
        assert!(matches!(e, BagError::Mcap { .. }), "cut at {cut}: {e}");
        assert!(e.to_string().contains(&format!("cut-{cut}.mcap")), "{e}");
    }
    let e = read_occupancy_grid(&temp("absent.mcap"), "/map", 100).unwrap_err();
    assert!(matches!(e, BagError::Io { .. }), "{e}");
}

#[test]
fn an_absent_topic_is_refused_listing_the_topics() {
    let path = temp("absent-topic.mcap");
    write_maps(&path, &[("/map", 1, grid(1, 1, vec![0]))]);
    let e = read_occupancy_grid(&path, "/costmap", 100).unwrap_err();
    let BagError::NoTopic { topic, topics, .. } = &e else {
        panic!("{e}")
    };
    assert_eq!(topic, "/costmap");
    assert_eq!(topics, &["/cmd_vel", "/map"]);
    assert!(e.to_string().contains("`/costmap`"), "{e}");
}

#[test]
fn a_topic_of_another_type_is_refused() {
    let path = temp("wrong-type.mcap");
    write_maps(&path, &[]);
    let e = read_occupancy_grid(&path, "/cmd_vel", 100).unwrap_err();
    let BagError::WrongSchema { found, .. } = &e else {
        panic!("{e}")
    };
    assert_eq!(found, "geometry_msgs/msg/Twist");
}

#[test]
fn bad_sizes_are_refused_naming_the_field() {
    let path = temp("bad-data.mcap");
    write_maps(&path, &[("/map", 1, grid(3, 2, vec![0; 5]))]);
    let e = read_occupancy_grid(&path, "/map", 100).unwrap_err();
    assert!(matches!(&e, BagError::Field { field: "data", .. }), "{e}");
    assert!(
        e.to_string()
            .contains("bad-data.mcap: topic `/map`: field `data` = 5 cells"),
        "{e}"
    );

    let path = temp("too-large.mcap");
    write_maps(&path, &[("/map", 1, grid(30, 30, vec![0; 900]))]);
    let e = read_occupancy_grid(&path, "/map", 899).unwrap_err();
    assert!(
        matches!(
            &e,
            BagError::Field {
                field: "info.width x info.height",
                ..
            }
        ),
        "{e}"
    );
    let mut g = grid(1, 1, vec![0]);
    g.info.resolution = 0.0;
    let path = temp("zero-res.mcap");
    write_maps(&path, &[("/map", 1, g)]);
    let e = read_occupancy_grid(&path, "/map", 10).unwrap_err();
    assert!(
        matches!(
            &e,
            BagError::Field {
                field: "info.resolution",
                ..
            }
        ),
        "{e}"
    );
}
