//! MovingAI `.map` files (Sturtevant, "Benchmarks for Grid-Based Pathfinding", 2012).

use std::path::Path;

use hyplan_core::Zone;

use crate::{GridMap, MapError};

/// Reads a MovingAI `.map` file into a two-zone map (resolution 1, origin (0, 0)).
///
/// The header is `type <name>`, `height <H>`, `width <W>` (in any order) then a line
/// `map`, followed by exactly `H` rows of `W` characters. `.`, `G` and `S` are passable
/// ([`Zone::Free`]); every other character (`@`, `O`, `T`, `W`, ...) is
/// [`Zone::Forbidden`]. Row 0 of the file is the top, i.e. map row `H - 1`. Blank lines
/// after the last row and `\r\n` line ends are accepted.
///
/// # Errors
///
/// [`MapError::Read`] if the file cannot be read, [`MapError::Line`] (with the file line)
/// for a missing or malformed header, no `map` line, or rows not matching the header,
/// [`MapError::TooLarge`] when the header gives more than
/// [`DEFAULT_MAX_CELLS`](crate::DEFAULT_MAX_CELLS) cells ([`load_map`](crate::load_map)
/// takes the limit from its options).
pub fn read_movingai(path: &Path) -> Result<GridMap, MapError> {
    read_movingai_limited(path, crate::io::DEFAULT_MAX_CELLS)
}

/// [`read_movingai`] with a memory limit of `max_cells` cells.
pub(crate) fn read_movingai_limited(path: &Path, max_cells: usize) -> Result<GridMap, MapError> {
    let bytes = std::fs::read(path).map_err(|source| MapError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    parse_movingai_limited(&bytes, path, max_cells)
}

/// Parses the bytes of a MovingAI `.map` file; `path` only names the file in errors.
///
/// # Errors
///
/// As [`read_movingai`], minus the io error.
///
/// ```
/// use envmap::parse_movingai;
/// use hyplan_core::Zone;
/// let text = b"type octile\nheight 2\nwidth 3\nmap\n..@\nT.G\n";
/// let map = parse_movingai(text, "tiny.map".as_ref())?;
/// assert_eq!((map.width(), map.height()), (3, 2));
/// assert_eq!(map.cell_zone(2, 1), Zone::Forbidden); // '@', top row
/// assert_eq!(map.cell_zone(0, 0), Zone::Forbidden); // 'T', bottom row
/// assert_eq!(map.zone_counts(), [4, 0, 2]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn parse_movingai(bytes: &[u8], path: &Path) -> Result<GridMap, MapError> {
    parse_movingai_limited(bytes, path, crate::io::DEFAULT_MAX_CELLS)
}

/// [`parse_movingai`] with a memory limit of `max_cells` cells, checked on the header.
fn parse_movingai_limited(
    bytes: &[u8],
    path: &Path,
    max_cells: usize,
) -> Result<GridMap, MapError> {
    let err = |line: usize, reason: String| MapError::Line {
        path: path.to_path_buf(),
        line,
        reason,
    };
    let mut lines = bytes
        .split(|&b| b == b'\n')
        .map(|l| l.strip_suffix(b"\r").unwrap_or(l))
        .enumerate()
        .map(|(k, l)| (k + 1, l));
    let (mut width, mut height) = (None, None);
    let mut last_line = 0;
    loop {
        let Some((n, line)) = lines.next() else {
            return Err(err(last_line, "no `map` line after the header".into()));
        };
        last_line = n;
        let text = String::from_utf8_lossy(line);
        let mut words = text.split_whitespace();
        match (words.next(), words.next(), words.next()) {
            (None, _, _) => continue,
            (Some("map"), None, _) => break,
            (Some("type"), Some(_), None) => {}
            (Some(key @ ("height" | "width")), Some(value), None) => {
                let v: usize =
                    value.parse().ok().filter(|&v| v > 0).ok_or_else(|| {
                        err(n, format!("{key} {value:?} is not a positive integer"))
                    })?;
                if key == "height" {
                    height = Some(v);
                } else {
                    width = Some(v);
                }
            }
            _ => {
                return Err(err(
                    n,
                    format!("unexpected header line {:?}", truncate(&text)),
                ));
            }
        }
    }
    let width = width.ok_or_else(|| err(last_line, "no `width` line before `map`".into()))?;
    let height = height.ok_or_else(|| err(last_line, "no `height` line before `map`".into()))?;
    crate::io::check_cells(path, width, height, max_cells)?;
    // Collect the rows before allocating, so a huge header cannot allocate more than the file.
    let mut rows = Vec::new();
    for (n, line) in lines {
        if rows.len() == height {
            if line.iter().all(u8::is_ascii_whitespace) {
                continue;
            }
            return Err(err(
                n,
                format!("more than the {height} rows the header gives"),
            ));
        }
        if line.len() != width {
            if line.is_empty() {
                // Tolerated only as trailing blank lines: checked by the count below.
                continue;
            }
            return Err(err(
                n,
                format!(
                    "row has {} characters, the header gives width {width}",
                    line.len()
                ),
            ));
        }
        rows.push(line);
    }
    if rows.len() != height {
        return Err(err(
            last_line + rows.len() + 1,
            format!("{} rows, the header gives height {height}", rows.len()),
        ));
    }
    let mut map = GridMap::filled(width, height, Zone::Free).map_err(|source| MapError::Grid {
        path: path.to_path_buf(),
        source,
    })?;
    let zones = map.zones_mut();
    for (r, row) in rows.iter().enumerate() {
        let j = height - 1 - r;
        for (i, &c) in row.iter().enumerate() {
            if !matches!(c, b'.' | b'G' | b'S') {
                zones[j * width + i] = Zone::Forbidden;
            }
        }
    }
    Ok(map)
}

fn truncate(s: &str) -> String {
    s.chars().take(40).collect()
}
