//! The three-zone occupancy grid.

use std::fmt;
use std::sync::OnceLock;

use hyplan_core::{Bounds, Point2, Zone};

use crate::{CellBits, CellFrame, DistanceField, Mask, distance_transform};

/// A grid map whose cells are [`Zone::Free`], [`Zone::Risk`] or [`Zone::Forbidden`].
///
/// # Frame conventions
///
/// - Cell `(i, j)`: `i` is the column (x), `j` the row **counted from the bottom** (y up),
///   as in ROS `map_server`. Cell `(0, 0)` is the lower-left cell.
/// - `origin` is the world position of the lower-left **corner** of cell `(0, 0)`;
///   `resolution` is the side of a cell in world units (metres for ROS maps, pixels or
///   millimetres for pictures, cells for MovingAI maps).
/// - Cell `(i, j)` covers the closed square `origin + [i, i+1] x [j, j+1] * resolution`;
///   its centre is [`cell_center`](GridMap::cell_center).
/// - Pictures and MovingAI files are written top row first, so their row `r` is map row
///   `height - 1 - r`. Loaders do this flip; [`from_ascii`](GridMap::from_ascii) too.
///
/// Zones take one byte per cell, stored row-major from the bottom row.
///
/// Which zones block motion is the map's [`blocked_from`](GridMap::blocked_from): by
/// default only [`Zone::Forbidden`]; [`avoiding_risk`](GridMap::avoiding_risk) makes the
/// high-risk band block too (a "safe map" in seed 000's sense).
///
/// ```
/// use envmap::GridMap;
/// use hyplan_core::{Point2, Zone};
/// let map = GridMap::from_ascii("
///     ..#
///     .~#
///     ...
/// ")?;
/// assert_eq!((map.width(), map.height()), (3, 3));
/// assert_eq!(map.cell_zone(2, 2), Zone::Forbidden); // top-right in the drawing
/// assert_eq!(map.cell_zone(1, 1), Zone::Risk);
/// assert_eq!(map.world_to_cell(Point2::new(2.5, 0.5)), Some((2, 0)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone)]
pub struct GridMap {
    width: usize,
    height: usize,
    resolution: f64,
    origin: Point2,
    /// The upper-right corner, `origin` plus the size times `resolution`, kept with the
    /// frame: [`bounds`](GridMap::bounds) is asked at every edge check and sample.
    corner: Point2,
    /// `1 / resolution` where that is a power of two, whose products are the quotients
    /// bit for bit ([`cell_units`](GridMap::cell_units)); `None` otherwise.
    inverse: Option<f64>,
    zones: Vec<Zone>,
    /// Cells whose zone is at least this one block motion (default [`Zone::Forbidden`]).
    pub blocked_from: Zone,
    /// Distance fields of the blocked cells for `blocked_from` = Risk and = Forbidden,
    /// computed on the first `clearance` query; reset when zones change.
    clearance_fields: [OnceLock<DistanceField>; 2],
    /// The stride tables of those fields ([`DistanceField::strides`]), made on first use;
    /// reset when zones change.
    stride_tables: [OnceLock<Vec<u8>>; 2],
    /// Those cells as packed bits ([`CellBits`]), made on first use; reset when zones
    /// change.
    cell_bits: [OnceLock<CellBits>; 2],
    /// Cells swept by edge checks since the zones last changed: past a share of the map,
    /// the checks make the stride table ([`crate::workspace`]).
    pub(crate) edge_work: crate::workspace::EdgeWork,
    /// Components of the passable cells and the runs the "no path" proof needs, computed
    /// on the first check ([`crate::connectivity`]); reset when zones change.
    connectivity: crate::connectivity::Cache,
    /// What callers prepared from the cells and handed back to be kept for their next
    /// call ([`keep`](GridMap::keep)); dropped when zones change, empty in a clone.
    kept: Kept,
}

/// How many values a map keeps for its callers ([`GridMap::keep`]).
pub const KEPT_MAX: usize = 2;

/// The values kept with a map, of any type.
#[derive(Default)]
struct Kept(std::sync::Mutex<Vec<Box<dyn std::any::Any + Send>>>);

impl Clone for Kept {
    /// A clone keeps nothing: what was prepared belongs to the original's cells.
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl PartialEq for GridMap {
    /// Same size, frame, zones and `blocked_from` (cached distance fields are ignored).
    fn eq(&self, other: &Self) -> bool {
        self.width == other.width
            && self.height == other.height
            && self.resolution == other.resolution
            && self.origin == other.origin
            && self.blocked_from == other.blocked_from
            && self.zones == other.zones
    }
}

/// Why a grid map could not be built from in-memory data.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum GridError {
    /// Width or height is zero, or their product overflows.
    #[error("invalid map size {width} x {height}")]
    InvalidSize {
        /// Columns.
        width: usize,
        /// Rows.
        height: usize,
    },
    /// Resolution is not a finite positive number.
    #[error("invalid resolution {0}: must be finite and > 0")]
    InvalidResolution(f64),
    /// Origin is not finite.
    #[error("invalid origin ({0}, {1}): must be finite")]
    InvalidOrigin(f64, f64),
    /// The zone vector does not have `width * height` cells.
    #[error("expected {expected} cells, got {got}")]
    CellCount {
        /// `width * height`.
        expected: usize,
        /// Length given.
        got: usize,
    },
    /// An ASCII map row has the wrong length or an unknown character.
    #[error("ascii map line {line}: {reason}")]
    Ascii {
        /// 1-based line among the non-empty lines.
        line: usize,
        /// What is wrong.
        reason: String,
    },
}

hyplan_core::grid_size!(GridMap);

impl GridMap {
    /// A map of `width x height` cells, all `zone`, with resolution 1 and origin (0, 0).
    ///
    /// # Errors
    ///
    /// [`GridError::InvalidSize`] when a side is zero or the cell count overflows.
    pub fn filled(width: usize, height: usize, zone: Zone) -> Result<Self, GridError> {
        let n = width
            .checked_mul(height)
            .filter(|&n| n > 0 && width <= u32::MAX as usize && height <= u32::MAX as usize)
            .ok_or(GridError::InvalidSize { width, height })?;
        Ok(Self {
            width,
            height,
            resolution: 1.0,
            origin: Point2::origin(),
            corner: Point2::new(width as f64, height as f64),
            inverse: Some(1.0),
            zones: vec![zone; n],
            blocked_from: Zone::Forbidden,
            clearance_fields: Default::default(),
            stride_tables: Default::default(),
            cell_bits: Default::default(),
            edge_work: Default::default(),
            connectivity: Default::default(),
            kept: Kept::default(),
        })
    }

    /// A map from its zones, row-major from the bottom row (`zones[j * width + i]`).
    ///
    /// # Errors
    ///
    /// Bad size, resolution, origin or cell count.
    pub fn from_zones(
        width: usize,
        height: usize,
        resolution: f64,
        origin: Point2,
        zones: Vec<Zone>,
    ) -> Result<Self, GridError> {
        // Checked before any allocation: the zones given are the map's only cell buffer
        // (no filled map built and replaced), so a map from an array costs one copy.
        let n = width
            .checked_mul(height)
            .filter(|&n| n > 0 && width <= u32::MAX as usize && height <= u32::MAX as usize)
            .ok_or(GridError::InvalidSize { width, height })?;
        if zones.len() != n {
            return Err(GridError::CellCount {
                expected: n,
                got: zones.len(),
            });
        }
        Self {
            width,
            height,
            resolution: 1.0,
            origin: Point2::origin(),
            corner: Point2::origin(),
            inverse: None,
            zones,
            blocked_from: Zone::Forbidden,
            clearance_fields: Default::default(),
            stride_tables: Default::default(),
            cell_bits: Default::default(),
            edge_work: Default::default(),
            connectivity: Default::default(),
            kept: Kept::default(),
        }
        .with_frame(resolution, origin)
    }

    /// The same map with another resolution and origin.
    ///
    /// # Errors
    ///
    /// [`GridError::InvalidResolution`] or [`GridError::InvalidOrigin`].
    pub fn with_frame(mut self, resolution: f64, origin: Point2) -> Result<Self, GridError> {
        if !(resolution.is_finite() && resolution > 0.0) {
            return Err(GridError::InvalidResolution(resolution));
        }
        if !(origin.x.is_finite() && origin.y.is_finite()) {
            return Err(GridError::InvalidOrigin(origin.x, origin.y));
        }
        self.resolution = resolution;
        self.origin = origin;
        self.corner = Point2::new(
            origin.x + self.width as f64 * resolution,
            origin.y + self.height as f64 * resolution,
        );
        self.inverse = exact_inverse(resolution);
        Ok(self)
    }

    /// A map drawn in ASCII, top row first (as it looks): `.` free, `~` high-risk, `#` (or
    /// `@`, `T`) forbidden. Blank lines and leading/trailing spaces are ignored.
    ///
    /// # Errors
    ///
    /// [`GridError::Ascii`] for ragged rows or unknown characters, or an empty drawing.
    pub fn from_ascii(text: &str) -> Result<Self, GridError> {
        let rows: Vec<&str> = text
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty())
            .collect();
        let height = rows.len();
        let width = rows.first().map_or(0, |r| r.chars().count());
        let mut map = Self::filled(width, height, Zone::Free)?;
        for (r, row) in rows.iter().enumerate() {
            if row.chars().count() != width {
                return Err(GridError::Ascii {
                    line: r + 1,
                    reason: format!("{} characters, expected {width}", row.chars().count()),
                });
            }
            let j = height - 1 - r;
            for (i, c) in row.chars().enumerate() {
                let zone = match c {
                    '.' => Zone::Free,
                    '~' => Zone::Risk,
                    '#' | '@' | 'T' => Zone::Forbidden,
                    other => {
                        return Err(GridError::Ascii {
                            line: r + 1,
                            reason: format!("unknown character {other:?} at column {}", i + 1),
                        });
                    }
                };
                map.zones[j * width + i] = zone;
            }
        }
        Ok(map)
    }

    /// Side of a cell, world units.
    #[must_use]
    pub const fn resolution(&self) -> f64 {
        self.resolution
    }

    /// World position of the lower-left corner of cell (0, 0).
    #[must_use]
    pub const fn origin(&self) -> Point2 {
        self.origin
    }

    /// The zones, row-major from the bottom row, one byte each.
    #[must_use]
    pub fn zones(&self) -> &[Zone] {
        &self.zones
    }

    /// Mutable access to the zones (row-major from the bottom row).
    pub fn zones_mut(&mut self) -> &mut [Zone] {
        self.clearance_fields = Default::default();
        self.stride_tables = Default::default();
        self.cell_bits = Default::default();
        self.edge_work = Default::default();
        self.connectivity = Default::default();
        self.kept = Kept::default();
        &mut self.zones
    }

    /// The flat index of cell `(i, j)`; the caller guarantees `i < width`, `j < height`.
    #[must_use]
    pub const fn cell_index(&self, i: usize, j: usize) -> usize {
        j * self.width + i
    }

    /// The zone of cell `(i, j)`, or `Forbidden` outside the map.
    #[must_use]
    pub fn cell_zone(&self, i: usize, j: usize) -> Zone {
        if i < self.width && j < self.height {
            self.zones[j * self.width + i]
        } else {
            Zone::Forbidden
        }
    }

    /// Sets the zone of cell `(i, j)`; ignored outside the map.
    pub fn set_cell_zone(&mut self, i: usize, j: usize, zone: Zone) {
        if i < self.width && j < self.height {
            self.clearance_fields = Default::default();
            self.stride_tables = Default::default();
            self.cell_bits = Default::default();
            self.edge_work = Default::default();
            self.connectivity = Default::default();
            self.kept = Kept::default();
            self.zones[j * self.width + i] = zone;
        }
    }

    /// Whether cell `(i, j)` lets motion through under [`blocked_from`](GridMap::blocked_from).
    #[must_use]
    pub fn cell_free(&self, i: usize, j: usize) -> bool {
        self.cell_zone(i, j) < self.blocked_from
    }

    /// The cell containing world point `p`, or `None` outside the map (or NaN).
    #[must_use]
    pub fn world_to_cell(&self, p: Point2) -> Option<(usize, usize)> {
        let (u, v) = self.cell_units(p);
        if !(u >= 0.0 && v >= 0.0) {
            return None;
        }
        // Truncation is the floor here (u and v are not negative), without libm's call;
        // through `i64` (a few instructions, where a conversion to unsigned is a dozen),
        // which differs from `as usize` only past 2^63, far outside any map.
        let (i, j) = (u as i64 as usize, v as i64 as usize);
        // A point on the upper or right border belongs to the last cell.
        let i = if i == self.width && u == self.width as f64 {
            i - 1
        } else {
            i
        };
        let j = if j == self.height && v == self.height as f64 {
            j - 1
        } else {
            j
        };
        (i < self.width && j < self.height).then_some((i, j))
    }

    /// The world position of the centre of cell `(i, j)`.
    #[must_use]
    pub fn cell_center(&self, i: usize, j: usize) -> Point2 {
        Point2::new(
            self.origin.x + (i as f64 + 0.5) * self.resolution,
            self.origin.y + (j as f64 + 0.5) * self.resolution,
        )
    }

    /// Where the cells lie in the world (without [`GridMap::world_to_cell`]'s rule for
    /// points on the upper and right borders).
    #[must_use]
    #[inline]
    pub const fn frame(&self) -> CellFrame {
        CellFrame::new(self.origin, self.resolution, self.width, self.height)
    }

    /// The world box the map covers.
    #[must_use]
    #[inline]
    pub const fn bounds(&self) -> Bounds {
        Bounds::new(self.origin, self.corner)
    }

    /// `p` in cells from the origin, `(p - origin) / resolution` on each axis, bit for
    /// bit: by a product where the resolution is a power of two (a division waits about
    /// four times as long, and the edge checks make two or three).
    #[inline]
    pub(crate) fn cell_units(&self, p: Point2) -> (f64, f64) {
        let (dx, dy) = (p.x - self.origin.x, p.y - self.origin.y);
        match self.inverse {
            Some(k) => (dx * k, dy * k),
            None => (dx / self.resolution, dy / self.resolution),
        }
    }

    /// The same map with the high-risk band blocking motion too (`blocked_from = Risk`).
    #[must_use]
    pub fn avoiding_risk(mut self) -> Self {
        self.blocked_from = Zone::Risk;
        self
    }

    /// The exact distance transform of the cells that block motion under the current
    /// [`blocked_from`](GridMap::blocked_from), computed once and cached (`None` when every
    /// cell blocks, i.e. `blocked_from == Zone::Free`).
    #[must_use]
    pub fn blocked_distance(&self) -> Option<&DistanceField> {
        self.distance_from(self.blocked_from)
    }

    /// The exact distance transform of the cells whose zone is at least `zone` (`Risk`:
    /// the band and the obstacles; `Forbidden`: the obstacles), computed once and cached
    /// (`None` for `Zone::Free`).
    #[must_use]
    pub fn distance_from(&self, zone: Zone) -> Option<&DistanceField> {
        let k = cache_slot(zone)?;
        Some(
            self.clearance_fields[k]
                .get_or_init(|| distance_transform(&Mask::from_zones_at_least(self, zone))),
        )
    }

    /// The stride table of the cells whose zone is at least `zone`
    /// ([`DistanceField::strides`] of [`distance_from`](Self::distance_from): a byte per
    /// cell, row-major from the bottom row, 0 on those cells, otherwise 1 + the whole
    /// cells a segment may run from any point of the cell without touching one), made
    /// once and cached (`None` for `Zone::Free`). Ray marches and edge checks stride
    /// through open space with it.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::Zone;
    /// let map = GridMap::from_ascii("#.....")?;
    /// let strides = map.strides_from(Zone::Forbidden).unwrap();
    /// assert_eq!(strides, &[0, 1, 1, 2, 3, 4]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn strides_from(&self, zone: Zone) -> Option<&[u8]> {
        let k = cache_slot(zone)?;
        let field = self.distance_from(zone)?;
        Some(self.stride_tables[k].get_or_init(|| field.strides()))
    }

    /// The cells whose zone is at least `zone` as packed bits by rows and by columns
    /// ([`CellBits`]), made once and cached (`None` for `Zone::Free`). Ray marches scan
    /// the last cells before an obstacle with them, a row or a column at a time.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::Zone;
    /// let map = GridMap::from_ascii("..#..#")?;
    /// let bits = map.bits_from(Zone::Forbidden).unwrap();
    /// assert_eq!(bits.first_in_row(0, 3, 5), Some(5));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn bits_from(&self, zone: Zone) -> Option<&CellBits> {
        let k = cache_slot(zone)?;
        Some(
            self.cell_bits[k]
                .get_or_init(|| CellBits::from_mask(&Mask::from_zones_at_least(self, zone))),
        )
    }

    /// Keeps `value`, something a caller prepared from this map's cells (a planner's
    /// search structures), for a later [`take_kept`](GridMap::take_kept): so that a query
    /// through an interface that hands over only the map (`hyplan_core::Planner`) costs
    /// what it searches, not the preparation again. Changing a zone drops what is kept;
    /// so does a clone, which keeps nothing. At most [`KEPT_MAX`] values are kept (the
    /// oldest goes first), as each may be as large as the map.
    ///
    /// ```
    /// use envmap::GridMap;
    /// let mut map = GridMap::from_ascii("...")?;
    /// map.keep(vec![1u8, 2, 3]);
    /// assert_eq!(map.take_kept(|v: &Vec<u8>| v.len() == 3), Some(vec![1, 2, 3]));
    /// assert_eq!(map.take_kept(|_: &Vec<u8>| true), None); // taken
    /// map.keep(7u32);
    /// map.set_cell_zone(0, 0, hyplan_core::Zone::Forbidden);
    /// assert_eq!(map.take_kept(|_: &u32| true), None); // the cells changed
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn keep<T: std::any::Any + Send>(&self, value: T) {
        // A poisoned lock only means another thread panicked while holding it; the list
        // itself is always whole.
        let mut kept = self
            .kept
            .0
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if kept.len() >= KEPT_MAX {
            kept.remove(0);
        }
        kept.push(Box::new(value));
    }

    /// Takes back the most recently kept value of type `T` that `fits` accepts
    /// ([`keep`](GridMap::keep)), if any.
    pub fn take_kept<T: std::any::Any + Send>(&self, fits: impl Fn(&T) -> bool) -> Option<T> {
        let mut kept = self
            .kept
            .0
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let k = kept
            .iter()
            .rposition(|v| v.downcast_ref::<T>().is_some_and(&fits))?;
        kept.remove(k).downcast::<T>().ok().map(|v| *v)
    }

    /// The blocked cells' stride table if it is made already
    /// ([`blocked_strides`](Self::blocked_strides) makes it, in time that grows with the
    /// map): for a caller with a deadline, which may not spend that time.
    ///
    /// ```
    /// use envmap::GridMap;
    /// let map = GridMap::from_ascii("..#\n...")?;
    /// assert!(map.made_blocked_strides().is_none());
    /// let made = map.blocked_strides().map(<[u8]>::to_vec);
    /// assert_eq!(map.made_blocked_strides().map(<[u8]>::to_vec), made);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn made_blocked_strides(&self) -> Option<&[u8]> {
        self.stride_tables[cache_slot(self.blocked_from)?]
            .get()
            .map(Vec::as_slice)
    }

    /// [`bits_from`](Self::bits_from) the cells that block motion under the current
    /// [`blocked_from`](GridMap::blocked_from) (`None` when nothing blocks).
    #[must_use]
    pub fn blocked_bits(&self) -> Option<&CellBits> {
        self.bits_from(self.blocked_from)
    }

    /// [`strides_from`](Self::strides_from) the cells that block motion under the current
    /// [`blocked_from`](GridMap::blocked_from), made with their
    /// [`blocked_bits`](Self::blocked_bits) (a pass over the cells, where the strides need a
    /// distance transform): the edge checks' preparation.
    #[must_use]
    pub fn blocked_strides(&self) -> Option<&[u8]> {
        let strides = self.strides_from(self.blocked_from)?;
        let _ = self.blocked_bits();
        Some(strides)
    }

    /// A lower bound on the distance, world units, from `p` to the nearest cell that
    /// blocks motion; 0 where `p` is not free (or outside, or NaN), infinite on a map with
    /// no blocked cell. The map border is not an obstacle here (it is for `is_free`):
    /// clearance measures how close a path runs to obstacles.
    ///
    /// From the exact distance transform between cell centres (computed on the first call
    /// and cached): with `d` the distance from the centre `c` of `p`'s cell to the nearest
    /// blocked centre, the bound is `d - |p - c| - resolution * sqrt(2) / 2`, so it is never
    /// above the true distance and at most about 2.1 cells below it.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::{Point2, Workspace};
    /// let map = GridMap::from_ascii("
    ///     .......
    ///     .......
    ///     ...#...
    ///     .......
    ///     .......
    /// ")?;
    /// assert_eq!(map.clearance(Point2::new(3.5, 2.5)), Some(0.0));
    /// let c = map.clearance(Point2::new(0.5, 2.5)).unwrap(); // true distance 2.5
    /// assert!(c <= 2.5 && c >= 2.5 - 2.2);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn clearance_at(&self, p: Point2) -> f64 {
        if !hyplan_core::Workspace::is_free(self, p) {
            return 0.0;
        }
        let (Some((i, j)), Some(field)) = (self.world_to_cell(p), self.blocked_distance()) else {
            return 0.0;
        };
        let d = field.cell_dist(i, j);
        if d.is_infinite() {
            return f64::INFINITY;
        }
        let c = self.cell_center(i, j);
        let r = self.resolution;
        let bound = d * r - (p - c).norm() - r * std::f64::consts::FRAC_1_SQRT_2;
        bound.max(0.0)
    }

    /// The cached connectivity structures of this map.
    pub(crate) fn connectivity_cache(&self) -> &crate::connectivity::Cache {
        &self.connectivity
    }

    /// Number of cells in each zone: `[free, risk, forbidden]`.
    #[must_use]
    pub fn zone_counts(&self) -> [usize; 3] {
        let mut counts = [0; 3];
        for &z in &self.zones {
            counts[z as usize] += 1;
        }
        counts
    }
}

impl fmt::Debug for GridMap {
    /// Draws the map as [`from_ascii`](GridMap::from_ascii) reads it (top row first), for
    /// maps up to 200 x 200 cells; larger maps print their size only.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "GridMap {}x{} res {} origin ({}, {})",
            self.width, self.height, self.resolution, self.origin.x, self.origin.y
        )?;
        if self.width > 200 || self.height > 200 {
            return Ok(());
        }
        for j in (0..self.height).rev() {
            for i in 0..self.width {
                let c = match self.cell_zone(i, j) {
                    Zone::Free => '.',
                    Zone::Risk => '~',
                    Zone::Forbidden => '#',
                };
                write!(f, "{c}")?;
            }
            writeln!(f)?;
        }
        Ok(())
    }
}

/// Where the caches of the cells at least `zone` sit (`None` for `Zone::Free`: every cell).
const fn cache_slot(zone: Zone) -> Option<usize> {
    match zone {
        Zone::Free => None,
        Zone::Risk => Some(0),
        Zone::Forbidden => Some(1),
    }
}

/// `1 / r` when `r` is a power of two whose inverse is a normal number, else `None`. Then
/// `x * (1 / r)` equals `x / r` for every `x`: both are the same real number, rounded
/// once.
fn exact_inverse(r: f64) -> Option<f64> {
    const MANTISSA: u64 = (1 << 52) - 1;
    let inverse = 1.0 / r;
    (r.is_normal() && r.to_bits() & MANTISSA == 0 && inverse.is_normal()).then_some(inverse)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_powers_of_two_have_an_exact_inverse() {
        for r in [1.0, 0.5, 0.25, 0.125, 2.0, 1024.0, 2f64.powi(-40)] {
            assert_eq!(exact_inverse(r), Some(1.0 / r), "{r}");
        }
        for r in [0.05, 0.1, 3.0, 0.3, f64::MIN_POSITIVE / 4.0, f64::MAX] {
            assert_eq!(exact_inverse(r), None, "{r}");
        }
    }

    proptest::proptest! {
        /// Cell units by the product are the quotients, bit for bit, at every power-of-two
        /// resolution and any point.
        #[test]
        fn cell_units_are_the_quotients(
            k in -20..20_i32,
            origin in (-1.0e6..1.0e6_f64, -1.0e6..1.0e6_f64),
            p in (-1.0e7..1.0e7_f64, -1.0e7..1.0e7_f64),
        ) {
            let r = 2f64.powi(k);
            let map = GridMap::filled(3, 3, Zone::Free)
                .unwrap()
                .with_frame(r, Point2::new(origin.0, origin.1))
                .unwrap();
            proptest::prop_assert!(map.inverse.is_some());
            let p = Point2::new(p.0, p.1);
            let quotients = ((p.x - origin.0) / r, (p.y - origin.1) / r);
            let (u, v) = map.cell_units(p);
            proptest::prop_assert_eq!(u.to_bits(), quotients.0.to_bits());
            proptest::prop_assert_eq!(v.to_bits(), quotients.1.to_bits());
        }
    }
}
