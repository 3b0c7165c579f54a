//! A coarse grid of buckets over axis-aligned boxes, to find the boxes near a point
//! without testing them all: the walls near a person (ORCA), the segments within a
//! laser's horizon.

use hyplan_core::Point2;

/// The most buckets along a side: the grid coarsens on very large worlds.
const MAX_BUCKETS_PER_SIDE: usize = 256;

/// Boxes, each listed in every bucket it overlaps.
#[derive(Debug, Clone, Default)]
pub(crate) struct BoxGrid {
    /// Each box, (min, max).
    boxes: Vec<(Point2, Point2)>,
    /// Lower-left corner of the grid, m.
    origin: Point2,
    /// Side of a bucket, m.
    cell: f64,
    /// Buckets per row and per column.
    size: (usize, usize),
    /// Box indices of each bucket, row by row.
    buckets: Vec<Vec<u32>>,
}

/// What a [`BoxGrid::near`] query takes, kept between queries: per box, the last query
/// that met it, so that a box in several buckets is handed out once.
#[derive(Debug, Clone, Default)]
pub(crate) struct Marks {
    mark: Vec<u32>,
    generation: u32,
}

impl Marks {
    /// A new mark for a query over `n` boxes; on wrap-around every old mark is cleared.
    fn next(&mut self, n: usize) -> u32 {
        if self.mark.len() != n {
            self.mark = vec![0; n];
            self.generation = 0;
        }
        self.generation = self.generation.wrapping_add(1);
        if self.generation == 0 {
            self.mark.fill(0);
            self.generation = 1;
        }
        self.generation
    }
}

impl BoxGrid {
    /// `boxes` in buckets of about `cell` m (coarser on a world of more than
    /// [`MAX_BUCKETS_PER_SIDE`] such buckets a side).
    pub(crate) fn new(boxes: Vec<(Point2, Point2)>, cell: f64) -> Self {
        let mut grid = Self {
            boxes,
            ..Self::default()
        };
        let Some(&(first_lo, first_hi)) = grid.boxes.first() else {
            return grid;
        };
        let (lo, hi) = grid.boxes.iter().fold((first_lo, first_hi), |(lo, hi), b| {
            (
                Point2::new(lo.x.min(b.0.x), lo.y.min(b.0.y)),
                Point2::new(hi.x.max(b.1.x), hi.y.max(b.1.y)),
            )
        });
        let longest = (hi.x - lo.x).max(hi.y - lo.y);
        grid.cell = cell.max(longest / MAX_BUCKETS_PER_SIDE as f64).max(1e-3);
        grid.origin = lo;
        let side = |len: f64| (len / grid.cell).floor() as usize + 1;
        grid.size = (side(hi.x - lo.x), side(hi.y - lo.y));
        grid.buckets = vec![Vec::new(); grid.size.0 * grid.size.1];
        for (k, &(a, b)) in grid.boxes.iter().enumerate() {
            let ((i0, j0), (i1, j1)) = (grid.cell_of(a), grid.cell_of(b));
            for j in j0..=j1 {
                for i in i0..=i1 {
                    grid.buckets[j * grid.size.0 + i].push(k as u32);
                }
            }
        }
        grid
    }

    /// Number of boxes.
    pub(crate) fn len(&self) -> usize {
        self.boxes.len()
    }

    /// The bucket holding `p`, clamped to the grid.
    fn cell_of(&self, p: Point2) -> (usize, usize) {
        let index = |v: f64, n: usize| ((v / self.cell).floor().max(0.0) as usize).min(n - 1);
        (
            index(p.x - self.origin.x, self.size.0),
            index(p.y - self.origin.y, self.size.1),
        )
    }

    /// Calls `f` once with the index of every box within `reach` of `p` (the box's
    /// nearest point no farther), in no particular order.
    pub(crate) fn near(&self, p: Point2, reach: f64, marks: &mut Marks, mut f: impl FnMut(u32)) {
        if self.buckets.is_empty() {
            return;
        }
        let generation = marks.next(self.boxes.len());
        let r = nalgebra::Vector2::new(reach, reach);
        let ((i0, j0), (i1, j1)) = (self.cell_of(p - r), self.cell_of(p + r));
        for j in j0..=j1 {
            for &k in self.buckets[j * self.size.0 + i0..=j * self.size.0 + i1]
                .iter()
                .flatten()
            {
                let mark = &mut marks.mark[k as usize];
                if *mark == generation {
                    continue;
                }
                *mark = generation;
                if within(self.boxes[k as usize], p, reach) {
                    f(k);
                }
            }
        }
    }
}

/// Whether box `(lo, hi)` comes within `reach` of `p` (its nearest point no farther): the
/// test of [`BoxGrid::near`], for those who keep a box's bounds themselves.
#[inline]
pub(crate) fn within((lo, hi): (Point2, Point2), p: Point2, reach: f64) -> bool {
    let dx = (lo.x - p.x).max(p.x - hi.x).max(0.0);
    let dy = (lo.y - p.y).max(p.y - hi.y).max(0.0);
    dx * dx + dy * dy <= reach * reach
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The query hands out exactly the boxes a scan of all of them finds, each once.
        #[test]
        fn near_equals_the_scan_of_every_box(
            raw in prop::collection::vec((0.0..50.0f64, 0.0..50.0f64, 0.0..8.0f64, 0.0..8.0f64), 1..60),
            queries in prop::collection::vec((-10.0..60.0f64, -10.0..60.0f64, 0.0..12.0f64), 1..8),
            cell in 0.2..6.0f64,
        ) {
            let boxes: Vec<_> = raw
                .iter()
                .map(|&(x, y, w, h)| (Point2::new(x, y), Point2::new(x + w, y + h)))
                .collect();
            let grid = BoxGrid::new(boxes.clone(), cell);
            let mut marks = Marks::default();
            for (x, y, reach) in queries {
                let p = Point2::new(x, y);
                let mut got = Vec::new();
                grid.near(p, reach, &mut marks, |k| got.push(k));
                got.sort_unstable();
                let want: Vec<u32> = (0..boxes.len() as u32)
                    .filter(|&k| {
                        let (lo, hi) = boxes[k as usize];
                        let dx = (lo.x - p.x).max(p.x - hi.x).max(0.0);
                        let dy = (lo.y - p.y).max(p.y - hi.y).max(0.0);
                        dx * dx + dy * dy <= reach * reach
                    })
                    .collect();
                prop_assert_eq!(got, want);
            }
        }
    }
}
