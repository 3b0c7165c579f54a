//! `CellBits`: a binary grid packed 64 cells a word, by rows and by columns, for scans
//! along a row or a column a word at a time.

use std::ops::RangeInclusive;

use crate::Mask;

/// A binary grid packed one bit a cell twice: by rows (row `j` holds cells `(0, j)` to
/// `(width - 1, j)`) and by columns (column `i` holds `(i, 0)` to `(i, height - 1)`), so
/// that the first or last set cell of a stretch of either is found 64 cells at a time.
/// Rows are counted from the bottom, as in [`crate::GridMap`]. Two bits a cell: 1 MB for
/// 2000 x 2000 cells.
///
/// ```
/// use envmap::{CellBits, Mask};
/// let mut mask = Mask::new(100, 3);
/// mask.set(70, 1, true);
/// mask.set(90, 1, true);
/// let bits = CellBits::from_mask(&mask);
/// assert_eq!(bits.first_in_row(1, 0, 99), Some(70));
/// assert_eq!(bits.last_in_row(1, 0, 89), Some(70));
/// assert_eq!(bits.first_in_row(1, 71, 89), None);
/// assert_eq!(bits.first_in_column(70, 0, 2), Some(1));
/// assert!(bits.get(90, 1) && !bits.get(89, 1));
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CellBits {
    width: usize,
    height: usize,
    /// Words per row and per column.
    row_words: usize,
    col_words: usize,
    rows: Vec<u64>,
    cols: Vec<u64>,
}

hyplan_core::grid_size!(CellBits);

impl CellBits {
    /// The set cells of `mask`.
    #[must_use]
    pub fn from_mask(mask: &Mask) -> Self {
        let (width, height) = (mask.width(), mask.height());
        let (row_words, col_words) = (width.div_ceil(64), height.div_ceil(64));
        let mut rows = vec![0; row_words * height];
        let mut cols = vec![0; col_words * width];
        for (k, _) in mask.cells().iter().enumerate().filter(|(_, set)| **set) {
            let (i, j) = (k % width, k / width);
            rows[j * row_words + i / 64] |= 1 << (i % 64);
            cols[i * col_words + j / 64] |= 1 << (j % 64);
        }
        Self {
            width,
            height,
            row_words,
            col_words,
            rows,
            cols,
        }
    }

    /// Whether cell `(i, j)` is set (`false` outside the grid).
    #[must_use]
    pub fn get(&self, i: usize, j: usize) -> bool {
        i < self.width
            && j < self.height
            && self.rows[j * self.row_words + i / 64] >> (i % 64) & 1 == 1
    }

    /// The lowest `i` in `from..=to` with cell `(i, j)` set (cells past the row's end are
    /// clear; a row outside the grid has none).
    #[must_use]
    pub fn first_in_row(&self, j: usize, from: usize, to: usize) -> Option<usize> {
        (j < self.height).then(|| first_set(self.row(j), from, to))?
    }

    /// The highest `i` in `from..=to` with cell `(i, j)` set (as
    /// [`first_in_row`](Self::first_in_row)).
    #[must_use]
    pub fn last_in_row(&self, j: usize, from: usize, to: usize) -> Option<usize> {
        (j < self.height).then(|| last_set(self.row(j), from, to))?
    }

    /// The lowest `j` in `from..=to` with cell `(i, j)` set (as
    /// [`first_in_row`](Self::first_in_row), along column `i`).
    #[must_use]
    pub fn first_in_column(&self, i: usize, from: usize, to: usize) -> Option<usize> {
        (i < self.width).then(|| first_set(self.column(i), from, to))?
    }

    /// The highest `j` in `from..=to` with cell `(i, j)` set.
    #[must_use]
    pub fn last_in_column(&self, i: usize, from: usize, to: usize) -> Option<usize> {
        (i < self.width).then(|| last_set(self.column(i), from, to))?
    }

    /// Whether no cell `(i, j)` with `i` in `columns` and `j` in `rows` is set (cells
    /// outside the grid are clear): the packed rows a word at a time, for a box of a few
    /// cells a few words in all.
    ///
    /// ```
    /// use envmap::{CellBits, Mask};
    /// let mut mask = Mask::new(100, 4);
    /// mask.set(70, 2, true);
    /// let bits = CellBits::from_mask(&mask);
    /// assert!(!bits.box_clear(60..=80, 0..=3));
    /// assert!(bits.box_clear(60..=69, 0..=3));
    /// assert!(bits.box_clear(60..=80, 3..=9));
    /// ```
    #[must_use]
    #[inline]
    pub fn box_clear(&self, columns: RangeInclusive<usize>, rows: RangeInclusive<usize>) -> bool {
        let (from, to) = (*columns.start(), *columns.end());
        let to = to.min((self.row_words * 64).wrapping_sub(1));
        if self.row_words == 0 || self.height == 0 || from > to {
            return true;
        }
        let (first, last) = (from / 64, to / 64);
        let (lo, hi) = (u64::MAX << (from % 64), u64::MAX >> (63 - to % 64));
        // `span` and `within` per row and word, as the scans above, cost arena RRT-Connect 2 %
        // more instructions (`rrt_only`): here the masks are made once for every row, and
        // the rows are a plain loop (an iterator's closure over them was not inlined).
        let end = (*rows.end()).min(self.height - 1) + 1;
        for j in *rows.start()..end {
            let at = j * self.row_words;
            let clear = if first == last {
                self.rows[at + first] & lo & hi == 0
            } else {
                self.rows[at + first] & lo == 0
                    && self.rows[at + first + 1..at + last].iter().all(|&w| w == 0)
                    && self.rows[at + last] & hi == 0
            };
            if !clear {
                return false;
            }
        }
        true
    }

    fn row(&self, j: usize) -> &[u64] {
        &self.rows[j * self.row_words..(j + 1) * self.row_words]
    }

    fn column(&self, i: usize) -> &[u64] {
        &self.cols[i * self.col_words..(i + 1) * self.col_words]
    }
}

/// The lowest set bit of `line` in `from..=to` (none when `from > to`).
#[inline]
fn first_set(line: &[u64], from: usize, to: usize) -> Option<usize> {
    let (words, to) = span(line, from, to)?;
    words
        .into_iter()
        .find_map(|w| set_bit(w, within(line, w, from, to), u64::trailing_zeros))
}

/// The highest set bit of `line` in `from..=to` (none when `from > to`).
#[inline]
fn last_set(line: &[u64], from: usize, to: usize) -> Option<usize> {
    let (words, to) = span(line, from, to)?;
    words
        .rev()
        .find_map(|w| set_bit(w, within(line, w, from, to), |b| 63 - b.leading_zeros()))
}

/// The words of `line` holding bits `from..=to`, and `to` cut to the line (the bits past
/// its last cell are clear, so only the words bound it); none when that leaves no bit.
#[inline]
fn span(line: &[u64], from: usize, to: usize) -> Option<(std::ops::RangeInclusive<usize>, usize)> {
    let to = to.min((line.len() * 64).wrapping_sub(1));
    (!line.is_empty() && from <= to).then_some((from / 64..=to / 64, to))
}

/// Word `w` of `line` with only its bits in `from..=to` kept.
#[inline]
fn within(line: &[u64], w: usize, from: usize, to: usize) -> u64 {
    let mut word = line[w];
    if w == from / 64 {
        word &= u64::MAX << (from % 64);
    }
    if w == to / 64 {
        word &= u64::MAX >> (63 - to % 64);
    }
    word
}

/// The cell of bit `pick(word)` of word `w`, if the word has a set bit.
#[inline]
fn set_bit(w: usize, word: u64, pick: impl Fn(u64) -> u32) -> Option<usize> {
    (word != 0).then(|| w * 64 + pick(word) as usize)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Every scan equals a cell-by-cell search of the mask.
        #[test]
        fn scans_match_the_cells(
            (w, h, cells) in (1usize..150, 1usize..150).prop_flat_map(|(w, h)| {
                (Just(w), Just(h), proptest::collection::vec(proptest::bool::weighted(0.05), w * h))
            }),
            line in 0usize..160,
            from in 0usize..170,
            to in 0usize..170,
        ) {
            let mask = Mask::from_cells(w, h, cells).unwrap();
            let bits = CellBits::from_mask(&mask);
            let set = |i: usize, j: usize| i < w && j < h && mask.get(i, j);
            let range = from..=to;
            prop_assert_eq!(bits.first_in_row(line, from, to), range.clone().find(|&i| set(i, line)));
            prop_assert_eq!(bits.last_in_row(line, from, to), range.clone().rev().find(|&i| set(i, line)));
            prop_assert_eq!(bits.first_in_column(line, from, to), range.clone().find(|&j| set(line, j)));
            prop_assert_eq!(bits.last_in_column(line, from, to), range.clone().rev().find(|&j| set(line, j)));
            let rows = line.min(from)..=line.max(to);
            prop_assert_eq!(
                bits.box_clear(range.clone(), rows.clone()),
                !rows.clone().any(|j| range.clone().any(|i| set(i, j)))
            );
            for j in 0..h {
                for i in 0..w {
                    prop_assert_eq!(bits.get(i, j), mask.get(i, j));
                }
            }
        }
    }
}
