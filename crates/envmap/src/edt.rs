//! Stage 4: the exact Euclidean distance transform in linear time.
//!
//! P. F. Felzenszwalb and D. P. Huttenlocher, "Distance Transforms of Sampled Functions",
//! Theory of Computing 8 (2012): the squared distance is separable, so a 1-D transform per
//! column then per row gives the exact 2-D result; each 1-D transform is the lower envelope
//! of the parabolas `(x - q)^2 + f(q)`, built in one left-to-right pass.

use crate::Mask;

/// Squared distances, in cells, from every cell centre to the nearest obstacle cell centre.
///
/// Distances are exact integers (`dx^2 + dy^2`). Maps with no obstacle hold
/// [`DistanceField::NONE`] everywhere.
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct DistanceField {
    width: usize,
    height: usize,
    dist_sq: Vec<u32>,
}

hyplan_core::grid_size!(DistanceField);

impl DistanceField {
    /// The value of cells with no obstacle anywhere in the map.
    pub const NONE: u32 = u32::MAX;

    /// Squared distances in cells^2, row-major from the bottom row ([`NONE`](Self::NONE)
    /// when there is no obstacle).
    #[must_use]
    pub fn dist_sq(&self) -> &[u32] {
        &self.dist_sq
    }

    /// Squared distance of cell `(i, j)` in cells^2 ([`NONE`](Self::NONE) outside or with
    /// no obstacle).
    #[must_use]
    pub fn cell_dist_sq(&self, i: usize, j: usize) -> u32 {
        if i < self.width && j < self.height {
            self.dist_sq[j * self.width + i]
        } else {
            Self::NONE
        }
    }

    /// Distance of cell `(i, j)` in cells (`f64::INFINITY` with no obstacle or outside).
    #[must_use]
    pub fn cell_dist(&self, i: usize, j: usize) -> f64 {
        match self.cell_dist_sq(i, j) {
            Self::NONE => f64::INFINITY,
            d => f64::from(d).sqrt(),
        }
    }

    /// The stride table of ray marches and edge checks: a byte per cell, row-major like
    /// [`dist_sq`](Self::dist_sq), 0 on an obstacle cell, otherwise 1 + the whole number
    /// of cells a segment may run from any point of the cell without touching the closed
    /// square of an obstacle cell (at most 254, which a map with no obstacle holds).
    ///
    /// No obstacle square is nearer to a point of the cell than the distance between
    /// the two centres minus half a diagonal for each square; the table keeps a
    /// millionth of a cell more, far above the rounding of the coordinates and of
    /// [`GridMap::segment_cells`](crate::GridMap::segment_cells)' touch margin. A byte
    /// keeps the table a quarter of the field's size, so more of it stays in cache.
    ///
    /// ```
    /// use envmap::{distance_transform, Mask};
    /// let mut mask = Mask::new(12, 1);
    /// mask.set(0, 0, true);
    /// let strides = distance_transform(&mask).strides();
    /// assert_eq!(strides[0], 0); // the obstacle
    /// assert_eq!(strides[1], 1); // 1 - 1.41: no room
    /// assert_eq!(strides[11], 1 + 9); // 11 - 1.41 = 9.59 cells
    /// ```
    #[must_use]
    pub fn strides(&self) -> Vec<u8> {
        self.dist_sq
            .iter()
            .map(|&d2| {
                if d2 == 0 {
                    0
                } else {
                    let safe = f64::from(d2).sqrt() - std::f64::consts::SQRT_2 - 1e-6;
                    1 + safe.clamp(0.0, 253.0) as u8
                }
            })
            .collect()
    }
}

/// The exact Euclidean distance transform of `mask`: for each cell, the squared distance
/// from its centre to the centre of the nearest `true` cell, in cells^2.
///
/// Linear in the number of cells (Felzenszwalb-Huttenlocher): a vertical pass gives each
/// cell's distance to the nearest obstacle in its column, then a lower envelope of
/// parabolas per row combines them exactly.
///
/// Exact for masks up to 65 535 cells per side (beyond, no map fits in memory anyway);
/// squared distances above `u32::MAX - 1` (sides above 46 340) saturate to `u32::MAX - 1`.
///
/// ```
/// use envmap::{distance_transform, Mask};
/// let mut mask = Mask::new(5, 4);
/// mask.set(0, 0, true);
/// let d = distance_transform(&mask);
/// assert_eq!(d.cell_dist_sq(0, 0), 0);
/// assert_eq!(d.cell_dist_sq(4, 3), 16 + 9);
/// assert_eq!(d.cell_dist(3, 4), f64::INFINITY); // outside
/// ```
#[must_use]
pub fn distance_transform(mask: &Mask) -> DistanceField {
    let (w, h) = (mask.width(), mask.height());
    // Vertical pass, in the output buffer.
    let mut out = column_distances(mask, u32::MAX, |d| d.saturating_add(1));
    // Horizontal pass, in place: lower envelope of parabolas (x - q)^2 + g(q)^2 per row.
    let mut env = Envelope::with_capacity(w);
    for row in out.chunks_exact_mut(w.max(1)) {
        env.transform(row);
    }
    DistanceField {
        width: w,
        height: h,
        dist_sq: out,
    }
}

/// Distance in cells from each cell to the nearest obstacle of its column, row-major:
/// 0 on an obstacle, `next` of the neighbour's distance otherwise, `far` where no obstacle
/// is below (before the downward sweep) or above (`next` saturates at `far`, which must
/// be its fixed point). Row by row, so memory is read in order.
pub(crate) fn column_distances<T: Copy + Ord + Default>(
    mask: &Mask,
    far: T,
    next: impl Fn(T) -> T,
) -> Vec<T> {
    let (w, h) = (mask.width(), mask.height());
    let cells = mask.cells();
    let mut out = vec![far; w * h];
    for j in 0..h {
        let (done, rest) = out.split_at_mut(j * w);
        let row = &mut rest[..w];
        let m = &cells[j * w..(j + 1) * w];
        if j == 0 {
            for (c, &o) in row.iter_mut().zip(m) {
                *c = if o { T::default() } else { far };
            }
        } else {
            let below = &done[(j - 1) * w..j * w];
            for ((c, &o), &b) in row.iter_mut().zip(m).zip(below) {
                *c = if o { T::default() } else { next(b) };
            }
        }
    }
    for j in (0..h.saturating_sub(1)).rev() {
        let (lo, hi) = out.split_at_mut((j + 1) * w);
        let row = &mut lo[j * w..];
        let above = &hi[..w];
        for (c, &a) in row.iter_mut().zip(above) {
            *c = (*c).min(next(a));
        }
    }
    out
}

/// Buffers of the 1-D lower envelope, reused across rows.
struct Envelope {
    /// Positions of the parabolas of the envelope.
    v: Vec<usize>,
    /// Left boundary of parabola `v[k]`'s part of the envelope, as the fraction
    /// `z_num[k] / z_den[k]` (`z_den > 0`); unused for `k = 0` (minus infinity).
    z_num: Vec<i64>,
    /// Denominators of the boundaries.
    z_den: Vec<i64>,
    /// Squared heights `g(q)^2` of the row.
    f: Vec<i64>,
}

impl Envelope {
    fn with_capacity(n: usize) -> Self {
        Self {
            v: Vec::with_capacity(n),
            z_num: Vec::with_capacity(n),
            z_den: Vec::with_capacity(n),
            f: Vec::with_capacity(n),
        }
    }

    /// In place: `row[x] = min_q (x - q)^2 + row[q]^2` over the finite `row[q]` (`u32::MAX`
    /// is infinite); all `NONE` if there is none.
    ///
    /// Integer arithmetic only: parabolas p < q meet at
    /// `s = ((f[q] + q^2) - (f[p] + p^2)) / (2 (q - p))`, kept as a fraction and compared by
    /// cross-multiplication (numerators < 2^33 and denominators < 2^17 for sides below
    /// 65 536 cells, so products stay far below 2^63).
    fn transform(&mut self, row: &mut [u32]) {
        let (v, z_num, z_den, f) = (&mut self.v, &mut self.z_num, &mut self.z_den, &mut self.f);
        v.clear();
        z_num.clear();
        z_den.clear();
        f.clear();
        f.extend(row.iter().map(|&d| {
            if d == u32::MAX {
                -1
            } else {
                i64::from(d) * i64::from(d)
            }
        }));
        for q in 0..row.len() {
            if f[q] < 0 {
                continue;
            }
            let qi = q as i64;
            let hq = f[q] + qi * qi;
            loop {
                let Some(&p) = v.last() else {
                    v.push(q);
                    z_num.push(0);
                    z_den.push(1);
                    break;
                };
                let pi = p as i64;
                let (num, den) = (hq - (f[p] + pi * pi), 2 * (qi - pi));
                let k = v.len() - 1;
                // s <= z[k] (never for k = 0, whose boundary is minus infinity): q hides p.
                if k > 0 && num * z_den[k] <= z_num[k] * den {
                    v.pop();
                    z_num.pop();
                    z_den.pop();
                    continue;
                }
                v.push(q);
                z_num.push(num);
                z_den.push(den);
                break;
            }
        }
        if v.is_empty() {
            row.fill(DistanceField::NONE);
            return;
        }
        let mut k = 0;
        for (x, o) in row.iter_mut().enumerate() {
            let xi = x as i64;
            // Advance while z[k + 1] < x.
            while k + 1 < v.len() && z_num[k + 1] < xi * z_den[k + 1] {
                k += 1;
            }
            let dx = xi - v[k] as i64;
            let d = dx * dx + f[v[k]];
            *o = u32::try_from(d).unwrap_or(u32::MAX - 1).min(u32::MAX - 1);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute(mask: &Mask) -> Vec<u32> {
        let (w, h) = (mask.width(), mask.height());
        let obstacles: Vec<(i64, i64)> = (0..h)
            .flat_map(|j| (0..w).map(move |i| (i, j)))
            .filter(|&(i, j)| mask.get(i, j))
            .map(|(i, j)| (i as i64, j as i64))
            .collect();
        (0..h)
            .flat_map(|j| (0..w).map(move |i| (i as i64, j as i64)))
            .map(|(i, j)| {
                obstacles
                    .iter()
                    .map(|&(a, b)| ((a - i).pow(2) + (b - j).pow(2)) as u32)
                    .min()
                    .unwrap_or(u32::MAX)
            })
            .collect()
    }

    #[test]
    fn tiny_maps_match_brute_force() {
        let patterns: [&[(usize, usize)]; 4] = [
            &[],
            &[(0, 0)],
            &[(3, 1), (0, 4)],
            &[(1, 1), (2, 1), (5, 3), (5, 4), (0, 0)],
        ];
        for cells in patterns {
            let mut mask = Mask::new(6, 5);
            for &(i, j) in cells {
                mask.set(i, j, true);
            }
            assert_eq!(distance_transform(&mask).dist_sq, brute(&mask), "{cells:?}");
        }
    }

    #[test]
    fn single_row_and_column() {
        let mut mask = Mask::new(7, 1);
        mask.set(2, 0, true);
        assert_eq!(
            distance_transform(&mask).dist_sq,
            vec![4, 1, 0, 1, 4, 9, 16]
        );
        let mut mask = Mask::new(1, 4);
        mask.set(0, 3, true);
        assert_eq!(distance_transform(&mask).dist_sq, vec![9, 4, 1, 0]);
    }
}
