//! Which cells of a padded grid are free, one bit per cell, in rows and again in columns:
//! the lines that jump point search scans and Theta*'s lines of sight read, 64 cells at a
//! time.

/// Which padded cells are free, one bit per cell: rows (line `y`, bit `PAD + x`) and
/// columns (line `x`, bit `PAD + y`).
#[derive(Debug, Clone)]
pub(super) struct BitGrid {
    pub(super) rows: Lines,
    pub(super) cols: Lines,
}

/// Bits before cell 0 of a bit line: one word, so that a window ending at a cell near the
/// low end of the line starts at a non-negative bit.
pub(super) const PAD: usize = 64;

/// Lines per slide of [`Lines::slides`].
pub(super) const SLIDE: usize = 8;

/// Bit lines of equal length, each padded with zero words so that a 64-bit window may
/// start or end at any cell of it.
#[derive(Debug, Clone)]
pub(super) struct Lines {
    /// Words per line.
    words: usize,
    bits: Vec<u64>,
}

impl Lines {
    /// How many lines.
    fn count(&self) -> usize {
        self.bits.len() / self.words
    }

    /// These lines taken [`SLIDE`] at a time from every line: bit `c` of slide `l` is set
    /// when cell `c` is free in every line of `l .. l + SLIDE` (a slide that runs past the
    /// last line is blocked). As many words as the lines.
    pub(super) fn slides(&self) -> Self {
        let count = self.count();
        let mut slides = Self {
            words: self.words,
            bits: vec![0; self.bits.len()],
        };
        for l in 0..count.saturating_sub(SLIDE - 1) {
            let slide = &mut slides.bits[l * self.words..][..self.words];
            slide.copy_from_slice(&self.bits[l * self.words..][..self.words]);
            for line in
                self.bits[(l + 1) * self.words..(l + SLIDE) * self.words].chunks_exact(self.words)
            {
                for (s, &w) in slide.iter_mut().zip(line) {
                    *s &= w;
                }
            }
        }
        slides
    }

    /// `count` all-blocked lines of `len` cells.
    pub(super) fn new(count: usize, len: usize) -> Self {
        // A window at the line's last cell reads the word after it.
        let words = (PAD + len) / 64 + 2;
        Self {
            words,
            bits: vec![0; words * count],
        }
    }

    pub(super) fn set(&mut self, l: usize, at: usize) {
        let b = PAD + at;
        self.bits[l * self.words + b / 64] |= 1 << (b % 64);
    }

    pub(super) fn clear(&mut self, l: usize, at: usize) {
        let b = PAD + at;
        self.bits[l * self.words + b / 64] &= !(1 << (b % 64));
    }

    /// Whether cell `at` of line `l` is free (one word read, where a window reads two).
    #[inline(always)]
    pub(super) fn get(&self, l: usize, at: usize) -> bool {
        let b = PAD + at;
        (self.bits[l * self.words + b / 64] >> (b % 64)) & 1 != 0
    }

    /// The 64 cells of line `l` from cell `at` on (bit 0: cell `at`).
    #[inline(always)]
    pub(super) fn window(&self, l: usize, at: usize) -> u64 {
        self.bits_from(l, PAD + at)
    }

    /// The 64 bits of line `l` from bit `b` on.
    #[inline(always)]
    pub(super) fn bits_from(&self, l: usize, b: usize) -> u64 {
        let (w, s) = (l * self.words + b / 64, b % 64);
        let pair = &self.bits[w..w + 2];
        // `<< 1 << (63 - s)`: a shift by 64 - s without the overflow at s = 0.
        (pair[0] >> s) | ((pair[1] << 1) << (63 - s))
    }

    /// Whether cells `lo` to `hi` of line `l` are all free, 64 at a time.
    pub(super) fn run_free(&self, l: usize, lo: usize, hi: usize) -> bool {
        let mut at = lo;
        while at <= hi {
            if !self.window_free(l, at, hi.min(at + 63)) {
                return false;
            }
            at += 64;
        }
        true
    }

    /// Whether cells `lo` to `hi` of line `l` (`lo <= hi < lo + 64`) are all free: one
    /// window.
    #[inline(always)]
    pub(super) fn window_free(&self, l: usize, lo: usize, hi: usize) -> bool {
        let mask = u64::MAX >> (63 - (hi - lo));
        self.window(l, lo) & mask == mask
    }

    /// The window of a jump at cell `at` of line `l`: the 64 cells from `at` on when
    /// `FWD`, else the 64 ending at `at` (bit 63: cell `at`).
    #[inline(always)]
    pub(super) fn window_at<const FWD: bool>(&self, l: usize, at: usize) -> u64 {
        self.bits_from(l, if FWD { PAD + at } else { PAD + at - 63 })
    }

    /// The windows from bit `b` on of line `l` and of the lines below and above it.
    #[inline(always)]
    pub(super) fn windows(&self, l: usize, b: usize) -> (u64, u64, u64) {
        let words = self.words;
        let (w, s) = (b / 64, b % 64);
        let start = (l - 1) * words + w;
        // The three lines' words in one slice: one bounds check.
        let span = &self.bits[start..start + 2 * words + 2];
        let at = |i: usize| (span[i] >> s) | ((span[i + 1] << 1) << (63 - s));
        (at(words), at(0), at(2 * words))
    }
}

impl BitGrid {
    /// An all-blocked `pw x ph` grid.
    pub(super) fn new(pw: usize, ph: usize) -> Self {
        Self {
            rows: Lines::new(ph, pw),
            cols: Lines::new(pw, ph),
        }
    }

    pub(super) fn set_free(&mut self, x: usize, y: usize) {
        self.rows.set(y, x);
        self.cols.set(x, y);
    }

    pub(super) fn set_blocked(&mut self, x: usize, y: usize) {
        self.rows.clear(y, x);
        self.cols.clear(x, y);
    }

    #[inline]
    pub(super) fn free(&self, x: usize, y: usize) -> bool {
        self.rows.get(y, x)
    }
}
