//! The k-d tree behind [`crate::NearestIndex`]: two axes, leaves of `B` points stored by
//! axis (all x, then all y), so that a leaf's squared distances are computed a vector
//! register at a time and its nearest point found without a branch per point.
//!
//! Why not kiddo's mutable tree, which this replaced: its leaves keep each point's axes
//! together and its scan takes a branch per point; on an RRT's queries (samples far from a
//! tree that fills a maze slowly visit many leaves) the scan was most of the planner's time.
//! The structure is the usual one (Friedman, Bentley and Finkel 1977; kiddo's search keeps
//! the same per-axis offsets to bound a subtree's distance); what differs is the leaf, and
//! that a leaf is read only when the bounding box of its points is within reach.
//!
//! Only finite points are inserted, and never two equal ones: [`KdTree::add`] finds an
//! equal point in the leaf it descends to (equal points take the same way down) and
//! reports it instead. A full leaf therefore always has two points that differ on some
//! axis, and can be split.

/// A node: a stem's index, or a leaf's with [`LEAF`] set.
type NodeRef = u32;

/// Marks a [`NodeRef`] as a leaf's.
const LEAF: NodeRef = 1 << 31;

/// How many running minima a leaf scan keeps (a leaf's size is a multiple of it).
const LANES: usize = 8;

/// The most leaves a tree may have for its nearest query to read every leaf's box at once
/// ([`KdTree::nearest_flat`]) rather than descend.
const FLAT_LEAVES: usize = 32;
const _: () = assert!(
    FLAT_LEAVES <= u32::BITS as usize,
    "a query's leaves are bits of a u32"
);

/// Leaves to a [`BoxChunk`]: the `f64` lanes of an AVX2 register.
const BOX_LANES: usize = 4;

/// An inner node: points below `split` on `axis` are on the `below` side.
#[derive(Debug, Clone, Copy)]
struct Stem {
    split: f64,
    axis: usize,
    below: NodeRef,
    above: NodeRef,
}

/// A leaf's bounding box as a split gathers it, lowest and highest on each axis (inverted
/// when empty); the tree keeps them in [`BoxChunk`]s.
#[derive(Debug, Clone, Copy)]
struct Bounds {
    lo: [f64; 2],
    hi: [f64; 2],
}

impl Bounds {
    const EMPTY: Self = Self {
        lo: [f64::INFINITY; 2],
        hi: [f64::NEG_INFINITY; 2],
    };

    /// Grown to hold `p` (finite).
    #[inline(always)]
    fn grow(&mut self, p: [f64; 2]) {
        for ((lo, hi), x) in self.lo.iter_mut().zip(&mut self.hi).zip(p) {
            widen(lo, hi, x);
        }
    }
}

/// `[lo, hi]` widened to hold `x` (finite: plain comparisons, without `f64::min`'s rule for
/// NaN): a leaf's box, or a split's spread.
#[inline(always)]
fn widen(lo: &mut f64, hi: &mut f64, x: f64) {
    *lo = if x < *lo { x } else { *lo };
    *hi = if x > *hi { x } else { *hi };
}

/// The squared distance from `q` to the box from `lo` to `hi` (infinite when empty: `lo`
/// infinite, `hi` negative infinite; `q` is finite, so no NaN arises and plain comparisons
/// do, without `f64::max`'s rule for it).
#[inline(always)]
fn box_distance(lo: [f64; 2], hi: [f64; 2], q: [f64; 2]) -> f64 {
    let gap = |axis: usize| {
        let below = lo[axis] - q[axis];
        let above = q[axis] - hi[axis];
        let gap = if below > above { below } else { above };
        if gap > 0.0 { gap } else { 0.0 }
    };
    let (dx, dy) = (gap(0), gap(1));
    dx * dx + dy * dy
}

/// The boxes of [`BOX_LANES`] consecutive leaves, by side and axis, so that a small tree's
/// query computes every leaf's box distance a vector register at a time (unused lanes
/// hold empty boxes).
#[derive(Debug, Clone, Copy)]
struct BoxChunk {
    lo: [[f64; BOX_LANES]; 2],
    hi: [[f64; BOX_LANES]; 2],
}

impl BoxChunk {
    const EMPTY: Self = Self {
        lo: [[f64::INFINITY; BOX_LANES]; 2],
        hi: [[f64::NEG_INFINITY; BOX_LANES]; 2],
    };

    #[inline(always)]
    fn set(&mut self, lane: usize, b: Bounds) {
        for axis in 0..2 {
            self.lo[axis][lane] = b.lo[axis];
            self.hi[axis][lane] = b.hi[axis];
        }
    }

    /// Lane `lane`'s box grown to hold `p` (finite).
    #[inline(always)]
    fn grow(&mut self, lane: usize, p: [f64; 2]) {
        for (axis, x) in p.into_iter().enumerate() {
            widen(&mut self.lo[axis][lane], &mut self.hi[axis][lane], x);
        }
    }

    /// The squared distance from `q` to lane `lane`'s box.
    #[inline(always)]
    fn distance(&self, lane: usize, q: [f64; 2]) -> f64 {
        let side = |s: &[[f64; BOX_LANES]; 2]| [s[0][lane], s[1][lane]];
        box_distance(side(&self.lo), side(&self.hi), q)
    }

    /// [`distance`](Self::distance) for every lane.
    #[inline(always)]
    fn distances(&self, q: [f64; 2]) -> [f64; BOX_LANES] {
        std::array::from_fn(|lane| self.distance(lane, q))
    }
}

/// The squared distance between `p` and `q` as the tree computes it, bit for bit (the
/// leaf scans use this expression): a caller may compare its own distances with a query's.
#[inline(always)]
pub(crate) fn squared_distance(p: [f64; 2], q: [f64; 2]) -> f64 {
    let (dx, dy) = (p[0] - q[0], p[1] - q[1]);
    dx * dx + dy * dy
}

/// Up to `B` points, by axis; the unused slots hold infinite coordinates, whose distance to
/// any query is infinite, so that a scan reads whole leaves.
#[derive(Debug, Clone)]
struct Leaf<const B: usize> {
    axes: [[f64; B]; 2],
    ids: [u64; B],
    len: usize,
}

impl<const B: usize> Leaf<B> {
    fn empty() -> Self {
        Self {
            axes: [[f64::INFINITY; B]; 2],
            ids: [0; B],
            len: 0,
        }
    }

    fn push(&mut self, p: [f64; 2], id: u64) {
        // The count read once: through `self.len` at each store, it was read (and
        // checked) again after every one.
        let k = self.len;
        self.axes[0][k] = p[0];
        self.axes[1][k] = p[1];
        self.ids[k] = id;
        self.len = k + 1;
    }

    /// The slot nearest `q` and its squared distance (infinite when the leaf is empty): of
    /// the [`lanes`](Self::lanes)' minima, the first least one.
    ///
    /// `S` is how the lanes carry slot numbers ([`Slot`]).
    #[inline(always)]
    fn nearest<S: Slot>(&self, q: [f64; 2]) -> (f64, usize) {
        let (min, at) = self.lanes::<S>(q);
        (0..LANES).fold((f64::INFINITY, 0), |best, l| {
            if min[l] < best.0 {
                (min[l], at[l].index())
            } else {
                best
            }
        })
    }

    /// The scan: for each lane (slots modulo [`LANES`]), the least squared distance from
    /// `q` and the first slot at it (slot 0 at an infinite distance).
    ///
    /// The lanes' minima are independent and so fill vector registers; one minimum would be
    /// a chain of dependent comparisons, one slot after another.
    #[inline(always)]
    fn lanes<S: Slot>(&self, q: [f64; 2]) -> ([f64; LANES], [S; LANES]) {
        let mut min = [f64::INFINITY; LANES];
        let mut at = [S::of(0); LANES];
        let mut slot: [S; LANES] = std::array::from_fn(S::of);
        for (xs, ys) in self.chunks() {
            for l in 0..LANES {
                let d = squared_distance([xs[l], ys[l]], q);
                let nearer = d < min[l];
                min[l] = if nearer { d } else { min[l] };
                at[l] = if nearer { slot[l] } else { at[l] };
                slot[l] = slot[l].after_chunk();
            }
        }
        (min, at)
    }

    /// The chunks of [`LANES`] slots that hold points, x and y (the rest are infinite).
    fn chunks(&self) -> impl Iterator<Item = (&[f64], &[f64])> {
        self.axes[0]
            .chunks_exact(LANES)
            .zip(self.axes[1].chunks_exact(LANES))
            .take(self.len.div_ceil(LANES))
    }

    /// Each point's item and squared distance from `q`.
    fn squared_distances(&self, q: [f64; 2]) -> impl Iterator<Item = (u64, f64)> + '_ {
        (0..self.len).map(move |k| {
            let p = [self.axes[0][k], self.axes[1][k]];
            (self.ids[k], squared_distance(p, q))
        })
    }
}

/// A slot number as a leaf scan's lanes carry it: `usize` in the baseline x86-64 build,
/// `f64` in the AVX2 build ([`Wide`]), whose blends LLVM makes on `f64` lanes (`usize`
/// slots it moved one lane at a time there; `f64` ones are slower with SSE2's three-step
/// blends). Both give the same slot.
trait Slot: Copy {
    fn of(k: usize) -> Self;
    /// The same lane's slot in the next chunk.
    fn after_chunk(self) -> Self;
    fn index(self) -> usize;
}

impl Slot for usize {
    #[inline(always)]
    fn of(k: usize) -> Self {
        k
    }
    #[inline(always)]
    fn after_chunk(self) -> Self {
        self + LANES
    }
    #[inline(always)]
    fn index(self) -> usize {
        self
    }
}

/// Slot `k` as the `f64` `2^52 + k`, whose bits are `2^52`'s plus `k`: an index again by a
/// subtraction of bits. `k as f64` back to `usize` took a saturating conversion of a dozen
/// instructions for each of the eight lanes at the end of every scan, about a third of a
/// 48-point leaf's scan.
impl Slot for f64 {
    #[inline(always)]
    fn of(k: usize) -> Self {
        SLOT_BASE + k as f64
    }
    #[inline(always)]
    fn after_chunk(self) -> Self {
        self + LANES as f64
    }
    #[inline(always)]
    fn index(self) -> usize {
        // Slots are below a leaf's size, far below 2^52: every one is exact, with the
        // exponent of 2^52, and its low mantissa bits are the slot.
        (self.to_bits() - SLOT_BASE.to_bits()) as usize
    }
}

/// 2^52, where consecutive `f64` are whole numbers one apart.
const SLOT_BASE: f64 = 4_503_599_627_370_496.0;

/// Whether this CPU runs the leaf scan compiled for AVX2 (x86-64-v3), found when a tree is
/// made. The scan is the same arithmetic in the same lanes either way, so it finds the same
/// point (ties included); AVX2 does four lanes an instruction where the baseline build's
/// SSE2 does two.
#[derive(Debug, Clone, Copy)]
struct Wide(#[cfg(target_arch = "x86_64")] Option<pulp::x86::V3>);

impl Wide {
    fn detect() -> Self {
        Self(
            #[cfg(target_arch = "x86_64")]
            pulp::x86::V3::try_new(),
        )
    }

    /// [`KdTree::nearest_flat`], in the AVX2 build where the CPU has it.
    #[inline(always)]
    fn nearest_flat<const B: usize>(self, tree: &KdTree<B>, q: [f64; 2]) -> (u64, f64) {
        #[cfg(target_arch = "x86_64")]
        if let Some(v3) = self.0 {
            return v3.vectorize(InV3 { v3, of: tree, q });
        }
        baseline_flat(tree, q)
    }

    /// [`Leaf::nearest`], in the AVX2 build where the CPU has it.
    #[inline(always)]
    fn nearest<const B: usize>(self, leaf: &Leaf<B>, q: [f64; 2]) -> (f64, usize) {
        #[cfg(target_arch = "x86_64")]
        if let Some(v3) = self.0 {
            return v3.vectorize(InV3 { v3, of: leaf, q });
        }
        baseline_nearest(leaf, q)
    }
}

/// [`Leaf::nearest`] in the baseline build, out of line: inlined, it gave every caller of
/// [`Wide::nearest`] (the AVX2 build's among them) its registers and frame to save.
#[inline(never)]
fn baseline_nearest<const B: usize>(leaf: &Leaf<B>, q: [f64; 2]) -> (f64, usize) {
    leaf.nearest::<usize>(q)
}

/// [`KdTree::nearest_flat`] in the baseline build, out of line as [`baseline_nearest`].
#[inline(never)]
fn baseline_flat<const B: usize>(tree: &KdTree<B>, q: [f64; 2]) -> (u64, f64) {
    tree.nearest_flat(q, BaselineScan)
}

/// A query of a leaf ([`Leaf::nearest`]) or of a small tree ([`KdTree::nearest_flat`])
/// handed to [`pulp`], which compiles it for AVX2 only when it is inlined into pulp's entry
/// (a closure was not).
#[cfg(target_arch = "x86_64")]
struct InV3<'a, T> {
    v3: pulp::x86::V3,
    of: &'a T,
    q: [f64; 2],
}

#[cfg(target_arch = "x86_64")]
impl<const B: usize> pulp::NullaryFnOnce for InV3<'_, Leaf<B>> {
    type Output = (f64, usize);

    #[inline(always)]
    fn call(self) -> Self::Output {
        V3Scan(self.v3).nearest(self.of, self.q)
    }
}

#[cfg(target_arch = "x86_64")]
impl<const B: usize> pulp::NullaryFnOnce for InV3<'_, KdTree<B>> {
    type Output = (u64, f64);

    #[inline(always)]
    fn call(self) -> Self::Output {
        self.of.nearest_flat(self.q, V3Scan(self.v3))
    }
}

/// [`Leaf::nearest`] as a build has it, for a caller generic over the build (a closure
/// called from pulp's AVX2 entry was compiled apart, for the baseline).
trait LeafScan: Copy {
    fn nearest<const B: usize>(self, leaf: &Leaf<B>, q: [f64; 2]) -> (f64, usize);
}

/// The baseline build's scan.
#[derive(Clone, Copy)]
struct BaselineScan;

impl LeafScan for BaselineScan {
    #[inline(always)]
    fn nearest<const B: usize>(self, leaf: &Leaf<B>, q: [f64; 2]) -> (f64, usize) {
        leaf.nearest::<usize>(q)
    }
}

/// The AVX2 build's scan (called within pulp's AVX2 entry).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct V3Scan(pulp::x86::V3);

#[cfg(target_arch = "x86_64")]
impl LeafScan for V3Scan {
    #[inline(always)]
    fn nearest<const B: usize>(self, leaf: &Leaf<B>, q: [f64; 2]) -> (f64, usize) {
        let (min, at) = leaf.lanes::<f64>(q);
        first_least(self.0, min, at)
    }
}

/// [`Leaf::nearest`]'s choice among the lanes, in vector registers: the least of the
/// minima, then the first lane that holds it (the scalar fold's lane: it keeps the first
/// of equal minima), from the sign bits of one comparison. About a third of the
/// instructions of the fold, which compares the eight lanes one after another.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn first_least(v3: pulp::x86::V3, min: [f64; LANES], at: [f64; LANES]) -> (f64, usize) {
    use pulp::f64x4;
    let lo: f64x4 = pulp::cast([min[0], min[1], min[2], min[3]]);
    let hi: f64x4 = pulp::cast([min[4], min[5], min[6], min[7]]);
    let pair: [f64; 4] = pulp::cast(v3.avx._mm256_min_pd(pulp::cast(lo), pulp::cast(hi)));
    // No lane holds NaN (the points and the query are finite; unused slots are infinitely
    // far): a plain comparison, without `f64::min`'s rule for NaN.
    let lesser = |a: f64, b: f64| if a < b { a } else { b };
    let least = lesser(lesser(pair[0], pair[1]), lesser(pair[2], pair[3]));
    let least4 = v3.splat_f64x4(least);
    let bits = |half: f64x4| {
        v3.avx
            ._mm256_movemask_pd(pulp::cast(v3.cmp_eq_f64x4(half, least4)))
    };
    let lanes = (bits(lo) | bits(hi) << 4) as u32;
    // Some lane equals the least; the bound only spares a check.
    let lane = (lanes.trailing_zeros() as usize).min(LANES - 1);
    (least, at[lane].index())
}

/// A 2-D k-d tree over finite, pairwise distinct points, each with a `u64` item; distances
/// are squared Euclidean.
#[derive(Debug, Clone)]
pub(crate) struct KdTree<const B: usize> {
    stems: Vec<Stem>,
    leaves: Vec<Leaf<B>>,
    /// The leaves' bounding boxes, leaf `k`'s in lane `k % BOX_LANES` of chunk
    /// `k / BOX_LANES`, from the first split on (a tree of one leaf reads it whole). A
    /// leaf's region reaches far beyond its points at the edge of a growing tree, which is
    /// where an RRT's samples fall: the box, not the region, tells whether its points may
    /// be near.
    boxes: Vec<BoxChunk>,
    root: NodeRef,
    len: usize,
    /// The leaves reserved at the first split.
    room: usize,
    wide: Wide,
}

impl<const B: usize> Default for KdTree<B> {
    fn default() -> Self {
        Self::with_capacity(0)
    }
}

impl<const B: usize> KdTree<B> {
    /// An empty tree with room for about `n` points (leaves half full) before reallocating,
    /// reserved at its first split: until then it holds one leaf (most of RRT-Connect's
    /// trees never split, and a leaf is 1.5 kB).
    pub(crate) fn with_capacity(n: usize) -> Self {
        Self {
            stems: Vec::new(),
            leaves: vec![Leaf::empty()],
            boxes: Vec::new(),
            root: LEAF,
            len: 0,
            room: (n / (B / 2).max(1)).max(1),
            wide: Wide::detect(),
        }
    }

    /// How many points the tree holds.
    pub(crate) const fn len(&self) -> usize {
        self.len
    }

    /// Adds `p` (finite) with item `id`, unless a point equal to it (`==` on both axes, so
    /// -0.0 and 0.0 are one) is in the tree already: then nothing is added and that point's
    /// item is returned.
    pub(crate) fn add(&mut self, p: [f64; 2], id: u64) -> Option<u64> {
        let (node, parent) = self.descend(p);
        let leaf = &self.leaves[(node & !LEAF) as usize];
        // The leaf's points without an early exit (vector registers; the unused slots of
        // the last chunk are infinite, never equal), then the slot only when there is one.
        let equal = |x: f64, y: f64| (x == p[0]) & (y == p[1]);
        let mut hit = [false; LANES];
        for (xs, ys) in leaf.chunks() {
            for l in 0..LANES {
                hit[l] |= equal(xs[l], ys[l]);
            }
        }
        if hit.contains(&true)
            && let Some(k) = (0..leaf.len).position(|k| equal(leaf.axes[0][k], leaf.axes[1][k]))
        {
            return Some(leaf.ids[k]);
        }
        self.put(p, id, node, parent);
        None
    }

    /// Adds `p` (finite) with item `id`, known to equal no point of the tree: [`add`](Self::add)
    /// without its search of the leaf for an equal point. A caller knows it when `p` is
    /// nearer to some query than the tree's nearest point, in the distances
    /// [`squared_distance`] computes (as the tree does): an equal point would be as near.
    pub(crate) fn add_new(&mut self, p: [f64; 2], id: u64) {
        let (node, parent) = self.descend(p);
        debug_assert!(
            self.leaves[(node & !LEAF) as usize]
                .squared_distances(p)
                .all(|(_, d)| d > 0.0),
            "{p:?} is in the tree"
        );
        self.put(p, id, node, parent);
    }

    /// The leaf `p` belongs in, and the link to it (its stem, and whether it is that stem's
    /// `above` side; `None` for the root).
    #[inline]
    fn descend(&self, p: [f64; 2]) -> (NodeRef, Option<(usize, bool)>) {
        let mut parent: Option<(usize, bool)> = None;
        let mut node = self.root;
        while node & LEAF == 0 {
            let stem = self.stems[node as usize];
            let above = p[stem.axis] >= stem.split;
            parent = Some((node as usize, above));
            node = if above { stem.above } else { stem.below };
        }
        (node, parent)
    }

    /// Puts `p`, equal to no point of the tree, in leaf `node` (linked from `parent`),
    /// splitting the leaf when it is full.
    #[inline]
    fn put(&mut self, p: [f64; 2], id: u64, node: NodeRef, parent: Option<(usize, bool)>) {
        const {
            assert!(
                B >= 2 && B.is_multiple_of(LANES),
                "a leaf splits into two, and scans in lanes"
            )
        };
        let at = (node & !LEAF) as usize;
        self.len += 1;
        if self.leaves[at].len < B {
            self.leaves[at].push(p, id);
            // A one-leaf tree has no boxes yet (the first split makes them).
            if let Some(chunk) = self.boxes.get_mut(at / BOX_LANES) {
                chunk.grow(at % BOX_LANES, p);
            }
            return;
        }
        self.split(p, id, node, parent);
    }

    /// [`put`](Self::put) into a full leaf: its points and `p` split at the middle of their
    /// wider axis. Both sides get at least one (the points differ on that axis), so
    /// neither overflows. Out of line: one insertion in `B / 2` or more splits, and the
    /// others, kept apart, save and restore fewer registers.
    #[cold]
    #[inline(never)]
    fn split(&mut self, p: [f64; 2], id: u64, node: NodeRef, parent: Option<(usize, bool)>) {
        let at = (node & !LEAF) as usize;
        let leaf = &self.leaves[at];
        let spread = |axis: usize| {
            // In lanes, as the scans (a single running minimum is a chain of dependent
            // comparisons).
            let (mut lo, mut hi) = ([p[axis]; LANES], [p[axis]; LANES]);
            for c in leaf.axes[axis].chunks_exact(LANES) {
                for l in 0..LANES {
                    widen(&mut lo[l], &mut hi[l], c[l]);
                }
            }
            let lo = lo.iter().fold(p[axis], |m, &x| if x < m { x } else { m });
            let hi = hi.iter().fold(p[axis], |m, &x| if x > m { x } else { m });
            (lo, hi)
        };
        let (x, y) = (spread(0), spread(1));
        let (axis, (lo, hi)) = if x.1 - x.0 >= y.1 - y.0 {
            (0, x)
        } else {
            (1, y)
        };
        let mid = lo + (hi - lo) / 2.0;
        // Rounding can put the middle on the lowest value: the highest then splits.
        let split = if mid > lo { mid } else { hi };
        // The points above the split move to a new leaf; the others close up in place.
        let mut above = Leaf::empty();
        let leaf = &mut self.leaves[at];
        // Both sides' counts and boxes in locals (a push per point kept the new leaf's
        // count in memory, and a split costs a few per cent of a short RRT run).
        let (mut kept, mut bounds) = (0, Bounds::EMPTY);
        let (mut moved, mut moved_bounds) = (0, Bounds::EMPTY);
        for k in 0..B {
            let (q, item) = ([leaf.axes[0][k], leaf.axes[1][k]], leaf.ids[k]);
            if q[axis] >= split {
                above.axes[0][moved] = q[0];
                above.axes[1][moved] = q[1];
                above.ids[moved] = item;
                moved_bounds.grow(q);
                moved += 1;
            } else {
                leaf.axes[0][kept] = q[0];
                leaf.axes[1][kept] = q[1];
                leaf.ids[kept] = item;
                bounds.grow(q);
                kept += 1;
            }
        }
        above.len = moved;
        leaf.axes[0][kept..].fill(f64::INFINITY);
        leaf.axes[1][kept..].fill(f64::INFINITY);
        leaf.len = kept;
        if p[axis] >= split {
            above.push(p, id);
            moved_bounds.grow(p);
        } else {
            leaf.push(p, id);
            bounds.grow(p);
        }
        if self.stems.capacity() == 0 {
            // The room promised, and as many stems and boxes as those leaves need.
            self.leaves
                .reserve(self.room.saturating_sub(self.leaves.len()));
            self.stems.reserve(self.leaves.capacity() - 1);
            self.boxes.reserve(
                self.leaves
                    .capacity()
                    .div_ceil(BOX_LANES)
                    .saturating_sub(self.boxes.len()),
            );
        }
        let new = self.leaves.len();
        if self.boxes.is_empty() {
            self.boxes.push(BoxChunk::EMPTY);
        }
        self.boxes[at / BOX_LANES].set(at % BOX_LANES, bounds);
        if new.is_multiple_of(BOX_LANES) {
            self.boxes.push(BoxChunk::EMPTY);
        }
        self.boxes[new / BOX_LANES].set(new % BOX_LANES, moved_bounds);
        let new_leaf = new as NodeRef | LEAF;
        self.leaves.push(above);
        let stem = self.stems.len() as NodeRef;
        self.stems.push(Stem {
            split,
            axis,
            below: node,
            above: new_leaf,
        });
        match parent {
            None => self.root = stem,
            Some((s, true)) => self.stems[s].above = stem,
            Some((s, false)) => self.stems[s].below = stem,
        }
    }

    /// The item nearest `q` and its squared distance (`None` when empty). Ties go to any
    /// of the nearest.
    ///
    /// Inlined into its callers, with what a small tree's query takes in the AVX2 build:
    /// that and the call into pulp's entry. A function of its own saved and restored six
    /// registers for a query of a few hundred instructions.
    #[inline]
    pub(crate) fn nearest_one(&self, q: [f64; 2]) -> Option<(u64, f64)> {
        if self.len == 0 {
            return None;
        }
        if self.root & LEAF != 0 {
            // One leaf (a run's first `B` points): scanned without the recursive search's
            // frame and box test. It holds a point: `len` is not 0.
            let leaf = &self.leaves[(self.root & !LEAF) as usize];
            let (min, k) = self.wide.nearest(leaf, q);
            return Some((leaf.ids[k], min));
        }
        if self.leaves.len() <= FLAT_LEAVES {
            return Some(self.wide.nearest_flat(self, q));
        }
        self.nearest_by_search(q)
    }

    /// [`nearest_one`](Self::nearest_one) down the stems.
    #[inline(never)]
    fn nearest_by_search(&self, q: [f64; 2]) -> Option<(u64, f64)> {
        let mut nearest = Nearest {
            best: None,
            wide: self.wide,
        };
        self.search(self.root, q, [0.0; 2], 0.0, &mut nearest);
        nearest.best
    }

    /// [`nearest_one`](Self::nearest_one) of a tree of several leaves, at most
    /// [`FLAT_LEAVES`], without descending: every leaf's box distance, a vector register
    /// of boxes at a time; then the leaf of the nearest box is scanned, and the others
    /// only where their box is nearer than the nearest point so far. On an RRT's trees
    /// (hundreds of points) a query reads 1.2 leaves, and the descent to them cost more
    /// than the scans.
    ///
    /// `scan` is [`Leaf::nearest`] as the caller's build has it.
    #[inline(always)]
    fn nearest_flat(&self, q: [f64; 2], scan: impl LeafScan) -> (u64, f64) {
        debug_assert!((2..=FLAT_LEAVES).contains(&self.leaves.len()));
        // The boxes' distances by chunk, and the least in each lane. Unused lanes hold
        // empty boxes, infinitely far.
        let chunks = &self.boxes[..self.boxes.len().min(FLAT_LEAVES / BOX_LANES)];
        let mut d = [[f64::INFINITY; BOX_LANES]; FLAT_LEAVES / BOX_LANES];
        let mut least = [f64::INFINITY; BOX_LANES];
        for (dc, chunk) in d.iter_mut().zip(chunks) {
            *dc = chunk.distances(q);
            for l in 0..BOX_LANES {
                least[l] = if dc[l] < least[l] { dc[l] } else { least[l] };
            }
        }
        let least = least
            .into_iter()
            .fold(f64::INFINITY, |m, x| if x < m { x } else { m });
        // Bit `k` set where leaf `k`'s box passes `test`, from one comparison a chunk.
        let leaves_where = |test: &dyn Fn(f64) -> bool| {
            d[..chunks.len()]
                .iter()
                .enumerate()
                .fold(0_u32, |bits, (c, dc)| {
                    let lanes = (0..BOX_LANES).fold(0, |b, l| b | u32::from(test(dc[l])) << l);
                    bits | lanes << (c * BOX_LANES)
                })
        };
        // The first leaf at the least box distance. Unused lanes are infinitely far, as
        // far as any leaf can be (when squared distances overflow), so never first.
        let first = leaves_where(&|x| x == least).trailing_zeros() as usize;
        let leaf = &self.leaves[first];
        let (mut best, slot) = scan.nearest(leaf, q);
        let mut id = leaf.ids[slot];
        let mut more = leaves_where(&|x| x < best) & !(1 << first);
        while more != 0 {
            let k = more.trailing_zeros() as usize;
            more &= more - 1;
            if d[k / BOX_LANES][k % BOX_LANES] < best {
                let leaf = &self.leaves[k];
                let (min, slot) = scan.nearest(leaf, q);
                if min < best {
                    (best, id) = (min, leaf.ids[slot]);
                }
            }
        }
        (id, best)
    }

    /// Every item within squared distance `r2` of `q`, with its squared distance, in no
    /// particular order.
    pub(crate) fn within(&self, q: [f64; 2], r2: f64, out: &mut impl FnMut(u64, f64)) {
        if self.len > 0 {
            self.search(self.root, q, [0.0; 2], 0.0, &mut Within { r2, out });
        }
    }

    /// The `k` items nearest `q` with their squared distances, nearest first (fewer when
    /// the tree holds fewer).
    pub(crate) fn nearest_n(&self, q: [f64; 2], k: usize) -> Vec<(u64, f64)> {
        let mut nearest = NearestN {
            k,
            found: Vec::with_capacity(k + 1),
        };
        if k > 0 && self.len > 0 {
            self.search(self.root, q, [0.0; 2], 0.0, &mut nearest);
        }
        nearest.found
    }

    /// Hands `visit` the leaves below `node` that may hold a point within its bound of
    /// `q`, the nearer side of each split first; `node`'s region lies at squared distance
    /// at least `rd` from `q`, `off` being `q`'s offset from it on each axis.
    fn search(
        &self,
        node: NodeRef,
        q: [f64; 2],
        off: [f64; 2],
        rd: f64,
        visit: &mut impl Visit<B>,
    ) {
        if node & LEAF != 0 {
            let at = (node & !LEAF) as usize;
            let leaf = &self.leaves[at];
            // Read unless its points are provably beyond the bound (a one-leaf tree's box
            // is not kept: read).
            let beyond = self
                .boxes
                .get(at / BOX_LANES)
                .is_some_and(|chunk| chunk.distance(at % BOX_LANES, q) > visit.bound());
            if !beyond {
                visit.leaf(leaf, q);
            }
            return;
        }
        let stem = self.stems[node as usize];
        let gap = q[stem.axis] - stem.split;
        let (near, far) = if gap < 0.0 {
            (stem.below, stem.above)
        } else {
            (stem.above, stem.below)
        };
        self.search(near, q, off, rd, visit);
        let far_rd = rd - off[stem.axis] * off[stem.axis] + gap * gap;
        // Visited unless provably beyond the bound (overflowing offsets give NaN).
        if far_rd <= visit.bound() || far_rd.is_nan() {
            let mut far_off = off;
            far_off[stem.axis] = gap;
            self.search(far, q, far_off, far_rd, visit);
        }
    }
}

/// What a [`KdTree::search`] collects from the leaves it reads, and the squared distance
/// beyond which it needs no more.
trait Visit<const B: usize> {
    fn bound(&self) -> f64;
    fn leaf(&mut self, leaf: &Leaf<B>, q: [f64; 2]);
}

/// The nearest item and its squared distance so far (`None` before the first point: a
/// squared distance may overflow to infinity, and a point must still be found).
struct Nearest {
    best: Option<(u64, f64)>,
    wide: Wide,
}

impl<const B: usize> Visit<B> for Nearest {
    fn bound(&self) -> f64 {
        self.best.map_or(f64::INFINITY, |b| b.1)
    }

    #[inline(always)]
    fn leaf(&mut self, leaf: &Leaf<B>, q: [f64; 2]) {
        let (min, k) = self.wide.nearest(leaf, q);
        if leaf.len > 0 && self.best.is_none_or(|b| min < b.1) {
            self.best = Some((leaf.ids[k], min));
        }
    }
}

/// Every item within squared distance `r2`, handed to `out`.
struct Within<'a, F> {
    r2: f64,
    out: &'a mut F,
}

impl<const B: usize, F: FnMut(u64, f64)> Visit<B> for Within<'_, F> {
    fn bound(&self) -> f64 {
        self.r2
    }

    fn leaf(&mut self, leaf: &Leaf<B>, q: [f64; 2]) {
        for (item, d) in leaf.squared_distances(q) {
            if d <= self.r2 {
                (self.out)(item, d);
            }
        }
    }
}

/// The `k` nearest items so far, sorted, nearest first.
struct NearestN {
    k: usize,
    found: Vec<(u64, f64)>,
}

impl<const B: usize> Visit<B> for NearestN {
    fn bound(&self) -> f64 {
        if self.found.len() < self.k {
            f64::INFINITY
        } else {
            self.found[self.k - 1].1
        }
    }

    fn leaf(&mut self, leaf: &Leaf<B>, q: [f64; 2]) {
        for (item, d) in leaf.squared_distances(q) {
            if self.found.len() < self.k || d < self.found[self.k - 1].1 {
                let at = self.found.partition_point(|&(_, x)| x <= d);
                self.found.insert(at, (item, d));
                self.found.truncate(self.k);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The slot [`Leaf::nearest`] must find: the least (exact squared distance, lane,
    /// slot) over every point.
    fn reference<const B: usize>(leaf: &Leaf<B>, q: [f64; 2]) -> (f64, usize) {
        (0..leaf.len)
            .map(|k| {
                let d = squared_distance([leaf.axes[0][k], leaf.axes[1][k]], q);
                (d, k % LANES, k)
            })
            .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)))
            .map_or((f64::INFINITY, 0), |(d, _, k)| (d, k))
    }

    proptest::proptest! {
        /// The scan finds the same slot whichever way its lanes carry slots, and in the
        /// AVX2 build where this CPU has one, and it is the reference's: on leaves of
        /// lattice points (ties, equal distances across lanes) and of points far from the
        /// query.
        #[test]
        fn every_scan_finds_the_same_slot(
            points in proptest::collection::vec((-6..6_i32, -6..6_i32), 1..=64),
            q in (-8..8_i32, -8..8_i32),
            scale in proptest::sample::select(vec![0.5, 1.0, 3.0e150]),
        ) {
            let mut leaf = Leaf::<64>::empty();
            for (id, &(x, y)) in points.iter().enumerate() {
                leaf.push([f64::from(x) * scale, f64::from(y) * scale], id as u64);
            }
            let q = [f64::from(q.0) * scale, f64::from(q.1) * scale];
            let baseline = leaf.nearest::<usize>(q);
            proptest::prop_assert_eq!(baseline, leaf.nearest::<f64>(q));
            proptest::prop_assert_eq!(baseline, Wide::detect().nearest(&leaf, q));
            proptest::prop_assert_eq!(baseline, reference(&leaf, q));
        }

        /// A tree's nearest point is the nearest of all its points, through splits and
        /// queries that read several leaves, at scales from millimetres to far beyond a map
        /// (and to squared distances that overflow, where any point is as near as another);
        /// down the stems and from every box alike (trees of 1 to 50 leaves).
        #[test]
        fn tree_nearest_is_the_least_distance(
            points in proptest::collection::vec((-1000..1000_i32, -1000..1000_i32), 1..400),
            queries in proptest::collection::vec((-1200..1200_i32, -1200..1200_i32), 1..20),
            scale in proptest::sample::select(vec![1.0e-3, 0.05, 1.0, 7.0e9, 3.0e150]),
        ) {
            let mut tree = KdTree::<16>::with_capacity(0);
            let mut kept = Vec::new();
            for (id, &(x, y)) in points.iter().enumerate() {
                let p = [f64::from(x) * scale, f64::from(y) * scale];
                if tree.add(p, id as u64).is_none() {
                    kept.push(p);
                }
            }
            for &(x, y) in &queries {
                let q = [f64::from(x) * scale * 1.01, f64::from(y) * scale * 0.99];
                let least = kept.iter().map(|&p| squared_distance(p, q)).fold(f64::INFINITY, f64::min);
                let point = |item: u64| {
                    let (x, y) = points[item as usize];
                    [f64::from(x) * scale, f64::from(y) * scale]
                };
                let (item, d) = tree.nearest_one(q).unwrap();
                proptest::prop_assert_eq!(d, least);
                proptest::prop_assert_eq!(squared_distance(point(item), q), least);
                // Both ways through a tree of several leaves, whichever the query took.
                let leaves = tree.leaves.len();
                if leaves > 1 {
                    let (item, d) = tree.nearest_by_search(q).unwrap();
                    proptest::prop_assert_eq!((d, squared_distance(point(item), q)), (least, least));
                }
                if (2..=FLAT_LEAVES).contains(&leaves) {
                    for (item, d) in [
                        tree.nearest_flat(q, BaselineScan),
                        tree.wide.nearest_flat(&tree, q),
                    ] {
                        proptest::prop_assert_eq!((d, squared_distance(point(item), q)), (least, least));
                    }
                }
            }
        }
    }
}
