//! MovingAI scenario files (`.scen`, version 1).
//!
//! Sturtevant's grid-pathfinding benchmark (N. Sturtevant, "Benchmarks for Grid-Based
//! Pathfinding", IEEE TCIAIG 4(2), 2012). A `.scen` file starts with `version 1`; every later
//! line holds 9 tab-separated fields: bucket, map file, map width, map height, start x,
//! start y, goal x, goal y, optimal length. `x` is the column and `y` the row **counted from
//! the top** of the `.map` file (its first row after `map`). The lengths are for 8-connected
//! moves costing 1 and sqrt 2 with no corner cutting.

use std::path::{Path, PathBuf};

/// One scenario line of a `.scen` file.
#[derive(Debug, Clone, PartialEq)]
pub struct ScenEntry {
    /// 1-based line number in the file.
    pub line: usize,
    /// Bucket (field 1).
    pub bucket: u32,
    /// The map file as written (old files carry a directory, e.g. `maps/dao/arena.map`).
    pub map: String,
    /// Map width the file declares, cells.
    pub width: usize,
    /// Map height the file declares, cells.
    pub height: usize,
    /// Start `(x, y)`: column, row from the top.
    pub start: (usize, usize),
    /// Goal `(x, y)`: column, row from the top.
    pub goal: (usize, usize),
    /// The optimal length the file gives.
    pub optimal: f64,
}

impl ScenEntry {
    /// The map file name without its directory (`arena.map` for `maps/dao/arena.map`).
    #[must_use]
    pub fn map_file_name(&self) -> &str {
        self.map.rsplit(['/', '\\']).next().unwrap_or(&self.map)
    }

    /// Converts a `.scen` `(x, y)` (row from the top) to a grid cell `(i, j)` (row from the
    /// bottom) of a map `height` rows tall; `None` when `y >= height`.
    #[must_use]
    pub fn to_cell((x, y): (usize, usize), height: usize) -> Option<(usize, usize)> {
        (y < height).then(|| (x, height - 1 - y))
    }
}

/// Why a `.scen` file could not be read.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ScenError {
    /// The file could not be read.
    #[error("{}: cannot read: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The first line is not `version 1` (or `version 1.0`).
    #[error("{}:{line}: expected `version 1`, found {found:?}", path.display())]
    Version {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// What the line says.
        found: String,
    },
    /// A scenario line does not have 9 fields.
    #[error("{}:{line}: expected 9 tab-separated fields, found {found}", path.display())]
    FieldCount {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// Fields found.
        found: usize,
    },
    /// A numeric field does not parse, or the length is negative or not finite.
    #[error("{}:{line}: field {field} is not a valid {expected}: {value:?}", path.display())]
    Number {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// The field's name (`bucket`, `width`, `start x`, ..., `optimal length`).
        field: &'static str,
        /// What it should be.
        expected: &'static str,
        /// The text found.
        value: String,
    },
}

/// Reads a `.scen` file.
///
/// # Errors
///
/// [`ScenError`] naming the file and the 1-based line: unreadable file, missing `version`
/// line, a line with fewer or more than 9 fields, a field that is not a number.
pub fn read_scen(path: impl AsRef<Path>) -> Result<Vec<ScenEntry>, ScenError> {
    let path = path.as_ref();
    let text = std::fs::read_to_string(path).map_err(|source| ScenError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse_scen(&text, path)
}

/// Parses the text of a `.scen` file; `path` only names the file in errors.
///
/// Fields are split on tabs; lines without tabs (hand-written files) are split on
/// whitespace. Blank lines are skipped.
///
/// # Errors
///
/// As [`read_scen`], except I/O.
///
/// # Example
///
/// ```
/// use search::parse_scen;
/// let text = "version 1\n0\tmaps/dao/arena.map\t49\t49\t1\t11\t1\t12\t1\n";
/// let scen = parse_scen(text, "arena.map.scen".as_ref())?;
/// assert_eq!(scen[0].start, (1, 11));
/// assert_eq!(scen[0].map_file_name(), "arena.map");
/// assert!(parse_scen("version 1\n0\tarena.map\t49\n", "x.scen".as_ref()).is_err());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn parse_scen(text: &str, path: &Path) -> Result<Vec<ScenEntry>, ScenError> {
    let mut out = Vec::new();
    let mut seen_version = false;
    for (n, raw) in text.lines().enumerate() {
        let line = n + 1;
        let raw = raw.trim_end_matches('\r');
        if raw.trim().is_empty() {
            continue;
        }
        if !seen_version {
            let mut words = raw.split_whitespace();
            let ok = words.next() == Some("version")
                && words.next().is_some_and(|v| v == "1" || v == "1.0")
                && words.next().is_none();
            if !ok {
                return Err(ScenError::Version {
                    path: path.to_path_buf(),
                    line,
                    found: raw.to_string(),
                });
            }
            seen_version = true;
            continue;
        }
        let fields: Vec<&str> = if raw.contains('\t') {
            raw.split('\t').map(str::trim).collect()
        } else {
            raw.split_whitespace().collect()
        };
        if fields.len() != 9 {
            return Err(ScenError::FieldCount {
                path: path.to_path_buf(),
                line,
                found: fields.len(),
            });
        }
        let int = |k: usize, field: &'static str| -> Result<usize, ScenError> {
            fields[k].parse().map_err(|_| ScenError::Number {
                path: path.to_path_buf(),
                line,
                field,
                expected: "non-negative integer",
                value: fields[k].to_string(),
            })
        };
        let optimal: f64 = fields[8]
            .parse()
            .ok()
            .filter(|v: &f64| v.is_finite() && *v >= 0.0)
            .ok_or_else(|| ScenError::Number {
                path: path.to_path_buf(),
                line,
                field: "optimal length",
                expected: "finite non-negative number",
                value: fields[8].to_string(),
            })?;
        out.push(ScenEntry {
            line,
            bucket: u32::try_from(int(0, "bucket")?).map_err(|_| ScenError::Number {
                path: path.to_path_buf(),
                line,
                field: "bucket",
                expected: "32-bit integer",
                value: fields[0].to_string(),
            })?,
            map: fields[1].to_string(),
            width: int(2, "map width")?,
            height: int(3, "map height")?,
            start: (int(4, "start x")?, int(5, "start y")?),
            goal: (int(6, "goal x")?, int(7, "goal y")?),
            optimal,
        });
    }
    if !seen_version {
        return Err(ScenError::Version {
            path: path.to_path_buf(),
            line: 1,
            found: String::new(),
        });
    }
    Ok(out)
}
