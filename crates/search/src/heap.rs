//! The private open lists: [`Entry`] for the generic searches (a min-heap on `f` with ties
//! broken toward larger `g`) and [`MinHeap`], the grid searches' binary heap of packed keys.

use std::cmp::Ordering;

/// An open-list entry for [`std::collections::BinaryHeap`] (a max-heap), ordered so that the
/// entry with the **smallest** `f` comes out first and, among equal `f`, the one with the
/// **largest** `g` (the one deepest toward the goal, which usually ends the search sooner).
///
/// Costs are plain `f64` compared with [`f64::total_cmp`], so callers never wrap their costs
/// and a NaN cannot panic the heap (it sorts after every finite number).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Entry<T> {
    pub f: f64,
    pub g: f64,
    pub item: T,
}

impl<T> PartialEq for Entry<T> {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl<T> Eq for Entry<T> {}

impl<T> PartialOrd for Entry<T> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<T> Ord for Entry<T> {
    fn cmp(&self, other: &Self) -> Ordering {
        // Reversed on f (min-heap), then larger g first.
        other
            .f
            .total_cmp(&self.f)
            .then_with(|| self.g.total_cmp(&other.g))
    }
}

/// A binary min-heap of `u128` keys for the grid searches, whose callers pack their order
/// (f, then the tie-break on g) and the cell into the key.
///
/// `WHOLE = true` orders by the whole key; `WHOLE = false` only by its upper 64 bits (one
/// `u64` comparison): the lower half then only carries the cell, and keys with equal upper
/// halves come out in any order.
///
/// Compared with `BinaryHeap<Reverse<u128>>`: the hole is sifted without swaps, the smaller
/// child is picked by arithmetic on the comparison (no data-dependent branch to mispredict),
/// and [`pop`](MinHeap::pop) walks a number of levels that depends only on the size: the
/// slots past the last key hold `u128::MAX`, so the last level needs no branch either.
#[derive(Debug, Clone, Default)]
pub(crate) struct MinHeap<const WHOLE: bool> {
    /// The keys in `[0, len)`, then `u128::MAX` up to at least `2 len + 1` slots.
    keys: Vec<u128>,
    len: usize,
}

impl<const WHOLE: bool> MinHeap<WHOLE> {
    /// Whether `a` comes out before `b`.
    #[inline(always)]
    fn lt(a: u128, b: u128) -> bool {
        if WHOLE {
            a < b
        } else {
            ((a >> 64) as u64) < ((b >> 64) as u64)
        }
    }

    /// Removes every key, keeping the capacity.
    #[inline]
    pub fn clear(&mut self) {
        self.keys[..self.len].fill(u128::MAX);
        self.len = 0;
    }

    /// Adds `key`.
    #[inline]
    pub fn push(&mut self, key: u128) {
        let mut i = self.len;
        self.len += 1;
        if self.keys.len() < 2 * self.len + 1 {
            let grown = (4 * self.len + 1).max(64);
            self.keys.resize(grown, u128::MAX);
        }
        let keys = &mut self.keys;
        while i > 0 {
            let parent = (i - 1) / 2;
            let up = keys[parent];
            if !Self::lt(key, up) {
                break;
            }
            keys[i] = up;
            i = parent;
        }
        keys[i] = key;
    }

    /// The smallest key, left in the heap.
    #[inline]
    pub fn peek(&self) -> Option<u128> {
        (self.len > 0).then(|| self.keys[0])
    }

    /// Replaces the smallest key by `key`: a pop and a push in one sift from the root,
    /// which stops at once when `key` is still the smallest (a search that follows a
    /// corridor pushes the cell it expands next).
    ///
    /// The heap must not be empty.
    #[inline]
    pub fn replace_top(&mut self, key: u128) {
        let keys = &mut self.keys;
        let n = self.len;
        let mut i = 0;
        let mut l = 1;
        // Children past the last key are `u128::MAX`, never smaller than `key`... unless
        // `key` is `u128::MAX` too, which the `l < n` bound settles.
        while l < n {
            let pair = &keys[l..l + 2];
            let c = usize::from(Self::lt(pair[1], pair[0]));
            let child = pair[c];
            if !Self::lt(child, key) {
                break;
            }
            keys[i] = child;
            i = l + c;
            l = 2 * i + 1;
        }
        keys[i] = key;
    }

    /// Removes and returns the smallest key.
    ///
    /// The hole left at the root goes down along the smaller children through the full
    /// levels (their number depends only on the size, so the loop's branch is
    /// predictable), then into the last, partial level when a key is there (chosen by
    /// arithmetic); the last key then moves up into the hole (usually not at all).
    #[inline]
    pub fn pop(&mut self) -> Option<u128> {
        let n = self.len.checked_sub(1)?;
        self.len = n;
        let keys = &mut self.keys;
        let top = keys[0];
        let last = std::mem::replace(&mut keys[n], u128::MAX);
        if n == 0 {
            return Some(top);
        }
        // Levels 0 to `depth - 1` are full; level `depth` holds the keys from 2^depth - 1.
        let depth = n.ilog2();
        let mut i = 0;
        for _ in 1..depth {
            let l = 2 * i + 1;
            let pair = &keys[l..l + 2];
            let c = usize::from(Self::lt(pair[1], pair[0]));
            keys[i] = pair[c];
            i = l + c;
        }
        if depth > 0 {
            let l = 2 * i + 1;
            let pair = &keys[l..l + 2];
            let c = usize::from(Self::lt(pair[1], pair[0]));
            let j = l + c;
            let j = if j < n { j } else { i };
            keys[i] = keys[j];
            i = j;
        }
        while i > 0 {
            let parent = (i - 1) / 2;
            let up = keys[parent];
            if !Self::lt(last, up) {
                break;
            }
            keys[i] = up;
            i = parent;
        }
        keys[i] = last;
        Some(top)
    }
}

#[cfg(test)]
mod tests {
    use super::{Entry, MinHeap};

    #[test]
    fn min_heap_pops_in_order() {
        let mut heap = MinHeap::<true>::default();
        let mut keys: Vec<u128> = (0..500u128)
            .map(|i| (i * 7919 + 13) % 1009 + ((i % 3) << 100))
            .collect();
        for &k in &keys {
            heap.push(k);
        }
        keys.sort_unstable();
        let mut popped = Vec::new();
        // Interleave: pop half, push them back, pop all.
        for _ in 0..250 {
            popped.push(heap.pop().unwrap());
        }
        for &k in &popped {
            heap.push(k);
        }
        popped.clear();
        while let Some(k) = heap.pop() {
            popped.push(k);
        }
        assert_eq!(popped, keys);
        heap.push(3);
        heap.clear();
        assert_eq!(heap.pop(), None);
        // Upper halves only: the lower half is carried, not compared.
        let mut heap = MinHeap::<false>::default();
        let mut small: Vec<u128> = keys.iter().map(|&k| k % 1009).collect();
        for (i, &k) in small.iter().enumerate() {
            heap.push((k << 64) | (i as u128 % 7));
        }
        let tops: Vec<u128> = std::iter::from_fn(|| heap.pop()).map(|k| k >> 64).collect();
        small.sort_unstable();
        assert_eq!(tops, small);
    }
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;

    #[test]
    fn min_heap_matches_a_sorted_model_under_mixed_operations() {
        // Sizes cross many powers of two (the padded last level of `pop`), keys repeat.
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut heap = MinHeap::<true>::default();
        let mut model = BinaryHeap::new();
        for round in 0..20_000 {
            let r = next();
            let key = u128::from(r % 97) << 70 | u128::from(r >> 40);
            match r % 7 {
                0..=2 => {
                    heap.push(key);
                    model.push(Reverse(key));
                }
                3 | 4 => assert_eq!(heap.pop(), model.pop().map(|k| k.0), "round {round}"),
                5 if !model.is_empty() => {
                    heap.replace_top(key);
                    model.pop();
                    model.push(Reverse(key));
                }
                _ => assert_eq!(heap.peek(), model.peek().map(|k| k.0)),
            }
            if round % 5_000 == 4_999 {
                heap.clear();
                model.clear();
            }
        }
        while let Some(Reverse(k)) = model.pop() {
            assert_eq!(heap.pop(), Some(k));
        }
        assert_eq!(heap.pop(), None);
    }

    #[test]
    fn smallest_f_first_then_largest_g() {
        let mut heap = BinaryHeap::new();
        for (f, g, item) in [
            (3.0, 0.0, 'a'),
            (1.0, 0.5, 'b'),
            (1.0, 0.9, 'c'),
            (2.0, 2.0, 'd'),
        ] {
            heap.push(Entry { f, g, item });
        }
        let order: Vec<char> = std::iter::from_fn(|| heap.pop().map(|e| e.item)).collect();
        assert_eq!(order, vec!['c', 'b', 'd', 'a']);
    }
}
