//! The private open-list entry: a min-heap on `f` with ties broken toward larger `g`.

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

#[cfg(test)]
mod tests {
    use super::Entry;
    use std::collections::BinaryHeap;

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
