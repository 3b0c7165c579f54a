//! The map layer: a grid of cells, each one colour of a small palette, placed in the world
//! by its lower-left corner and cell size (rows bottom-up, the map frame).

use envmap::CellFrame;
use hyplan_core::Point2;

use crate::{FigureError, Rgba};

/// A grid of palette-indexed cells placed in the world: the map layer of a
/// [`Scene`](crate::Scene) and one frame of an indexed animation ([`apng_indexed`](crate::apng_indexed)).
///
/// Cell `(i, j)` covers `[origin.x + i r, origin.x + (i + 1) r) x [origin.y + j r, ...)`
/// with `r` the resolution: row 0 is the bottom row, as in `envmap::GridMap` and ROS maps.
///
/// ```
/// use hyplan_core::Point2;
/// use viz::GridImage;
/// let frame = envmap::CellFrame::new(Point2::new(0.0, 0.0), 0.5, 3, 2);
/// let mut grid = GridImage::filled(frame, vec![[255; 4], [0, 0, 0, 255]]);
/// grid.paint(Point2::new(1.2, 0.9), 1);
/// assert_eq!(grid.get(2, 1), 1);
/// assert_eq!(grid.get(0, 0), 0);
/// # Ok::<(), viz::FigureError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct GridImage {
    frame: CellFrame,
    palette: Vec<Rgba>,
    cells: Vec<u8>,
}

impl GridImage {
    /// A grid of `frame`'s cells, all colour 0 of `palette`. A palette longer than 256
    /// colours is cut to 256; an empty one becomes white.
    #[must_use]
    pub fn filled(frame: CellFrame, mut palette: Vec<Rgba>) -> Self {
        palette.truncate(256);
        if palette.is_empty() {
            palette.push([255; 4]);
        }
        Self {
            frame,
            palette,
            cells: vec![0; frame.width * frame.height],
        }
    }

    /// Columns.
    #[must_use]
    pub const fn width(&self) -> usize {
        self.frame.width
    }

    /// Rows.
    #[must_use]
    pub const fn height(&self) -> usize {
        self.frame.height
    }

    /// A grid from its cells (row 0 at the bottom).
    ///
    /// # Errors
    ///
    /// [`FigureError::GridSize`] when `cells` is not `width * height` long;
    /// [`FigureError::Palette`] when the palette is empty, longer than 256 colours, or a
    /// cell names a colour beyond it.
    pub fn from_cells(
        frame: CellFrame,
        palette: Vec<Rgba>,
        cells: Vec<u8>,
    ) -> Result<Self, FigureError> {
        if cells.len() != frame.width * frame.height {
            return Err(FigureError::GridSize {
                width: frame.width,
                height: frame.height,
                cells: cells.len(),
            });
        }
        let max_index = cells.iter().copied().max().unwrap_or(0);
        if palette.is_empty() || palette.len() > 256 || usize::from(max_index) >= palette.len() {
            return Err(FigureError::Palette {
                len: palette.len(),
                max_index,
            });
        }
        Ok(Self {
            frame,
            palette,
            cells,
        })
    }

    /// A picture of `envmap` (one pixel per cell, top row first, as
    /// [`envmap::render_zones`] draws a map) as a grid placed at `origin` with cells
    /// `resolution` wide; its distinct colours become the palette (at most 256 kept, the
    /// rest drawn in the last).
    #[must_use]
    pub fn from_picture(picture: &envmap::Picture, origin: Point2, resolution: f64) -> Self {
        let (w, h) = (picture.width(), picture.height());
        let mut palette: Vec<Rgba> = Vec::new();
        let mut cells = vec![0u8; w * h];
        for y in 0..h {
            for x in 0..w {
                let p = picture.pixel(x, y);
                let c = match p.len() {
                    1 | 2 => [p[0], p[0], p[0], 255],
                    _ => [p[0], p[1], p[2], 255],
                };
                let k = palette.iter().position(|&q| q == c).unwrap_or_else(|| {
                    if palette.len() < 256 {
                        palette.push(c);
                    }
                    palette.len() - 1
                });
                cells[(h - 1 - y) * w + x] = k as u8;
            }
        }
        Self::filled(CellFrame::new(origin, resolution, w, h), palette).with_cells(cells)
    }

    fn with_cells(mut self, cells: Vec<u8>) -> Self {
        self.cells = cells;
        self
    }

    /// The world position of the lower-left corner.
    #[must_use]
    pub const fn origin(&self) -> Point2 {
        self.frame.origin
    }

    /// Side of a cell, world units.
    #[must_use]
    pub const fn resolution(&self) -> f64 {
        self.frame.resolution
    }

    /// The colours.
    #[must_use]
    pub fn palette(&self) -> &[Rgba] {
        &self.palette
    }

    /// The palette index of every cell, row 0 (the bottom) first.
    #[must_use]
    pub fn cells(&self) -> &[u8] {
        &self.cells
    }

    /// Mutable palette indices, row 0 (the bottom) first (an index beyond the palette is
    /// drawn in its last colour).
    pub fn cells_mut(&mut self) -> &mut [u8] {
        &mut self.cells
    }

    /// The palette index of cell `(i, j)` (0 outside the grid).
    #[must_use]
    pub fn get(&self, i: usize, j: usize) -> u8 {
        if i < self.frame.width && j < self.frame.height {
            self.cells[j * self.frame.width + i]
        } else {
            0
        }
    }

    /// The colour of cell `(i, j)`.
    #[must_use]
    pub fn colour(&self, i: usize, j: usize) -> Rgba {
        let k = usize::from(self.get(i, j)).min(self.palette.len() - 1);
        self.palette[k]
    }

    /// Sets cell `(i, j)` to palette index `index` (nothing outside the grid).
    pub fn set(&mut self, i: usize, j: usize, index: u8) {
        if i < self.frame.width && j < self.frame.height {
            self.cells[j * self.frame.width + i] = index;
        }
    }

    /// Where the cells lie in the world.
    #[must_use]
    pub const fn frame(&self) -> CellFrame {
        self.frame
    }

    /// The cell holding the world point `p`, if inside.
    #[must_use]
    pub fn cell_of(&self, p: Point2) -> Option<(usize, usize)> {
        self.frame().cell_of(p)
    }

    /// Sets the cell holding the world point `p` to `index` (nothing outside the grid).
    pub fn paint(&mut self, p: Point2, index: u8) {
        if let Some((i, j)) = self.cell_of(p) {
            self.set(i, j, index);
        }
    }

    /// The grid as an indexed PNG, `scale` pixels per cell (at least 1), top row first.
    ///
    /// # Errors
    ///
    /// [`FigureError::Draw`] with the PNG encoder's message.
    pub fn png_bytes(&self, scale: usize) -> Result<Vec<u8>, FigureError> {
        let s = scale.max(1);
        let frame = crate::apng::IndexedFrame::of(self, s);
        crate::apng::encode_indexed(std::iter::once(frame), 1, &self.palette, None)
    }

    /// The palette indices as pixel rows, top row first, each cell `scale` pixels square.
    pub(crate) fn rows_top_down(&self, scale: usize) -> Vec<u8> {
        let (w, h) = (self.frame.width * scale, self.frame.height * scale);
        let last = (self.palette.len() - 1) as u8;
        let mut out = Vec::with_capacity(w * h);
        for y in 0..h {
            let j = self.frame.height - 1 - y / scale;
            let row = &self.cells[j * self.frame.width..(j + 1) * self.frame.width];
            if scale == 1 {
                // One pixel per cell (the exploration's animation): a straight copy.
                out.extend(row.iter().map(|&c| c.min(last)));
            } else {
                for &c in row {
                    out.extend(std::iter::repeat_n(c.min(last), scale));
                }
            }
        }
        out
    }
}
