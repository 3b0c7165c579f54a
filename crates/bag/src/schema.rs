//! The `ros2msg` schemas: each message's definition followed by those of the types it
//! uses, as rosbag2 writes them into an MCAP schema record.

use serde::Serialize;
use serde::de::DeserializeOwned;

/// A ROS 2 message type: its name and its `ros2msg` schema text.
///
/// ```
/// use bag::{OccupancyGrid, RosMessage};
/// assert_eq!(OccupancyGrid::NAME, "nav_msgs/msg/OccupancyGrid");
/// assert!(OccupancyGrid::schema().contains("\nMSG: nav_msgs/MapMetaData\n"));
/// ```
pub trait RosMessage: Serialize + DeserializeOwned {
    /// `package/msg/Type`.
    const NAME: &'static str;

    /// The definition of the type and, after a line of `=` and `MSG: package/Type`, of
    /// every type it uses (depth first, each once).
    #[must_use]
    fn schema() -> String {
        schema_text(Self::NAME)
    }
}

/// The separator rosbag2 puts between two definitions.
const SEPARATOR: &str =
    "================================================================================";

/// The definitions, by `package/Type` (the form used inside definitions).
const DEFINITIONS: &[(&str, &str)] = &[
    ("builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"),
    ("builtin_interfaces/Duration", "int32 sec\nuint32 nanosec\n"),
    (
        "std_msgs/Header",
        "builtin_interfaces/Time stamp\nstring frame_id\n",
    ),
    (
        "std_msgs/ColorRGBA",
        "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n",
    ),
    ("geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"),
    ("geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"),
    (
        "geometry_msgs/Quaternion",
        "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
    ),
    (
        "geometry_msgs/Pose",
        "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n",
    ),
    (
        "geometry_msgs/Twist",
        "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n",
    ),
    (
        "geometry_msgs/PoseWithCovariance",
        "geometry_msgs/Pose pose\nfloat64[36] covariance\n",
    ),
    (
        "geometry_msgs/TwistWithCovariance",
        "geometry_msgs/Twist twist\nfloat64[36] covariance\n",
    ),
    (
        "geometry_msgs/Transform",
        "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n",
    ),
    (
        "geometry_msgs/TransformStamped",
        "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n",
    ),
    (
        "geometry_msgs/PoseStamped",
        "std_msgs/Header header\ngeometry_msgs/Pose pose\n",
    ),
    (
        "tf2_msgs/TFMessage",
        "geometry_msgs/TransformStamped[] transforms\n",
    ),
    (
        "nav_msgs/MapMetaData",
        "builtin_interfaces/Time map_load_time\nfloat32 resolution\nuint32 width\n\
         uint32 height\ngeometry_msgs/Pose origin\n",
    ),
    (
        "nav_msgs/OccupancyGrid",
        "std_msgs/Header header\nnav_msgs/MapMetaData info\nint8[] data\n",
    ),
    (
        "nav_msgs/Odometry",
        "std_msgs/Header header\nstring child_frame_id\n\
         geometry_msgs/PoseWithCovariance pose\ngeometry_msgs/TwistWithCovariance twist\n",
    ),
    (
        "nav_msgs/Path",
        "std_msgs/Header header\ngeometry_msgs/PoseStamped[] poses\n",
    ),
    (
        "sensor_msgs/LaserScan",
        "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\n\
         float32 angle_increment\nfloat32 time_increment\nfloat32 scan_time\n\
         float32 range_min\nfloat32 range_max\nfloat32[] ranges\nfloat32[] intensities\n",
    ),
    (
        "sensor_msgs/CompressedImage",
        "std_msgs/Header header\nstring format\nuint8[] data\n",
    ),
    ("visualization_msgs/UVCoordinate", "float32 u\nfloat32 v\n"),
    (
        "visualization_msgs/MeshFile",
        "string filename\nuint8[] data\n",
    ),
    (
        "visualization_msgs/Marker",
        "int32 ARROW=0\nint32 CUBE=1\nint32 SPHERE=2\nint32 CYLINDER=3\nint32 LINE_STRIP=4\n\
         int32 LINE_LIST=5\nint32 CUBE_LIST=6\nint32 SPHERE_LIST=7\nint32 POINTS=8\n\
         int32 TEXT_VIEW_FACING=9\nint32 MESH_RESOURCE=10\nint32 TRIANGLE_LIST=11\n\
         int32 ARROW_STRIP=12\nint32 ADD=0\nint32 MODIFY=0\nint32 DELETE=2\nint32 DELETEALL=3\n\
         std_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\n\
         geometry_msgs/Pose pose\ngeometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\n\
         builtin_interfaces/Duration lifetime\nbool frame_locked\ngeometry_msgs/Point[] points\n\
         std_msgs/ColorRGBA[] colors\nstring texture_resource\n\
         sensor_msgs/CompressedImage texture\n\
         visualization_msgs/UVCoordinate[] uv_coordinates\nstring text\n\
         string mesh_resource\nvisualization_msgs/MeshFile mesh_file\n\
         bool mesh_use_embedded_materials\n",
    ),
    (
        "visualization_msgs/MarkerArray",
        "visualization_msgs/Marker[] markers\n",
    ),
];

/// The definition of `package/Type`.
fn definition(short: &str) -> &'static str {
    DEFINITIONS
        .iter()
        .find(|(n, _)| *n == short)
        .map_or("", |(_, d)| d)
}

/// The types a definition's fields use (`package/Type`, arrays stripped), in order.
fn used_types(def: &str) -> impl Iterator<Item = &str> {
    def.lines()
        .filter_map(|l| l.split_whitespace().next())
        .map(|t| t.split('[').next().unwrap_or(t))
        .filter(|t| t.contains('/'))
}

/// The schema text of `package/msg/Type`: its definition, then its dependencies.
fn schema_text(name: &str) -> String {
    let short = name.replace("/msg/", "/");
    let mut text = definition(&short).to_string();
    let mut seen = vec![short.clone()];
    let mut stack: Vec<&str> = used_types(definition(&short)).collect();
    stack.reverse();
    while let Some(t) = stack.pop() {
        if seen.iter().any(|s| s == t) {
            continue;
        }
        seen.push(t.to_string());
        let def = definition(t);
        text.push_str(&format!("{SEPARATOR}\nMSG: {t}\n{def}"));
        let mut inner: Vec<&str> = used_types(def).collect();
        inner.reverse();
        stack.extend(inner);
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_used_type_is_defined() {
        for (name, def) in DEFINITIONS {
            for t in used_types(def) {
                assert!(!definition(t).is_empty(), "{name} uses {t}, undefined");
            }
        }
    }

    #[test]
    fn odometry_schema_lists_each_dependency_once_depth_first() {
        let s = schema_text("nav_msgs/msg/Odometry");
        let msgs: Vec<&str> = s.lines().filter_map(|l| l.strip_prefix("MSG: ")).collect();
        assert_eq!(
            msgs,
            [
                "std_msgs/Header",
                "builtin_interfaces/Time",
                "geometry_msgs/PoseWithCovariance",
                "geometry_msgs/Pose",
                "geometry_msgs/Point",
                "geometry_msgs/Quaternion",
                "geometry_msgs/TwistWithCovariance",
                "geometry_msgs/Twist",
                "geometry_msgs/Vector3",
            ]
        );
        assert!(s.starts_with("std_msgs/Header header\n"));
    }
}
