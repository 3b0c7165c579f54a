//! Whether two cells are joined by the search's moves, without computing costs: a
//! breadth-first search grown from both cells in turn.

use super::*;

/// Per-cell marks of the last [`GridSearch::connected`] query and its two queues.
#[derive(Debug, Clone, Default)]
pub(super) struct Reach {
    /// `2 * generation + side` where a side reached the cell; older values mean unseen.
    marks: Vec<u32>,
    generation: u32,
    queues: [Vec<u32>; 2],
}

impl GridSearch {
    /// Whether A* and Dijkstra would find a path from `start` to `goal`: a breadth-first
    /// search over the same moves grown from both cells in turn, which stops as soon as
    /// the two meet or either runs out. A goal walled off from a large reachable area is
    /// answered at the cost of the smaller of the two regions, where a search that fails
    /// expands every cell the start reaches.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use search::{GridOptions, GridSearch};
    /// let map = GridMap::from_ascii("
    ///     ..#..
    ///     ..#..
    /// ")?;
    /// let mut search = GridSearch::new(&map, GridOptions::default())?;
    /// assert!(search.connected((0, 0), (1, 1))?);
    /// assert!(!search.connected((0, 0), (4, 0))?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    ///
    /// As [`astar`](GridSearch::astar): start or goal outside the map or blocked.
    pub fn connected(
        &mut self,
        start: (usize, usize),
        goal: (usize, usize),
    ) -> Result<bool, GridSearchError> {
        let s = self.check(start, true)?;
        let t = self.check(goal, false)?;
        if s == t {
            return Ok(true);
        }
        let reach = &mut self.reach;
        if reach.marks.len() != self.passable.len() {
            reach.marks = vec![0; self.passable.len()];
            reach.generation = 0;
        }
        reach.generation += 1;
        if reach.generation >= u32::MAX / 2 {
            reach.marks.fill(0);
            reach.generation = 1;
        }
        let base = 2 * reach.generation;
        let pw = self.pw as isize;
        // The straight moves suffice: a legal diagonal move has a free side cell (both
        // without corner cutting), through which two straight moves join the same cells.
        let offsets: [isize; 4] =
            std::array::from_fn(|d| DIRS[d].1 as isize * pw + DIRS[d].0 as isize);
        for (side, cell) in [s, t].into_iter().enumerate() {
            reach.marks[cell as usize] = base + side as u32;
            reach.queues[side].clear();
            reach.queues[side].push(cell);
        }
        let mut heads = [0usize; 2];
        loop {
            for (side, head) in heads.iter_mut().enumerate() {
                let Some(&p) = reach.queues[side].get(*head) else {
                    // This side's region is exhausted without meeting the other.
                    return Ok(false);
                };
                *head += 1;
                let mine = base + side as u32;
                let moves = self.moves[p as usize];
                for (d, &off) in offsets.iter().enumerate() {
                    if moves & (1 << d) == 0 {
                        continue;
                    }
                    let q = (p as isize + off) as usize;
                    let mark = reach.marks[q];
                    if mark == mine {
                        continue;
                    }
                    // Straight moves are symmetric, so the other side's cells are
                    // reached from this one.
                    if mark == base + 1 - side as u32 {
                        return Ok(true);
                    }
                    reach.marks[q] = mine;
                    reach.queues[side].push(q as u32);
                }
            }
        }
    }
}
