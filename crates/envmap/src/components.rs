//! Stage 2: 8-connected components of the obstacle mask.

use crate::{CellRect, Mask};

/// One 8-connected component of obstacle cells.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Component {
    /// Number of cells.
    pub cells: usize,
    /// The smallest axis-aligned rectangle of cells holding the component.
    pub rect: CellRect,
}

/// Labels of the 8-connected components of a mask.
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct Labels {
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Per cell (row-major from the bottom row): 0 for background, `k + 1` for a cell of
    /// `components[k]`.
    pub labels: Vec<u32>,
    /// The components, in the order their first cell appears scanning rows from the bottom.
    pub components: Vec<Component>,
}

/// The 8-connected components of the `true` cells of `mask` (two cells are connected when
/// they share a side or a corner), with their sizes and bounding rectangles.
///
/// Linear time: a flood fill with an explicit stack (no recursion, no stack overflow on
/// large obstacles).
///
/// ```
/// use envmap::{label_components, GridMap, Mask};
/// use hyplan_core::Zone;
/// let map = GridMap::from_ascii("
///     #...
///     .#..
///     ...#
/// ")?;
/// let labels = label_components(&Mask::from_zones_at_least(&map, Zone::Forbidden));
/// assert_eq!(labels.components.len(), 2); // the diagonal pair is one component
/// assert_eq!(labels.components.iter().map(|c| c.cells).sum::<usize>(), 3);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn label_components(mask: &Mask) -> Labels {
    let (w, h) = (mask.width(), mask.height());
    let cells = mask.cells();
    let mut labels = vec![0u32; cells.len()];
    let mut components = Vec::new();
    let mut stack = Vec::new();
    for start in 0..cells.len() {
        if !cells[start] || labels[start] != 0 {
            continue;
        }
        let label = u32::try_from(components.len() + 1).unwrap_or(u32::MAX);
        let (i0, j0) = (start % w, start / w);
        let mut rect = CellRect::cell(i0, j0);
        let mut count = 0;
        labels[start] = label;
        stack.push(start);
        while let Some(k) = stack.pop() {
            count += 1;
            let (i, j) = (k % w, k / w);
            rect = rect.including(i, j);
            for nj in j.saturating_sub(1)..=(j + 1).min(h - 1) {
                for ni in i.saturating_sub(1)..=(i + 1).min(w - 1) {
                    let n = nj * w + ni;
                    if cells[n] && labels[n] == 0 {
                        labels[n] = label;
                        stack.push(n);
                    }
                }
            }
        }
        components.push(Component { cells: count, rect });
    }
    Labels {
        width: w,
        height: h,
        labels,
        components,
    }
}
