//! Stage 3: approximate obstacles by axis-aligned rectangles (seed 000, section 4.1).

use hyplan_core::{Bounds, Point2};

use crate::{Component, GridMap, Mask};

/// An axis-aligned rectangle of cells, bounds **inclusive**, in map cell coordinates
/// (`j` from the bottom).
#[derive(Clone, Copy, PartialEq, Eq, Debug, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CellRect {
    /// Lowest column.
    pub i_min: usize,
    /// Lowest row (from the bottom).
    pub j_min: usize,
    /// Highest column (inclusive).
    pub i_max: usize,
    /// Highest row (inclusive).
    pub j_max: usize,
}

impl CellRect {
    /// The rectangle of the single cell `(i, j)`.
    #[must_use]
    pub const fn cell(i: usize, j: usize) -> Self {
        Self {
            i_min: i,
            j_min: j,
            i_max: i,
            j_max: j,
        }
    }

    /// The smallest rectangle holding `self` and cell `(i, j)`.
    #[must_use]
    pub fn including(self, i: usize, j: usize) -> Self {
        Self {
            i_min: self.i_min.min(i),
            j_min: self.j_min.min(j),
            i_max: self.i_max.max(i),
            j_max: self.j_max.max(j),
        }
    }

    /// Whether cell `(i, j)` lies in the rectangle.
    #[must_use]
    pub const fn contains(&self, i: usize, j: usize) -> bool {
        self.i_min <= i && i <= self.i_max && self.j_min <= j && j <= self.j_max
    }

    /// Columns spanned.
    #[must_use]
    pub const fn width(&self) -> usize {
        self.i_max - self.i_min + 1
    }

    /// Rows spanned.
    #[must_use]
    pub const fn height(&self) -> usize {
        self.j_max - self.j_min + 1
    }

    /// The world box the rectangle's cells cover in `map`'s frame.
    #[must_use]
    pub fn to_world(&self, map: &GridMap) -> Bounds {
        let (o, r) = (map.origin(), map.resolution());
        Bounds::new(
            Point2::new(o.x + self.i_min as f64 * r, o.y + self.j_min as f64 * r),
            Point2::new(
                o.x + (self.i_max + 1) as f64 * r,
                o.y + (self.j_max + 1) as f64 * r,
            ),
        )
    }
}

/// The approximating rectangles of the obstacles: one axis-aligned bounding rectangle per
/// 8-connected component, as in seed `000_9b224721fe327833.txt`, section 4.1 (Fig. 6(c)).
/// Every obstacle cell lies in the rectangle of its component.
#[must_use]
pub fn bounding_rectangles(components: &[Component]) -> Vec<CellRect> {
    components.iter().map(|c| c.rect).collect()
}

/// A `width x height` mask with every cell of every rectangle set (rectangles are clipped
/// to the mask).
///
/// ```
/// use envmap::{fill_rectangles, CellRect};
/// let mask = fill_rectangles(4, 3, &[CellRect { i_min: 1, j_min: 0, i_max: 2, j_max: 1 }]);
/// assert_eq!(mask.count(), 4);
/// assert!(mask.get(2, 1) && !mask.get(3, 1));
/// ```
#[must_use]
pub fn fill_rectangles(width: usize, height: usize, rects: &[CellRect]) -> Mask {
    let mut mask = Mask::new(width, height);
    for r in rects {
        if r.i_min >= width || r.j_min >= height {
            continue;
        }
        let (i1, j1) = (r.i_max.min(width - 1), r.j_max.min(height - 1));
        for j in r.j_min..=j1 {
            mask.cells_mut()[j * width + r.i_min..=j * width + i1].fill(true);
        }
    }
    mask
}
