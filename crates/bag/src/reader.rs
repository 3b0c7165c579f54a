//! Reading the last `nav_msgs/msg/OccupancyGrid` of a topic from a bag, with every
//! size checked before it is trusted.

use std::collections::BTreeSet;
use std::io::{BufReader, Read};
use std::path::Path;

use crate::msgs::OccupancyGrid;
use crate::schema::RosMessage;
use crate::{BagError, CdrError};

/// The topic maps are read from when none is named (Nav2's and slam_toolbox's).
pub const DEFAULT_MAP_TOPIC: &str = "/map";

/// Reads the last OccupancyGrid on `topic` of the MCAP file at `path`, refusing grids of
/// more than `max_cells` cells.
///
/// The file is read as a stream: memory holds one chunk and the last map seen.
///
/// # Errors
///
/// [`BagError::Io`] (missing file), [`BagError::Mcap`] (malformed or truncated file),
/// [`BagError::NoTopic`], [`BagError::WrongSchema`] (not an OccupancyGrid in CDR),
/// [`BagError::Decode`], and [`BagError::Field`] for a grid whose `data` does not hold
/// `width x height` cells, whose size exceeds `max_cells`, or whose resolution is not
/// finite and positive.
///
/// ```no_run
/// let grid = bag::read_occupancy_grid("run.mcap".as_ref(), "/map", 100_000_000)?;
/// println!("{} x {} at {} m", grid.info.width, grid.info.height, grid.info.resolution);
/// # Ok::<(), bag::BagError>(())
/// ```
pub fn read_occupancy_grid(
    path: &Path,
    topic: &str,
    max_cells: usize,
) -> Result<OccupancyGrid, BagError> {
    let file = std::fs::File::open(path).map_err(|source| BagError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    occupancy_grid_from(BufReader::new(file), path, topic, max_cells)
}

/// [`read_occupancy_grid`] from any reader of MCAP bytes; `path` names it in errors.
///
/// # Errors
///
/// As [`read_occupancy_grid`].
pub fn occupancy_grid_from(
    source: impl Read,
    path: &Path,
    topic: &str,
    max_cells: usize,
) -> Result<OccupancyGrid, BagError> {
    let mut topics = BTreeSet::new();
    let mut last: Option<(u64, Vec<u8>)> = None;
    for message in mcap::io::MessageReader::new(source) {
        let message = message.map_err(|source| BagError::Mcap {
            path: path.to_path_buf(),
            source,
        })?;
        let channel = &message.channel;
        if channel.topic != topic {
            topics.insert(channel.topic.clone());
            continue;
        }
        let schema = channel.schema.as_ref().map_or("", |s| s.name.as_str());
        if schema != OccupancyGrid::NAME || channel.message_encoding != "cdr" {
            return Err(BagError::WrongSchema {
                path: path.to_path_buf(),
                topic: topic.to_string(),
                found: schema.to_string(),
                encoding: channel.message_encoding.clone(),
                expected: OccupancyGrid::NAME,
            });
        }
        if last.as_ref().is_none_or(|(t, _)| message.log_time >= *t) {
            last = Some((message.log_time, message.data.into_owned()));
        }
    }
    let Some((log_time, data)) = last else {
        return Err(BagError::NoTopic {
            path: path.to_path_buf(),
            topic: topic.to_string(),
            topics: topics.into_iter().collect(),
        });
    };
    let grid: OccupancyGrid =
        crate::decode(&data).map_err(|source: CdrError| BagError::Decode {
            path: path.to_path_buf(),
            topic: topic.to_string(),
            log_time,
            source,
        })?;
    check_grid(&grid, path, topic, max_cells)?;
    Ok(grid)
}

/// The sizes of a decoded grid: cells within the limit, as many as the size says, a
/// usable resolution.
fn check_grid(
    grid: &OccupancyGrid,
    path: &Path,
    topic: &str,
    max_cells: usize,
) -> Result<(), BagError> {
    let field = |field: &'static str, value: String, reason: String| BagError::Field {
        path: path.to_path_buf(),
        topic: topic.to_string(),
        field,
        value,
        reason,
    };
    let (w, h) = (grid.info.width as usize, grid.info.height as usize);
    let size = format!("{w} x {h}");
    match w.checked_mul(h) {
        Some(0) => {
            return Err(field(
                "info.width x info.height",
                size,
                "must be >= 1 cell".into(),
            ));
        }
        Some(n) if n <= max_cells => {}
        _ => {
            return Err(field(
                "info.width x info.height",
                size,
                format!("above the memory limit of {max_cells} cells"),
            ));
        }
    }
    if grid.data.len() != w * h {
        return Err(field(
            "data",
            format!("{} cells", grid.data.len()),
            format!("must hold info.width x info.height = {} cells", w * h),
        ));
    }
    let r = grid.info.resolution;
    if !(r.is_finite() && r > 0.0) {
        return Err(field(
            "info.resolution",
            r.to_string(),
            "must be finite and > 0".into(),
        ));
    }
    let o = grid.info.origin.position;
    if !(o.x.is_finite() && o.y.is_finite()) {
        return Err(field(
            "info.origin.position",
            format!("({}, {})", o.x, o.y),
            "must be finite".into(),
        ));
    }
    Ok(())
}
