//! The generators' drawing surface: a grid of blocked and free cells, and the few
//! questions the generators ask of it.

use hyplan_core::{Point2, Zone};

use super::Generated;
use crate::{Connectivity, GridMap, Mask, flood_fill};

/// A lattice of `nx x ny` square cells (`inner` cells a side) in a walled grid, walls
/// `wall` cells thick: the layout the maze and the room grid share.
pub(super) struct Lattice {
    pub nx: usize,
    pub ny: usize,
    pub inner: usize,
    pub wall: usize,
}

impl Lattice {
    /// At least one lattice cell each way, walls at least one cell thick, insides at
    /// least `min_inner` cells a side.
    pub fn new(nx: usize, ny: usize, inner: usize, min_inner: usize, wall: usize) -> Self {
        Self {
            nx: nx.max(1),
            ny: ny.max(1),
            inner: inner.max(min_inner),
            wall: wall.max(1),
        }
    }

    /// Inner side plus one wall.
    pub fn pitch(&self) -> usize {
        self.inner + self.wall
    }

    /// The lower-left cell of lattice cell `(i, j)`.
    pub fn origin(&self, i: usize, j: usize) -> (usize, usize) {
        (self.wall + i * self.pitch(), self.wall + j * self.pitch())
    }

    /// The centre cell of lattice cell `(i, j)`.
    pub fn centre(&self, i: usize, j: usize) -> (usize, usize) {
        let (x, y) = self.origin(i, j);
        (x + self.inner / 2, y + self.inner / 2)
    }

    /// A canvas all wall but the lattice cells' insides.
    pub fn carve(&self) -> Canvas {
        let mut canvas = Canvas::new(
            self.nx * self.pitch() + self.wall,
            self.ny * self.pitch() + self.wall,
        );
        canvas.rect(0, 0, canvas.width, canvas.height, true);
        for j in 0..self.ny {
            for i in 0..self.nx {
                let (x, y) = self.origin(i, j);
                canvas.rect(x, y, x + self.inner, y + self.inner, false);
            }
        }
        canvas
    }

    /// Finishes `canvas` with the start in the lower-left lattice cell and the goal in
    /// the upper-right one.
    pub fn finish(&self, canvas: Canvas) -> Generated {
        canvas.finish(self.centre(0, 0), self.centre(self.nx - 1, self.ny - 1))
    }
}

/// A builder over a Forbidden/Free cell grid, x right and y up from the lower-left cell.
pub(super) struct Canvas {
    pub width: usize,
    pub height: usize,
    pub blocked: Vec<bool>,
}

impl Canvas {
    pub fn new(width: usize, height: usize) -> Self {
        let (width, height) = (width.max(1), height.max(1));
        Self {
            width,
            height,
            blocked: vec![false; width * height],
        }
    }

    /// Sets the cells of `[x0, x1) x [y0, y1)` (clipped to the grid).
    pub fn rect(&mut self, x0: usize, y0: usize, x1: usize, y1: usize, blocked: bool) {
        if x0 >= x1 {
            return;
        }
        for y in y0.min(self.height)..y1.min(self.height) {
            self.blocked[y * self.width + x0.min(self.width)..y * self.width + x1.min(self.width)]
                .fill(blocked);
        }
    }

    pub fn get(&self, x: usize, y: usize) -> bool {
        x >= self.width || y >= self.height || self.blocked[y * self.width + x]
    }

    pub fn centre(x: usize, y: usize) -> Point2 {
        Point2::new(x as f64 + 0.5, y as f64 + 0.5)
    }

    pub fn finish(self, start: (usize, usize), goal: (usize, usize)) -> Generated {
        let zones = self
            .blocked
            .iter()
            .map(|&b| if b { Zone::Forbidden } else { Zone::Free })
            .collect();
        let map = GridMap::from_zones(self.width, self.height, 1.0, Point2::origin(), zones)
            .unwrap_or_else(|_| unreachable!("the canvas has at least one cell"));
        Generated {
            map,
            start: Self::centre(start.0, start.1),
            goal: Self::centre(goal.0, goal.1),
        }
    }
}

/// The free cell nearest to `p` in growing square rings (`p` itself if free).
pub(super) fn nearest_free(canvas: &Canvas, p: (usize, usize)) -> (usize, usize) {
    let n = canvas.width.max(canvas.height);
    for r in 0..n {
        let (x0, y0) = (p.0.saturating_sub(r), p.1.saturating_sub(r));
        for y in y0..=(p.1 + r).min(canvas.height - 1) {
            for x in x0..=(p.0 + r).min(canvas.width - 1) {
                if !canvas.get(x, y) {
                    return (x, y);
                }
            }
        }
    }
    p
}

/// Whether `a` and `b` are joined by 4-connected free cells (a plain flood fill; used
/// while generating, where maps are small).
pub(super) fn connected(canvas: &Canvas, a: (usize, usize), b: (usize, usize)) -> bool {
    let free = canvas.blocked.iter().map(|&x| !x).collect();
    Mask::from_cells(canvas.width, canvas.height, free)
        .is_some_and(|free| flood_fill(&free, a, Connectivity::Four).get(b.0, b.1))
}

/// The 4-neighbours of cell `(i, j)` of an `nx` x `ny` lattice (of maze cells or rooms),
/// in the order the generators draw from: left, right, down, up.
pub(super) fn lattice_neighbours(i: usize, j: usize, nx: usize, ny: usize) -> Vec<(usize, usize)> {
    let mut v = Vec::with_capacity(4);
    if i > 0 {
        v.push((i - 1, j));
    }
    if i + 1 < nx {
        v.push((i + 1, j));
    }
    if j > 0 {
        v.push((i, j - 1));
    }
    if j + 1 < ny {
        v.push((i, j + 1));
    }
    v
}
