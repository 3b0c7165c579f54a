//! Random grid maps drawn from bytes (proptest's), shared with the hybrid planners' tests,
//! which include this file.

use envmap::GridMap;
use hyplan_core::{Point2, Zone};

/// A random `w x h` grid: each cell forbidden with probability `density`, drawn from the
/// bits of `cells` (one byte per cell; 255 * density is the threshold).
pub fn random_map(w: usize, h: usize, density: f64, cells: &[u8]) -> GridMap {
    let threshold = (density * 256.0) as u32;
    let zones = (0..w * h)
        .map(|k| {
            if u32::from(cells[k % cells.len()]) < threshold {
                Zone::Forbidden
            } else {
                Zone::Free
            }
        })
        .collect();
    GridMap::from_zones(w, h, 1.0, Point2::origin(), zones).unwrap()
}
