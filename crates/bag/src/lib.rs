//! ROS 2 bags in MCAP: what hyplan writes for Foxglove and RViz, and the maps it reads
//! from a robot's bag.
//!
//! rosbag2's default storage is MCAP (foxglove's format, read here with its `mcap`
//! crate); each message is CDR-encoded (`cdr-encoding`) and its type described by a
//! `ros2msg` schema: the `.msg` definition and those of the types it uses.
//!
//! # Contents
//!
//! - Messages, field for field as in ROS 2 (Humble and later): [`OccupancyGrid`]
//!   ([`MapMetaData`]), [`LaserScan`], [`Odometry`] ([`PoseWithCovariance`],
//!   [`TwistWithCovariance`]), [`TFMessage`] ([`TransformStamped`], [`Transform`]),
//!   [`Twist`], [`PoseStamped`], [`Path`], [`MarkerArray`] ([`Marker`], [`ColorRGBA`]);
//!   their parts [`Header`], [`Time`], [`Duration`], [`Pose`], [`Point`], [`Vector3`],
//!   [`Quaternion`], [`CompressedImage`], [`UVCoordinate`], [`MeshFile`].
//! - [`RosMessage`]: a message's ROS name and `ros2msg` schema.
//! - [`encode`] ([`encode_into`]), [`decode`] ([`CdrError`], [`CDR_LE_HEADER`]): CDR with
//!   its encapsulation header.
//! - [`BagWriter`]: a bag being written (channels registered once per topic, log time =
//!   publish time = the stamp).
//! - [`read_occupancy_grid`], [`occupancy_grid_from`]: the last map on a topic
//!   ([`DEFAULT_MAP_TOPIC`]), sizes checked.
//! - [`BagError`]: every failure, naming the file, topic and field.
//!
//! # Example
//!
//! ```
//! use bag::{BagWriter, Header, MapMetaData, OccupancyGrid, Pose};
//! let path = std::env::temp_dir().join(format!("bag-lib-{}.mcap", std::process::id()));
//! let grid = OccupancyGrid {
//!     header: Header::at(0, "map"),
//!     info: MapMetaData { resolution: 0.05, width: 2, height: 1, origin: Pose::planar(-1.0, 0.0, 0.0), ..Default::default() },
//!     data: vec![0, 100],
//! };
//! let mut bag = BagWriter::create(&path)?;
//! bag.write("/map", 0, &grid)?;
//! bag.finish()?;
//! assert_eq!(bag::read_occupancy_grid(&path, "/map", 1000)?, grid);
//! # std::fs::remove_file(&path).ok();
//! # Ok::<(), bag::BagError>(())
//! ```

mod cdr;
mod error;
mod msgs;
mod reader;
mod schema;
mod writer;

pub use cdr::{CDR_LE_HEADER, CdrError, decode, encode, encode_into};
pub use error::BagError;
pub use msgs::{
    ColorRGBA, CompressedImage, Duration, Header, LaserScan, MapMetaData, Marker, MarkerArray,
    MeshFile, OccupancyGrid, Odometry, Path, Point, Pose, PoseStamped, PoseWithCovariance,
    Quaternion, TFMessage, Time, Transform, TransformStamped, Twist, TwistWithCovariance,
    UVCoordinate, Vector3,
};
pub use reader::{DEFAULT_MAP_TOPIC, occupancy_grid_from, read_occupancy_grid};
pub use schema::RosMessage;
pub use writer::BagWriter;
