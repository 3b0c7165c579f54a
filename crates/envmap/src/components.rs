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
/// they share a side or a corner), with their sizes and bounding rectangles, and a label
/// per cell.
///
/// Linear time, run-based: each row is split into runs of obstacle cells, and a run is
/// merged (union-find) with the runs of the row below that it touches, corners included.
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
/// // The top two touch at a corner; the third is two columns away.
/// assert_eq!(labels.components.len(), 2);
/// assert_eq!(labels.components[0].cells, 1); // first in scan order: the bottom row
/// assert_eq!(labels.components[1].cells, 2);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn label_components(mask: &Mask) -> Labels {
    let runs = Runs::of(mask);
    let (ids, components) = runs.components();
    let (w, h) = (mask.width(), mask.height());
    let mut labels = vec![0u32; w * h];
    for (r, &id) in runs.runs.iter().zip(&ids) {
        labels[r.j * w + r.i0..r.j * w + r.i1].fill(id + 1);
    }
    Labels {
        width: w,
        height: h,
        labels,
        components,
    }
}

/// The 8-connected components of the `true` cells of `mask`, without the per-cell labels
/// (what [`Pipeline`](crate::Pipeline) needs; faster than [`label_components`]).
#[must_use]
pub fn components(mask: &Mask) -> Vec<Component> {
    Runs::of(mask).components().1
}

/// A horizontal run of obstacle cells `[i0, i1)` in row `j`.
struct Run {
    j: usize,
    i0: usize,
    i1: usize,
}

/// The runs of a mask, merged into components by union-find.
struct Runs {
    runs: Vec<Run>,
    parent: Vec<u32>,
}

impl Runs {
    fn of(mask: &Mask) -> Self {
        let w = mask.width();
        let mut runs: Vec<Run> = Vec::new();
        let mut parent: Vec<u32> = Vec::new();
        // Runs of the previous row: indices [prev_start, row_start).
        let mut prev_start = 0;
        for (j, row) in mask.cells().chunks_exact(w.max(1)).enumerate() {
            let row_start = runs.len();
            let mut i = 0;
            let mut below = prev_start;
            while i < w {
                // Skip free cells.
                match row[i..].iter().position(|&c| c) {
                    Some(k) => i += k,
                    None => break,
                }
                let i0 = i;
                let i1 = row[i..].iter().position(|&c| !c).map_or(w, |k| i + k);
                i = i1;
                let id = runs.len() as u32;
                runs.push(Run { j, i0, i1 });
                parent.push(id);
                // Runs below touching [i0 - 1, i1] (8-connectivity): they are sorted by i0,
                // so skip those ending before i0 - 1 and stop at those starting after i1.
                while below < row_start && runs[below].i1 < i0 {
                    below += 1;
                }
                let mut k = below;
                while k < row_start && runs[k].i0 <= i1 {
                    union(&mut parent, id, k as u32);
                    k += 1;
                }
            }
            prev_start = row_start;
        }
        Self { runs, parent }
    }

    /// Component index of every run, and the components in order of first cell.
    fn components(&self) -> (Vec<u32>, Vec<Component>) {
        let mut parent = self.parent.clone();
        let mut id_of_root = vec![u32::MAX; parent.len()];
        let mut ids = Vec::with_capacity(self.runs.len());
        let mut comps: Vec<Component> = Vec::new();
        for (k, r) in self.runs.iter().enumerate() {
            let root = find(&mut parent, k as u32) as usize;
            if id_of_root[root] == u32::MAX {
                id_of_root[root] = comps.len() as u32;
                comps.push(Component {
                    cells: 0,
                    rect: CellRect::cell(r.i0, r.j),
                });
            }
            let id = id_of_root[root];
            let c = &mut comps[id as usize];
            c.cells += r.i1 - r.i0;
            c.rect = c.rect.including(r.i0, r.j).including(r.i1 - 1, r.j);
            ids.push(id);
        }
        (ids, comps)
    }
}

/// Union-find root of `x`, with path halving (shared with `connectivity`).
pub(crate) fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let up = parent[parent[x as usize] as usize];
        parent[x as usize] = up; // path halving
        x = up;
    }
    x
}

/// Joins the sets of `a` and `b`; the smaller index stays the root.
pub(crate) fn union(parent: &mut [u32], a: u32, b: u32) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    // The smaller index is the root, so roots are the earliest runs.
    if ra < rb {
        parent[rb as usize] = ra;
    } else if rb < ra {
        parent[ra as usize] = rb;
    }
}
