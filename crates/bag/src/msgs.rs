//! The ROS 2 messages hyplan writes, field for field as their `.msg` files declare them
//! (Humble and later), so that serde's CDR encoding of a struct is the message's wire
//! form. Fixed arrays are Rust arrays (no length on the wire), sequences are `Vec`s.

use serde::{Deserialize, Serialize};

use crate::schema::RosMessage;

/// `builtin_interfaces/msg/Time`: a time since the epoch (here: since the run's start).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Time {
    /// Whole seconds.
    pub sec: i32,
    /// Nanoseconds, below 10^9.
    pub nanosec: u32,
}

impl Time {
    /// The time `ns` nanoseconds after zero (seconds saturate at `i32::MAX`).
    ///
    /// ```
    /// let t = bag::Time::from_nanos(2_500_000_000);
    /// assert_eq!((t.sec, t.nanosec), (2, 500_000_000));
    /// assert_eq!(t.nanos(), 2_500_000_000);
    /// ```
    #[must_use]
    pub fn from_nanos(ns: u64) -> Self {
        Self {
            sec: i32::try_from(ns / 1_000_000_000).unwrap_or(i32::MAX),
            nanosec: (ns % 1_000_000_000) as u32,
        }
    }

    /// Nanoseconds since zero (negative seconds count as zero).
    #[must_use]
    pub fn nanos(&self) -> u64 {
        u64::try_from(self.sec).unwrap_or(0) * 1_000_000_000 + u64::from(self.nanosec)
    }
}

/// `builtin_interfaces/msg/Duration`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Duration {
    /// Whole seconds.
    pub sec: i32,
    /// Nanoseconds, below 10^9.
    pub nanosec: u32,
}

/// `std_msgs/msg/Header`: when and in which frame.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Header {
    /// The stamp.
    pub stamp: Time,
    /// The frame the data is expressed in (`map`, `odom`, `base_link`, `laser`).
    pub frame_id: String,
}

impl Header {
    /// A header stamped `ns` nanoseconds in frame `frame_id`.
    ///
    /// ```
    /// let h = bag::Header::at(1_000_000_000, "map");
    /// assert_eq!((h.stamp.sec, h.frame_id.as_str()), (1, "map"));
    /// ```
    #[must_use]
    pub fn at(ns: u64, frame_id: &str) -> Self {
        Self {
            stamp: Time::from_nanos(ns),
            frame_id: frame_id.to_string(),
        }
    }
}

/// `std_msgs/msg/ColorRGBA`, components in `[0, 1]`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ColorRGBA {
    /// Red.
    pub r: f32,
    /// Green.
    pub g: f32,
    /// Blue.
    pub b: f32,
    /// Opacity.
    pub a: f32,
}

/// `geometry_msgs/msg/Point`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Point {
    /// x, m.
    pub x: f64,
    /// y, m.
    pub y: f64,
    /// z, m.
    pub z: f64,
}

/// `geometry_msgs/msg/Vector3`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Vector3 {
    /// x.
    pub x: f64,
    /// y.
    pub y: f64,
    /// z.
    pub z: f64,
}

/// `geometry_msgs/msg/Quaternion`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Quaternion {
    /// x.
    pub x: f64,
    /// y.
    pub y: f64,
    /// z.
    pub z: f64,
    /// w.
    pub w: f64,
}

impl Default for Quaternion {
    fn default() -> Self {
        Self::from_yaw(0.0)
    }
}

impl Quaternion {
    /// A rotation by `yaw` radians about z.
    ///
    /// ```
    /// let q = bag::Quaternion::from_yaw(1.0);
    /// assert!((q.yaw() - 1.0).abs() < 1e-12);
    /// ```
    #[must_use]
    pub fn from_yaw(yaw: f64) -> Self {
        let (s, c) = (0.5 * yaw).sin_cos();
        Self {
            x: 0.0,
            y: 0.0,
            z: s,
            w: c,
        }
    }

    /// The rotation's yaw about z, radians (roll and pitch ignored).
    #[must_use]
    pub fn yaw(&self) -> f64 {
        let Self { x, y, z, w } = *self;
        (2.0 * (w * z + x * y)).atan2(1.0 - 2.0 * (y * y + z * z))
    }
}

/// `geometry_msgs/msg/Pose`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Pose {
    /// Position.
    pub position: Point,
    /// Orientation.
    pub orientation: Quaternion,
}

impl Pose {
    /// A planar pose: `(x, y)` and a heading `yaw`.
    ///
    /// ```
    /// let p = bag::Pose::planar(1.0, 2.0, 0.5);
    /// assert_eq!(p.position.y, 2.0);
    /// ```
    #[must_use]
    pub fn planar(x: f64, y: f64, yaw: f64) -> Self {
        Self {
            position: Point { x, y, z: 0.0 },
            orientation: Quaternion::from_yaw(yaw),
        }
    }
}

/// `geometry_msgs/msg/Twist`: linear and angular velocity.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Twist {
    /// m/s (`linear.x` is the forward speed).
    pub linear: Vector3,
    /// rad/s (`angular.z` is the turn rate).
    pub angular: Vector3,
}

/// `geometry_msgs/msg/PoseWithCovariance`; the covariance is row-major 6 x 6 (x, y, z,
/// roll, pitch, yaw), a `float64[36]` on the wire.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct PoseWithCovariance {
    /// The pose.
    pub pose: Pose,
    /// Its covariance, rows of 6.
    pub covariance: [[f64; 6]; 6],
}

/// `geometry_msgs/msg/TwistWithCovariance`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct TwistWithCovariance {
    /// The twist.
    pub twist: Twist,
    /// Its covariance, rows of 6.
    pub covariance: [[f64; 6]; 6],
}

/// `geometry_msgs/msg/Transform`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Transform {
    /// Translation, m.
    pub translation: Vector3,
    /// Rotation.
    pub rotation: Quaternion,
}

/// `geometry_msgs/msg/TransformStamped`: where `child_frame_id` is in `header.frame_id`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct TransformStamped {
    /// Stamp and parent frame.
    pub header: Header,
    /// The child frame.
    pub child_frame_id: String,
    /// The child's pose in the parent.
    pub transform: Transform,
}

/// `geometry_msgs/msg/PoseStamped`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct PoseStamped {
    /// Stamp and frame.
    pub header: Header,
    /// The pose.
    pub pose: Pose,
}

/// `tf2_msgs/msg/TFMessage`: the `/tf` topic.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct TFMessage {
    /// The transforms.
    pub transforms: Vec<TransformStamped>,
}

/// `nav_msgs/msg/MapMetaData`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct MapMetaData {
    /// When the map was loaded.
    pub map_load_time: Time,
    /// Metres per cell.
    pub resolution: f32,
    /// Cells per row.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// The lower-left corner of cell (0, 0) in the header's frame; its yaw turns the grid.
    pub origin: Pose,
}

/// `nav_msgs/msg/OccupancyGrid`: row-major from the bottom row, occupancy percent 0..=100,
/// -1 unknown.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct OccupancyGrid {
    /// Stamp and frame.
    pub header: Header,
    /// Size, resolution, origin.
    pub info: MapMetaData,
    /// The cells (an `int8[]`: written as one block of bytes).
    #[serde(with = "int8_sequence")]
    pub data: Vec<i8>,
}

/// `nav_msgs/msg/Odometry`: the robot's pose in `header.frame_id` and its twist in
/// `child_frame_id`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Odometry {
    /// Stamp and frame (`odom`).
    pub header: Header,
    /// The body frame (`base_link`).
    pub child_frame_id: String,
    /// The pose.
    pub pose: PoseWithCovariance,
    /// The twist, in the body frame.
    pub twist: TwistWithCovariance,
}

/// `nav_msgs/msg/Path`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Path {
    /// Stamp and frame.
    pub header: Header,
    /// The poses, in order.
    pub poses: Vec<PoseStamped>,
}

impl Path {
    /// A path of planar points (headings 0) in `frame`, every pose stamped `ns`.
    ///
    /// ```
    /// let p = bag::Path::planar(5, "map", [(0.0, 0.0), (1.0, 2.0)]);
    /// assert_eq!(p.poses[1].pose.position.y, 2.0);
    /// assert_eq!(p.poses[1].header, p.header);
    /// ```
    #[must_use]
    pub fn planar(ns: u64, frame: &str, points: impl IntoIterator<Item = (f64, f64)>) -> Self {
        let header = Header::at(ns, frame);
        let poses = points
            .into_iter()
            .map(|(x, y)| PoseStamped {
                header: header.clone(),
                pose: Pose::planar(x, y, 0.0),
            })
            .collect();
        Self { header, poses }
    }
}

/// `sensor_msgs/msg/LaserScan` (REP 117: readings out of range are `+inf`).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct LaserScan {
    /// Stamp and the laser's frame.
    pub header: Header,
    /// Angle of the first beam, rad.
    pub angle_min: f32,
    /// Angle of the last beam, rad.
    pub angle_max: f32,
    /// Angle between beams, rad.
    pub angle_increment: f32,
    /// Time between beams, s.
    pub time_increment: f32,
    /// Time between scans, s.
    pub scan_time: f32,
    /// Smallest range reported, m.
    pub range_min: f32,
    /// Largest range reported, m.
    pub range_max: f32,
    /// The ranges, m.
    pub ranges: Vec<f32>,
    /// Intensities (empty: none measured).
    pub intensities: Vec<f32>,
}

/// `sensor_msgs/msg/CompressedImage` (a marker's texture; hyplan sends none).
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct CompressedImage {
    /// Stamp and frame.
    pub header: Header,
    /// `jpeg` or `png`.
    pub format: String,
    /// The image file's bytes.
    #[serde(with = "uint8_sequence")]
    pub data: Vec<u8>,
}

/// `visualization_msgs/msg/UVCoordinate`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct UVCoordinate {
    /// u.
    pub u: f32,
    /// v.
    pub v: f32,
}

/// `visualization_msgs/msg/MeshFile` (a marker's embedded mesh; hyplan sends none).
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct MeshFile {
    /// The file's name.
    pub filename: String,
    /// Its bytes.
    #[serde(with = "uint8_sequence")]
    pub data: Vec<u8>,
}

/// `visualization_msgs/msg/Marker` (the Humble layout, with texture and mesh file).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Marker {
    /// Stamp and frame.
    pub header: Header,
    /// Namespace.
    pub ns: String,
    /// Id within the namespace.
    pub id: i32,
    /// [`Marker::SPHERE_LIST`], [`Marker::LINE_LIST`], ...
    #[serde(rename = "type")]
    pub kind: i32,
    /// [`Marker::ADD`], [`Marker::DELETEALL`], ...
    pub action: i32,
    /// Pose of the marker's points.
    pub pose: Pose,
    /// Size (line width in `scale.x` for lines).
    pub scale: Vector3,
    /// Colour.
    pub color: ColorRGBA,
    /// How long it is shown (zero: until replaced).
    pub lifetime: Duration,
    /// Whether it moves with its frame.
    pub frame_locked: bool,
    /// Points (lines, lists).
    pub points: Vec<Point>,
    /// Per-point colours.
    pub colors: Vec<ColorRGBA>,
    /// Texture URI.
    pub texture_resource: String,
    /// Texture.
    pub texture: CompressedImage,
    /// Texture coordinates.
    pub uv_coordinates: Vec<UVCoordinate>,
    /// Text.
    pub text: String,
    /// Mesh URI.
    pub mesh_resource: String,
    /// Embedded mesh.
    pub mesh_file: MeshFile,
    /// Use the mesh's materials.
    pub mesh_use_embedded_materials: bool,
}

impl Marker {
    /// `type`: a strip of connected points.
    pub const LINE_STRIP: i32 = 4;
    /// `type`: pairs of points, one segment each.
    pub const LINE_LIST: i32 = 5;
    /// `type`: cylinders (a person's disc).
    pub const CYLINDER: i32 = 3;
    /// `type`: a sphere at each point.
    pub const SPHERE_LIST: i32 = 7;
    /// `action`: add or modify.
    pub const ADD: i32 = 0;
    /// `action`: delete every marker shown so far (of every namespace).
    pub const DELETEALL: i32 = 3;
}

impl Marker {
    /// A marker of planar `points` (lines of width `width`, or points of that size):
    /// `kind` [`Marker::LINE_LIST`], [`Marker::LINE_STRIP`] or [`Marker::SPHERE_LIST`].
    ///
    /// ```
    /// use bag::{ColorRGBA, Header, Marker};
    /// let red = ColorRGBA { r: 1.0, g: 0.0, b: 0.0, a: 1.0 };
    /// let m = Marker::planar(Header::at(0, "map"), "tree", 0, Marker::LINE_LIST, 0.02, red,
    ///     [(0.0, 0.0), (1.0, 1.0)]);
    /// assert_eq!(m.points.len(), 2);
    /// assert_eq!(m.scale.x, 0.02);
    /// ```
    #[must_use]
    pub fn planar(
        header: Header,
        ns: &str,
        id: i32,
        kind: i32,
        width: f64,
        color: ColorRGBA,
        points: impl IntoIterator<Item = (f64, f64)>,
    ) -> Self {
        Self {
            header,
            ns: ns.to_string(),
            id,
            kind,
            action: Self::ADD,
            pose: Pose::default(),
            scale: Vector3 {
                x: width,
                y: width,
                z: width,
            },
            color,
            points: points
                .into_iter()
                .map(|(x, y)| Point { x, y, z: 0.0 })
                .collect(),
            ..Self::default()
        }
    }
}

/// `visualization_msgs/msg/MarkerArray`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct MarkerArray {
    /// The markers.
    pub markers: Vec<Marker>,
}

/// `uint8[]` as one block of bytes (CDR's sequence layout: a `u32` length and the bytes).
mod uint8_sequence {
    use serde::{Deserializer, Serializer};

    pub(super) fn serialize<S: Serializer>(v: &[u8], s: S) -> Result<S::Ok, S::Error> {
        s.serialize_bytes(v)
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<u8>, D::Error> {
        d.deserialize_byte_buf(super::int8_sequence::Bytes)
    }
}

/// `int8[]` as one block of bytes: serde would otherwise encode each cell of a map on its
/// own, a call per cell.
mod int8_sequence {
    use serde::de::{self, Visitor};
    use serde::{Deserializer, Serializer};

    pub(super) fn serialize<S: Serializer>(v: &[i8], s: S) -> Result<S::Ok, S::Error> {
        let bytes: Vec<u8> = v.iter().map(|&c| c as u8).collect();
        s.serialize_bytes(&bytes)
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<i8>, D::Error> {
        let bytes = d.deserialize_byte_buf(Bytes)?;
        Ok(bytes.into_iter().map(|b| b as i8).collect())
    }

    /// Accepts a block of bytes, or a sequence of them from other formats.
    pub(super) struct Bytes;

    impl<'de> Visitor<'de> for Bytes {
        type Value = Vec<u8>;

        fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            f.write_str("a sequence of bytes")
        }

        fn visit_bytes<E: de::Error>(self, v: &[u8]) -> Result<Vec<u8>, E> {
            Ok(v.to_vec())
        }

        fn visit_byte_buf<E: de::Error>(self, v: Vec<u8>) -> Result<Vec<u8>, E> {
            Ok(v)
        }

        fn visit_seq<A: de::SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<u8>, A::Error> {
            let mut out = Vec::new();
            while let Some(b) = seq.next_element::<u8>()? {
                out.push(b);
            }
            Ok(out)
        }
    }
}

/// Implements [`RosMessage`] for the top-level types with their ROS names.
macro_rules! ros_message {
    ($($ty:ty => $name:literal),* $(,)?) => {
        $(impl RosMessage for $ty {
            const NAME: &'static str = $name;
        })*
    };
}

ros_message! {
    OccupancyGrid => "nav_msgs/msg/OccupancyGrid",
    LaserScan => "sensor_msgs/msg/LaserScan",
    Odometry => "nav_msgs/msg/Odometry",
    TFMessage => "tf2_msgs/msg/TFMessage",
    TransformStamped => "geometry_msgs/msg/TransformStamped",
    Twist => "geometry_msgs/msg/Twist",
    PoseStamped => "geometry_msgs/msg/PoseStamped",
    Path => "nav_msgs/msg/Path",
    Marker => "visualization_msgs/msg/Marker",
    MarkerArray => "visualization_msgs/msg/MarkerArray",
}
