//! `Workspace` for `GridMap`: exact cell-level collision queries.

use std::sync::atomic::{AtomicU64, Ordering};

use hyplan_core::{Bounds, PlanError, Point2, Workspace, Zone};

use crate::GridMap;

impl GridMap {
    /// Visits every cell whose closed square the closed segment `a`-`b` touches, corner
    /// touches included, until `visit` returns `false`; returns whether every visit
    /// returned `true`.
    ///
    /// **The boundary rule: cells are closed.** A segment (or a point, `a == b`) that
    /// reaches a cell's edge or corner touches that cell, wherever on the segment the
    /// contact is: at an end point, in the middle, or along a whole grid line (then the
    /// cells on both sides are touched). Floating-point rounding never lets a contact
    /// slip through: a segment that misses a cell by less than [`TOUCH_TOLERANCE`] cells
    /// (measured along the minor axis) counts as touching it, and the sweep's rounding
    /// errors stay far below that margin on maps up to 10^6 cells a side. So the visited
    /// set is the exact closed-cell set, plus at most cells missed by a hair.
    ///
    /// The segment is swept along its major axis one column (or row) at a time, so the
    /// cost grows with the number of cells crossed, not with the map size. Cells outside
    /// the map are not visited; callers check the end points against the bounds.
    pub fn segment_cells(
        &self,
        a: Point2,
        b: Point2,
        mut visit: impl FnMut(usize, usize) -> bool,
    ) -> bool {
        // The quotient by the resolution, not a product by a rounded 1/resolution: an edge
        // given in world units (origin + k * resolution) then lands on k whenever that is
        // representable.
        let (ua, va) = self.cell_units(a);
        let (ub, vb) = self.cell_units(b);
        let (w, h) = (self.width(), self.height());
        let all = (f64::NEG_INFINITY, f64::INFINITY);
        if (ub - ua).abs() >= (vb - va).abs() {
            sweep(ua, va, ub, vb, (w, h), all, &mut visit)
        } else {
            sweep(va, ua, vb, ub, (h, w), all, |r, c| visit(c, r))
        }
    }

    /// Whether every cell the closed segment touches lets motion through, and both end
    /// points lie inside the map.
    ///
    /// Exact at the cell level: a segment that only grazes the corner of a blocked cell is
    /// blocked. This is stricter than OMPL's sampled motion checks, which can cut corners.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::Point2;
    /// let map = GridMap::from_ascii("
    ///     .#
    ///     ..
    /// ")?;
    /// // (0,0) -> (2,2) passes exactly through the corner of the blocked cell (1, 1).
    /// assert!(!map.segment_free_cells(Point2::new(0.0, 0.0), Point2::new(2.0, 2.0)));
    /// assert!(map.segment_free_cells(Point2::new(0.5, 0.5), Point2::new(1.5, 0.5)));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Cost
    ///
    /// Once the map's stride table is made ([`blocked_strides`](Self::blocked_strides):
    /// call it to prepare the map, or let the edge checks make it once they have swept as
    /// many columns as the map has cells), the open stretches at both ends of the segment are
    /// crossed in strides of up to 253 cells, and only the columns left between are
    /// swept, with the same answer; a segment of 5 cells or less is checked by one look at
    /// the stride of its middle where that covers both halves, else by a look at the packed
    /// rows of its bounding box ([`blocked_bits`](Self::blocked_bits), made with the
    /// strides), and swept only when that box holds a blocked cell.
    #[must_use]
    pub fn segment_free_cells(&self, a: Point2, b: Point2) -> bool {
        let bounds = self.bounds();
        if !(bounds.contains(a) && bounds.contains(b)) {
            return false;
        }
        let (ua, va) = self.cell_units(a);
        let (ub, vb) = self.cell_units(b);
        let (w, h) = (self.width(), self.height());
        let major_u = (ub - ua).abs() >= (vb - va).abs();
        // Where along the major axis the columns that need a sweep lie.
        let mut middle = (f64::NEG_INFINITY, f64::INFINITY);
        let (du, dv) = (ub - ua, vb - va);
        let len_sq = du * du + dv * dv;
        if len_sq <= SHORT_SQ {
            // A segment within a few cells is swept at once (no stride would pay), unless
            // the stride at its middle covers both halves: one look, which is the common
            // case in open space.
            // Counted toward making the table as the longer segments are: a map whose checks
            // are all short gets its table too.
            if let Some(strides) = self.edge_strides(du.abs().max(dv.abs())) {
                let (um, vm) = (ua + du / 2.0, va + dv / 2.0);
                let run = f64::from(strides[floor_index(vm, 0, h) * w + floor_index(um, 0, w)]);
                if run >= 2.0 && 4.0 * (run - 1.0) * (run - 1.0) >= len_sq {
                    return true;
                }
                if self.box_clear((ua, va), (ub, vb)) {
                    return true;
                }
            }
        } else if let Some(strides) = self.edge_strides(du.abs().max(dv.abs())) {
            let len = len_sq.sqrt();
            let (eu, ev) = (du / len, dv / len);
            let from_a = open_stretch(strides, (w, h), (ua, va), (eu, ev), len);
            if from_a >= len {
                return true;
            }
            let from_b = open_stretch(strides, (w, h), (ub, vb), (-eu, -ev), len - from_a);
            if from_a + from_b >= len {
                return true;
            }
            let (pa, dp) = if major_u { (ua, du) } else { (va, dv) };
            let (ma, mb) = (pa + from_a * dp / len, pa + dp - from_b * dp / len);
            middle = (ma.min(mb), ma.max(mb));
        }
        let free = |i, j| self.cell_free(i, j);
        if major_u {
            sweep(ua, va, ub, vb, (w, h), middle, free)
        } else {
            sweep(va, ua, vb, ub, (h, w), middle, |r, c| free(c, r))
        }
    }

    /// Whether no blocked cell touches the box with corners `(ua, va)` and `(ub, vb)` (cell
    /// units from the map's origin, inside the map): the cells a sweep of the segment between
    /// them visits lie in that box, whose margin is twice the sweep's [`TOUCH_TOLERANCE`] so
    /// that the sweep's rounding stays inside. One look at a packed row a row: near a wall,
    /// a short edge mostly passes here without the sweep.
    #[inline]
    fn box_clear(&self, (ua, va): (f64, f64), (ub, vb): (f64, f64)) -> bool {
        let Some(bits) = self.blocked_bits() else {
            return false;
        };
        let margin = 2.0 * TOUCH_TOLERANCE;
        let (w, h) = (self.width(), self.height());
        bits.box_clear(
            ceil_index(ua.min(ub) - margin, -1, w)..=floor_index(ua.max(ub) + margin, 0, w),
            ceil_index(va.min(vb) - margin, -1, h)..=floor_index(va.max(vb) + margin, 0, h),
        )
    }

    /// The stride table edge checks may use, counting `cells` of sweep toward making it
    /// when it is not made.
    #[inline]
    fn edge_strides(&self, cells: f64) -> Option<&[u8]> {
        match self.made_blocked_strides() {
            Some(t) => Some(t),
            None => self.count_edge_work(cells),
        }
    }

    /// [`edge_strides`](Self::edge_strides) before the table is made: counts the work, and
    /// makes the table when it is due. Out of line: once the table is made, the checks only
    /// look it up.
    #[cold]
    #[inline(never)]
    fn count_edge_work(&self, cells: f64) -> Option<&[u8]> {
        // A relaxed load and store, not an atomic add: a count lost to a race between
        // threads only delays the table.
        let work = self.edge_work.0.load(Ordering::Relaxed) + cells as u64 + 1;
        self.edge_work.0.store(work, Ordering::Relaxed);
        // Making the table costs about two column sweeps a cell, so it is made once the
        // checks have swept as many columns as the map has cells: at most about twice the
        // sweeping it saves, on a map edited between few checks.
        if work > (self.width() * self.height()) as u64 {
            self.blocked_strides()
        } else {
            None
        }
    }

    /// The most dangerous zone among the cells whose closed squares contain `p`
    /// (`Forbidden` outside the map or for NaN).
    #[must_use]
    pub fn zone_at(&self, p: Point2) -> Zone {
        if !self.bounds().contains(p) {
            return Zone::Forbidden;
        }
        let mut zone = Zone::Free;
        self.segment_cells(p, p, |i, j| {
            zone = zone.max(self.cell_zone(i, j));
            true
        });
        zone
    }
}

/// The squared length, cells², up to which [`GridMap::segment_free_cells`] checks a segment by
/// the stride at its middle and the bits of its box, then sweeps it whole, instead of crossing
/// its ends in strides: 5 cells, with a margin so that a step of exactly 5 cells, which
/// rounding can make a few ulps longer, stays on this side. The bound was 3 cells without a
/// margin: a quarter to a third of the 3-cell steps of RRT and RRT-Connect on the arena map
/// took the longer way, which costs more near walls, and so did every 5-cell step.
const SHORT_SQ: f64 = 25.0 * (1.0 + 1e-9);

/// How close, in cells, a segment may pass to a cell and still count as touching it in
/// [`GridMap::segment_cells`]: a margin for the rounding of world-to-cell conversion and of
/// the sweep, never a gap a path could use (1e-9 cells is a nanometre on a 1 m grid).
pub const TOUCH_TOLERANCE: f64 = 1e-9;

/// Cells swept by edge checks since a map's zones last changed (see
/// [`GridMap::segment_free_cells`]); a clone starts again from zero.
#[derive(Debug, Default)]
pub(crate) struct EdgeWork(AtomicU64);

impl Clone for EdgeWork {
    fn clone(&self) -> Self {
        Self::default()
    }
}

/// How far, in cells along the unit direction `e`, the segment from `p` (cell units from
/// the map's origin, inside the `w x h` map) is known to touch no blocked square, by
/// strides of the map's stride table ([`GridMap::blocked_strides`]); stops at `len` or
/// where the strides get short (under two cells, where a cell sweep is as cheap). Edge
/// checks and lines of sight cross the open ends of their segments with it.
///
/// ```
/// use envmap::{GridMap, open_stretch};
/// let map = GridMap::from_ascii("..........#")?;
/// let strides = map.blocked_strides().unwrap();
/// // From the first cell's centre toward the blocked cell 10 cells away: 8 cells known free.
/// assert_eq!(open_stretch(strides, (11, 1), (0.5, 0.5), (1.0, 0.0), 20.0), 8.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[inline]
#[must_use]
pub fn open_stretch(
    strides: &[u8],
    (w, h): (usize, usize),
    (pu, pv): (f64, f64),
    (eu, ev): (f64, f64),
    len: f64,
) -> f64 {
    let mut t = 0.0;
    loop {
        // A point on the map's upper or right edge is in the last cell, whose stride
        // holds for its closed square.
        let (i, j) = (
            floor_index(pu + eu * t, 0, w),
            floor_index(pv + ev * t, 0, h),
        );
        let stride = strides[j * w + i];
        if stride < 3 {
            return t;
        }
        t += f64::from(stride - 1);
        if t >= len {
            return len;
        }
    }
}

/// Sweeps the closed segment (p0, q0)-(p1, q1) along the major axis p, with
/// |p1 - p0| >= |q1 - q0|, visiting (column, row) pairs of the closed unit cells it meets
/// within `[0, np) x [0, nq)`, in the columns from the one before `middle.0`'s to the one
/// after `middle.1`'s (the others are known free; all: infinite bounds).
fn sweep(
    p0: f64,
    q0: f64,
    p1: f64,
    q1: f64,
    (np, nq): (usize, usize),
    middle: (f64, f64),
    mut visit: impl FnMut(usize, usize) -> bool,
) -> bool {
    let (lo, hi) = (p0.min(p1), p0.max(p1));
    if !(lo.is_finite() && hi.is_finite() && q0.is_finite() && q1.is_finite()) {
        return false;
    }
    // q on the segment at p. The end points return their own q, not a value recomputed
    // through the slope: a segment that ends exactly on a grid line must reach it
    // (recomputing 0.375 + 2.875 * (1.625 / 2.875) gives 1.9999999999999998, which missed
    // the cell above; issue 16). Inside, the product comes before the division so that a
    // line through a grid corner lands on it whenever the inputs are exact.
    let q_at = |p: f64| {
        if p == p0 {
            q0
        } else if p == p1 {
            q1
        } else {
            q0 + (p - p0) * (q1 - q0) / (p1 - p0)
        }
    };
    let tol = TOUCH_TOLERANCE;
    // Closed strip [c, c+1] meets [lo, hi] iff ceil(lo) - 1 <= c <= floor(hi).
    let c_first = ceil_index(lo - tol, -1, np).max(floor_index(middle.0, -1, np));
    let c_last = floor_index(hi + tol, 0, np).min(floor_index(middle.1, 1, np));
    // A column's q at its right edge is the next one's at its left (both p clamp the same
    // line into [lo, hi]): computed once.
    let mut qa = q_at(lo.max(c_first as f64).min(hi));
    for c in c_first..=c_last {
        let qb = q_at(hi.min(c as f64 + 1.0).max(lo));
        let (qlo, qhi) = (qa.min(qb) - tol, qa.max(qb) + tol);
        for r in ceil_index(qlo, -1, nq)..=floor_index(qhi, 0, nq) {
            if !visit(c, r) {
                return false;
            }
        }
        qa = qb;
    }
    true
}

/// `floor(x) + k` clamped to `[0, n - 1]` (`n > 0`; 0 for NaN). The floor is the truncation, one
/// lower for a negative `x` with a fraction: the baseline x86-64 target has no rounding
/// instruction, so `f64::floor` is a libm call, and the sweep makes several a cell.
#[inline]
fn floor_index(x: f64, k: i64, n: usize) -> usize {
    if k == 0 {
        // The truncation differs from the floor only for a negative `x`, where both clamp
        // to 0 (NaN too: `as` makes it 0): a few instructions instead of a score (the
        // short edge checks take two of these).
        return clamp_cell(x as i64, n);
    }
    if x.is_nan() {
        return 0;
    }
    // Saturating for infinite bounds; exact below 2^53, where every larger float is whole.
    let t = x as i64;
    let floor = if (t as f64) > x {
        t.saturating_sub(1)
    } else {
        t
    };
    clamp_cell(floor.saturating_add(k), n)
}

/// `ceil(x) + k` clamped to `[0, n - 1]`, as [`floor_index`].
#[inline]
fn ceil_index(x: f64, k: i64, n: usize) -> usize {
    if x.is_nan() {
        return 0;
    }
    let t = x as i64;
    let ceil = if (t as f64) < x {
        t.saturating_add(1)
    } else {
        t
    };
    clamp_cell(ceil.saturating_add(k), n)
}

/// `c` clamped to `[0, n - 1]`.
#[inline]
fn clamp_cell(c: i64, n: usize) -> usize {
    usize::try_from(c).map_or(0, |c| c.min(n - 1))
}

impl GridMap {
    /// The cell whose square holds `p` more than 1e-6 cells from each of its edges (far
    /// beyond the sweep's touch margin [`TOUCH_TOLERANCE`] and the rounding of the cell
    /// coordinates), or `None`: the point test that needs no sweep.
    #[inline]
    fn interior_cell(&self, p: Point2) -> Option<(usize, usize)> {
        let (i, j, inside) = self.cell_of(p)?;
        inside().then_some((i, j))
    }

    /// Whether `p` lies in a blocked cell's [`interior_cell`](Self::interior_cell) square:
    /// the cell is read first, and the margins only for a blocked one (most points tested
    /// are in free cells).
    #[inline]
    fn in_blocked_interior(&self, p: Point2) -> bool {
        self.cell_of(p)
            .is_some_and(|(i, j, inside)| !self.cell_free(i, j) && inside())
    }

    /// The cell whose half-open square holds `p` (`None` outside the map or for NaN), and
    /// whether `p` is more than 1e-6 cells from each of its edges.
    #[inline(always)]
    fn cell_of(&self, p: Point2) -> Option<(usize, usize, impl FnOnce() -> bool)> {
        let (u, v) = self.cell_units(p);
        if !(u >= 0.0 && v >= 0.0) {
            return None;
        }
        // Truncation is the floor here (u and v are not negative), without libm's call;
        // through `i64`, whose conversion is a few instructions where one to unsigned is a
        // dozen (not negative, it keeps its value as `usize`). Compared with the size as
        // integers (a `usize` made `f64` is half a dozen instructions): a point at or beyond
        // the far edge truncates (or saturates) to at least the size, as `u < width` would
        // refuse it. Unsigned, as the cell's own lookup compares, which then needs no test
        // of its own.
        let (i, j) = (u as i64 as usize, v as i64 as usize);
        if i >= self.width() || j >= self.height() {
            return None;
        }
        let inside = |t: f64, k: usize| t - k as f64 > 1e-6 && k as f64 + 1.0 - t > 1e-6;
        Some((i, j, move || inside(u, i) && inside(v, j)))
    }
}

/// The grid map behind a workspace, for the planners that need one.
impl GridMap {
    /// The grid map behind `ws`, for `planner`, which runs on grid maps only: the one
    /// place a workspace is downcast (a grid planner's `Planner` impl calls it; its own
    /// `plan` takes a `&GridMap`).
    ///
    /// # Errors
    ///
    /// [`PlanError::InvalidParameter`] named `workspace`, naming the planner, when `ws` is
    /// not a grid map.
    ///
    /// ```
    /// use envmap::GridMap;
    /// let map = GridMap::from_ascii("..")?;
    /// assert!(GridMap::of_workspace(&map, "astar").is_ok());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn of_workspace<'a, W: Workspace + ?Sized>(
        ws: &'a W,
        planner: &'static str,
    ) -> Result<&'a Self, PlanError> {
        Self::try_of_workspace(ws).ok_or_else(|| PlanError::InvalidParameter {
            name: "workspace",
            value: format!("not an envmap::GridMap (given to {planner})"),
            reason: "this planner runs on grid maps only",
        })
    }

    /// The grid map behind `ws`, if it is one: for planners with an exact path on grids
    /// and a sampled one elsewhere.
    #[must_use]
    pub fn try_of_workspace<W: Workspace + ?Sized>(ws: &W) -> Option<&Self> {
        ws.as_any().and_then(|a| a.downcast_ref::<Self>())
    }
}

/// The zone queries along segments that the papers' planners need, exact on the cells.
impl GridMap {
    /// Whether the closed segment touches only `Free` cells (neither high-risk nor
    /// forbidden) and both ends lie inside the map: seed 003's "safe" edge.
    ///
    /// ```
    /// use envmap::GridMap;
    /// use hyplan_core::Point2;
    /// let map = GridMap::from_ascii("....\n.~~.\n....")?;
    /// assert!(map.segment_in_safe_zone(Point2::new(0.5, 0.5), Point2::new(3.5, 0.5)));
    /// assert!(!map.segment_in_safe_zone(Point2::new(0.5, 1.5), Point2::new(3.5, 1.5)));
    /// assert!((map.risk_length(Point2::new(0.5, 1.5), Point2::new(3.5, 1.5)) - 2.0).abs() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn segment_in_safe_zone(&self, a: Point2, b: Point2) -> bool {
        let bounds = self.bounds();
        bounds.contains(a)
            && bounds.contains(b)
            && self.segment_cells(a, b, |i, j| self.cell_zone(i, j) == Zone::Free)
    }

    /// Length of the segment inside high-risk cells, world units (each cell's share
    /// clipped exactly, [`clipped_length`](Self::clipped_length)): seed 003's risk cost.
    #[must_use]
    pub fn risk_length(&self, a: Point2, b: Point2) -> f64 {
        let mut len = 0.0;
        self.segment_cells(a, b, |i, j| {
            if self.cell_zone(i, j) == Zone::Risk {
                len += self.clipped_length(i, j, a, b);
            }
            true
        });
        len.min((b - a).norm())
    }

    /// Length of segment `a`-`b` inside the closed square of cell `(i, j)` (Liang-Barsky).
    #[must_use]
    pub fn clipped_length(&self, i: usize, j: usize, a: Point2, b: Point2) -> f64 {
        let r = self.resolution();
        let o = self.origin();
        let (x0, y0) = (o.x + i as f64 * r, o.y + j as f64 * r);
        let (x1, y1) = (x0 + r, y0 + r);
        let d = b - a;
        let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
        for (p, q) in [
            (-d.x, a.x - x0),
            (d.x, x1 - a.x),
            (-d.y, a.y - y0),
            (d.y, y1 - a.y),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return 0.0;
                }
            } else {
                let t = q / p;
                if p < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
            }
        }
        if t1 > t0 { (t1 - t0) * d.norm() } else { 0.0 }
    }

    /// Distance from `p` to the nearest cell that blocks motion (its `blocked_from`), if one lies within
    /// `radius` (world units); `None` when none does. Exact point-to-square distances over
    /// the cells of the disc's bounding box.
    #[must_use]
    pub fn blocked_within(&self, p: Point2, radius: f64) -> Option<f64> {
        let r = self.resolution();
        let o = self.origin();
        let (u, v) = ((p.x - o.x) / r, (p.y - o.y) / r);
        let k = radius / r;
        let i0 = (u - k).floor().max(0.0) as usize;
        let j0 = (v - k).floor().max(0.0) as usize;
        let i1 = ((u + k).floor().max(0.0) as usize).min(self.width().saturating_sub(1));
        let j1 = ((v + k).floor().max(0.0) as usize).min(self.height().saturating_sub(1));
        let mut best: Option<f64> = None;
        for j in j0..=j1 {
            for i in i0..=i1 {
                if self.cell_free(i, j) {
                    continue;
                }
                let dx = (i as f64 - u).max(0.0).max(u - (i as f64 + 1.0));
                let dy = (j as f64 - v).max(0.0).max(v - (j as f64 + 1.0));
                let d = dx.hypot(dy) * r;
                if d < radius && best.is_none_or(|b| d < b) {
                    best = Some(d);
                }
            }
        }
        best
    }
}

impl Workspace for GridMap {
    fn bounds(&self) -> Bounds {
        GridMap::bounds(self)
    }

    /// A point well inside one cell (the usual case for a random sample) is answered by
    /// that cell alone; a point on or near a cell edge goes through the sweep, which
    /// treats cells as closed. The same answer either way.
    #[inline]
    fn is_free(&self, p: Point2) -> bool {
        match self.interior_cell(p) {
            Some((i, j)) => self.cell_free(i, j),
            None => self.segment_free_cells(p, p),
        }
    }

    /// A segment that ends well inside a blocked cell is refused without the sweep (the
    /// sweep would meet that cell); any other goes through it.
    #[inline]
    fn segment_free(&self, a: Point2, b: Point2) -> bool {
        !self.in_blocked_interior(b) && self.segment_free_cells(a, b)
    }

    fn zone(&self, p: Point2) -> Zone {
        self.zone_at(p)
    }

    fn clearance(&self, p: Point2) -> Option<f64> {
        Some(self.clearance_at(p))
    }

    fn disconnection(&self, query: &hyplan_core::Query) -> Option<hyplan_core::NoPathCause> {
        crate::connectivity::disconnection(self, query, crate::connectivity::Moves::Four)
    }

    fn cells(&self) -> Option<usize> {
        Some(self.width() * self.height())
    }

    fn as_any(&self) -> Option<&dyn std::any::Any> {
        Some(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// libm's floor and ceil, clamped as the sweep had them.
    fn reference(x: f64, n: usize) -> usize {
        if x < 0.0 {
            0
        } else if x >= n as f64 {
            n - 1
        } else {
            x as usize
        }
    }

    proptest! {
        /// The sweep's index rounding without libm equals libm's, clamped, for any float.
        #[test]
        fn index_rounding_equals_floor_and_ceil(
            x in prop_oneof![
                -5.0..300.0f64,
                (-3i64..300).prop_map(|k| k as f64),
                any::<f64>(),
                Just(f64::INFINITY),
                Just(f64::NEG_INFINITY),
                Just(f64::NAN),
                Just(-0.0),
            ],
            k in -1i64..=1,
            n in 1usize..300,
        ) {
            prop_assert_eq!(floor_index(x, k, n), reference(x.floor() + k as f64, n));
            prop_assert_eq!(ceil_index(x, k, n), reference(x.ceil() + k as f64, n));
        }

        /// A point's cell, found by truncation, is the one found with libm's floor: on
        /// cell edges, on the map's borders, off the map, and for non-finite points.
        #[test]
        fn truncation_finds_the_floors_cell(
            x in prop_oneof![
                -3.0..12.0f64,
                (-3i64..13).prop_map(|k| k as f64 * 0.5),
                any::<f64>(),
                Just(f64::INFINITY),
                Just(f64::NAN),
                Just(-0.0),
            ],
            y in -3.0..9.0f64,
        ) {
            let map = GridMap::from_ascii("....#\n.#...\n.....")
                .unwrap()
                .with_frame(2.0, Point2::new(-1.0, 0.5))
                .unwrap();
            let p = Point2::new(x, y);
            let u = (p.x - map.origin().x) / map.resolution();
            let v = (p.y - map.origin().y) / map.resolution();
            let (w, h) = (map.width() as f64, map.height() as f64);
            let floor = (u >= 0.0 && v >= 0.0).then(|| {
                let i = if u == w { w - 1.0 } else { u.floor() };
                let j = if v == h { h - 1.0 } else { v.floor() };
                (i < w && j < h).then_some((i as usize, j as usize))
            });
            prop_assert_eq!(map.world_to_cell(p), floor.flatten());
            let interior = (u >= 0.0 && v >= 0.0 && u < w && v < h)
                .then(|| {
                    let (i, j) = (u.floor(), v.floor());
                    let inside = |t: f64, k: f64| t - k > 1e-6 && k + 1.0 - t > 1e-6;
                    (inside(u, i) && inside(v, j)).then_some((i as usize, j as usize))
                })
                .flatten();
            prop_assert_eq!(map.interior_cell(p), interior);
        }
    }

    #[test]
    fn clipped_length_of_a_diagonal() {
        let map = GridMap::filled(4, 4, Zone::Free).unwrap();
        let (a, b) = (Point2::new(0.0, 0.0), Point2::new(2.0, 2.0));
        let l = map.clipped_length(0, 0, a, b);
        assert!((l - 2f64.sqrt()).abs() < 1e-12);
        assert_eq!(map.clipped_length(3, 0, a, b), 0.0);
    }

    #[test]
    fn blocked_within_finds_the_nearest_cell() {
        let map = GridMap::from_ascii(".....\n....#\n.....").unwrap();
        let d = map.blocked_within(Point2::new(2.5, 1.5), 5.0).unwrap();
        assert!((d - 1.5).abs() < 1e-12);
        assert!(map.blocked_within(Point2::new(0.5, 1.5), 2.0).is_none());
    }

    fn cells(map: &GridMap, a: (f64, f64), b: (f64, f64)) -> Vec<(usize, usize)> {
        let mut v = Vec::new();
        map.segment_cells(Point2::new(a.0, a.1), Point2::new(b.0, b.1), |i, j| {
            v.push((i, j));
            true
        });
        v.sort_unstable();
        v
    }

    #[test]
    fn segments_touch_the_cells_they_meet() {
        // (map side, from, to, the cells touched)
        let cases = [
            // Horizontal through cell centres: one row.
            (
                5,
                (0.5, 2.5),
                (3.5, 2.5),
                vec![(0, 2), (1, 2), (2, 2), (3, 2)],
            ),
            // Diagonal through a cell corner: the four cells around it.
            (
                5,
                (0.5, 0.5),
                (1.5, 1.5),
                vec![(0, 0), (0, 1), (1, 0), (1, 1)],
            ),
            // Along a grid line: both sides.
            (
                4,
                (0.5, 2.0),
                (1.5, 2.0),
                vec![(0, 1), (0, 2), (1, 1), (1, 2)],
            ),
        ];
        for (side, a, b, touched) in cases {
            let map = GridMap::filled(side, side, Zone::Free).unwrap();
            assert_eq!(cells(&map, a, b), touched, "{a:?} -> {b:?}");
        }
    }

    #[test]
    fn point_on_map_border_stays_inside() {
        let map = GridMap::filled(2, 2, Zone::Free).unwrap();
        assert_eq!(cells(&map, (2.0, 2.0), (2.0, 2.0)), vec![(1, 1)]);
        assert!(map.is_free(Point2::new(2.0, 2.0)));
        assert!(!map.is_free(Point2::new(2.0, 2.01)));
    }

    #[test]
    fn steep_segment_sweeps_rows() {
        let map = GridMap::filled(4, 8, Zone::Free).unwrap();
        assert_eq!(
            cells(&map, (0.5, 0.5), (1.5, 6.5)),
            vec![
                (0, 0),
                (0, 1),
                (0, 2),
                (0, 3),
                (1, 3),
                (1, 4),
                (1, 5),
                (1, 6)
            ]
        );
    }

    /// Issue 16: the segment ends on the bottom edge of cell (2, 2); the slope
    /// recomputation put the end at y = 1.9999999999999998 and missed that cell.
    #[test]
    fn segment_ending_on_a_cell_edge_touches_that_cell() {
        let map = GridMap::filled(5, 4, Zone::Free).unwrap();
        assert_eq!(
            cells(&map, (0.0, 0.375), (2.875, 2.0)),
            vec![(0, 0), (1, 0), (1, 1), (2, 1), (2, 2)]
        );
        assert_eq!(
            cells(&map, (2.875, 2.0), (0.0, 0.375)),
            vec![(0, 0), (1, 0), (1, 1), (2, 1), (2, 2)]
        );
        let mut blocked = map.clone();
        blocked.set_cell_zone(2, 2, Zone::Forbidden);
        assert!(!blocked.segment_free(Point2::new(0.0, 0.375), Point2::new(2.875, 2.0)));
        assert!(!blocked.is_free(Point2::new(2.875, 2.0)));
        assert!(blocked.is_free(Point2::new(2.875, 1.999)));
    }

    /// A line through a grid corner with coordinates that are not exact in binary
    /// (0.1, 0.3, 1.9, 1.7): the corner (1, 1) is reached, so the cells meeting there
    /// are touched.
    #[test]
    fn corner_contact_survives_rounding() {
        let mut map = GridMap::filled(3, 3, Zone::Free).unwrap();
        map.set_cell_zone(0, 1, Zone::Forbidden);
        let (a, b) = (Point2::new(0.1, 0.3), Point2::new(1.9, 1.7));
        assert!(!map.segment_free(a, b));
        assert!(!map.segment_free(b, a));
        // In a world frame whose edges are not exact in binary either.
        let shifted = map
            .clone()
            .with_frame(0.05, Point2::new(-10.0, 3.3))
            .unwrap();
        let to_world = |p: Point2| Point2::new(-10.0 + p.x * 0.05, 3.3 + p.y * 0.05);
        assert!(!shifted.segment_free(to_world(a), to_world(b)));
        // A point on the corner of the blocked cell is not free; just off it, it is.
        assert!(!shifted.is_free(to_world(Point2::new(1.0, 1.0))));
        assert!(shifted.is_free(to_world(Point2::new(1.01, 0.99))));
    }

    /// Edge checks make the stride table once they have swept as many columns as the map
    /// has cells, whether their segments are short or long.
    #[test]
    fn short_checks_make_the_stride_table_too() {
        for len in [3.0, 5.0, 12.0] {
            let map = GridMap::from_ascii(
                "....................\n....#...............\n....................\n....................",
            )
            .unwrap();
            let (a, b) = (Point2::new(0.5, 3.5), Point2::new(0.5 + len, 3.5));
            let mut checks = 0;
            while map.made_blocked_strides().is_none() && checks < 100 {
                assert!(map.segment_free(a, b));
                checks += 1;
            }
            // 80 cells, and a check counts its columns and one more.
            assert!(map.made_blocked_strides().is_some(), "{len} cells");
            assert!(checks <= 21, "{len} cells: {checks} checks");
        }
    }

    #[test]
    fn nan_is_never_free() {
        let map = GridMap::filled(2, 2, Zone::Free).unwrap();
        assert!(!map.is_free(Point2::new(f64::NAN, 1.0)));
        assert!(!map.segment_free(Point2::new(0.5, 0.5), Point2::new(f64::NAN, 1.0)));
    }
}
