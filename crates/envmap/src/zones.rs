//! Stage 5: the three zones of a safe map (seed 000, section 4.1).

use hyplan_core::Zone;

use crate::{DistanceField, Mask};

/// The zones of a safe map: obstacle cells are [`Zone::Forbidden`]; a free cell is
/// [`Zone::Risk`] (high-risk) when the Euclidean distance from its centre to the centre of
/// the nearest obstacle cell is **at most** `safety_radius` cells, and [`Zone::Free`]
/// (safe) beyond. Row-major from the bottom row, like [`GridMap`](crate::GridMap).
///
/// `dist` must be the [`distance_transform`](crate::distance_transform) of `obstacles`.
/// The comparison is exact: `dx^2 + dy^2 <= r^2` on integers (`r` may be fractional).
/// A radius of 0 (or NaN / negative, treated as 0) gives no high-risk band. Seed
/// `000_9b224721fe327833.txt` uses 20 cells (px).
///
/// ```
/// use envmap::{distance_transform, zones, Mask};
/// use hyplan_core::Zone;
/// let mut mask = Mask::new(5, 1);
/// mask.set(0, 0, true);
/// let z = zones(&mask, &distance_transform(&mask), 2.0);
/// assert_eq!(z, vec![Zone::Forbidden, Zone::Risk, Zone::Risk, Zone::Free, Zone::Free]);
/// ```
#[must_use]
pub fn zones(obstacles: &Mask, dist: &DistanceField, safety_radius: f64) -> Vec<Zone> {
    let r = if safety_radius > 0.0 {
        safety_radius
    } else {
        0.0
    };
    // Largest integer d^2 with d^2 <= r^2 (r^2 may be fractional).
    let r_sq = (r * r).floor();
    let limit = if r_sq >= f64::from(u32::MAX - 1) {
        u32::MAX - 1
    } else {
        r_sq as u32
    };
    obstacles
        .cells()
        .iter()
        .zip(dist.dist_sq())
        .map(|(&o, &d)| {
            if o {
                Zone::Forbidden
            } else if d <= limit {
                Zone::Risk
            } else {
                Zone::Free
            }
        })
        .collect()
}
