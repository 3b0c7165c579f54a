//! The size accessors every grid type of the workspace shares.

/// Gives a grid type with `width` and `height` fields (cells, `usize`) its `width()` and
/// `height()` accessors: one definition and one doc for every grid of the workspace (maps,
/// masks, pictures, distance and cost fields, occupancy grids, images).
///
/// ```
/// struct Cells {
///     width: usize,
///     height: usize,
/// }
/// hyplan_core::grid_size!(Cells);
/// let c = Cells { width: 3, height: 2 };
/// assert_eq!((c.width(), c.height()), (3, 2));
/// ```
#[macro_export]
macro_rules! grid_size {
    ($grid:ty) => {
        impl $grid {
            /// Columns (cells per row).
            #[must_use]
            #[inline]
            pub const fn width(&self) -> usize {
                self.width
            }

            /// Rows.
            #[must_use]
            #[inline]
            pub const fn height(&self) -> usize {
                self.height
            }
        }
    };
}
