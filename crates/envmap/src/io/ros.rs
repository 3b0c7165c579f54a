//! ROS `map_server` maps: a YAML file plus an image, read with Nav2's rules.

use std::path::{Path, PathBuf};

use hyplan_core::{Point2, Zone};
use serde_yaml_ng::Value;

use crate::{GridMap, MapError, Picture};

/// How map_server turns pixel values into occupancy (`mode` in the YAML).
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum RosMode {
    /// Occupied, free or unknown by the two thresholds (the default).
    #[default]
    Trinary,
    /// As trinary, but cells between the thresholds get a graded cost: hyplan reads them
    /// as [`Zone::Risk`].
    Scale,
    /// The value is the occupancy in percent: 0 free, 100 occupied, 1..=99 graded (read as
    /// [`Zone::Risk`]), anything else unknown.
    Raw,
}

/// The metadata of a ROS map YAML file.
#[derive(Clone, PartialEq, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RosMapMeta {
    /// The image, resolved relative to the YAML file's directory.
    pub image: PathBuf,
    /// Metres per cell.
    pub resolution: f64,
    /// Map-frame position of the lower-left corner of the lower-left cell, metres.
    pub origin: Point2,
    /// Rotation of the grid about `origin`, radians counter-clockwise (the third entry of
    /// `origin` in the YAML). The grid stays axis-aligned in its own frame; see
    /// [`InputFrame::MapFrame`](crate::InputFrame::MapFrame) for the conversion.
    pub yaw: f64,
    /// Swap black and white.
    pub negate: bool,
    /// Occupancy probability above which a cell is occupied, in `[0, 1]`.
    pub occupied_thresh: f64,
    /// Occupancy probability below which a cell is free, in `[0, 1]`.
    pub free_thresh: f64,
    /// The interpretation of pixel values.
    pub mode: RosMode,
}

/// Reads the YAML file of a ROS map (no image yet).
///
/// Required keys, as Nav2's `map_io`: `image`, `resolution` (> 0), `origin`
/// (`[x, y, yaw]`), `occupied_thresh` and `free_thresh` (in `[0, 1]`, free <= occupied).
/// Optional: `negate` (0/1 or boolean, default 0), `mode` (`trinary` default, `scale`,
/// `raw`). A non-zero yaw is kept in [`RosMapMeta::yaw`], as Nav2's map server keeps it
/// in the map's origin pose.
///
/// # Errors
///
/// [`MapError::Read`], [`MapError::Yaml`], or [`MapError::Field`] naming the missing or
/// out-of-range key and its value.
pub fn read_ros_yaml(path: &Path) -> Result<RosMapMeta, MapError> {
    let bytes = std::fs::read(path).map_err(|source| MapError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    parse_ros_yaml(&bytes, path)
}

/// Parses the bytes of a ROS map YAML file; `path` names the file in errors and anchors a
/// relative `image`.
///
/// # Errors
///
/// As [`read_ros_yaml`], minus the io error.
///
/// ```
/// use envmap::{parse_ros_yaml, RosMode};
/// let yaml = b"image: map.pgm\nresolution: 0.05\norigin: [-10.0, -10.0, 0.0]\n\
///              negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
/// let meta = parse_ros_yaml(yaml, "maps/world.yaml".as_ref())?;
/// assert_eq!(meta.image, std::path::Path::new("maps/map.pgm"));
/// assert_eq!(meta.mode, RosMode::Trinary);
/// assert_eq!(meta.origin.x, -10.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn parse_ros_yaml(bytes: &[u8], path: &Path) -> Result<RosMapMeta, MapError> {
    let doc: Value = serde_yaml_ng::from_slice(bytes).map_err(|source| MapError::Yaml {
        path: path.to_path_buf(),
        source,
    })?;
    let field = |field: &'static str, value: String, reason: &str| MapError::Field {
        path: path.to_path_buf(),
        field,
        value,
        reason: reason.to_string(),
    };
    let Value::Mapping(map) = &doc else {
        return Err(field(
            "(document)",
            show(&doc),
            "expected a mapping of keys",
        ));
    };
    let get = |key: &'static str| map.get(key);
    let required =
        |key: &'static str| get(key).ok_or_else(|| field(key, "missing".into(), "required"));
    let number = |key: &'static str, v: &Value| {
        v.as_f64()
            .filter(|x| x.is_finite())
            .ok_or_else(|| field(key, show(v), "expected a finite number"))
    };

    let image = match required("image")? {
        Value::String(s) if !s.is_empty() => s.clone(),
        v => return Err(field("image", show(v), "expected a file name")),
    };
    let resolution = number("resolution", required("resolution")?)?;
    if resolution <= 0.0 {
        return Err(field(
            "resolution",
            show(&Value::from(resolution)),
            "must be > 0",
        ));
    }
    let (origin, yaw) = match required("origin")? {
        Value::Sequence(s) if s.len() == 3 => {
            let xs = s
                .iter()
                .map(|v| number("origin", v))
                .collect::<Result<Vec<_>, _>>()?;
            (Point2::new(xs[0], xs[1]), xs[2])
        }
        v => return Err(field("origin", show(v), "expected [x, y, yaw]")),
    };
    let thresh = |key: &'static str| -> Result<f64, MapError> {
        let t = number(key, required(key)?)?;
        if (0.0..=1.0).contains(&t) {
            Ok(t)
        } else {
            Err(field(key, show(&Value::from(t)), "must be in [0, 1]"))
        }
    };
    let occupied_thresh = thresh("occupied_thresh")?;
    let free_thresh = thresh("free_thresh")?;
    if free_thresh > occupied_thresh {
        return Err(field(
            "free_thresh",
            show(&Value::from(free_thresh)),
            &format!("must not exceed occupied_thresh {occupied_thresh}"),
        ));
    }
    let negate = match get("negate") {
        None => false,
        Some(Value::Bool(b)) => *b,
        Some(v) => match v.as_i64() {
            Some(0) => false,
            Some(1) => true,
            _ => return Err(field("negate", show(v), "expected 0, 1, true or false")),
        },
    };
    let mode = match get("mode") {
        None => RosMode::Trinary,
        Some(Value::String(s)) => match s.as_str() {
            "trinary" => RosMode::Trinary,
            "scale" => RosMode::Scale,
            "raw" => RosMode::Raw,
            _ => return Err(field("mode", s.clone(), "expected trinary, scale or raw")),
        },
        Some(v) => return Err(field("mode", show(v), "expected trinary, scale or raw")),
    };
    let image = PathBuf::from(image);
    let image = if image.is_absolute() {
        image
    } else {
        path.parent().unwrap_or(Path::new("")).join(image)
    };
    Ok(RosMapMeta {
        image,
        resolution,
        origin,
        yaw,
        negate,
        occupied_thresh,
        free_thresh,
        mode,
    })
}

/// A YAML value on one line, shortened, for error messages: scalars as written, lists
/// as `[a, b, c]`, mappings as `{k: v}`.
fn show(v: &Value) -> String {
    let s = one_line(v);
    let s = s.trim();
    if s.chars().count() > 60 {
        format!("{}...", s.chars().take(60).collect::<String>())
    } else {
        s.to_string()
    }
}

/// What one ROS cell is, before unknown cells are given a zone.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum RosCell {
    /// Free.
    Free,
    /// Between the thresholds in `scale` mode, or 1..=99 in `raw` mode.
    Graded,
    /// Occupied.
    Occupied,
    /// Unknown.
    Unknown,
}

impl RosMapMeta {
    /// Classifies one pixel from its channel mean `shade` in `[0, 255]`, as Nav2's
    /// `loadMapFromFile`: `occ = (255 - shade) / 255` (or `shade / 255` with `negate`);
    /// occupied if `occ > occupied_thresh`, free if `occ < free_thresh`, else unknown
    /// (trinary) or graded (scale). Raw mode reads `round(shade)` as a percentage.
    #[must_use]
    pub fn classify(&self, shade: f64) -> RosCell {
        let s = shade / 255.0;
        match self.mode {
            RosMode::Raw => match shade.round() {
                0.0 => RosCell::Free,
                100.0 => RosCell::Occupied,
                v if (1.0..100.0).contains(&v) => RosCell::Graded,
                _ => RosCell::Unknown,
            },
            RosMode::Trinary | RosMode::Scale => {
                self.classify_occupancy(if self.negate { s } else { 1.0 - s })
            }
        }
    }

    /// Classifies an occupancy probability `occ` in `[0, 1]` by the thresholds: occupied
    /// above `occupied_thresh`, free below `free_thresh`, else graded (`scale`) or
    /// unknown. The one rule for pictures and for `nav_msgs/OccupancyGrid` cells (whose
    /// value is the occupancy in percent).
    ///
    /// ```
    /// use envmap::{RosCell, RosMapMeta, RosMode};
    /// let meta = RosMapMeta {
    ///     image: "map.pgm".into(), resolution: 0.05, origin: hyplan_core::Point2::origin(),
    ///     yaw: 0.0, negate: false, occupied_thresh: 0.65, free_thresh: 0.196,
    ///     mode: RosMode::Trinary,
    /// };
    /// assert_eq!(meta.classify_occupancy(1.0), RosCell::Occupied);
    /// assert_eq!(meta.classify_occupancy(0.5), RosCell::Unknown);
    /// ```
    #[must_use]
    pub fn classify_occupancy(&self, occ: f64) -> RosCell {
        if occ > self.occupied_thresh {
            RosCell::Occupied
        } else if occ < self.free_thresh {
            RosCell::Free
        } else if self.mode == RosMode::Scale {
            RosCell::Graded
        } else {
            RosCell::Unknown
        }
    }

    /// The map of a picture under these rules: occupied -> `Forbidden`, free -> `Free`,
    /// graded -> `Risk`, unknown -> `unknown` (hyplan's default is `Forbidden`). Pixel
    /// `(x, y)` (row from the top) is cell `(x, height - 1 - y)`; alpha is ignored.
    ///
    /// # Errors
    ///
    /// [`MapError::Grid`] if the picture is empty.
    pub fn to_map(&self, picture: &Picture, unknown: Zone) -> Result<GridMap, MapError> {
        let (w, h) = (picture.width(), picture.height());
        let grid_err = |source| MapError::Grid {
            path: self.image.clone(),
            source,
        };
        let mut map = GridMap::filled(w, h, Zone::Free).map_err(grid_err)?;
        // 256 possible shades per channel count: classify each grey level once.
        let zone_of = |c: RosCell| match c {
            RosCell::Free => Zone::Free,
            RosCell::Graded => Zone::Risk,
            RosCell::Occupied => Zone::Forbidden,
            RosCell::Unknown => unknown,
        };
        let zones = map.zones_mut();
        for y in 0..h {
            let j = h - 1 - y;
            for x in 0..w {
                zones[j * w + x] = zone_of(self.classify(picture.channel_mean(x, y)));
            }
        }
        map.with_frame(self.resolution, self.origin)
            .map_err(grid_err)
    }
}

/// Counts of a ROS map's cells by class: `[free, graded, occupied, unknown]`.
#[must_use]
pub fn ros_cell_counts(meta: &RosMapMeta, picture: &Picture) -> [usize; 4] {
    let mut counts = [0; 4];
    for y in 0..picture.height() {
        for x in 0..picture.width() {
            let k = match meta.classify(picture.channel_mean(x, y)) {
                RosCell::Free => 0,
                RosCell::Graded => 1,
                RosCell::Occupied => 2,
                RosCell::Unknown => 3,
            };
            counts[k] += 1;
        }
    }
    counts
}

/// Grey value of free cells in the files [`write_ros`] and [`write_ros_occupancy`] write
/// (map_saver's value): `occ` = 0.004, below `free_thresh`.
pub const ROS_FREE: u8 = 254;
/// Grey value of high-risk cells in the files [`write_ros`] writes: `occ` = 0.498, strictly
/// between the thresholds, so `mode: scale` reads it as a graded cost (hyplan: `Risk`;
/// Nav2: occupancy 67 of 100) and the trinary rule as unknown.
pub const ROS_RISK: u8 = 128;
/// Grey value of forbidden / occupied cells in the files [`write_ros`] and
/// [`write_ros_occupancy`] write (map_saver's value): `occ` = 1, above `occupied_thresh`.
pub const ROS_OCCUPIED: u8 = 0;
/// Grey value of unknown cells in the files [`write_ros_occupancy`] writes (map_saver's
/// value in trinary mode): `occ` = 0.19608, just above `free_thresh` 0.196 and below
/// `occupied_thresh`, hence unknown.
pub const ROS_UNKNOWN: u8 = 205;
/// `occupied_thresh` in the YAML files hyplan writes (map_saver's).
pub const ROS_OCCUPIED_THRESH: f64 = 0.65;
/// `free_thresh` in the YAML files hyplan writes (map_saver's).
pub const ROS_FREE_THRESH: f64 = 0.196;

/// One cell of an occupancy grid as ROS's `nav_msgs/OccupancyGrid` knows it (values 0,
/// 100 and -1), for [`write_ros_occupancy`].
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Occupancy {
    /// Seen and free (ROS 0).
    Free,
    /// Seen and occupied (ROS 100).
    Occupied,
    /// Never seen (ROS -1).
    Unknown,
}

/// Writes a three-zone `map` as a ROS map: `yaml_path` plus a binary PGM (`P5`) beside it
/// with the same stem.
///
/// Encoding (ours: map_saver has no notion of a high-risk zone): `mode: scale`,
/// `negate: 0`, `occupied_thresh: 0.65`, `free_thresh: 0.196` and the map's resolution and
/// origin (yaw 0); safe cells are [`ROS_FREE`] (254) and forbidden cells [`ROS_OCCUPIED`]
/// (0), as map_saver writes free and occupied cells, and high-risk cells [`ROS_RISK`]
/// (128), whose occupancy 0.498 lies strictly between the thresholds. So every reader
/// keeps the zones apart: [`load_map`](crate::load_map) and map_server in `scale` mode read
/// high-risk cells as a graded cost (hyplan's `Risk`, Nav2's occupancy 67), and a reader
/// applying the trinary rule sees them as unknown, never as free. Rows are written top
/// (highest y) first, as map_server expects. For an occupancy grid with unknown cells, use
/// [`write_ros_occupancy`].
///
/// # Errors
///
/// [`MapError::Write`] on io failures.
pub fn write_ros(map: &GridMap, yaml_path: &Path) -> Result<(), MapError> {
    write_ros_turned(map, 0.0, yaml_path)
}

/// [`write_ros`] with `yaw` (radians) as the origin's third value: the grid turned by
/// `yaw` about its lower-left corner in the map frame, as a ROS map loaded with that yaw
/// was ([`InputFrame::yaw`](crate::InputFrame::yaw)), so that its cells land where the
/// input's did. A yaw that is not finite is written as 0.
///
/// ```
/// use envmap::{GridMap, LoadOptions, load_map, write_ros_turned};
/// let dir = std::env::temp_dir().join(format!("envmap-turned-{}", std::process::id()));
/// std::fs::create_dir_all(&dir)?;
/// let yaml = dir.join("turned.yaml");
/// let map = GridMap::from_ascii("..#\n...")?.with_frame(0.05, hyplan_core::Point2::new(2.0, 1.0))?;
/// write_ros_turned(&map, 3.14, &yaml)?;
/// assert!(std::fs::read_to_string(&yaml)?.contains("origin: [2.0, 1.0, 3.14]"));
/// let back = load_map(&yaml, &LoadOptions::default())?;
/// assert_eq!(back.frame.yaw(), 3.14);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`MapError::Write`] on io failures.
pub fn write_ros_turned(map: &GridMap, yaw: f64, yaml_path: &Path) -> Result<(), MapError> {
    let (w, h) = (map.width(), map.height());
    let mut data = vec![0u8; w * h];
    for j in 0..h {
        for i in 0..w {
            data[(h - 1 - j) * w + i] = match map.cell_zone(i, j) {
                Zone::Free => ROS_FREE,
                Zone::Risk => ROS_RISK,
                Zone::Forbidden => ROS_OCCUPIED,
            };
        }
    }
    write_pair(
        yaml_path,
        (w, h, data),
        map.resolution(),
        (map.origin(), if yaw.is_finite() { yaw } else { 0.0 }),
        RosMode::Scale,
    )
}

/// Writes an occupancy grid of free, occupied and unknown cells as map_saver writes one: a
/// binary PGM (`P5`) with free cells [`ROS_FREE`] (254), occupied cells [`ROS_OCCUPIED`]
/// (0) and unknown cells [`ROS_UNKNOWN`] (205), and `yaml_path` beside it saying
/// `mode: trinary`, `negate: 0`, `occupied_thresh: 0.65`, `free_thresh: 0.196`,
/// `resolution` and `origin` (yaw 0). Every ROS map reader gives back the three classes;
/// [`load_map`](crate::load_map) reads unknown cells as `Forbidden`, or `Free` with
/// [`LoadOptions::unknown_free`](crate::LoadOptions).
///
/// `cells` is row-major from the bottom row (cell `(i, j)` at `j * width + i`, as
/// `nav_msgs/OccupancyGrid` and [`GridMap`] store them); rows are written top (highest y)
/// first. `origin` is the lower-left corner of cell (0, 0), metres.
///
/// # Errors
///
/// [`MapError::InvalidParameter`] when `cells` does not hold `width x height` cells, a
/// side is 0, or `resolution` is not finite and > 0, or `origin` is not finite;
/// [`MapError::Write`] on io failures.
///
/// ```
/// use envmap::{Occupancy, RosCell, write_ros_occupancy};
/// use hyplan_core::Point2;
/// let dir = std::env::temp_dir().join(format!("envmap-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir)?;
/// let yaml = dir.join("built.yaml");
/// let cells = [Occupancy::Free, Occupancy::Occupied, Occupancy::Unknown];
/// write_ros_occupancy(&cells, 3, 1, 0.05, Point2::new(-1.0, 2.0), &yaml)?;
/// let pgm = std::fs::read(dir.join("built.pgm"))?;
/// assert!(pgm.starts_with(b"P5\n"));
/// assert!(pgm.ends_with(&[254, 0, 205]));
/// let meta = envmap::read_ros_yaml(&yaml)?;
/// assert_eq!(meta.classify(205.0), RosCell::Unknown);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_ros_occupancy(
    cells: &[Occupancy],
    width: usize,
    height: usize,
    resolution: f64,
    origin: Point2,
    yaml_path: &Path,
) -> Result<(), MapError> {
    let invalid = |name: &'static str, value: String, reason: &str| MapError::InvalidParameter {
        name,
        value,
        reason: reason.to_string(),
    };
    if width == 0 || height == 0 || width.checked_mul(height) != Some(cells.len()) {
        return Err(invalid(
            "cells",
            format!("{} cells for {width} x {height}", cells.len()),
            "must hold width x height >= 1 cells",
        ));
    }
    if !(resolution.is_finite() && resolution > 0.0) {
        return Err(invalid(
            "resolution",
            resolution.to_string(),
            "must be finite and > 0",
        ));
    }
    if !(origin.x.is_finite() && origin.y.is_finite()) {
        return Err(invalid(
            "origin",
            format!("({}, {})", origin.x, origin.y),
            "must be finite",
        ));
    }
    let mut data = vec![0u8; cells.len()];
    for (j, row) in cells.chunks_exact(width).enumerate() {
        let out = &mut data[(height - 1 - j) * width..(height - j) * width];
        for (px, c) in out.iter_mut().zip(row) {
            *px = match c {
                Occupancy::Free => ROS_FREE,
                Occupancy::Occupied => ROS_OCCUPIED,
                Occupancy::Unknown => ROS_UNKNOWN,
            };
        }
    }
    write_pair(
        yaml_path,
        (width, height, data),
        resolution,
        (origin, 0.0),
        RosMode::Trinary,
    )
}

/// Writes the PGM (`P5`, rows top first in `data`) beside `yaml_path` and the YAML naming
/// it, in `mode` with map_saver's thresholds, the origin's corner and yaw given.
fn write_pair(
    yaml_path: &Path,
    (w, h, data): (usize, usize, Vec<u8>),
    resolution: f64,
    (origin, yaw): (Point2, f64),
    mode: RosMode,
) -> Result<(), MapError> {
    let pgm_path = yaml_path.with_extension("pgm");
    let pgm_name = pgm_path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "map.pgm".into());
    let pic = Picture::grey(w, h, data).expect("w * h bytes");
    let bytes = crate::io::image::encode_pnm(
        &pic,
        crate::io::image::Pnm::Grey,
        &format!("{resolution:?} m/pix"),
    );
    std::fs::write(&pgm_path, bytes).map_err(|source| MapError::Write {
        path: pgm_path.clone(),
        source,
    })?;
    let pgm_name = serde_yaml_ng::to_string(&Value::String(pgm_name)).unwrap_or_default();
    let mode = match mode {
        RosMode::Trinary => "trinary",
        RosMode::Scale => "scale",
        RosMode::Raw => "raw",
    };
    let yaml = format!(
        "image: {}\nmode: {mode}\nresolution: {:?}\norigin: [{:?}, {:?}, {:?}]\n\
         negate: 0\noccupied_thresh: {ROS_OCCUPIED_THRESH:?}\nfree_thresh: {ROS_FREE_THRESH:?}\n",
        pgm_name.trim(),
        resolution,
        origin.x,
        origin.y,
        yaw
    );
    std::fs::write(yaml_path, yaml).map_err(|source| MapError::Write {
        path: yaml_path.to_path_buf(),
        source,
    })
}

/// `v` in YAML's flow style, on one line.
fn one_line(v: &Value) -> String {
    match v {
        Value::Sequence(items) => {
            let items: Vec<String> = items.iter().map(one_line).collect();
            format!("[{}]", items.join(", "))
        }
        Value::Mapping(m) => {
            let items: Vec<String> = m
                .iter()
                .map(|(k, v)| format!("{}: {}", one_line(k), one_line(v)))
                .collect();
            format!("{{{}}}", items.join(", "))
        }
        Value::Tagged(t) => format!("{} {}", t.tag, one_line(&t.value)),
        scalar => serde_yaml_ng::to_string(scalar)
            .map(|s| s.trim().replace('\n', " "))
            .unwrap_or_else(|_| format!("{scalar:?}")),
    }
}
