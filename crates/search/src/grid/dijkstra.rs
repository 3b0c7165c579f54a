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
}
