//! The packed A* / Dijkstra engine shared by the grid searches: one word per cell
//! (generation, g, parent move), a radix-friendly heap key, and the expansion loop.

use super::*;

impl GridSearch {
    /// A* (`heuristic`) or Dijkstra from `s0` to `t0` (`NONE`: no target, run until the
    /// reachable cells are exhausted) on fixed-point integer costs.
    ///
    /// Open list: the [`MinHeap`] of [`GridKey`]s (smallest f first, ties toward larger g,
    /// i.e. smaller h; `u64` keys when [`Fixed::narrow`], else `u128`), with decrease-key
    /// through `slot`, plus a stack of cells whose f equals the f being expanded: they
    /// would come out of the heap next anyway (their g is final, the heuristic being
    /// consistent), so they skip it, and runs toward the goal go depth-first. Stale
    /// entries are skipped by the closed bit. Dijkstra (no heuristic) uses [`Buckets`]
    /// instead of the heap, which take its cells in the same order.
    pub(super) fn grid_search(
        &mut self,
        s0: u32,
        t0: u32,
        heuristic: bool,
    ) -> Result<GridPath, GridSearchError> {
        // Without a heuristic every successor's f is at least a straight move above the
        // expanded cell's, which lets buckets of one move's width replace the heap.
        let open = if heuristic {
            OpenKind::Heap
        } else {
            OpenKind::Buckets
        };
        self.grid_search_bounded(s0, t0, heuristic, open, u64::MAX)
    }

    /// [`grid_search`](GridSearch::grid_search) leaving out every cell whose g plus its
    /// octile distance to `t0` exceeds `bound` (fixed point; `u64::MAX`: none).
    pub(super) fn grid_search_bounded(
        &mut self,
        s0: u32,
        t0: u32,
        heuristic: bool,
        open: OpenKind,
        bound: u64,
    ) -> Result<GridPath, GridSearchError> {
        if self.fixed.narrow {
            self.grid_search_with::<u64>(s0, t0, heuristic, open, bound)
        } else {
            self.grid_search_with::<Upper>(s0, t0, heuristic, open, bound)
        }
    }

    /// [`grid_search_bounded`](GridSearch::grid_search_bounded) with open-list keys of
    /// type `K`.
    pub(super) fn grid_search_with<K: GridKey>(
        &mut self,
        s0: u32,
        t0: u32,
        heuristic: bool,
        open: OpenKind,
        bound: u64,
    ) -> Result<GridPath, GridSearchError> {
        let mut stats = SearchStats::default();
        let fx = self.fixed;
        let (unit, diag) = (fx.unit, fx.diag);
        let four = self.options.connectivity == Connectivity::Four;
        // h = hi * c_hi + lo * c_lo over the coordinate differences; zero for Dijkstra.
        let (c_hi, c_lo) = match (heuristic, four) {
            (false, _) => (0, 0),
            (true, true) => (unit, unit),
            (true, false) => (unit, diag - unit),
        };
        let (gx, gy) = if t0 == NONE { (0, 0) } else { self.xy(t0) };
        let h = move |x: u32, y: u32| {
            let dx = (i64::from(x) - i64::from(gx)).unsigned_abs();
            let dy = (i64::from(y) - i64::from(gy)).unsigned_abs();
            let (lo, hi) = if dx < dy { (dx, dy) } else { (dy, dx) };
            hi * c_hi + lo * c_lo
        };
        let (sx, sy) = self.xy(s0);
        let h0 = h(sx, sy);
        // `base | g << G_SHIFT | d << 1` is an open word of this query with cost g reached
        // by move d, `| 1` closes it.
        let base = self.begin(s0, &mut stats);
        let first = K::pack(fx, fx.order(h0, h0), s0);
        let run = Run {
            t0,
            base,
            f0: h0 >> fx.f_shift,
            pw: self.pw,
            magic: self.magic,
            fx,
            h,
            eight: !four,
            corner_cutting: self.options.corner_cutting,
            bound,
            goal: (gx, gy),
        };
        let Self {
            words,
            heap,
            wide_heap,
            buckets,
            stack,
            slot,
            limit,
            ..
        } = self;
        // The buckets need f's quantum below their width (it is, on any grid that fits
        // the words: f_shift = shift + bits(n) + 2 - 40 at most).
        let ended = if open == OpenKind::Buckets
            && !heuristic
            && fx.f_shift < fx.shift
            && K::fits_buckets(fx)
        {
            buckets.start(first, fx);
            let heap = K::heap(heap, wide_heap);
            if bound == u64::MAX {
                expand::<K, _, true, false>(
                    &run, words, heap, buckets, stack, slot, &mut stats, *limit,
                )
            } else {
                expand::<K, _, true, true>(
                    &run, words, heap, buckets, stack, slot, &mut stats, *limit,
                )
            }
        } else {
            let heap = K::heap(heap, wide_heap);
            heap.push(first);
            if bound == u64::MAX {
                expand::<K, _, false, false>(
                    &run, words, heap, buckets, stack, slot, &mut stats, *limit,
                )
            } else {
                expand::<K, _, false, true>(
                    &run, words, heap, buckets, stack, slot, &mut stats, *limit,
                )
            }
        };
        match ended {
            Expanded::Target(g) => {
                let cost = fx.to_cells(g);
                Ok(self.trace_words(t0, cost, stats))
            }
            Expanded::Exhausted => Err(GridSearchError::NoPath { stats }),
            Expanded::Limit => Err(GridSearchError::LimitReached { stats }),
        }
    }

    /// The A* / Dijkstra / Theta* entry point.
    pub(super) fn run(
        &mut self,
        map: Option<&GridMap>,
        start: (usize, usize),
        goal: (usize, usize),
        kind: Kind,
    ) -> Result<GridPath, GridSearchError> {
        let s0 = self.check(start, true)?;
        let t0 = self.check(goal, false)?;
        match (kind, map) {
            (Kind::Astar, _) => self.grid_search(s0, t0, true),
            (Kind::Dijkstra, _) | (Kind::ThetaStar | Kind::LazyThetaStar(_), None) => {
                self.grid_search(s0, t0, false)
            }
            (Kind::ThetaStar, Some(map)) => self.theta_search(s0, t0, false, self.sight(map), 1.0),
            (Kind::LazyThetaStar(weight), Some(map)) => {
                self.theta_search(s0, t0, true, self.sight(map), weight)
            }
        }
    }
}

/// The directions whose bits are set in `bits` (bit `d` for [`DIRS`]`[d]`), lowest first.
#[inline(always)]
pub(super) fn directions(bits: u8) -> impl Iterator<Item = usize> {
    let mut rest = bits;
    std::iter::from_fn(move || {
        (rest != 0).then(|| {
            let d = rest.trailing_zeros() as usize;
            rest &= rest - 1;
            d
        })
    })
}

/// The eight moves `(dx, dy, cost)`: E, W, N, S, then the diagonals NE, NW, SE, SW.
pub(super) const DIRS: [(i32, i32, f64); 8] = [
    (1, 0, 1.0),
    (-1, 0, 1.0),
    (0, 1, 1.0),
    (0, -1, 1.0),
    (1, 1, SQRT2),
    (-1, 1, SQRT2),
    (1, -1, SQRT2),
    (-1, -1, SQRT2),
];

/// Theta*'s open-list key: one `u64` compared as an integer, smallest first: the bits of
/// `f` as `f32` (non-negative floats' bits sort as the numbers do), then the cell index.
/// Half the width of an `f64` key with a tie-break on `g`, so the heap's sifts move and
/// compare half the bytes; only costs within about a part in 10^7 of each other can come
/// out in another order than by `f` (measured in docs/measurements/issue-31.md).
#[inline(always)]
pub(super) fn float_key(f: f64, p: u32) -> u64 {
    (u64::from((f as f32).to_bits()) << 32) | u64::from(p)
}

/// The fixed inputs of [`expand`].
pub(super) struct Run<H> {
    /// Target cell (`NONE`: none).
    t0: u32,
    /// The query's base word ([`GridSearch::base`]).
    pub(super) base: u64,
    /// `f >> f_shift` of the start.
    f0: u64,
    pub(super) pw: usize,
    pub(super) magic: u64,
    pub(super) fx: Fixed,
    /// Heuristic at padded coordinates.
    pub(super) h: H,
    /// The move rules: diagonal moves at all, and through a corner with one side blocked.
    eight: bool,
    corner_cutting: bool,
    /// Cells whose g plus octile distance to `goal` exceeds this are left out (when
    /// `BOUNDED`).
    bound: u64,
    /// The target's padded coordinates.
    goal: (u32, u32),
}

/// How [`expand`] ended.
pub(super) enum Expanded {
    /// The target was taken from the open list with this g.
    Target(u64),
    /// The open list ran out.
    Exhausted,
    /// The search's limit was reached first.
    Limit,
}

/// The loop of A* / Dijkstra (see [`GridSearch::grid_search`]) on the query's arrays,
/// passed apart so that nothing else can alias them: expands cells until the target is
/// taken from the open list (its g), the open list runs out, or the limit is reached.
/// The open list is `buckets` when `BUCKETS` (Dijkstra), else `heap`.
#[inline]
#[expect(
    clippy::too_many_arguments,
    reason = "the arrays are passed apart, see above"
)]
pub(super) fn expand<
    K: GridKey,
    H: Fn(u32, u32) -> u64,
    const BUCKETS: bool,
    const BOUNDED: bool,
>(
    run: &Run<H>,
    words: &mut [u64],
    heap: &mut MinHeap<K>,
    buckets: &mut Buckets,
    stack: &mut Vec<u32>,
    slot: &mut [u32],
    stats: &mut SearchStats,
    limit: Limit,
) -> Expanded {
    let mut check_at = limit.next_check(stats.expansions);
    let Run {
        t0,
        base,
        f0,
        pw,
        magic,
        fx,
        ref h,
        eight,
        corner_cutting,
        bound,
        goal: (gx, gy),
    } = *run;
    let (unit, diag) = (fx.unit, fx.diag);
    // The octile distance to the target, for the bound.
    let octile = |x: u32, y: u32| {
        let (dx, dy) = (u64::from(x.abs_diff(gx)), u64::from(y.abs_diff(gy)));
        dx.max(dy) * unit + dx.min(dy) * (diag - unit)
    };
    // Every word above this one belongs to an earlier query.
    let last = base | ((1 << GEN_SHIFT) - 1);
    // The f of the cell being expanded, as the key holds it (`f >> f_shift`): every cell
    // on the stack has it.
    let mut f_cur = f0;
    // Keeps `slot` up to date as the heap moves keys.
    macro_rules! place {
        () => {
            &mut |k: K, i: usize| slot[k.cell(fx) as usize] = i as u32
        };
    }
    // The heap's root is the cell being expanded (taken but not yet removed): the first
    // successor that goes to the heap replaces it (one sift instead of a pop and a push).
    let mut taken = false;
    loop {
        let p = if let Some(p) = stack.pop() {
            p
        } else if BUCKETS {
            let Some(k) = buckets.next::<K>(fx) else {
                break;
            };
            f_cur = k.order(fx) >> fx.tie_bits;
            let p = k.cell(fx);
            // An outdated entry of a cell that is open with a smaller g (reopened).
            let word = words[p as usize];
            if word & 1 == 0 && k.order(fx) != fx.order((word >> G_SHIFT) & G_MASK, 0) {
                continue;
            }
            p
        } else {
            if taken {
                heap.pop_placed(place!());
            }
            let Some(k) = heap.peek() else {
                break;
            };
            taken = true;
            f_cur = k.order(fx) >> fx.tie_bits;
            k.cell(fx)
        };
        let pu = p as usize;
        let word = words[pu];
        // Already closed: a stale entry. Queued cells are lowered in place, but a cell
        // whose lower f sends it to the stack leaves its heap entry behind (and, when f
        // values closer than the key's quantum were ordered wrongly, a closed cell can be
        // reopened and queued again).
        if word & 1 != 0 {
            continue;
        }
        words[pu] = word | 1;
        let g = (word >> G_SHIFT) & G_MASK;
        if p == t0 {
            return Expanded::Target(g);
        }
        if stats.expansions >= check_at {
            if limit.spent(stats.expansions) {
                return Expanded::Limit;
            }
            check_at = limit.next_check(stats.expansions);
        }
        stats.expansions += 1;
        let y = ((u128::from(p) * u128::from(magic)) >> 64) as u32;
        let x = p - y * pw as u32;
        // The 3 x 3 block around p as three rows of three words (south, middle, north),
        // so that the moves below index them with constants.
        let (below, rest) = words.split_at_mut(pu - 1);
        let (mid, above) = rest.split_at_mut(3);
        let (Some(south), Some(mid), Some(north)) = (
            below[pu - pw - 1..].first_chunk_mut::<3>(),
            mid.first_chunk_mut::<3>(),
            above[pw - 3..].first_chunk_mut::<3>(),
        ) else {
            // p is an inner cell of the padded grid: its 3 x 3 block exists.
            continue;
        };
        // One move: whether it is legal (all ones if not), word, bit, padded index, cost,
        // (dx, dy).
        macro_rules! relax {
            ($illegal:expr, $word:expr, $bit:expr, $q:expr, $cost:expr, $dx:expr, $dy:expr) => {{
                let word = &mut $word;
                let ng = g + $cost;
                // Relax a legal move unless q has a g from this query at least as
                // good (open, or closed: a closed cell's g is final, so never
                // worse). With the bits below g all set in `test`, one comparison
                // says it (a word of an earlier query is above every word of this
                // one, a blocked cell's word is 0, below every test), and an illegal
                // move's test is all ones, above every word. The word is read even
                // for an illegal move (it exists: the padded border), so that one
                // branch decides.
                let test = base | (ng << G_SHIFT) | ((1 << G_SHIFT) - 1) | $illegal;
                // A cell beyond the bound lies on no path of cost within it: it is
                // left out, its word untouched.
                let within = || {
                    !BOUNDED
                        || ng + octile(x.wrapping_add_signed($dx), y.wrapping_add_signed($dy))
                            <= bound
                };
                if test < *word && within() {
                    stats.reached += u64::from(*word > last);
                    *word = (test & !((1 << G_SHIFT) - 1)) | ($bit << 1);
                    let q: u32 = $q;
                    let hq = h(x.wrapping_add_signed($dx), y.wrapping_add_signed($dy));
                    // The heuristic is consistent and the arithmetic exact, so
                    // f >= f_cur.
                    if (ng + hq) >> fx.f_shift <= f_cur {
                        stack.push(q);
                    } else {
                        let key = K::pack(fx, fx.order(ng + hq, hq), q);
                        if BUCKETS {
                            buckets.offer(key, fx);
                        } else {
                            // Already queued (its g dropped): lower its key in place.
                            // The taken root is on its way out, so it does not count.
                            // (`K::MAX` holds no cell: the border cell with the last
                            // index is never queued.)
                            let i = slot[q as usize] as usize;
                            let queued = (heap.at(i).cell(fx) == q) & ((i != 0) | !taken);
                            if queued {
                                heap.decrease_placed(i, key, place!());
                            } else if taken {
                                heap.replace_top_placed(key, place!());
                                taken = false;
                            } else {
                                heap.push_placed(key, place!());
                            }
                        }
                    }
                    stats.pushes += 1;
                }
            }};
        }
        let pw32 = pw as u32;
        // The order of `DIRS`: E, W, N, S, NE, NW, SE, SW.
        // A straight move is legal exactly when its cell is passable, which the blocked
        // word says. A diagonal also needs the corner rule, on its two side cells: their
        // words are in the block already (a cell's word is 0 exactly when it is blocked,
        // whatever the queries wrote: read before the moves write them), so the rule
        // costs no load of the moves' masks, which on a large map is a cache miss an
        // expansion.
        let illegal = |side: u64, other: u64| {
            let (a, b) = (side != 0, other != 0);
            let legal = eight && if corner_cutting { a || b } else { a && b };
            u64::from(!legal).wrapping_neg()
        };
        let (east, west, up, down) = (mid[2], mid[0], north[1], south[1]);
        relax!(0, mid[2], 0, p + 1, unit, 1, 0);
        relax!(0, mid[0], 1, p - 1, unit, -1, 0);
        relax!(0, north[1], 2, p + pw32, unit, 0, 1);
        relax!(0, south[1], 3, p - pw32, unit, 0, -1);
        relax!(illegal(east, up), north[2], 4, p + pw32 + 1, diag, 1, 1);
        relax!(illegal(west, up), north[0], 5, p + pw32 - 1, diag, -1, 1);
        relax!(illegal(east, down), south[2], 6, p - pw32 + 1, diag, 1, -1);
        relax!(illegal(west, down), south[0], 7, p - pw32 - 1, diag, -1, -1);
    }
    Expanded::Exhausted
}

/// Which open list a search uses: the heap, or Dijkstra's [`Buckets`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum OpenKind {
    Heap,
    Buckets,
}

/// Dijkstra's open list: keys in buckets one straight move (`2^shift`) of f wide, the
/// current bucket sorted once and read in order.
///
/// Without a heuristic a successor's f is at least a straight move and less than two
/// above the expanded cell's, so it lands one or two buckets ahead: a bucket is complete
/// when its turn comes, and all its keys come before the next bucket's (the order's f
/// field is f in steps of `2^f_shift`, a divisor of the width). Read sorted, the cells
/// come out in the heap's order (with `u64` keys, whose cell bits settle ties, exactly
/// the same; with `u128` keys, ties by cell where the heap leaves them in any order).
/// A lowered key is queued again; the outdated entry comes later and is skipped.
///
/// Entries are `u64` for both key types ([`GridKey::to_bucket`]): a `u128` key keeps
/// only the f bits below the bucket's number, which is all that differs within a bucket.
#[derive(Debug, Clone, Default)]
pub(super) struct Buckets {
    /// The buckets after the current one, by bucket number modulo 4.
    ring: [Vec<u64>; 4],
    /// The current bucket, sorted.
    current: Vec<u64>,
    /// Next position in `current`.
    at: usize,
    /// The current bucket's number (f >> shift).
    number: u64,
    /// The buffer the current bucket is sorted into ([`sort_bucket`]).
    spare: Vec<u64>,
}

/// Sorts a bucket's entries in place (`spare` is the buffer of the pass): by their byte
/// just below the bits they all share, then each run of entries with equal bytes. A
/// bucket is a wavefront, hundreds to thousands of entries spread over its width, and
/// 256 short sorts cost less than a long one.
fn sort_bucket(entries: &mut Vec<u64>, spare: &mut Vec<u64>) {
    const SHORT: usize = 256;
    if entries.len() <= SHORT {
        entries.sort_unstable();
        return;
    }
    let (lo, hi) = entries
        .iter()
        .fold((u64::MAX, 0), |(lo, hi), &e| (lo.min(e), hi.max(e)));
    // Every entry lies between `lo` and `hi`, so it has their common high bits, and the
    // byte below those orders the entries as the entries do.
    let bits = u64::BITS - (lo ^ hi).leading_zeros();
    let shift = bits.saturating_sub(8);
    let byte = |e: u64| ((e >> shift) & 0xff) as usize;
    let mut starts = [0usize; 257];
    for &e in entries.iter() {
        starts[byte(e) + 1] += 1;
    }
    for b in 0..256 {
        starts[b + 1] += starts[b];
    }
    spare.clear();
    spare.resize(entries.len(), 0);
    let mut at = starts;
    for &e in entries.iter() {
        let b = byte(e);
        spare[at[b]] = e;
        at[b] += 1;
    }
    for b in 0..256 {
        spare[starts[b]..starts[b + 1]].sort_unstable();
    }
    std::mem::swap(entries, spare);
}

impl Buckets {
    /// Empties the list and queues `first`.
    pub(super) fn start<K: GridKey>(&mut self, first: K, fx: Fixed) {
        for bucket in &mut self.ring {
            bucket.clear();
        }
        self.current.clear();
        self.current.push(first.to_bucket(fx));
        self.at = 0;
        self.number = Self::number(first, fx);
    }

    /// The bucket of `key`.
    #[inline(always)]
    fn number<K: GridKey>(key: K, fx: Fixed) -> u64 {
        key.order(fx) >> (fx.tie_bits + fx.shift - fx.f_shift)
    }

    /// The key of the next cell to expand, or `None` when the list is empty.
    #[inline(always)]
    fn next<K: GridKey>(&mut self, fx: Fixed) -> Option<K> {
        loop {
            if let Some(&k) = self.current.get(self.at) {
                self.at += 1;
                return Some(K::from_bucket(k, self.number, fx));
            }
            // Keys go at most two buckets ahead.
            let number = (1..=2)
                .map(|d| self.number + d)
                .find(|&n| !self.ring[(n & 3) as usize].is_empty())?;
            std::mem::swap(&mut self.current, &mut self.ring[(number & 3) as usize]);
            self.ring[(number & 3) as usize].clear();
            sort_bucket(&mut self.current, &mut self.spare);
            self.at = 0;
            self.number = number;
        }
    }

    /// Queues `key` (a cell already queued with a larger key keeps that entry too, which
    /// comes out after it and is skipped).
    #[inline(always)]
    fn offer<K: GridKey>(&mut self, key: K, fx: Fixed) {
        let number = Self::number(key, fx);
        debug_assert!(number > self.number && number <= self.number + 2);
        self.ring[(number & 3) as usize].push(key.to_bucket(fx));
    }
}

/// The open-list key of A* and Dijkstra: the order ([`Fixed::order`]: f, then the
/// tie-break on h) above the cell, in one `u64` on grids where both fit
/// ([`Fixed::narrow`]), else in the two halves of a `u128` ordered by its upper half.
pub(super) trait GridKey: HeapKey {
    /// The key of cell `p` with order field `order`.
    fn pack(fx: Fixed, order: u64, p: u32) -> Self;
    /// The order field.
    fn order(self, fx: Fixed) -> u64;
    /// The cell.
    fn cell(self, fx: Fixed) -> u32;
    /// Whether [`Buckets`] hold this key type's Dijkstra keys on grids of scale `fx`.
    fn fits_buckets(fx: Fixed) -> bool;
    /// A Dijkstra key (no tie-break field) as [`Buckets`] hold it: a `u64` ordered as the
    /// keys of one bucket are.
    fn to_bucket(self, fx: Fixed) -> u64;
    /// The key of bucket entry `entry` of bucket `number`.
    fn from_bucket(entry: u64, number: u64, fx: Fixed) -> Self;
    /// The open list of this key type.
    fn heap<'a>(
        narrow: &'a mut MinHeap<u64>,
        wide: &'a mut MinHeap<Upper>,
    ) -> &'a mut MinHeap<Self>;
    /// The four-ary open list of this key type (jump point search's).
    fn quad_heap<'a>(
        narrow: &'a mut QuadHeap<u64>,
        wide: &'a mut QuadHeap<Upper>,
    ) -> &'a mut QuadHeap<Self>;
}

impl GridKey for u64 {
    #[inline(always)]
    fn pack(fx: Fixed, order: u64, p: u32) -> Self {
        (order << fx.cell_bits) | u64::from(p)
    }
    #[inline(always)]
    fn order(self, fx: Fixed) -> u64 {
        self >> fx.cell_bits
    }
    #[inline(always)]
    fn cell(self, fx: Fixed) -> u32 {
        (self & ((1 << fx.cell_bits) - 1)) as u32
    }
    fn fits_buckets(_: Fixed) -> bool {
        true
    }
    #[inline(always)]
    fn to_bucket(self, _: Fixed) -> u64 {
        self
    }
    #[inline(always)]
    fn from_bucket(entry: u64, _: u64, _: Fixed) -> Self {
        entry
    }
    fn heap<'a>(narrow: &'a mut MinHeap<u64>, _: &'a mut MinHeap<Upper>) -> &'a mut MinHeap<Self> {
        narrow
    }
    fn quad_heap<'a>(
        narrow: &'a mut QuadHeap<u64>,
        _: &'a mut QuadHeap<Upper>,
    ) -> &'a mut QuadHeap<Self> {
        narrow
    }
}

impl GridKey for Upper {
    #[inline(always)]
    fn pack(_: Fixed, order: u64, p: u32) -> Self {
        Upper((u128::from(order) << 64) | u128::from(p))
    }
    #[inline(always)]
    fn order(self, _: Fixed) -> u64 {
        (self.0 >> 64) as u64
    }
    #[inline(always)]
    fn cell(self, _: Fixed) -> u32 {
        self.0 as u32
    }
    fn fits_buckets(fx: Fixed) -> bool {
        // The f bits below the bucket's number go above the cell's 32.
        fx.shift - fx.f_shift <= 32
    }
    #[inline(always)]
    fn to_bucket(self, fx: Fixed) -> u64 {
        let f = self.order(fx) >> fx.tie_bits;
        ((f & ((1 << (fx.shift - fx.f_shift)) - 1)) << 32) | u64::from(self.cell(fx))
    }
    #[inline(always)]
    fn from_bucket(entry: u64, number: u64, fx: Fixed) -> Self {
        let f = (number << (fx.shift - fx.f_shift)) | (entry >> 32);
        Self::pack(fx, f << fx.tie_bits, entry as u32)
    }
    fn heap<'a>(_: &'a mut MinHeap<u64>, wide: &'a mut MinHeap<Upper>) -> &'a mut MinHeap<Self> {
        wide
    }
    fn quad_heap<'a>(
        _: &'a mut QuadHeap<u64>,
        wide: &'a mut QuadHeap<Upper>,
    ) -> &'a mut QuadHeap<Self> {
        wide
    }
}

/// Fixed-point costs of A* and Dijkstra: a straight move costs `unit = 2^k` and a diagonal
/// `diag`, the odd integer nearest to `sqrt(2) * 2^k` (relative error below `2^-k`), with
/// `k = 32` below 2^19 padded cells and smaller above so that g fits the 52 bits of its
/// field in a cell's word.
///
/// Sums are exact, so the octile heuristic in the same units is exactly consistent. A cost
/// `a * unit + b * diag` (a straight moves, b diagonals) determines `(a, b)` (diag is odd and
/// `b < 2^k`), so equal integer costs are equal real costs, and
/// [`to_cells`](Fixed::to_cells) returns `a + b * sqrt 2` exactly as `f64` sums it. Two
/// real path lengths closer than the approximation error (`b * 2^-k`) could be ordered
/// wrongly; for that, `|a' + b' sqrt 2|` must fall below `b 2^-k` for some integers of
/// that size, which needs `b` around `2^(k/2)` (65,536 diagonals at k = 32).
#[derive(Debug, Clone, Copy)]
pub(super) struct Fixed {
    /// `k`.
    pub(super) shift: u32,
    /// Cost of a straight move, `2^k`.
    pub(super) unit: u64,
    /// Cost of a diagonal move.
    pub(super) diag: u64,
    /// Inverse of `diag` modulo 2^64.
    pub(super) inv_diag: u64,
    /// Right shift of f for the f field of the order.
    pub(super) f_shift: u32,
    /// Right shift of h for the tie-break field of the order.
    pub(super) h_shift: u32,
    /// Bits of the tie-break field.
    pub(super) tie_bits: u32,
    /// Whether the open-list keys are `u64` (order above `cell_bits` bits of cell).
    pub(super) narrow: bool,
    /// Bits of the cell in a `u64` key.
    pub(super) cell_bits: u32,
}

impl Fixed {
    /// The scale for a padded grid of `pw x ph` cells.
    pub(super) fn new(pw: usize, ph: usize) -> Self {
        let n = pw * ph;
        // Any path visits each cell at most once, so g < n * diag < n * 2^(k + 1) <=
        // 2^(bits(n) + k + 1), which must fit the word's g field, and
        // f = g + h < 2 n 2^(k + 1) <= 2^(bits(n) + k + 2) <= 2^64.
        let bits = usize::BITS - n.leading_zeros();
        let shift = (GEN_SHIFT - G_SHIFT - 1).saturating_sub(bits).min(32);
        let unit = 1u64 << shift;
        let diag = ((std::f64::consts::SQRT_2 * unit as f64).round() as u64) | 1;
        // Newton's iteration for the inverse of an odd number modulo 2^64.
        let mut inv_diag = diag;
        for _ in 0..6 {
            inv_diag = inv_diag.wrapping_mul(2u64.wrapping_sub(diag.wrapping_mul(inv_diag)));
        }
        // h <= (pw + ph) * diag < (pw + ph) * 2^(k + 1).
        let h_bits = usize::BITS - (pw + ph).leading_zeros() + shift + 1;
        // The f field quantum is 2^(bits(n) + 2 - f_bits) cells: a `u64` key is used when
        // f gets at least bits(n) + 18 bits (a quantum of 2^-16 cells or finer) besides
        // the cell and at least 8 bits of tie-break.
        let cell_bits = usize::BITS - (n - 1).leading_zeros();
        let spare = (64 - cell_bits).saturating_sub(bits + 18);
        let narrow = spare >= 8;
        let (f_bits, tie_bits) = if narrow {
            let tie_bits = spare.min(16);
            (64 - cell_bits - tie_bits, tie_bits)
        } else {
            (40, 24)
        };
        Self {
            shift,
            unit,
            diag,
            inv_diag,
            f_shift: (bits + shift + 2).saturating_sub(f_bits),
            h_shift: h_bits.saturating_sub(tie_bits),
            tie_bits,
            narrow,
            cell_bits,
        }
    }

    /// The order of a cell with f and h (fixed point) in the open list: the top bits of f,
    /// then the top `tie_bits` bits of h (ties on f go to the smaller h, that is, the
    /// larger g). With `u64` keys the cell's bits follow (so the order of equal fields is
    /// by cell); with `u128` keys the order is the upper half, and equal ones come out in
    /// any order.
    ///
    /// Truncating f merges only f values less than `2^f_shift` units apart: 2^-18 cells on
    /// the peers' 101 x 101 maze, 2^-22 on the MovingAI arena, at most 2^-16 wherever keys
    /// are `u64` (up to about 2^19 padded cells), and 2^-16 cells at 2^22 cells with
    /// `u128` keys. Distinct lengths `a + b sqrt 2` of paths with fewer than about 10^4
    /// diagonals lie further apart than that, so there the order is exact; otherwise a
    /// cell may come out before one whose f is smaller by less than the quantum (a closed
    /// cell that later gets a smaller g is reopened), and the cost is within the quantum
    /// of the optimum. Truncating h only coarsens the tie-break.
    #[inline(always)]
    pub(super) fn order(self, f: u64, h: u64) -> u64 {
        // h < 2^(h_shift + tie_bits), so the tie field holds it.
        ((f >> self.f_shift) << self.tie_bits) | (h >> self.h_shift)
    }

    /// A fixed-point cost in cells: `a + b * sqrt 2` for `cost = a * unit + b * diag`.
    pub(super) fn to_cells(self, cost: u64) -> f64 {
        let b = cost.wrapping_mul(self.inv_diag) & (self.unit - 1);
        let a = cost.wrapping_sub(b.wrapping_mul(self.diag)) >> self.shift;
        a as f64 + b as f64 * SQRT2
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A random map, 2-60 cells a side, 0-40 % blocked (open grids have the most ties
    /// between equal costs), a start and a few goals, some blocked or unreachable.
    fn maps() -> impl Strategy<Value = (GridMap, Vec<(usize, usize)>)> {
        (2usize..60, 2usize..60, 0.0f64..0.4).prop_flat_map(|(w, h, density)| {
            (
                proptest::collection::vec(prop::bool::weighted(density), w * h),
                proptest::collection::vec((0..w, 0..h), 2..8),
            )
                .prop_map(move |(blocked, cells)| (test_map(w, h, blocked), cells))
        })
    }

    proptest! {
        /// A bucket sorted byte first, then by runs, is the bucket sorted: entries with a
        /// common prefix and spread below it (as a wavefront's are), equal ones, all
        /// lengths about the short sort's limit.
        #[test]
        fn a_bucket_sorts_as_a_slice_does(
            prefix in any::<u64>(),
            spread in 0u32..64,
            len in 200usize..700,
            seed in any::<u64>(),
            repeats in 0usize..4,
        ) {
            let mut x = seed | 1;
            let mask = if spread == 0 { 0 } else { u64::MAX >> (64 - spread) };
            let mut entries: Vec<u64> = (0..len)
                .map(|_| {
                    x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1442695040888963407);
                    (prefix & !mask) | (x & mask)
                })
                .collect();
            for k in 0..repeats.min(entries.len()) {
                entries[k] = entries[entries.len() - 1 - k];
            }
            let mut expected = entries.clone();
            expected.sort_unstable();
            sort_bucket(&mut entries, &mut Vec::new());
            prop_assert_eq!(entries, expected);
        }
    }

    /// On a grid of more than 2^19 cells (`u128` keys, whose equal keys the heap takes in
    /// any order) the buckets give every cell the heap's cost.
    #[test]
    fn buckets_on_a_large_grid_give_the_heap_costs() {
        let (w, h) = (800, 700);
        // 20 % of the cells blocked, from a fixed linear congruential sequence.
        let mut x: u64 = 1;
        let map = test_map(
            w,
            h,
            (0..w * h).map(|_| {
                x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                (x >> 33).is_multiple_of(5)
            }),
        );
        let mut heap = GridSearch::new(&map, GridOptions::default()).unwrap();
        let mut buckets = GridSearch::new(&map, GridOptions::default()).unwrap();
        let fx = heap.fixed;
        assert!(!fx.narrow && fx.f_shift < fx.shift && Upper::fits_buckets(fx));
        let s0 = (0..w * h)
            .find_map(|c| heap.check((c % w + w / 2, h / 2), true).ok())
            .unwrap();
        let t0 = (0..w * h)
            .find_map(|c| heap.check((w - 1 - c % w, h - 1 - c / w), false).ok())
            .unwrap();
        let a = heap
            .grid_search_with::<Upper>(s0, t0, false, OpenKind::Heap, u64::MAX)
            .unwrap();
        let b = buckets
            .grid_search_with::<Upper>(s0, t0, false, OpenKind::Buckets, u64::MAX)
            .unwrap();
        assert_eq!(a.cost, b.cost);
        // Bounded by its own cost, Dijkstra keeps its path with `u128` keys too.
        let (start, goal) = (heap.xy(s0), heap.xy(t0));
        let unpad = |(x, y): (u32, u32)| (x as usize - 1, y as usize - 1);
        let within = buckets
            .dijkstra_within(unpad(start), unpad(goal), b.cost)
            .unwrap();
        assert_eq!(within.cells, b.cells);
        assert!(within.stats.expansions < b.stats.expansions);
        let _ = heap.grid_search_with::<Upper>(s0, NONE, false, OpenKind::Heap, u64::MAX);
        let _ = buckets.grid_search_with::<Upper>(s0, NONE, false, OpenKind::Buckets, u64::MAX);
        let mut reached = 0;
        for p in 0..heap.words.len() as u32 {
            assert_eq!(heap.g_of(p), buckets.g_of(p), "cell {p}");
            reached += usize::from(heap.g_of(p).is_some());
        }
        assert!(reached > w * h / 2);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        /// Dijkstra's buckets take the cells in the heap's order: the same path, the
        /// same counts, and on a search without a target the same cost at every cell.
        #[test]
        fn buckets_expand_in_the_heap_order((map, cells) in maps(), four in any::<bool>()) {
            let options = GridOptions {
                connectivity: if four { Connectivity::Four } else { Connectivity::Eight },
                ..GridOptions::default()
            };
            let mut heap = GridSearch::new(&map, options).unwrap();
            let mut buckets = GridSearch::new(&map, options).unwrap();
            prop_assert!(heap.fixed.narrow);
            let Ok(s0) = heap.check(cells[0], true) else { return Ok(()) };
            for &goal in &cells[1..] {
                let t0 = heap.check(goal, false).unwrap_or(NONE);
                let a = heap.grid_search_with::<u64>(s0, t0, false, OpenKind::Heap, u64::MAX);
                let b = buckets.grid_search_with::<u64>(s0, t0, false, OpenKind::Buckets, u64::MAX);
                prop_assert_eq!(&a, &b);
                if t0 == NONE {
                    for p in 0..heap.words.len() as u32 {
                        prop_assert_eq!(heap.g_of(p), buckets.g_of(p));
                    }
                }
            }
        }
    }
}
