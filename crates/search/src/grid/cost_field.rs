//! The cost-to-go field of a one-to-all Dijkstra search toward a goal cell.

use super::*;

/// Cost-to-go field of a one-to-all Dijkstra search toward a goal cell.
///
/// For every cell: the cost in cells of the cheapest path to the goal (`None` when the goal
/// cannot be reached) and the next cell along that path, so a robot can follow it from
/// wherever it is ([`path_from`](CostField::path_from)).
#[derive(Debug, Clone, PartialEq)]
pub struct CostField {
    width: usize,
    height: usize,
    goal: (usize, usize),
    cost: Vec<f64>,
    next: Vec<u32>,
    stats: SearchStats,
}

hyplan_core::grid_size!(CostField);

impl CostField {
    /// The goal cell the field leads to.
    #[must_use]
    pub const fn goal(&self) -> (usize, usize) {
        self.goal
    }

    /// Counters of the search that built the field.
    #[must_use]
    pub const fn stats(&self) -> SearchStats {
        self.stats
    }

    /// Cost in cells from `(i, j)` to the goal; `None` outside the map, on blocked cells and
    /// where the goal cannot be reached.
    #[must_use]
    pub fn cost(&self, i: usize, j: usize) -> Option<f64> {
        (i < self.width && j < self.height)
            .then(|| self.cost[j * self.width + i])
            .filter(|c| c.is_finite())
    }

    /// The next cell on a cheapest path from `(i, j)` to the goal (`None` at the goal and
    /// where [`cost`](CostField::cost) is `None`).
    #[must_use]
    pub fn next(&self, i: usize, j: usize) -> Option<(usize, usize)> {
        self.cost(i, j)?;
        let n = self.next[j * self.width + i];
        (n != NONE).then(|| (n as usize % self.width, n as usize / self.width))
    }

    /// The cells of a cheapest path from `(i, j)` to the goal, both included.
    #[must_use]
    pub fn path_from(&self, i: usize, j: usize) -> Option<Vec<(usize, usize)>> {
        self.cost(i, j)?;
        let mut cells = vec![(i, j)];
        let mut here = (i, j);
        while let Some(n) = self.next(here.0, here.1) {
            cells.push(n);
            here = n;
        }
        Some(cells)
    }

    /// Costs row-major from the bottom row (`f64::INFINITY` where unreachable).
    #[must_use]
    pub fn costs(&self) -> &[f64] {
        &self.cost
    }
}

impl GridSearch {
    /// One-to-all Dijkstra from `goal`: the cost-to-go of every cell and the next cell
    /// toward the goal (moves are symmetric, so costs from the goal are costs to it).
    ///
    /// # Errors
    ///
    /// The goal outside the map or blocked.
    pub fn cost_to_go(&mut self, goal: (usize, usize)) -> Result<CostField, GridSearchError> {
        let g0 = self.check(goal, false)?;
        // Dijkstra without a target: runs until the reachable cells are exhausted.
        let stats = match self.grid_search(g0, NONE, false) {
            Err(GridSearchError::NoPath { stats }) => stats,
            _ => SearchStats::default(),
        };
        let (w, h) = (self.width, self.height);
        let mut cost = vec![f64::INFINITY; w * h];
        let mut next = vec![NONE; w * h];
        for j in 0..h {
            for i in 0..w {
                let p = self.index(i, j);
                if let Some(g) = self.g_of(p) {
                    cost[j * w + i] = self.fixed.to_cells(g);
                    if let Some(q) = self.parent(p) {
                        let (qi, qj) = self.cell(q);
                        next[j * w + i] = (qj * w + qi) as u32;
                    }
                }
            }
        }
        Ok(CostField {
            width: w,
            height: h,
            goal,
            cost,
            next,
            stats,
        })
    }
}
