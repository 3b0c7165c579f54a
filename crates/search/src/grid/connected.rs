//! Whether two cells are joined by the search's moves, without computing costs: a flood of
//! runs of passable cells, grown from both cells in turn over bit rows.

use super::*;

/// Per query of [`GridSearch::connected`]: the passable cells a bit each, what each side's
/// flood reached and the runs it has still to grow from.
#[derive(Debug, Clone, Default)]
pub(super) struct Reach {
    /// The padded grid's passable cells by rows, bit `x % 64` of word `y * row_words +
    /// x / 64` for cell `(x, y)`: built by the first query, then kept up to date by
    /// [`GridSearch::refresh`] ([`Reach::refresh`]); empty until then.
    bits: Vec<u64>,
    row_words: usize,
    /// Per side, the cells its flood reached, as `bits`.
    seen: [Vec<u64>; 2],
    /// Per side, the runs reached, `(row, first, last)`, in the order reached.
    runs: [Vec<(u32, u32, u32)>; 2],
}

impl Reach {
    /// Re-reads the passable cells of padded rows `rows` and columns `columns` when the
    /// bit rows are built (else the next query builds them).
    pub(super) fn refresh(
        &mut self,
        passable: &[bool],
        pw: usize,
        columns: std::ops::Range<usize>,
        rows: std::ops::Range<usize>,
    ) {
        if self.bits.is_empty() {
            return;
        }
        let rw = self.row_words;
        for y in rows {
            for x in columns.clone() {
                let (w, b) = (y * rw + x / 64, x % 64);
                self.bits[w] = self.bits[w] & !(1 << b) | u64::from(passable[y * pw + x]) << b;
            }
        }
    }

    fn build(&mut self, passable: &[bool], pw: usize) {
        let rw = pw.div_ceil(64);
        self.row_words = rw;
        self.bits = vec![0; rw * (passable.len() / pw)];
        for (y, row) in passable.chunks(pw).enumerate() {
            for (x, _) in row.iter().enumerate().filter(|(_, free)| **free) {
                self.bits[y * rw + x / 64] |= 1 << (x % 64);
            }
        }
    }
}

/// Bit `x` of a bit row.
fn bit(row: &[u64], x: usize) -> bool {
    row[x / 64] >> (x % 64) & 1 == 1
}

/// The first `x` in `from..=to` whose bit is `set` in `row`, if any.
fn next(row: &[u64], from: usize, to: usize, set: bool) -> Option<usize> {
    let mut w = from / 64;
    let flip = if set { 0 } else { u64::MAX };
    let mut word = (row[w] ^ flip) & (u64::MAX << (from % 64));
    loop {
        if word != 0 {
            let x = w * 64 + word.trailing_zeros() as usize;
            return (x <= to).then_some(x);
        }
        w += 1;
        if w * 64 > to {
            return None;
        }
        word = row[w] ^ flip;
    }
}

/// The last `x` at or before `from` whose bit is clear in `row` (bit 0 must be clear).
fn prev_clear(row: &[u64], from: usize) -> usize {
    let mut w = from / 64;
    let mut word = !row[w] & (u64::MAX >> (63 - from % 64));
    while word == 0 {
        w -= 1;
        word = !row[w];
    }
    w * 64 + 63 - word.leading_zeros() as usize
}

/// Sets bits `lo..=hi` of `row`.
fn fill(row: &mut [u64], lo: usize, hi: usize) {
    let (wl, wh) = (lo / 64, hi / 64);
    let low = u64::MAX << (lo % 64);
    let high = u64::MAX >> (63 - hi % 64);
    if wl == wh {
        row[wl] |= low & high;
    } else {
        row[wl] |= low;
        row[wl + 1..wh].fill(u64::MAX);
        row[wh] |= high;
    }
}

impl GridSearch {
    /// Whether A* and Dijkstra would find a path from `start` to `goal`: a flood grown
    /// from both cells in turn, which stops as soon as the two meet or either runs out.
    /// A goal walled off from a large reachable area is answered at the cost of the
    /// smaller of the two regions, where a search that fails expands every cell the start
    /// reaches. The flood moves by runs of passable cells along a row, 64 cells a word, so
    /// it costs about the number of such runs it reaches, not of cells.
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
        let pw = self.pw;
        let reach = &mut self.reach;
        if reach.bits.is_empty() {
            reach.build(&self.passable, pw);
        }
        let Reach {
            bits,
            row_words: rw,
            seen,
            runs,
        } = reach;
        let rw = *rw;
        for side in seen.iter_mut() {
            side.clear();
            side.resize(bits.len(), 0);
        }
        // The straight moves suffice: a legal diagonal move has a free side cell (both
        // without corner cutting), through which two straight moves join the same cells.
        // So two cells are joined when a chain of runs of passable cells, each on a row
        // next to the one before and overlapping it, leads from one to the other. The
        // padded grid's border is blocked: every run ends inside it.
        let row = |y: usize| &bits[y * rw..(y + 1) * rw];
        let run_at = |y: usize, x: usize| {
            let r = row(y);
            let last = next(r, x, pw - 1, false).map_or(pw - 1, |c| c - 1);
            (prev_clear(r, x) + 1, last)
        };
        for (side, cell) in [s, t].into_iter().enumerate() {
            let (x, y) = (cell as usize % pw, cell as usize / pw);
            let (lo, hi) = run_at(y, x);
            if side == 1 && bit(&seen[0][y * rw..(y + 1) * rw], lo) {
                return Ok(true);
            }
            fill(&mut seen[side][y * rw..(y + 1) * rw], lo, hi);
            runs[side].clear();
            runs[side].push((y as u32, lo as u32, hi as u32));
        }
        let mut heads = [0usize; 2];
        loop {
            for side in 0..2 {
                let Some(&(y, lo, hi)) = runs[side].get(heads[side]) else {
                    // This side's region is exhausted without meeting the other.
                    return Ok(false);
                };
                heads[side] += 1;
                let (y, lo, hi) = (y as usize, lo as usize, hi as usize);
                for ny in [y - 1, y + 1] {
                    let r = row(ny);
                    let mut x = lo;
                    // Each run of row `ny` that overlaps `lo..=hi`.
                    while let Some(first) = next(r, x, hi, true) {
                        let (a, b) = run_at(ny, first);
                        x = b + 1;
                        let span = ny * rw..(ny + 1) * rw;
                        // A flood marks whole runs, so a run's first cell tells.
                        if bit(&seen[side][span.clone()], a) {
                            continue;
                        }
                        if bit(&seen[1 - side][span.clone()], a) {
                            return Ok(true);
                        }
                        fill(&mut seen[side][span], a, b);
                        runs[side].push((ny as u32, a as u32, b as u32));
                        if x > hi {
                            break;
                        }
                    }
                }
            }
        }
    }
}
