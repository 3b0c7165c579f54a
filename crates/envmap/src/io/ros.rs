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
                let occ = if self.negate { s } else { 1.0 - s };
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

/// Grey value written for free cells by [`write_ros`] (map_saver's value).
pub const ROS_FREE: u8 = 254;
/// Grey value written for high-risk cells by [`write_ros`]: `occ` = 0.498, between the
/// thresholds, read back as graded (`Risk`) in `scale` mode.
pub const ROS_RISK: u8 = 128;
/// Grey value written for forbidden cells by [`write_ros`] (map_saver's value).
pub const ROS_OCCUPIED: u8 = 0;

/// Writes `map` as a ROS map: `yaml_path` plus a binary PGM beside it with the same stem.
///
/// The YAML says `mode: scale`, `negate: 0`, `occupied_thresh: 0.65`,
/// `free_thresh: 0.196` and the map's resolution and origin (yaw 0). Free cells are 254,
/// forbidden 0 (as map_saver writes them) and high-risk 128, which `scale` mode reads as a
/// graded cost between the thresholds, so all three zones survive the round trip through
/// [`load_map`](crate::load_map) (a trinary reader would see high-risk cells as unknown).
///
/// # Errors
///
/// [`MapError::Write`] / [`MapError::Encode`] on io failures,
/// [`MapError::NoImageSupport`] without the `image` feature.
pub fn write_ros(map: &GridMap, yaml_path: &Path) -> Result<(), MapError> {
    let pgm_path = yaml_path.with_extension("pgm");
    let pgm_name = pgm_path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "map.pgm".into());
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
    let pic = Picture::grey(w, h, data).expect("w * h bytes");
    crate::write_picture(&pic, &pgm_path)?;
    let o = map.origin();
    let pgm_name = serde_yaml_ng::to_string(&Value::String(pgm_name)).unwrap_or_default();
    let yaml = format!(
        "image: {}\nmode: scale\nresolution: {:?}\norigin: [{:?}, {:?}, 0.0]\n\
         negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
        pgm_name.trim(),
        map.resolution(),
        o.x,
        o.y
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
