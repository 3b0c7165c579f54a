//! Loading maps from files: pictures, ROS map_server YAML, MovingAI `.map`, ROS 2 bags.

pub(crate) mod image;
pub(crate) mod mcap;
pub(crate) mod movingai;
pub(crate) mod ros;

use std::path::Path;

use hyplan_core::Zone;

use crate::{Component, GridMap, InputFrame, MapError, Mask, Pipeline, PipelineOutput};

/// Options of [`load_map`].
#[derive(Clone, Copy, PartialEq, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LoadOptions {
    /// Pictures: luminance threshold, darker is an obstacle (see
    /// [`binarize`](crate::binarize)). Default 100. Ignored for ROS and MovingAI maps.
    pub threshold: u8,
    /// Pictures: brighter pixels are obstacles instead. Default `false`.
    pub invert: bool,
    /// Replace every obstacle by its bounding rectangle before adding the high-risk band.
    /// Default `false`.
    pub rectangles: bool,
    /// Radius of the high-risk band, in the input's units: cells for pictures and
    /// MovingAI maps, metres (world units) for ROS maps. `None` (default) means 20 cells
    /// for pictures (seed 000) and no band for ROS and MovingAI maps, whose obstacles are
    /// already given.
    pub safety_radius: Option<f64>,
    /// ROS maps: unknown cells become `Free` instead of `Forbidden` (the default).
    pub unknown_free: bool,
    /// The memory limit, in cells: a file declaring more cells (width x height) is
    /// refused with [`MapError::TooLarge`] before its pixels or rows are decoded. Default
    /// [`DEFAULT_MAX_CELLS`].
    pub max_cells: usize,
}

/// The default memory limit of [`LoadOptions::max_cells`]: 10^8 cells (10,000 x 10,000).
///
/// Loading and planning keep several arrays per cell (the decoded picture, the obstacle
/// mask, component labels, the distance transform, the zones, and a grid search's words),
/// a few tens of bytes per cell in all: 10^8 cells is a few GB, the most a workstation can
/// be expected to hold.
pub const DEFAULT_MAX_CELLS: usize = 100_000_000;

/// `Err(TooLarge)` when `width x height` exceeds `limit`.
pub(crate) fn check_cells(
    path: &Path,
    width: usize,
    height: usize,
    limit: usize,
) -> Result<(), MapError> {
    if width.checked_mul(height).is_none_or(|n| n > limit) {
        return Err(MapError::TooLarge {
            path: path.to_path_buf(),
            width,
            height,
            limit,
        });
    }
    Ok(())
}

impl Default for LoadOptions {
    fn default() -> Self {
        Self {
            threshold: 100,
            invert: false,
            rectangles: false,
            safety_radius: None,
            unknown_free: false,
            max_cells: DEFAULT_MAX_CELLS,
        }
    }
}

/// What kind of file a path holds, by extension.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum MapKind {
    /// `.map`: MovingAI.
    MovingAi,
    /// `.yaml` / `.yml`: ROS map_server.
    Ros,
    /// `.mcap`: a ROS 2 bag, its last `nav_msgs/msg/OccupancyGrid` on a topic.
    Mcap,
    /// Anything else: a picture.
    Picture,
}

impl MapKind {
    /// The kind of `path` by its extension (case-insensitive).
    #[must_use]
    pub fn of(path: &Path) -> Self {
        match path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase())
            .as_deref()
        {
            Some("map") => Self::MovingAi,
            Some("yaml" | "yml") => Self::Ros,
            Some("mcap") => Self::Mcap,
            _ => Self::Picture,
        }
    }
}

/// A map loaded by [`load_map`], with what the pipeline found on the way.
#[derive(Clone, Debug)]
pub struct LoadedMap {
    /// The three-zone map.
    pub map: GridMap,
    /// How users give coordinates for this input.
    pub frame: InputFrame,
    /// What kind of file it came from.
    pub kind: MapKind,
    /// Obstacle cells before rectangles and band: dark pixels, `.map` blocked cells, ROS
    /// forbidden cells (occupied, and unknown unless `unknown_free`).
    pub mask: Mask,
    /// The 8-connected components of `mask`, with their bounding rectangles.
    pub components: Vec<Component>,
}

/// Loads a map, choosing the reader by extension: `.map` MovingAI
/// ([`read_movingai`](crate::read_movingai)), `.yaml` / `.yml` ROS map_server
/// ([`read_ros_yaml`](crate::read_ros_yaml) plus its image), anything else a picture
/// ([`read_picture`](crate::read_picture)) run through the seed-000
/// [`Pipeline`](crate::Pipeline).
///
/// Frames: pictures and `.map` files give a map with resolution 1 and origin (0, 0), and
/// [`InputFrame::Cells`] (y down); ROS maps keep their resolution and origin and use
/// [`InputFrame::World`] (metres, y up), or [`InputFrame::MapFrame`] when the YAML's
/// `origin` has a non-zero yaw (the grid is then axis-aligned in its own frame, and
/// map-frame coordinates are rotated into it).
///
/// # Errors
///
/// Any [`MapError`] of the readers, [`MapError::TooLarge`] for a file with more than
/// [`LoadOptions::max_cells`] cells, and [`MapError::InvalidParameter`] for a negative or
/// non-finite safety radius.
///
/// ```no_run
/// use envmap::{load_map, LoadOptions};
/// let loaded = load_map("arena.map".as_ref(), &LoadOptions::default())?;
/// let start = loaded.frame.to_world(1.5, 2.5); // column 1, row 2 from the top
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn load_map(path: &Path, opts: &LoadOptions) -> Result<LoadedMap, MapError> {
    load_map_topic(path, DEFAULT_MAP_TOPIC, opts)
}

/// The topic [`load_map`] reads a ROS 2 bag's map from.
pub const DEFAULT_MAP_TOPIC: &str = "/map";

/// [`load_map`], reading a ROS 2 bag's (`.mcap`) map from `topic`; other files ignore it.
///
/// A bag's map is its last `nav_msgs/msg/OccupancyGrid` on the topic, with its resolution
/// and origin ([`InputFrame::World`], or [`InputFrame::MapFrame`] when the origin has a
/// yaw, as for YAML); cells hold the occupancy in percent and are classified as a ROS
/// map's pixels are, with map_saver's thresholds ([`RosMapMeta::classify_occupancy`](crate::RosMapMeta::classify_occupancy)):
/// 0 free, 100 occupied, -1 unknown.
///
/// # Errors
///
/// As [`load_map`]; for bags `MapError::Bag` (feature `mcap`) naming the file, the topic and the field
/// (malformed or truncated file, absent topic, another message type, `data` not holding
/// `width x height` cells, more than [`LoadOptions::max_cells`] cells), or
/// [`MapError::NoMcapSupport`] without the `mcap` feature.
///
/// ```no_run
/// use envmap::{load_map_topic, LoadOptions};
/// let loaded = load_map_topic("robot.mcap".as_ref(), "/map_updates", &LoadOptions::default())?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn load_map_topic(path: &Path, topic: &str, opts: &LoadOptions) -> Result<LoadedMap, MapError> {
    let kind = MapKind::of(path);
    if let Some(r) = opts.safety_radius
        && !(r.is_finite() && r >= 0.0)
    {
        return Err(MapError::InvalidParameter {
            name: "safety_radius",
            value: r.to_string(),
            reason: "must be finite and >= 0".into(),
        });
    }
    let mut pipeline = Pipeline {
        threshold: opts.threshold,
        invert: opts.invert,
        rectangles: opts.rectangles,
        safety_radius: opts.safety_radius.unwrap_or(0.0),
    };
    let mut yaw = 0.0;
    let (out, frame_res, origin, frame_kind_world) = match kind {
        MapKind::Picture => {
            let picture = self::image::read_picture_limited(path, opts.max_cells)?;
            pipeline.safety_radius = opts
                .safety_radius
                .unwrap_or(Pipeline::default().safety_radius);
            (pipeline.run(&picture)?, 1.0, None, false)
        }
        MapKind::MovingAi => {
            let map = movingai::read_movingai_limited(path, opts.max_cells)?;
            let mask = Mask::from_zones_at_least(&map, Zone::Forbidden);
            (pipeline.run_mask(mask, &[])?, 1.0, None, false)
        }
        MapKind::Ros => {
            let meta = ros::read_ros_yaml(path)?;
            yaw = meta.yaw;
            let picture = self::image::read_picture_limited(&meta.image, opts.max_cells)?;
            let unknown = if opts.unknown_free {
                Zone::Free
            } else {
                Zone::Forbidden
            };
            let map = meta.to_map(&picture, unknown)?;
            let mask = Mask::from_zones_at_least(&map, Zone::Forbidden);
            pipeline.safety_radius = opts.safety_radius.unwrap_or(0.0) / meta.resolution;
            let out = pipeline.run_mask(mask, map.zones())?;
            (out, meta.resolution, Some(meta.origin), true)
        }
        MapKind::Mcap => {
            let unknown = if opts.unknown_free {
                Zone::Free
            } else {
                Zone::Forbidden
            };
            let read = mcap::read_bag_map(path, topic, opts.max_cells, unknown)?;
            yaw = read.yaw;
            let (res, origin) = (read.map.resolution(), read.map.origin());
            let mask = Mask::from_zones_at_least(&read.map, Zone::Forbidden);
            pipeline.safety_radius = opts.safety_radius.unwrap_or(0.0) / res;
            let out = pipeline.run_mask(mask, read.map.zones())?;
            (out, res, Some(origin), true)
        }
    };
    let PipelineOutput {
        mask,
        components,
        map,
        ..
    } = out;
    let origin = origin.unwrap_or_else(hyplan_core::Point2::origin);
    let map = map
        .with_frame(frame_res, origin)
        .map_err(|source| MapError::Grid {
            path: path.to_path_buf(),
            source,
        })?;
    let frame = if frame_kind_world {
        InputFrame::ros(map.origin(), yaw)
    } else {
        InputFrame::Cells {
            height: map.height(),
            resolution: map.resolution(),
            origin: map.origin(),
        }
    };
    Ok(LoadedMap {
        map,
        frame,
        kind,
        mask,
        components,
    })
}
