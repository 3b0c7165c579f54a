//! Dijkstra's algorithm over a graph given as closures (Dijkstra, 1959).

use std::hash::Hash;

use crate::{NotFound, SearchResult, astar};

/// Finds a cheapest path from `start` to a node satisfying `success`, by Dijkstra's
/// algorithm: [`astar`] with a zero heuristic.
///
/// # Arguments
///
/// - `start`: the first node.
/// - `successors(n)`: the neighbours of `n` with edge costs, finite and `>= 0`.
/// - `success(n)`: whether `n` is a goal.
///
/// # Errors
///
/// [`NotFound::Exhausted`] when the reachable graph holds no goal.
///
/// # Example
///
/// ```
/// use search::dijkstra;
/// // A line 0 - 1 - 2 - 3 with a costly shortcut 0 - 3.
/// let found = dijkstra(
///     &0u32,
///     |&n| {
///         let mut v = vec![];
///         if n < 3 { v.push((n + 1, 1.0)); }
///         if n == 0 { v.push((3, 5.0)); }
///         v
///     },
///     |&n| n == 3,
/// )?;
/// assert_eq!(found.path, vec![0, 1, 2, 3]);
/// assert_eq!(found.cost, 3.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn dijkstra<N: Eq + Hash + Clone, IN: IntoIterator<Item = (N, f64)>>(
    start: &N,
    successors: impl FnMut(&N) -> IN,
    success: impl FnMut(&N) -> bool,
) -> Result<SearchResult<N>, NotFound> {
    astar(start, successors, |_| 0.0, success)
}
