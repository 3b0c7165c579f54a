//! Cell sets as horizontal runs, their connected components, and exact Euclidean
//! dilations: the pieces of the connectivity proof.
//!
//! A map of a few megapixels has only thousands to a few hundred thousand runs, so working
//! on runs instead of cells makes a flood fill or a thresholded distance test cost what
//! the map's shapes cost, not what its pixels cost.

use hyplan_core::Zone;

use super::{Moves, Target};
use crate::GridMap;
use crate::components::{find, union};

/// A set of cells: per row, sorted disjoint runs `[i0, i1)` of columns that do not touch
/// (a gap of at least one cell between runs of a row).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Runs {
    width: usize,
    /// `row_start[j]..row_start[j + 1]` are the runs of row `j`.
    row_start: Vec<u32>,
    runs: Vec<(u32, u32)>,
}

impl Runs {
    fn empty(width: usize) -> Self {
        Self {
            width,
            row_start: vec![0],
            runs: Vec::new(),
        }
    }

    /// Rows.
    pub(crate) fn height(&self) -> usize {
        self.row_start.len() - 1
    }

    /// Whether the set has no cell.
    pub(crate) fn is_empty(&self) -> bool {
        self.runs.is_empty()
    }

    /// The runs of row `j`.
    pub(crate) fn row(&self, j: usize) -> &[(u32, u32)] {
        &self.runs[self.row_start[j] as usize..self.row_start[j + 1] as usize]
    }

    /// Index (into the whole run list) of the run of row `j` holding column `i`.
    fn run_at(&self, i: usize, j: usize) -> Option<usize> {
        if j >= self.height() {
            return None;
        }
        let row = self.row(j);
        let k = row.partition_point(|&(_, i1)| i1 as usize <= i);
        (k < row.len() && row[k].0 as usize <= i).then_some(self.row_start[j] as usize + k)
    }

    /// Builds a set row by row from `row_runs(j, &mut buffer)`, which appends the row's
    /// intervals `[i0, i1)` in any order, overlapping or not; they are sorted and merged.
    fn from_rows(
        width: usize,
        height: usize,
        mut row_runs: impl FnMut(usize, &mut Vec<(u32, u32)>),
    ) -> Self {
        let mut out = Self::empty(width);
        out.row_start.reserve(height);
        let mut buf = Vec::new();
        for j in 0..height {
            buf.clear();
            row_runs(j, &mut buf);
            out.push_merged(&mut buf);
            out.row_start.push(out.runs.len() as u32);
        }
        out
    }

    /// Appends the union of the intervals `buf` (any order, overlapping or not) as the
    /// runs of the row being built.
    fn push_merged(&mut self, buf: &mut [(u32, u32)]) {
        buf.sort_unstable();
        let mut cur: Option<(u32, u32)> = None;
        for &(a, b) in buf.iter() {
            if a >= b {
                continue;
            }
            cur = match cur {
                Some((c0, c1)) if a <= c1 => Some((c0, c1.max(b))),
                Some(done) => {
                    self.runs.push(done);
                    Some((a, b))
                }
                None => Some((a, b)),
            };
        }
        self.runs.extend(cur);
    }

    /// The cells whose centre lies within squared distance `t` (cells^2, inclusive) of a
    /// cell of the set: the exact Euclidean dilation by a disc. Row `j` of the result is
    /// the union, over `dy` with `dy^2 <= t`, of the runs of row `j + dy` widened by the
    /// largest `dx` with `dx^2 <= t - dy^2`.
    ///
    /// Maps repeat rows (a wall crossing a room is the same run for hundreds of rows), so
    /// the rows are grouped into blocks of equal rows, and a block contributes once, with
    /// the widening of its row nearest `j`; and a result row whose window meets the same
    /// blocks at the same distances as the row before is a copy of it. The cost is the
    /// number of runs near block boundaries times the disc's diameter, not the map's area.
    pub(crate) fn dilate(&self, t: u64) -> Self {
        let h = self.height();
        let r = t.isqrt().min(h as u64) as usize;
        let w = self.width as u64;
        let half: Vec<u64> = (0..=r as u64).map(|dy| (t - dy * dy).isqrt()).collect();
        // block_start[b]..block_start[b + 1]: rows equal to row block_start[b].
        let mut block_start = vec![0];
        for j in 1..h {
            if self.row(j) != self.row(j - 1) {
                block_start.push(j);
            }
        }
        block_start.push(h);
        let mut out = Self::empty(self.width);
        out.row_start.reserve(h);
        let mut buf = Vec::new();
        // (first row of the block, widening) of the blocks in the window of the last row.
        let mut window: Vec<(usize, u64)> = Vec::new();
        let mut last: Vec<(usize, u64)> = Vec::new();
        let mut first_block = 0;
        for j in 0..h {
            let (lo, hi) = (j.saturating_sub(r), (j + r).min(h - 1));
            while block_start[first_block + 1] <= lo {
                first_block += 1;
            }
            window.clear();
            let mut b = first_block;
            while block_start[b] <= hi {
                let (b0, b1) = (block_start[b].max(lo), (block_start[b + 1] - 1).min(hi));
                // The block's row nearest j widens most.
                let near = if j < b0 { b0 - j } else { j.saturating_sub(b1) };
                if !self.row(b0).is_empty() {
                    window.push((block_start[b], half[near]));
                }
                b += 1;
            }
            if j > 0 && window == last {
                let (a, z) = (out.row_start[j - 1] as usize, out.row_start[j] as usize);
                out.runs.extend_from_within(a..z);
            } else {
                buf.clear();
                for &(y, dx) in &window {
                    buf.extend(self.row(y).iter().map(|&(a, b)| {
                        let a = u64::from(a).saturating_sub(dx);
                        let b = (u64::from(b) + dx).min(w);
                        (a as u32, b as u32)
                    }));
                }
                out.push_merged(&mut buf);
            }
            std::mem::swap(&mut window, &mut last);
            out.row_start.push(out.runs.len() as u32);
        }
        out
    }

    /// The cells of `self` that are not in `other`.
    pub(crate) fn minus(&self, other: &Self) -> Self {
        Self::from_rows(self.width, self.height(), |j, buf| {
            let cut = other.row(j);
            let mut k = 0;
            for &(a, b) in self.row(j) {
                let mut a = a;
                while k < cut.len() && cut[k].1 <= a {
                    k += 1;
                }
                let mut m = k;
                while a < b && m < cut.len() && cut[m].0 < b {
                    if cut[m].0 > a {
                        buf.push((a, cut[m].0));
                    }
                    a = a.max(cut[m].1);
                    m += 1;
                }
                if a < b {
                    buf.push((a, b));
                }
            }
        })
    }

    /// The cells in both sets.
    pub(crate) fn and(&self, other: &Self) -> Self {
        Self::from_rows(self.width, self.height(), |j, buf| {
            let (x, y) = (self.row(j), other.row(j));
            let (mut p, mut q) = (0, 0);
            while p < x.len() && q < y.len() {
                let (a, b) = (x[p].0.max(y[q].0), x[p].1.min(y[q].1));
                if a < b {
                    buf.push((a, b));
                }
                if x[p].1 < y[q].1 {
                    p += 1;
                } else {
                    q += 1;
                }
            }
        })
    }

    /// Whether every cell of `self` is in `other`.
    pub(crate) fn within(&self, other: &Self) -> bool {
        (0..self.height()).all(|j| {
            let cover = other.row(j);
            self.row(j).iter().all(|&(a, b)| {
                // Runs of a row never touch, so one run of `other` must hold all of [a, b).
                let k = cover.partition_point(|&(_, c1)| c1 <= a);
                k < cover.len() && cover[k].0 <= a && b <= cover[k].1
            })
        })
    }
}

/// The runs of a map's zones, from one pass over its cells.
#[derive(Clone, Debug)]
pub(crate) struct ZoneRuns {
    /// Free cells.
    pub(crate) free: Runs,
    /// High-risk cells.
    pub(crate) risk: Runs,
    /// Forbidden cells.
    pub(crate) obstacles: Runs,
    /// Free or high-risk cells.
    pub(crate) passable: Runs,
}

impl ZoneRuns {
    pub(crate) fn of(map: &GridMap) -> Self {
        let w = map.width();
        // Indexed by zone discriminant, then PASSABLE.
        let mut out: [Runs; 4] = std::array::from_fn(|_| Runs::empty(w));
        for row in map.zones().chunks_exact(w) {
            let mut passable_from: Option<usize> = None;
            let mut i = 0;
            while i < w {
                let zone = row[i];
                let end = run_end(row, i);
                out[zone as usize].runs.push((i as u32, end as u32));
                match (zone, passable_from) {
                    (Zone::Forbidden, Some(a)) => {
                        out[PASSABLE].runs.push((a as u32, i as u32));
                        passable_from = None;
                    }
                    (Zone::Free | Zone::Risk, None) => passable_from = Some(i),
                    _ => {}
                }
                i = end;
            }
            if let Some(a) = passable_from {
                out[PASSABLE].runs.push((a as u32, w as u32));
            }
            for set in &mut out {
                set.row_start.push(set.runs.len() as u32);
            }
        }
        let [free, risk, obstacles, passable] = out;
        Self {
            free,
            risk,
            obstacles,
            passable,
        }
    }
}

/// The index of the passable cells among [`ZoneRuns::of`]'s sets (the zones' own sets
/// are at their discriminants).
const PASSABLE: usize = 3;

/// The end of the run of equal zones that starts at `i`: skips 32 cells at a time with a
/// comparison the compiler vectorises, then cell by cell.
fn run_end(row: &[Zone], i: usize) -> usize {
    const CHUNK: usize = 32;
    let zone = row[i];
    let mut k = i + 1;
    while k + CHUNK <= row.len()
        && row[k..k + CHUNK]
            .iter()
            .fold(true, |same, &z| same & (z == zone))
    {
        k += CHUNK;
    }
    while k < row.len() && row[k] == zone {
        k += 1;
    }
    k
}

/// A set of cells with the connected component of each run.
#[derive(Clone, Debug)]
pub(crate) struct Components {
    runs: Runs,
    /// Per run, a component id (the index of the component's first run).
    label: Vec<u32>,
}

impl Components {
    /// The components of `runs` under `moves`: runs of consecutive rows join when they
    /// share a column (`Four`) or a column or a corner (`Eight`). Union-find over the runs.
    pub(crate) fn of(runs: Runs, moves: Moves) -> Self {
        let reach = u32::from(moves == Moves::Eight);
        let mut parent: Vec<u32> = (0..runs.runs.len() as u32).collect();
        for j in 1..runs.height() {
            let (below, here) = (runs.row(j - 1), runs.row(j));
            let (b0, h0) = (runs.row_start[j - 1], runs.row_start[j]);
            let mut k = 0;
            for (m, &(a0, a1)) in here.iter().enumerate() {
                while k < below.len() && below[k].1 + reach <= a0 {
                    k += 1;
                }
                let mut n = k;
                while n < below.len() && below[n].0 < a1 + reach {
                    union(&mut parent, h0 + m as u32, b0 + n as u32);
                    n += 1;
                }
            }
        }
        for k in 0..parent.len() {
            parent[k] = find(&mut parent, k as u32);
        }
        Self {
            runs,
            label: parent,
        }
    }

    /// Whether cell `start` lies in the set and a cell of the target lies in its component.
    pub(crate) fn joins(&self, start: (usize, usize), target: &Target) -> bool {
        let Some(s) = self.runs.run_at(start.0, start.1) else {
            return false;
        };
        let s = self.label[s];
        let (t_lo, t_hi) = target.rows();
        (t_lo..=t_hi.min(self.runs.height().saturating_sub(1))).any(|j| {
            let Some((lo, hi)) = target.row(j) else {
                return false;
            };
            let row = self.runs.row(j);
            let base = self.runs.row_start[j] as usize;
            let first = row.partition_point(|&(_, i1)| (i1 as usize) <= lo);
            row[first..]
                .iter()
                .take_while(|&&(i0, _)| i0 as usize <= hi)
                .enumerate()
                .any(|(m, _)| self.label[base + first + m] == s)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(w: usize, rows: &[&[(u32, u32)]]) -> Runs {
        Runs::from_rows(w, rows.len(), |j, buf| buf.extend_from_slice(rows[j]))
    }

    fn cells(r: &Runs) -> Vec<(usize, usize)> {
        (0..r.height())
            .flat_map(|j| {
                r.row(j)
                    .iter()
                    .flat_map(move |&(a, b)| (a as usize..b as usize).map(move |i| (i, j)))
            })
            .collect()
    }

    #[test]
    fn dilation_is_the_disc() {
        let src = set(9, &[&[], &[], &[], &[], &[(4, 5)], &[], &[], &[], &[]]);
        for t in 0..20 {
            let d = cells(&src.dilate(t));
            // Row by row, as `cells` lists them.
            let want: Vec<(usize, usize)> = (0..9)
                .flat_map(|j| (0..9).map(move |i| (i, j)))
                .filter(|&(i, j)| ((i as i64 - 4).pow(2) + (j as i64 - 4).pow(2)) as u64 <= t)
                .collect();
            assert_eq!(d, want, "t = {t}");
        }
    }

    #[test]
    fn set_operations() {
        let a = set(10, &[&[(0, 4), (6, 10)]]);
        let b = set(10, &[&[(2, 7)]]);
        assert_eq!(a.minus(&b).row(0), &[(0, 2), (7, 10)]);
        assert_eq!(a.and(&b).row(0), &[(2, 4), (6, 7)]);
        assert!(set(10, &[&[(1, 3)]]).within(&a));
        assert!(!b.within(&a));
    }

    #[test]
    fn components_four_and_eight() {
        // Two runs touching at a corner only.
        let r = set(4, &[&[(0, 2)], &[(2, 4)]]);
        let four = Components::of(r.clone(), Moves::Four);
        assert_ne!(four.label[0], four.label[1]);
        let eight = Components::of(r, Moves::Eight);
        assert_eq!(eight.label[0], eight.label[1]);
    }

    proptest::proptest! {
        /// Dilation against brute force, on sets whose rows repeat (a few patterns), as
        /// the row blocks of `dilate` expect.
        #[test]
        fn dilation_matches_brute_force(
            patterns in proptest::collection::vec(proptest::collection::vec(proptest::bool::weighted(0.2), 12), 1..4),
            pick in proptest::collection::vec(0usize..4, 1..16),
            t in 0u64..40,
        ) {
            let w = 12;
            let h = pick.len();
            let on = |i: usize, j: usize| patterns[pick[j] % patterns.len()][i];
            let src = Runs::from_rows(w, h, |j, buf| {
                buf.extend((0..w).filter(|&i| on(i, j)).map(|i| (i as u32, i as u32 + 1)));
            });
            let want: Vec<(usize, usize)> = (0..h)
                .flat_map(|j| (0..w).map(move |i| (i, j)))
                .filter(|&(i, j)| {
                    (0..h).any(|b| (0..w).any(|a| on(a, b)
                        && ((a as i64 - i as i64).pow(2) + (b as i64 - j as i64).pow(2)) as u64 <= t))
                })
                .collect();
            proptest::prop_assert_eq!(cells(&src.dilate(t)), want);
        }
    }
}
