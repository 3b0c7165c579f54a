//! Grid Dijkstra: optimal cell paths without a heuristic.

use super::*;

impl GridSearch {
    /// Optimal path from `start` to `goal` by Dijkstra's algorithm (no heuristic).
    ///
    /// # Errors
    ///
    /// As [`astar`](GridSearch::astar).
    pub fn dijkstra(
        &mut self,
        start: (usize, usize),
        goal: (usize, usize),
    ) -> Result<GridPath, GridSearchError> {
        self.run(None, start, goal, Kind::Dijkstra)
    }

    /// [`dijkstra`](GridSearch::dijkstra)'s own path, cell for cell, found among fewer
    /// cells when an upper bound on its cost is known (from a faster search, such as
    /// [`JumpPointSearch`](crate::JumpPointSearch)): cells whose cost from the start plus
    /// octile distance to the goal exceed `bound` (in cells) lie on no path that short,
    /// and are left out.
    ///
    /// Dijkstra's tie-breaks are kept (its path is the first one its order of expansion
    /// reaches), which A* and jump point search do not keep: a caller whose runs must not
    /// change gets the path it had, at the cost of the cells within the bound.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use search::{GridOptions, GridSearch};
    /// let map = GridMap::from_ascii("
    ///     ............
    ///     .....#......
    ///     .....#......
    ///     ............
    /// ")?;
    /// let mut search = GridSearch::new(&map, GridOptions::default())?;
    /// let full = search.dijkstra((4, 2), (9, 2))?;
    /// let within = search.dijkstra_within((4, 2), (9, 2), full.cost)?;
    /// assert_eq!(within.cells, full.cells);
    /// assert!(within.stats.expansions < full.stats.expansions, "the cells west of the start");
    /// assert!(search.dijkstra_within((4, 2), (9, 2), full.cost - 0.5).is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    ///
    /// As [`dijkstra`](GridSearch::dijkstra); [`GridSearchError::NoPath`] also when every
    /// path costs more than `bound` (or `bound` is NaN).
    pub fn dijkstra_within(
        &mut self,
        start: (usize, usize),
        goal: (usize, usize),
        bound: f64,
    ) -> Result<GridPath, GridSearchError> {
        let s0 = self.check(start, true)?;
        let t0 = self.check(goal, false)?;
        let fx = self.fixed;
        let unit = fx.unit as f64;
        // A path of a straight moves and b diagonals costs a + b sqrt 2 cells, and
        // a * unit + b * diag in fixed point: scaled by the larger of 1 and
        // diag / (sqrt 2 unit), the bound covers it; the margin covers the rounding.
        let scale = unit * (fx.diag as f64 / (SQRT2 * unit)).max(1.0);
        let fixed = (bound * scale * (1.0 + 1e-9)).ceil() + 1.0;
        // NaN and negative bounds become 0 (no cell but the start), huge ones no bound.
        let bound = if fixed >= u64::MAX as f64 {
            u64::MAX
        } else {
            fixed as u64
        };
        self.grid_search_bounded(s0, t0, false, OpenKind::Buckets, bound)
    }
}
