//! `Mask`: a binary grid in map cell coordinates.

use hyplan_core::Zone;

use crate::GridMap;

/// A binary grid (`true` = obstacle), in map cell coordinates: cell `(i, j)` with `j`
/// counted from the **bottom**, stored row-major from the bottom row, like [`GridMap`].
///
/// ```
/// use envmap::Mask;
/// let mut mask = Mask::new(3, 2);
/// mask.set(2, 1, true);
/// assert!(mask.get(2, 1));
/// assert_eq!(mask.count(), 1);
/// ```
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct Mask {
    width: usize,
    height: usize,
    cells: Vec<bool>,
}

hyplan_core::grid_size!(Mask);

impl Mask {
    /// An all-`false` mask of `width x height` cells.
    ///
    /// # Panics
    ///
    /// If `width * height` overflows `usize`.
    #[must_use]
    pub fn new(width: usize, height: usize) -> Self {
        let n = width
            .checked_mul(height)
            .expect("mask size overflows usize");
        Self {
            width,
            height,
            cells: vec![false; n],
        }
    }

    /// A mask from its cells, row-major from the bottom row; `None` if the length is not
    /// `width * height`.
    #[must_use]
    pub fn from_cells(width: usize, height: usize, cells: Vec<bool>) -> Option<Self> {
        (width.checked_mul(height) == Some(cells.len())).then_some(Self {
            width,
            height,
            cells,
        })
    }

    /// The cells of `map` whose zone is at least `zone` (e.g. `Zone::Forbidden`: obstacles).
    #[must_use]
    pub fn from_zones_at_least(map: &GridMap, zone: Zone) -> Self {
        Self {
            width: map.width(),
            height: map.height(),
            cells: map.zones().iter().map(|&z| z >= zone).collect(),
        }
    }

    /// The cells, row-major from the bottom row.
    #[must_use]
    pub fn cells(&self) -> &[bool] {
        &self.cells
    }

    /// Mutable cells, row-major from the bottom row.
    pub fn cells_mut(&mut self) -> &mut [bool] {
        &mut self.cells
    }

    /// Cell `(i, j)`; `false` outside the mask.
    #[must_use]
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> bool {
        i < self.width && j < self.height && self.cells[j * self.width + i]
    }

    /// Sets cell `(i, j)`; ignored outside the mask.
    #[inline]
    pub fn set(&mut self, i: usize, j: usize, value: bool) {
        if i < self.width && j < self.height {
            self.cells[j * self.width + i] = value;
        }
    }

    /// Number of `true` cells.
    #[must_use]
    pub fn count(&self) -> usize {
        self.cells.iter().filter(|&&c| c).count()
    }
}
