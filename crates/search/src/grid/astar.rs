//! Grid A*: optimal cell paths with the octile (or Manhattan) heuristic.

use super::*;

impl GridSearch {
    /// Optimal path from `start` to `goal` by A* with the octile (or Manhattan) heuristic.
    ///
    /// # Errors
    ///
    /// Start or goal outside the map or blocked; [`GridSearchError::NoPath`] after every
    /// cell reachable from the start was expanded.
    pub fn astar(
        &mut self,
        start: (usize, usize),
        goal: (usize, usize),
    ) -> Result<GridPath, GridSearchError> {
        self.run(None, start, goal, Kind::Astar)
    }
}
