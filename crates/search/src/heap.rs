//! The private open lists: [`Entry`] for the generic searches (a min-heap on `f` with ties
//! broken toward larger `g`), and the grid searches' heaps of packed keys (feature `grid`):
//! `MinHeap`, binary, with an index of where each key sits (A* and Dijkstra's decrease-key),
//! and `QuadHeap`, four-ary, without (Theta* and jump point search).

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

#[cfg(feature = "grid")]
/// A key of [`MinHeap`]: its order, and the value that fills the slots past the last key.
pub(crate) trait HeapKey: Copy {
    /// Above or equal to every key.
    const MAX: Self;
    /// Whether `a` comes out before `b`.
    fn lt(a: Self, b: Self) -> bool;
}

/// Unsigned integers are keys ordered as integers: `u64` for Theta* and for the grid
/// searches on grids where their keys fit 64 bits (`u128` too).
macro_rules! integer_heap_key {
    ($($int:ty),*) => {$(
        #[cfg(feature = "grid")]
        impl HeapKey for $int {
            const MAX: Self = <$int>::MAX;
            #[inline(always)]
            fn lt(a: Self, b: Self) -> bool {
                a < b
            }
        }
    )*};
}
integer_heap_key!(u64, u128);

#[cfg(feature = "grid")]
/// A key ordered by its upper 64 bits only (one `u64` comparison): the lower half carries
/// the cell, and keys with equal upper halves come out in any order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Upper(pub u128);

#[cfg(feature = "grid")]
impl HeapKey for Upper {
    const MAX: Self = Upper(u128::MAX);
    #[inline(always)]
    fn lt(a: Self, b: Self) -> bool {
        ((a.0 >> 64) as u64) < ((b.0 >> 64) as u64)
    }
}

#[cfg(feature = "grid")]
/// A binary min-heap for the grid searches, whose callers pack their order (f, then the
/// tie-break on g) and the cell into the key.
///
/// Compared with `BinaryHeap<Reverse<u128>>`: the hole is sifted without swaps, the smaller
/// child is picked by arithmetic on the comparison (no data-dependent branch to mispredict),
/// and [`pop`](MinHeap::pop) walks a number of levels that depends only on the size: the
/// slots past the last key hold [`HeapKey::MAX`], so the last level needs no branch either.
#[derive(Debug, Clone)]
pub(crate) struct MinHeap<K> {
    /// The keys in `[0, len)`, then `K::MAX` up to at least `2 len + 1` slots.
    keys: Vec<K>,
    len: usize,
}

#[cfg(feature = "grid")]
impl<K: HeapKey> Default for MinHeap<K> {
    fn default() -> Self {
        Self {
            keys: Vec::new(),
            len: 0,
        }
    }
}

#[cfg(feature = "grid")]
impl<K: HeapKey> MinHeap<K> {
    /// Removes every key, keeping the capacity.
    #[inline]
    pub fn clear(&mut self) {
        self.keys[..self.len].fill(K::MAX);
        self.len = 0;
    }

    /// Adds `key`.
    #[inline]
    pub fn push(&mut self, key: K) {
        self.push_placed(key, &mut |_, _| {});
    }

    /// Removes and returns the smallest key (the tests'; the searches keep an index).
    #[cfg(test)]
    pub fn pop(&mut self) -> Option<K> {
        self.pop_placed(&mut |_, _| {})
    }

    /// Replaces the smallest key by `key` (see
    /// [`replace_top_placed`](MinHeap::replace_top_placed); the tests').
    #[cfg(test)]
    pub fn replace_top(&mut self, key: K) {
        self.replace_top_placed(key, &mut |_, _| {});
    }

    /// The smallest key, left in the heap.
    #[inline]
    pub fn peek(&self) -> Option<K> {
        (self.len > 0).then(|| self.keys[0])
    }

    /// The key at position `i`, or `K::MAX` if `i` holds none.
    #[inline]
    pub fn at(&self, i: usize) -> K {
        // Slots from `len` on hold `K::MAX`.
        self.keys.get(i).copied().unwrap_or(K::MAX)
    }

    /// Moves `key` up from the hole at position `i` to where it belongs.
    #[inline(always)]
    fn sift_up(&mut self, mut i: usize, key: K, place: &mut impl FnMut(K, usize)) {
        let keys = &mut self.keys;
        while i > 0 {
            let parent = (i - 1) / 2;
            let up = keys[parent];
            if !K::lt(key, up) {
                break;
            }
            keys[i] = up;
            place(up, i);
            i = parent;
        }
        keys[i] = key;
        place(key, i);
    }

    /// Adds `key`. `place(k, i)` is called for every key `k` that lands at position `i`
    /// (here and in the other `_placed` operations), so that callers can keep an index.
    #[inline]
    pub fn push_placed(&mut self, key: K, place: &mut impl FnMut(K, usize)) {
        let i = self.len;
        self.len += 1;
        if self.keys.len() < 2 * self.len + 1 {
            let grown = (4 * self.len + 1).max(64);
            self.keys.resize(grown, K::MAX);
        }
        self.sift_up(i, key, place);
    }

    /// Lowers the key at position `i` to `key` (which must not come after it).
    #[inline]
    pub fn decrease_placed(&mut self, i: usize, key: K, place: &mut impl FnMut(K, usize)) {
        self.sift_up(i, key, place);
    }

    /// Replaces the smallest key by `key`: a pop and a push in one sift from the root,
    /// which stops at once when `key` is still the smallest (a search that follows a
    /// corridor pushes the cell it expands next).
    ///
    /// The heap must not be empty.
    #[inline]
    pub fn replace_top_placed(&mut self, key: K, place: &mut impl FnMut(K, usize)) {
        let keys = &mut self.keys;
        let n = self.len;
        let mut i = 0;
        let mut l = 1;
        // Children past the last key are `K::MAX`, never smaller than `key`... unless
        // `key` is `K::MAX` too, which the `l < n` bound settles.
        while l < n {
            let (a, b) = (keys[l], keys[l + 1]);
            let c = K::lt(b, a);
            let child = if c { b } else { a };
            let c = usize::from(c);
            if !K::lt(child, key) {
                break;
            }
            keys[i] = child;
            place(child, i);
            i = l + c;
            l = 2 * i + 1;
        }
        keys[i] = key;
        place(key, i);
    }

    /// Removes and returns the smallest key.
    ///
    /// The hole left at the root goes down along the smaller children through the full
    /// levels (their number depends only on the size, so the loop's branch is
    /// predictable), then into the last, partial level when a key is there (chosen by
    /// arithmetic); the last key then moves up into the hole (usually not at all).
    #[inline]
    pub fn pop_placed(&mut self, place: &mut impl FnMut(K, usize)) -> Option<K> {
        let n = self.len.checked_sub(1)?;
        self.len = n;
        let keys = &mut self.keys;
        let top = keys[0];
        let last = std::mem::replace(&mut keys[n], K::MAX);
        if n == 0 {
            return Some(top);
        }
        // Levels 0 to `depth - 1` are full; level `depth` holds the keys from 2^depth - 1.
        let depth = n.ilog2();
        let mut i = 0;
        for _ in 1..depth {
            let l = 2 * i + 1;
            let (a, b) = (keys[l], keys[l + 1]);
            let c = K::lt(b, a);
            let child = if c { b } else { a };
            keys[i] = child;
            place(child, i);
            i = l + usize::from(c);
        }
        if depth > 0 {
            let l = 2 * i + 1;
            let c = usize::from(K::lt(keys[l + 1], keys[l]));
            let j = l + c;
            if j < n {
                let child = keys[j];
                keys[i] = child;
                place(child, i);
                i = j;
            }
        }
        self.sift_up(i, last, place);
        Some(top)
    }
}

#[cfg(feature = "grid")]
/// A four-ary min-heap, for the open lists that need no decrease-key (Theta*'s, jump point
/// search's): half the levels of a binary heap, a node's four children adjacent in memory
/// and compared without branches. Slots past the last key hold [`HeapKey::MAX`], so a
/// node's four children are always read whole.
#[derive(Debug, Clone)]
pub(crate) struct QuadHeap<K> {
    /// The keys in `[0, len)`, then `K::MAX` up to at least `4 len + 5` slots.
    keys: Vec<K>,
    len: usize,
}

#[cfg(feature = "grid")]
impl<K: HeapKey> Default for QuadHeap<K> {
    fn default() -> Self {
        Self {
            keys: Vec::new(),
            len: 0,
        }
    }
}

#[cfg(feature = "grid")]
impl<K: HeapKey> QuadHeap<K> {
    /// Removes every key, keeping the capacity.
    #[inline]
    pub fn clear(&mut self) {
        self.keys[..self.len].fill(K::MAX);
        self.len = 0;
    }

    /// The smallest key, left in the heap.
    #[inline]
    pub fn peek(&self) -> Option<K> {
        (self.len > 0).then(|| self.keys[0])
    }

    /// Adds `key`.
    #[inline]
    pub fn push(&mut self, key: K) {
        let mut i = self.len;
        self.len += 1;
        if self.keys.len() < 4 * self.len + 5 {
            let grown = (8 * self.len + 5).max(256);
            self.keys.resize(grown, K::MAX);
        }
        let keys = &mut self.keys;
        while i > 0 {
            let parent = (i - 1) / 4;
            let up = keys[parent];
            if !K::lt(key, up) {
                break;
            }
            keys[i] = up;
            i = parent;
        }
        keys[i] = key;
    }

    /// The smallest of node `i`'s four children and its position.
    #[inline(always)]
    fn least_child(keys: &[K], i: usize) -> (K, usize) {
        let c = 4 * i + 1;
        let four = &keys[c..c + 4];
        let (a, b) = if K::lt(four[1], four[0]) {
            (four[1], c + 1)
        } else {
            (four[0], c)
        };
        let (x, y) = if K::lt(four[3], four[2]) {
            (four[3], c + 3)
        } else {
            (four[2], c + 2)
        };
        if K::lt(x, a) { (x, y) } else { (a, b) }
    }

    /// Moves `key` down from the root to where it belongs.
    #[inline(always)]
    fn sift_down(&mut self, key: K) {
        let (keys, n) = (&mut self.keys, self.len);
        let mut i = 0;
        while 4 * i + 1 < n {
            let (child, j) = Self::least_child(keys, i);
            if !K::lt(child, key) {
                break;
            }
            keys[i] = child;
            i = j;
        }
        keys[i] = key;
    }

    /// Replaces the smallest key by `key` (a pop and a push in one sift, which stops at
    /// once when `key` is still the smallest). The heap must not be empty.
    #[inline]
    pub fn replace_top(&mut self, key: K) {
        self.sift_down(key);
    }

    /// Removes and returns the smallest key.
    #[inline]
    pub fn pop(&mut self) -> Option<K> {
        let n = self.len.checked_sub(1)?;
        self.len = n;
        let top = self.keys[0];
        let last = std::mem::replace(&mut self.keys[n], K::MAX);
        if n > 0 {
            self.sift_down(last);
        }
        Some(top)
    }
}

#[cfg(test)]
mod tests {
    use super::Entry;
    #[cfg(feature = "grid")]
    use super::{MinHeap, QuadHeap, Upper};

    #[cfg(feature = "grid")]
    #[test]
    fn min_heap_pops_in_order() {
        let mut heap = MinHeap::<u128>::default();
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
        let mut heap = MinHeap::<Upper>::default();
        let mut small: Vec<u128> = keys.iter().map(|&k| k % 1009).collect();
        for (i, &k) in small.iter().enumerate() {
            heap.push(Upper((k << 64) | (i as u128 % 7)));
        }
        let tops: Vec<u128> = std::iter::from_fn(|| heap.pop())
            .map(|k| k.0 >> 64)
            .collect();
        small.sort_unstable();
        assert_eq!(tops, small);
    }
    #[cfg(feature = "grid")]
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;

    #[cfg(feature = "grid")]
    /// A xorshift64 sequence from `state` (not 0).
    fn xorshift(mut state: u64) -> impl FnMut() -> u64 {
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        }
    }

    #[cfg(feature = "grid")]
    #[test]
    fn min_heap_matches_a_sorted_model_under_mixed_operations() {
        // Sizes cross many powers of two (the padded last level of `pop`), keys repeat.
        let mut next = xorshift(0x9e37_79b9_7f4a_7c15_u64);
        let mut heap = MinHeap::<u128>::default();
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

    #[cfg(feature = "grid")]
    #[test]
    fn quad_heap_matches_a_sorted_model_under_mixed_operations() {
        // Sizes cross many powers of four, keys repeat, and the heap empties and refills.
        let mut next = xorshift(0x6a09_e667_f3bc_c908_u64);
        let mut heap = QuadHeap::<u64>::default();
        let mut model = BinaryHeap::new();
        for round in 0..40_000 {
            let r = next();
            let key = (r % 251) << 40 | (r >> 50);
            match r % 9 {
                0..=3 => {
                    heap.push(key);
                    model.push(Reverse(key));
                }
                4..=6 => assert_eq!(heap.pop(), model.pop().map(|k| k.0), "round {round}"),
                7 if !model.is_empty() => {
                    heap.replace_top(key);
                    model.pop();
                    model.push(Reverse(key));
                }
                8 if round % 5_000 == 0 => {
                    heap.clear();
                    model.clear();
                }
                _ => {}
            }
            assert_eq!(heap.peek(), model.peek().map(|k| k.0), "round {round}");
        }
        while let Some(Reverse(k)) = model.pop() {
            assert_eq!(heap.pop(), Some(k));
        }
        assert_eq!(heap.pop(), None);
    }

    #[cfg(feature = "grid")]
    #[test]
    fn placed_operations_keep_an_index_of_every_key() {
        // Keys carry their "cell" in the low 16 bits; `place` records where each sits, as
        // the grid searches' slots do, and `decrease_placed` uses it.
        let mut next = xorshift(0x2545_f491_4f6c_dd1d_u64);
        let mut heap = MinHeap::<u64>::default();
        let mut slot = vec![usize::MAX; 1 << 16];
        let mut key_of = vec![None::<u64>; 1 << 16];
        macro_rules! place {
            () => {
                &mut |k: u64, i: usize| slot[(k & 0xffff) as usize] = i
            };
        }
        let mut next_cell = 0u64;
        for round in 0..20_000 {
            let r = next();
            match r % 4 {
                0 | 1 => {
                    let key = ((r >> 40) << 16) | next_cell;
                    key_of[next_cell as usize] = Some(key);
                    heap.push_placed(key, place!());
                    next_cell += 1;
                }
                2 => {
                    if let Some(k) = heap.pop_placed(place!()) {
                        key_of[(k & 0xffff) as usize] = None;
                    }
                }
                _ => {
                    // Lower a queued key.
                    let cell = (r >> 20) % next_cell.max(1);
                    if let Some(old) = key_of[cell as usize] {
                        let new = ((old >> 16) / 2) << 16 | cell;
                        key_of[cell as usize] = Some(new);
                        let i = slot[cell as usize];
                        assert_eq!(heap.at(i), old, "round {round}");
                        heap.decrease_placed(i, new, place!());
                    }
                }
            }
            if next_cell == 1 << 16 {
                break;
            }
        }
        // Every queued key sits where its slot says, and they come out in order.
        for (cell, key) in key_of.iter().enumerate() {
            if let Some(k) = key {
                assert_eq!(heap.at(slot[cell]), *k);
            }
        }
        let mut expected: Vec<u64> = key_of.iter().flatten().copied().collect();
        expected.sort_unstable();
        let got: Vec<u64> = std::iter::from_fn(|| heap.pop()).collect();
        assert_eq!(got, expected);
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
