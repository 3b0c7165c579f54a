//! Nearest-neighbour queries over a growing point set.
//!
//! One small type, [`NearestIndex`], hides the k-d tree (the crate's own two-axis tree,
//! whose leaves are scanned in vector registers), so swapping it for another index
//! touches this file only.

use hyplan_core::Point2;
// Fx, not SipHash: the keys are ids, which no one chooses.
use rustc_hash::FxHashMap as HashMap;

use crate::kdtree::KdTree;

/// The points a tree's leaves are reserved for at its first split
/// ([`NearestIndex::rooted_in_buckets`]).
const GROWN_ROOM: usize = 512;

/// A growing set of 2-D points with nearest and within-radius queries, in plain (not
/// squared) world-unit distances, in a k-d tree whose leaves hold `B` points.
///
/// The default `B`, 64, suits planners: an RRT on the maze of `cargo xtask bench-peers`
/// took 1.05x its time with 32 and 1.2x with 128 (and a leaf of 64 is still one scan on
/// open maps, where a query reads 1.3 leaves). A tree that grows for hours over a whole
/// building, queried from anywhere in it (an exploration's global frontier detector), is
/// faster with 256 ([`with_bucket_capacity`](Self::with_bucket_capacity)). `B` must be a
/// multiple of 8 (the scan's lanes).
///
/// Points get consecutive ids `0, 1, 2, ...` in insertion order, so callers keep their own
/// per-node data (parents, costs) in plain vectors indexed by the id.
///
/// # Performance
///
/// A k-d tree: `O(log n)` expected per insertion and nearest query.
///
/// # Duplicates and degenerate inputs
///
/// A leaf full of equal points could not be split, and nodes snapped to integer cells
/// (step 1) make such points common, so the tree holds each position once: an exact
/// duplicate (found in the leaf its position leads to) is kept in a side table and reported
/// with its twin by every query. Points with a NaN or infinite coordinate get an id but
/// are never reported by a query (they cannot be ordered).
///
/// ```
/// use hyplan_core::Point2;
/// use sampling::NearestIndex;
/// let mut index = NearestIndex::new();
/// index.insert(Point2::new(0.0, 0.0));
/// index.insert(Point2::new(3.0, 4.0));
/// assert_eq!(index.nearest(Point2::new(2.9, 4.2)), Some((1, Point2::new(2.9, 4.2).coords.metric_distance(&Point2::new(3.0, 4.0).coords))));
/// let mut ids: Vec<usize> = index.within(Point2::new(0.0, 0.0), 5.0).into_iter().map(|(i, _)| i).collect();
/// ids.sort();
/// assert_eq!(ids, [0, 1]);
/// ```
#[derive(Debug, Clone, Default)]
pub struct NearestIndex<const B: usize = 64> {
    tree: KdTree<B>,
    points: Vec<Point2>,
    /// Ids of exact duplicates, keyed by the id of the twin that is in the tree.
    twins: HashMap<u64, Vec<u64>>,
}

impl NearestIndex {
    /// An empty index.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty index with room for `n` points (its k-d tree's leaves reserved at their
    /// first split).
    #[must_use]
    pub fn with_capacity(n: usize) -> Self {
        Self::with_bucket_capacity(n)
    }

    /// An index holding only `root` (id 0), with room for a leaf of points (64): it grows
    /// with the tree, as a run's trees are mostly small (see
    /// [`rooted_in_buckets`](NearestIndex::rooted_in_buckets)).
    #[must_use]
    pub fn rooted_at(root: Point2) -> Self {
        Self::rooted_in_buckets(root)
    }
}

impl<const B: usize> NearestIndex<B> {
    /// An empty index of leaves of `B` points, with room for `n` points (the leaves for
    /// them reserved at the first split).
    ///
    /// ```
    /// use hyplan_core::Point2;
    /// use sampling::NearestIndex;
    /// let mut index = NearestIndex::<256>::with_bucket_capacity(16);
    /// index.insert(Point2::new(1.0, 2.0));
    /// assert_eq!(index.nearest(Point2::new(1.0, 3.0)), Some((0, 1.0)));
    /// ```
    #[must_use]
    pub fn with_bucket_capacity(n: usize) -> Self {
        Self {
            tree: KdTree::with_capacity(n),
            points: Vec::with_capacity(n),
            twins: HashMap::default(),
        }
    }

    /// [`rooted_at`](NearestIndex::rooted_at) with leaves of `B` points: room for one leaf's
    /// points, and leaves for about 512 points once the first leaf splits.
    ///
    /// The room follows the tree: RRT-Connect's trees hold a few dozen nodes on open maps,
    /// and a run that reserved for a thousand at once (about 70 kB a tree) freed enough at
    /// its end that the C allocator could give the memory back to the system and fault it in
    /// again on the next run (it did in `cargo xtask bench-peers`, which ran its arena
    /// RRT-Connect at twice the time of a run in a loop). A tree that splits is growing,
    /// and gets its leaves for hundreds at once: doubling from one leaf copied leaves of
    /// 1.5 kB again and again.
    #[must_use]
    pub fn rooted_in_buckets(root: Point2) -> Self {
        let mut index = Self {
            tree: KdTree::with_capacity(GROWN_ROOM),
            points: Vec::with_capacity(B),
            twins: HashMap::default(),
        };
        index.insert(root);
        index
    }

    /// Number of points inserted (duplicates and non-finite points included).
    #[must_use]
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether no point was inserted.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The point with id `id`.
    ///
    /// # Panics
    ///
    /// If `id >= self.len()`.
    #[must_use]
    pub fn point(&self, id: usize) -> Point2 {
        self.points[id]
    }

    /// Every point inserted, in id order (a tree's nodes, for
    /// [`Tree::points`](hyplan_core::Tree::points) or [`branch`](crate::branch)).
    #[must_use]
    pub fn points(&self) -> &[Point2] {
        &self.points
    }

    /// Every point inserted, in id order, taken out of the index.
    pub(crate) fn into_points(self) -> Vec<Point2> {
        self.points
    }

    /// Adds `p` and returns its id (the number of points inserted before it).
    pub fn insert(&mut self, p: Point2) -> usize {
        let id = self.points.len();
        self.points.push(p);
        if p.x.is_finite()
            && p.y.is_finite()
            && let Some(twin) = self.tree.add([p.x, p.y], id as u64)
        {
            self.twins.entry(twin).or_default().push(id as u64);
        }
        id
    }

    /// [`insert`](Self::insert) of a finite `p` known to be new: nearer to some point
    /// than the index's nearest point, in the distances the index computes
    /// ([`squared_distance`](crate::kdtree::squared_distance)), so that an equal point
    /// would have been as near. Skips the search for an equal point.
    #[inline]
    pub(crate) fn insert_new(&mut self, p: Point2) -> usize {
        let id = self.points.len();
        self.points.push(p);
        self.tree.add_new([p.x, p.y], id as u64);
        id
    }

    /// The id of a point nearest to `p` and its distance (world units); `None` when the
    /// index holds no finite point or `p` is not finite. Ties go to any of the nearest.
    #[must_use]
    #[inline]
    pub fn nearest(&self, p: Point2) -> Option<(usize, f64)> {
        if self.tree.len() == 0 || !(p.x.is_finite() && p.y.is_finite()) {
            return None;
        }
        let (item, d2) = self.tree.nearest_one([p.x, p.y])?;
        Some((item as usize, d2.sqrt()))
    }

    /// Every point within distance `radius` of `p` (closed ball), as `(id, distance)`, in no
    /// particular order. Empty for a negative or NaN radius or a non-finite `p`.
    #[must_use]
    pub fn within(&self, p: Point2, radius: f64) -> Vec<(usize, f64)> {
        let mut out = Vec::new();
        self.within_into(p, radius, &mut out);
        out
    }

    /// [`within`](Self::within) into a caller's buffer (cleared first), to reuse its memory.
    pub fn within_into(&self, p: Point2, radius: f64, out: &mut Vec<(usize, f64)>) {
        out.clear();
        if self.tree.len() == 0 || !(p.x.is_finite() && p.y.is_finite() && radius >= 0.0) {
            return;
        }
        self.tree
            .within([p.x, p.y], radius * radius, &mut |item, d2| {
                // The tree compares squared distances: keep exactly the closed ball in plain
                // units.
                let d = d2.sqrt();
                if d <= radius {
                    self.push_with_twins(item, d, out);
                }
            });
    }

    /// The `k` points nearest to `p` as `(id, distance)`, nearest first (fewer when the index
    /// holds fewer points).
    #[must_use]
    pub fn nearest_k(&self, p: Point2, k: usize) -> Vec<(usize, f64)> {
        let mut out = Vec::new();
        if k == 0 || self.tree.len() == 0 || !(p.x.is_finite() && p.y.is_finite()) {
            return out;
        }
        for (item, d2) in self.tree.nearest_n([p.x, p.y], k) {
            self.push_with_twins(item, d2.sqrt(), &mut out);
            if out.len() >= k {
                break;
            }
        }
        out.truncate(k);
        out
    }

    fn push_with_twins(&self, item: u64, d: f64, out: &mut Vec<(usize, f64)>) {
        out.push((item as usize, d));
        if !self.twins.is_empty()
            && let Some(twins) = self.twins.get(&item)
        {
            out.extend(twins.iter().map(|&t| (t as usize, d)));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn empty_index_answers_none() {
        let index = NearestIndex::new();
        assert_eq!(index.nearest(Point2::new(1.0, 1.0)), None);
        assert!(index.within(Point2::new(1.0, 1.0), 10.0).is_empty());
    }

    #[test]
    fn non_finite_points_are_never_reported() {
        let mut index = NearestIndex::new();
        assert_eq!(index.insert(Point2::new(f64::NAN, 0.0)), 0);
        assert_eq!(index.nearest(Point2::new(0.0, 0.0)), None);
        assert_eq!(index.insert(Point2::new(1.0, 0.0)), 1);
        assert_eq!(index.nearest(Point2::new(0.0, 0.0)), Some((1, 1.0)));
        assert_eq!(index.nearest(Point2::new(f64::NAN, 0.0)), None);
    }
}
