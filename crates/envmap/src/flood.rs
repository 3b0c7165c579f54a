//! Flood fills and breadth-first distances over a [`Mask`]: the workspace's one
//! traversal of connected cells (reachability, clusters, step counts, the nearest
//! passable cell).

use crate::Mask;

/// Which cells touch: sharing a side, or a side or a corner.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Connectivity {
    /// 4-connected: left, right, below, above.
    Four,
    /// 8-connected: the four sides and the four corners.
    Eight,
}

impl Connectivity {
    /// The neighbour offsets, rows from the bottom, columns from the left within a row.
    const fn offsets(self) -> &'static [(i64, i64)] {
        match self {
            Self::Four => &[(0, -1), (-1, 0), (1, 0), (0, 1)],
            Self::Eight => &[
                (-1, -1),
                (0, -1),
                (1, -1),
                (-1, 0),
                (1, 0),
                (-1, 1),
                (0, 1),
                (1, 1),
            ],
        }
    }
}

/// The neighbours of cell `(i, j)` inside a `w x h` grid, in [`Connectivity::offsets`] order.
fn neighbours(
    (i, j): (usize, usize),
    (w, h): (usize, usize),
    conn: Connectivity,
) -> impl Iterator<Item = (usize, usize)> {
    conn.offsets().iter().filter_map(move |&(di, dj)| {
        let (a, b) = (i as i64 + di, j as i64 + dj);
        (a >= 0 && b >= 0 && (a as usize) < w && (b as usize) < h)
            .then_some((a as usize, b as usize))
    })
}

/// The `true` cells of `mask` connected to `start` through `true` cells (an all-`false`
/// mask when `start` is outside or `false`).
///
/// ```
/// use envmap::{Connectivity, Mask, flood_fill};
/// // Two free cells touching at a corner only.
/// let free = Mask::from_cells(2, 2, vec![true, false, false, true]).unwrap();
/// assert_eq!(flood_fill(&free, (0, 0), Connectivity::Four).count(), 1);
/// assert_eq!(flood_fill(&free, (0, 0), Connectivity::Eight).count(), 2);
/// ```
#[must_use]
pub fn flood_fill(mask: &Mask, start: (usize, usize), conn: Connectivity) -> Mask {
    let (w, h) = (mask.width(), mask.height());
    let mut reach = Mask::new(w, h);
    if !mask.get(start.0, start.1) {
        return reach;
    }
    reach.set(start.0, start.1, true);
    let mut stack = vec![start];
    while let Some(c) = stack.pop() {
        for (a, b) in neighbours(c, (w, h), conn) {
            if mask.get(a, b) && !reach.get(a, b) {
                reach.set(a, b, true);
                stack.push((a, b));
            }
        }
    }
    reach
}

/// The clusters of connected `true` cells of `mask` that hold the `seeds`, each in
/// breadth-first discovery order, clusters in the order of their first seed; seeds that
/// are `false` or already in a cluster start none.
///
/// ```
/// use envmap::{Connectivity, Mask, clusters};
/// let cells = Mask::from_cells(3, 1, vec![true, false, true]).unwrap();
/// let all = [(0, 0), (1, 0), (2, 0)];
/// assert_eq!(clusters(&cells, all, Connectivity::Eight), vec![vec![(0, 0)], vec![(2, 0)]]);
/// ```
#[must_use]
pub fn clusters(
    mask: &Mask,
    seeds: impl IntoIterator<Item = (usize, usize)>,
    conn: Connectivity,
) -> Vec<Vec<(usize, usize)>> {
    let (w, h) = (mask.width(), mask.height());
    let mut seen = Mask::new(w, h);
    let mut out = Vec::new();
    for s in seeds {
        if !mask.get(s.0, s.1) || seen.get(s.0, s.1) {
            continue;
        }
        seen.set(s.0, s.1, true);
        let mut cluster = vec![s];
        let mut k = 0;
        while k < cluster.len() {
            let c = cluster[k];
            k += 1;
            for (a, b) in neighbours(c, (w, h), conn) {
                if mask.get(a, b) && !seen.get(a, b) {
                    seen.set(a, b, true);
                    cluster.push((a, b));
                }
            }
        }
        out.push(cluster);
    }
    out
}

/// Breadth-first steps from `start` through the `true` cells of `mask`, every move
/// counting one (`u32::MAX` where unreachable, row-major from the bottom row). The start
/// cell is entered whatever its value; an all-unreachable field when it is outside.
///
/// ```
/// use envmap::{Connectivity, Mask, steps_from};
/// let open = Mask::from_cells(3, 1, vec![true, true, true]).unwrap();
/// assert_eq!(steps_from(&open, (0, 0), Connectivity::Eight), vec![0, 1, 2]);
/// ```
#[must_use]
pub fn steps_from(mask: &Mask, start: (usize, usize), conn: Connectivity) -> Vec<u32> {
    steps_from_cells(mask, [start], conn)
}

/// [`steps_from`] the nearest of several cells (`seeds`; those outside are skipped): the
/// steps to the nearest seed, each seed entered whatever its value.
///
/// ```
/// use envmap::{Connectivity, Mask, steps_from_cells};
/// let open = Mask::from_cells(4, 1, vec![true, true, false, true]).unwrap();
/// let steps = steps_from_cells(&open, [(0, 0), (3, 0)], Connectivity::Four);
/// assert_eq!(steps, vec![0, 1, u32::MAX, 0]);
/// ```
#[must_use]
pub fn steps_from_cells(
    mask: &Mask,
    seeds: impl IntoIterator<Item = (usize, usize)>,
    conn: Connectivity,
) -> Vec<u32> {
    let open = mask.cells();
    let mut flood = StepsFlood::new(mask.width(), mask.height(), conn);
    flood.restart(seeds);
    flood.grow_to(u32::MAX, |c| open[c]);
    flood.into_steps()
}

/// [`steps_from_cells`] grown on demand: a breadth-first flood that stops at a level of
/// steps and can go on from there, over the open cells a test names (by row-major
/// index), with its buffers kept from one flood to the next. A caller that needs the
/// steps of a few cells near the start (the nearest of several targets) floods only as
/// far as those.
///
/// ```
/// use envmap::{Connectivity, StepsFlood};
/// let open = [true, true, true, false, true];
/// let mut flood = StepsFlood::new(5, 1, Connectivity::Eight);
/// flood.restart([(0, 0)]);
/// flood.grow_to(1, |c| open[c]);
/// assert_eq!(flood.steps()[..3], [0, 1, u32::MAX]);
/// assert_eq!(flood.unreached_from(), 2);
/// flood.grow_to(u32::MAX, |c| open[c]);
/// assert!(flood.finished());
/// assert_eq!(flood.steps(), [0, 1, 2, u32::MAX, u32::MAX]);
/// ```
#[derive(Debug, Clone)]
pub struct StepsFlood {
    width: usize,
    height: usize,
    offsets: Vec<isize>,
    conn: Connectivity,
    steps: Vec<u32>,
    queue: Vec<u32>,
    head: usize,
    /// Every cell with fewer steps than this has been expanded.
    level: u32,
}

impl StepsFlood {
    /// An empty flood of a `width` x `height` grid (no cell reached until
    /// [`restart`](Self::restart)).
    #[must_use]
    pub fn new(width: usize, height: usize, conn: Connectivity) -> Self {
        let offsets = conn
            .offsets()
            .iter()
            .map(|&(di, dj)| dj as isize * width as isize + di as isize)
            .collect();
        Self {
            width,
            height,
            offsets,
            conn,
            steps: vec![u32::MAX; width * height],
            queue: Vec::new(),
            head: 0,
            level: 0,
        }
    }

    /// Starts again from `seeds` (0 steps each, entered whether open or not; those
    /// outside the grid are skipped).
    pub fn restart(&mut self, seeds: impl IntoIterator<Item = (usize, usize)>) {
        // Every reached cell is in the queue: clearing those costs the last flood's
        // size, not the grid's.
        for &c in &self.queue {
            self.steps[c as usize] = u32::MAX;
        }
        self.queue.clear();
        self.head = 0;
        self.level = 0;
        let w = self.width;
        for (i, j) in seeds {
            if i < w && j < self.height && self.steps[j * w + i] != 0 {
                self.steps[j * w + i] = 0;
                self.queue.push((j * w + i) as u32);
            }
        }
    }

    /// Expands every reached cell with fewer than `level` steps, through the cells
    /// `open` says are open: afterwards every cell within `level` steps has its steps.
    pub fn grow_to(&mut self, level: u32, open: impl Fn(usize) -> bool) {
        let (w, h, conn) = (self.width, self.height, self.conn);
        let Self {
            steps,
            queue,
            head,
            offsets,
            ..
        } = self;
        // Steps do not depend on the order neighbours are visited in: a plain vector is
        // the queue, and cells off the border skip the bounds tests.
        while *head < queue.len() {
            let c = queue[*head] as usize;
            if steps[c] >= level {
                break;
            }
            *head += 1;
            let next = steps[c] + 1;
            let (ci, cj) = (c % w, c / w);
            let mut visit = |n: usize| {
                if steps[n] == u32::MAX && open(n) {
                    steps[n] = next;
                    queue.push(n as u32);
                }
            };
            if ci > 0 && cj > 0 && ci + 1 < w && cj + 1 < h {
                for &o in offsets.iter() {
                    visit(c.wrapping_add_signed(o));
                }
            } else {
                for (a, b) in neighbours((ci, cj), (w, h), conn) {
                    visit(b * w + a);
                }
            }
        }
        self.level = self.level.max(level);
    }

    /// Whether every cell the seeds reach has its steps.
    #[must_use]
    pub fn finished(&self) -> bool {
        self.head == self.queue.len()
    }

    /// The least steps a cell not yet reached can have (`u32::MAX` once finished: it
    /// cannot be reached).
    #[must_use]
    pub fn unreached_from(&self) -> u32 {
        if self.finished() {
            u32::MAX
        } else {
            self.level.saturating_add(1)
        }
    }

    /// The cells reached so far (row-major indices), in the order they were reached: by
    /// nondecreasing steps, so that the cells a [`grow_to`](Self::grow_to) added are the
    /// ones past the length this had before it.
    ///
    /// ```
    /// use envmap::{Connectivity, StepsFlood};
    /// let mut flood = StepsFlood::new(4, 1, Connectivity::Eight);
    /// flood.restart([(1, 0)]);
    /// assert_eq!(flood.reached(), [1]);
    /// flood.grow_to(1, |_| true);
    /// assert_eq!(flood.reached()[1..].len(), 2, "cells 0 and 2, one step away");
    /// ```
    #[must_use]
    pub fn reached(&self) -> &[u32] {
        &self.queue
    }

    /// Steps per cell, row-major from the bottom row: `u32::MAX` where not (yet) reached.
    #[must_use]
    pub fn steps(&self) -> &[u32] {
        &self.steps
    }

    /// The steps per cell, as [`steps`](Self::steps), without a copy.
    #[must_use]
    pub fn into_steps(self) -> Vec<u32> {
        self.steps
    }

    /// The grid's width and height.
    #[must_use]
    pub const fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }
}

/// The passable cell nearest `cell` within `max_ring` rings (squares of cells around it),
/// `cell` itself when passable; on a ring, the least squared distance, the first found
/// (rows from the bottom, columns from the left) on ties. `None` when there is none.
///
/// ```
/// use envmap::nearest_passable;
/// let free = |i: usize, j: usize| i >= 2 && j < 4;
/// assert_eq!(nearest_passable((4, 4), (0, 0), 5, free), Some((2, 0)));
/// assert_eq!(nearest_passable((4, 4), (0, 0), 1, free), None);
/// ```
#[must_use]
pub fn nearest_passable(
    (w, h): (usize, usize),
    cell: (usize, usize),
    max_ring: usize,
    passable: impl Fn(usize, usize) -> bool,
) -> Option<(usize, usize)> {
    if cell.0 < w && cell.1 < h && passable(cell.0, cell.1) {
        return Some(cell);
    }
    let (ci, cj) = (cell.0 as i64, cell.1 as i64);
    (1..=max_ring as i64).find_map(|r| {
        let mut best: Option<((usize, usize), i64)> = None;
        for dj in -r..=r {
            for di in -r..=r {
                let (i, j) = (ci + di, cj + dj);
                if di.abs().max(dj.abs()) != r
                    || i < 0
                    || j < 0
                    || i as usize >= w
                    || j as usize >= h
                    || !passable(i as usize, j as usize)
                {
                    continue;
                }
                let d = di * di + dj * dj;
                if best.is_none_or(|b| d < b.1) {
                    best = Some(((i as usize, j as usize), d));
                }
            }
        }
        best.map(|(c, _)| c)
    })
}
