//! Rays and nearest points against a loaded map's own cells, at a cost set by the
//! distances involved rather than by the map's wall count or extent.
//!
//! A loaded map's obstacles are its forbidden cells; [`crate::StaticWorld::add_grid`] also
//! keeps them as the boundary segments between forbidden and other cells (the grid's
//! outside counts as not forbidden). A ray meets that boundary first where it first
//! changes between a forbidden and another cell, so casting it means finding that cell:
//! a march over a byte per cell ([`GridMap::strides_from`], from the grid's exact distance
//! transform, cached with the map) crosses open space in strides that cannot reach a forbidden
//! cell from any point of the cell they start in; near an obstacle the march scans the
//! rest of the ray's row (or column, for a ray nearer the y axis) at once from the map's
//! bits ([`GridMap::bits_from`]), taking the cells in the order and by the comparisons of a
//! cell-by-cell traversal (Amanatides-Woo), so that it finds the same cell exactly. The distance returned is
//! computed from the grid line the ray crosses, as the segment's own intersection would
//! be, so casts agree with the segment sweep to rounding (a property test checks it).

use envmap::{CellBits, CellFrame, GridMap};
use hyplan_core::{Point2, Zone};
use nalgebra::Vector2;

/// The shortest stride taken, cells: shorter ones cost more than the cells they skip.
const STRIDE_FROM: u8 = 2;

/// A loaded map's cells with their distances to the nearest forbidden cell.
#[derive(Debug, Clone, Copy)]
pub(crate) struct GridRays<'a> {
    frame: CellFrame,
    /// Squared distance (cells^2) from each cell centre to the nearest forbidden centre:
    /// 0 exactly on forbidden cells.
    dist_sq: &'a [u32],
    /// The march's table ([`GridMap::strides_from`] the forbidden cells).
    strides: &'a [u8],
    /// The forbidden cells' bits ([`GridMap::bits_from`]), for the last cells.
    bits: &'a CellBits,
    /// `1 / resolution`.
    per_cell: f64,
}

impl<'a> GridRays<'a> {
    /// The map's cells, its (cached) distance transform of the forbidden cells and its
    /// [`GridMap::strides_from`] table.
    pub(crate) fn new(map: &'a GridMap, strides: &'a [u8]) -> Option<Self> {
        let field = map.distance_from(Zone::Forbidden)?;
        let bits = map.bits_from(Zone::Forbidden)?;
        (strides.len() == field.dist_sq().len()).then(|| Self {
            frame: map.frame(),
            dist_sq: field.dist_sq(),
            strides,
            bits,
            per_cell: 1.0 / map.resolution(),
        })
    }

    /// The squared distance of cell `(i, j)`, which the caller keeps inside the grid.
    fn d2(&self, i: i64, j: i64) -> u32 {
        self.dist_sq[j as usize * self.frame.width + i as usize]
    }

    /// The stride byte of cell `(i, j)`, which the caller keeps inside the grid.
    #[inline]
    fn stride(&self, i: i64, j: i64) -> u8 {
        self.strides[j as usize * self.frame.width + i as usize]
    }

    fn in_grid(&self, i: i64, j: i64) -> bool {
        i >= 0 && j >= 0 && (i as usize) < self.frame.width && (j as usize) < self.frame.height
    }

    /// Vertical grid line `i` (as `add_grid` places the segments' ends).
    fn x_line(&self, i: i64) -> f64 {
        self.frame.origin.x + i as f64 * self.frame.resolution
    }

    /// Horizontal grid line `j`.
    fn y_line(&self, j: i64) -> f64 {
        self.frame.origin.y + j as f64 * self.frame.resolution
    }

    /// Lowers each of `ranges` (the beams along the unit `dirs` from `o`) to the distance
    /// to the first boundary of the forbidden cells, if there is one before the range and
    /// `limit` (a hit a rounding error beyond may be handed back: the caller compares).
    /// Exact to rounding but for rays through a cell corner or along a grid line, where
    /// the segments' ends decide ties that the traversal breaks one way. The beams'
    /// marches run [`LANES`] at a time, interleaved, so that the memory waits of one
    /// beam's strides overlap with the others' (each stride depends on the byte it
    /// reads, so a lone march waits on every load).
    pub(crate) fn lower(&self, o: Point2, dirs: &[Vector2<f64>], ranges: &mut [f64], limit: f64) {
        let mut lanes: [Option<(usize, March)>; LANES] = [None; LANES];
        let mut next = 0;
        let mut busy = 0;
        loop {
            // Fill the free lanes with the next beams that need a march.
            for lane in lanes.iter_mut().filter(|l| l.is_none()) {
                while next < dirs.len() {
                    let k = next;
                    next += 1;
                    match self.begin(o, dirs[k], ranges[k].min(limit)) {
                        Begin::Done(t) => lower_to(&mut ranges[k], t),
                        Begin::Search(m) => {
                            *lane = Some((k, m));
                            busy += 1;
                            break;
                        }
                    }
                }
            }
            if busy == 0 {
                return;
            }
            for lane in &mut lanes {
                if let Some((k, m)) = lane
                    && let Some(t) = self.advance(m)
                {
                    lower_to(&mut ranges[*k], t);
                    *lane = None;
                    busy -= 1;
                }
            }
        }
    }

    /// A beam's cast up to its march: the answer when it needs none (off the grid, the
    /// map's edge, a scanner in a forbidden cell), or where the march starts.
    fn begin(&self, o: Point2, d: Vector2<f64>, limit: f64) -> Begin {
        let (w, h) = (self.frame.width as i64, self.frame.height as i64);
        let inv = (1.0 / d.x, 1.0 / d.y);
        let (x_lines, y_lines) = (
            (self.x_line(0), self.x_line(w)),
            (self.y_line(0), self.y_line(h)),
        );
        let (tx_in, tx_out) = slab(o.x, d.x, inv.0, x_lines);
        let (ty_in, ty_out) = slab(o.y, d.y, inv.1, y_lines);
        let t_in = tx_in.max(ty_in).max(0.0);
        let t_end = tx_out.min(ty_out).min(limit);
        // A hit found a rounding error past the end is still handed back.
        let t_end = t_end + 1e-9 * (1.0 + t_end.abs());
        if t_in.is_nan() || t_end.is_nan() || t_in > t_end {
            return Begin::Done(None);
        }
        // The traversal runs in cell units.
        let end = t_end * self.per_cell;
        let mut walk = Walk::new(self, o, d, inv, t_in * self.per_cell);
        let start_forbidden = self.stride(walk.i, walk.j) == 0;
        if t_in > 0.0 {
            // Entering the grid from outside, where nothing is forbidden: the map's edge
            // is a boundary, at the exact (divided) distance of the side crossed last.
            return if start_forbidden {
                let exact = |o: f64, d: f64, (lo, hi): (f64, f64)| {
                    if d > 0.0 {
                        (lo - o) / d
                    } else if d < 0.0 {
                        (hi - o) / d
                    } else {
                        f64::NEG_INFINITY
                    }
                };
                Begin::Done(Some(exact(o.x, d.x, x_lines).max(exact(o.y, d.y, y_lines))))
            } else {
                Begin::Search(March::new(walk, t_in * self.per_cell, end))
            };
        }
        if !start_forbidden {
            return Begin::Search(March::new(walk, 0.0, end));
        }
        // The scanner stands in a forbidden cell: the boundary is where the ray leaves
        // the forbidden cells (into a free one or out of the grid).
        loop {
            if walk.step() > end {
                return Begin::Done(None);
            }
            if !self.in_grid(walk.i, walk.j) || self.stride(walk.i, walk.j) != 0 {
                return Begin::Done(Some(walk.entry(self)));
            }
        }
    }

    /// One stride or one cell of march `m` (from a cell that is not forbidden, toward the
    /// entry into the first forbidden cell before its end): `Some` with the answer when
    /// it ended (a hit, or `None` past its end), `None` while it goes on.
    #[inline]
    fn advance(&self, m: &mut March) -> Option<Option<f64>> {
        let clear = self.stride(m.walk.i, m.walk.j);
        if clear > STRIDE_FROM {
            m.s += f64::from(clear - 1);
            if m.s > m.end {
                return Some(None);
            }
            m.walk.jump(self, m.s);
            return None;
        }
        self.run(m)
    }

    /// The rest of march `m`'s current row (for a ray nearer the x axis) or column at
    /// once: the first forbidden cell the ray enters there is the answer, else the march
    /// moves into the next row or column. The same cells in the same order, by the same
    /// comparisons, as the cell-by-cell steps, so the answer is theirs; a ray grazing a
    /// wall crosses tens of cells of a row in one scan of its bits.
    #[inline]
    fn run(&self, m: &mut March) -> Option<Option<f64>> {
        let w = &mut m.walk;
        let x_major = w.d.x.abs() >= w.d.y.abs();
        let (along, across, o, d, inv, step, cells) = if x_major {
            (
                w.i,
                w.j,
                w.o.0,
                w.d.x,
                w.inv.0,
                w.step.0,
                self.frame.width as i64,
            )
        } else {
            (
                w.j,
                w.i,
                w.o.1,
                w.d.y,
                w.inv.1,
                w.step.1,
                self.frame.height as i64,
            )
        };
        // Where the ray leaves the current line (infinite when it runs along it).
        let leave = if x_major { w.cross_y() } else { w.cross_x() };
        // The ray enters cell `c` of the line across grid line `c` (forward) or `c + 1`.
        let entry = |c: i64| ((c + i64::from(step < 0)) as f64 - o) * inv;
        // Whether the ray enters a cell along at `e` before it leaves the line: the steps
        // cross a vertical grid line first only when strictly earlier (ties go to y).
        let before = |e: f64| if x_major { e < leave } else { e <= leave };
        // The last cell it enters before leaving the line; past the grid's end (`-1` or
        // `cells`) when it leaves the grid first.
        let forward = step > 0;
        let mut last = if !leave.is_finite() {
            if forward { cells } else { -1 }
        } else if forward {
            ((o + d * leave) as i64).clamp(along, cells)
        } else {
            ((o + d * leave) as i64).clamp(-1, along)
        };
        if forward {
            while last < cells && before(entry(last + 1)) {
                last += 1;
            }
            while last > along && !before(entry(last)) {
                last -= 1;
            }
        } else {
            while last > -1 && before(entry(last - 1)) {
                last -= 1;
            }
            while last < along && !before(entry(last)) {
                last += 1;
            }
        }
        let line = across as usize;
        let found = match (forward, x_major) {
            // No cell left in the line past this one.
            _ if last == along || (!forward && along == 0) => None,
            (true, true) => self
                .bits
                .first_in_row(line, along as usize + 1, last as usize),
            (true, false) => self
                .bits
                .first_in_column(line, along as usize + 1, last as usize),
            (false, true) => self
                .bits
                .last_in_row(line, last.max(0) as usize, along as usize - 1),
            (false, false) => {
                self.bits
                    .last_in_column(line, last.max(0) as usize, along as usize - 1)
            }
        };
        if let Some(f) = found {
            let f = f as i64;
            if entry(f) > m.end {
                return Some(None);
            }
            if x_major {
                w.i = f;
            } else {
                w.j = f;
            }
            w.last_x = x_major;
            return Some(Some(w.entry(self)));
        }
        if last < 0 || last >= cells || leave > m.end {
            return Some(None);
        }
        // Into the next line, at the cell where the ray crosses.
        if x_major {
            (w.i, w.j) = (last, w.j + w.step.1);
        } else {
            (w.i, w.j) = (w.i + w.step.0, last);
        }
        w.last_x = !x_major;
        w.aimed = false;
        m.s = leave;
        if !self.in_grid(w.i, w.j) {
            return Some(None);
        }
        if self.stride(w.i, w.j) == 0 {
            return Some(Some(w.entry(self)));
        }
        None
    }

    /// The nearest point of the forbidden cells to `p` and its distance, for `p` in a
    /// cell of the grid that is not forbidden (`None` otherwise: the caller sweeps the
    /// segments); `Some((INFINITY, p))` on a map with no forbidden cell.
    pub(crate) fn nearest(&self, p: Point2) -> Option<(f64, Point2)> {
        let (ci, cj) = self.frame.cell_of(p)?;
        let d2 = self.dist_sq[cj * self.frame.width + ci];
        if d2 == 0 {
            return None;
        }
        if d2 == envmap::DistanceField::NONE {
            return Some((f64::INFINITY, p));
        }
        let res = self.frame.resolution;
        let off = (p - self.frame.cell_center(ci, cj)).norm() / res;
        // In cells: the nearest forbidden centre is at D from this cell's centre, so its
        // square is at most D + off from p; a square that near has its centre at most
        // half a diagonal further, so within D + 2 off + 0.71 of this centre. Only the
        // ring between D and that radius can hold the nearest square.
        let outer = f64::from(d2).sqrt() + 2.0 * off + std::f64::consts::FRAC_1_SQRT_2 + 1e-6;
        let outer2 = outer * outer;
        let reach = outer.floor() as i64;
        let mut best = (f64::INFINITY, p);
        for b in -reach..=reach {
            let j = cj as i64 + b;
            let rest = outer2 - (b * b) as f64;
            if j < 0 || j as usize >= self.frame.height || rest < 0.0 {
                continue;
            }
            let a_hi = rest.sqrt().floor() as i64;
            // Offsets with a^2 + b^2 < D^2 hold no forbidden centre.
            let inner = i64::from(d2) - b * b;
            let a_lo = if inner <= 0 { 0 } else { isqrt_ceil(inner) };
            for a in a_lo..=a_hi {
                for i in [ci as i64 - a, ci as i64 + a] {
                    if i < 0 || i as usize >= self.frame.width || self.d2(i, j) != 0 {
                        continue;
                    }
                    let (x, y) = (self.x_line(i), self.y_line(j));
                    let q = Point2::new(p.x.clamp(x, x + res), p.y.clamp(y, y + res));
                    let dist = (p - q).norm();
                    if dist < best.0 {
                        best = (dist, q);
                    }
                }
            }
        }
        Some(best)
    }
}

/// Beams marched at a time by [`GridRays::lower`].
const LANES: usize = 4;

/// A march under way: the traversal, its parameter (cells) and where it ends.
#[derive(Debug, Clone, Copy)]
struct March {
    walk: Walk,
    s: f64,
    end: f64,
}

impl March {
    fn new(walk: Walk, s: f64, end: f64) -> Self {
        Self { walk, s, end }
    }
}

/// How a beam's cast begins ([`GridRays::begin`]).
enum Begin {
    /// Answered without a march.
    Done(Option<f64>),
    /// A march to run.
    Search(March),
}

/// Lowers `r` to a hit `t` nearer than it.
fn lower_to(r: &mut f64, t: Option<f64>) {
    if let Some(t) = t
        && t < *r
    {
        *r = t;
    }
}

/// The smallest `a >= 0` with `a * a >= n`, for `n > 0`.
fn isqrt_ceil(n: i64) -> i64 {
    let mut a = (n as f64).sqrt() as i64;
    while a * a < n {
        a += 1;
    }
    while a > 0 && (a - 1) * (a - 1) >= n {
        a -= 1;
    }
    a
}

/// Parameters where the ray `o + t d` (one axis, `inv` = `1 / d`) is between `lo` and
/// `hi`: an empty interval when it never is.
fn slab(o: f64, d: f64, inv: f64, (lo, hi): (f64, f64)) -> (f64, f64) {
    if d > 0.0 {
        ((lo - o) * inv, (hi - o) * inv)
    } else if d < 0.0 {
        ((hi - o) * inv, (lo - o) * inv)
    } else if (lo..=hi).contains(&o) {
        (f64::NEG_INFINITY, f64::INFINITY)
    } else {
        (f64::INFINITY, f64::NEG_INFINITY)
    }
}

/// A cell-by-cell traversal of a ray, in cell units (the grid's lines at the integers,
/// the ray's parameter in cells). Each crossing's parameter is computed from the line
/// itself (no running sums, which drift over a long beam), so a traversal moved on by a
/// stride picks up exactly.
#[derive(Debug, Clone, Copy)]
struct Walk {
    /// The ray's origin in cells, its direction (unit) and `1 / d` per axis (infinite
    /// along an axis the ray does not move on).
    o: (f64, f64),
    d: Vector2<f64>,
    inv: (f64, f64),
    /// The ray's origin in the world, for the exact distance of a hit.
    from: Point2,
    /// Cell step per axis, and the offset (1 or 0) of the line the ray leaves a cell by.
    step: (i64, i64),
    ahead: (i64, i64),
    i: i64,
    j: i64,
    /// Parameters of the next vertical and horizontal line crossings, when `aimed`.
    sx: f64,
    sy: f64,
    /// Whether `sx` and `sy` are those of the current cell: a stride moves on without
    /// them, so they are computed at the first step after it.
    aimed: bool,
    /// Whether the last step crossed a vertical line.
    last_x: bool,
}

impl Walk {
    /// The walk of ray `o + t d` (world) from the cell holding its point at `s` cells.
    fn new(g: &GridRays<'_>, o: Point2, d: Vector2<f64>, inv: (f64, f64), s: f64) -> Self {
        let origin = g.frame.origin;
        let mut walk = Self {
            o: ((o.x - origin.x) * g.per_cell, (o.y - origin.y) * g.per_cell),
            d,
            from: o,
            inv,
            step: (
                if d.x > 0.0 { 1 } else { -1 },
                if d.y > 0.0 { 1 } else { -1 },
            ),
            ahead: (i64::from(d.x > 0.0), i64::from(d.y > 0.0)),
            i: 0,
            j: 0,
            sx: 0.0,
            sy: 0.0,
            aimed: false,
            last_x: false,
        };
        walk.jump(g, s);
        walk
    }

    /// The ray's point at `s` cells, in cells.
    #[inline]
    fn at(&self, s: f64) -> (f64, f64) {
        (self.o.0 + self.d.x * s, self.o.1 + self.d.y * s)
    }

    /// Moves to the cell holding the ray's point at `s`, clamped to the grid (`s` may put
    /// the point a rounding error outside).
    #[inline]
    fn jump(&mut self, g: &GridRays<'_>, s: f64) {
        let (u, v) = self.at(s);
        // Truncation is flooring once clamped to the grid (and needs no libm call).
        self.i = (u as i64).clamp(0, g.frame.width as i64 - 1);
        self.j = (v as i64).clamp(0, g.frame.height as i64 - 1);
        self.aimed = false;
    }

    /// Where the ray leaves column `i` (infinite for a ray along y).
    #[inline]
    fn cross_x(&self) -> f64 {
        if self.d.x == 0.0 {
            return f64::INFINITY;
        }
        ((self.i + self.ahead.0) as f64 - self.o.0) * self.inv.0
    }

    #[inline]
    fn cross_y(&self) -> f64 {
        if self.d.y == 0.0 {
            return f64::INFINITY;
        }
        ((self.j + self.ahead.1) as f64 - self.o.1) * self.inv.1
    }

    /// Moves to the next cell; the parameter (cells) where the ray enters it.
    #[inline]
    fn step(&mut self) -> f64 {
        if !self.aimed {
            self.sx = self.cross_x();
            self.sy = self.cross_y();
            self.aimed = true;
        }
        self.last_x = self.sx < self.sy;
        if self.last_x {
            let s = self.sx;
            self.i += self.step.0;
            self.sx = self.cross_x();
            s
        } else {
            let s = self.sy;
            self.j += self.step.1;
            self.sy = self.cross_y();
            s
        }
    }

    /// The distance (world) where the ray entered the current cell, from the grid line
    /// it crossed, divided as a segment's intersection is.
    fn entry(&self, g: &GridRays<'_>) -> f64 {
        if self.last_x {
            (g.x_line(self.i + 1 - self.ahead.0) - self.from.x) / self.d.x
        } else {
            (g.y_line(self.j + 1 - self.ahead.1) - self.from.y) / self.d.y
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The reference march: cell by cell from where the cast begins, no strides, no runs.
    fn by_steps(g: &GridRays<'_>, o: Point2, d: Vector2<f64>, limit: f64) -> Option<f64> {
        let mut m = match g.begin(o, d, limit) {
            Begin::Done(t) => return t,
            Begin::Search(m) => m,
        };
        loop {
            m.s = m.walk.step();
            if m.s > m.end || !g.in_grid(m.walk.i, m.walk.j) {
                return None;
            }
            if g.stride(m.walk.i, m.walk.j) == 0 {
                return Some(m.walk.entry(g));
            }
        }
    }

    /// A map of `w x h` cells of side `res` with long walls along the axes (where rays
    /// graze for tens of cells) and a sprinkle of single forbidden cells.
    fn map(
        (w, h, res): (usize, usize, f64),
        walls: &[(usize, usize, usize, bool)],
        dots: &[(usize, usize)],
    ) -> GridMap {
        let mut zones = vec![Zone::Free; w * h];
        for &(i, j, len, along_x) in walls {
            for k in 0..len {
                let (a, b) = if along_x { (i + k, j) } else { (i, j + k) };
                if a < w && b < h {
                    zones[b * w + a] = Zone::Forbidden;
                }
            }
        }
        for &(i, j) in dots {
            zones[(j % h) * w + i % w] = Zone::Forbidden;
        }
        GridMap::from_zones(w, h, res, Point2::new(-1.0, -2.0), zones).unwrap()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(512))]
        /// The march (strides, then the rest of each row or column from the bits) lowers
        /// every beam to exactly the cell-by-cell traversal's answer, on maps wider than a
        /// word of bits, for rays near the axes (grazing the walls) and anywhere else.
        #[test]
        fn the_march_equals_the_cell_by_cell_traversal(
            (w, h) in (1usize..300, 1usize..300),
            res in prop_oneof![Just(0.05), 0.01..1.0f64],
            walls in proptest::collection::vec((0usize..300, 0usize..300, 1usize..250, any::<bool>()), 0..12),
            dots in proptest::collection::vec((0usize..300, 0usize..300), 0..30),
            (u, v) in (-0.1..1.1f64, -0.1..1.1f64),
            beams in proptest::collection::vec((0u8..4, -0.05..0.05f64, any::<bool>(), -3.2..3.2f64), 1..40),
            limit in prop_oneof![Just(f64::INFINITY), 0.1..40.0f64],
        ) {
            let map = map((w, h, res), &walls, &dots);
            let g = GridRays::new(&map, map.strides_from(Zone::Forbidden).unwrap()).unwrap();
            let o = Point2::new(-1.0 + u * w as f64 * res, -2.0 + v * h as f64 * res);
            for (quarter, tilt, near_axis, any_angle) in beams {
                let a = if near_axis {
                    f64::from(quarter) * std::f64::consts::FRAC_PI_2 + tilt
                } else {
                    any_angle
                };
                let d = Vector2::new(a.cos(), a.sin());
                let mut range = [f64::INFINITY];
                g.lower(o, &[d], &mut range, limit);
                let reference = by_steps(&g, o, d, limit).unwrap_or(f64::INFINITY);
                prop_assert_eq!(range[0], reference, "from {:?} along {}", o, a);
            }
        }
    }
}
