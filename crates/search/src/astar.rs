//! A* over a graph given as closures (Hart, Nilsson and Raphael, 1968).

use std::collections::hash_map::Entry as MapEntry;
use std::collections::{BinaryHeap, HashMap};
use std::hash::Hash;

use crate::heap::Entry;
use crate::{NotFound, SearchResult, SearchStats};

/// Finds a cheapest path from `start` to a node satisfying `success`, by A*.
///
/// The graph is given as closures, in the shape of the `pathfinding` crate, but costs are
/// plain `f64`: no `OrderedFloat` wrapper is needed.
///
/// # Arguments
///
/// - `start`: the first node.
/// - `successors(n)`: the neighbours of `n` with the cost of each edge; costs must be finite
///   and `>= 0`.
/// - `heuristic(n)`: an estimate of the cost from `n` to the goal; it must never
///   overestimate (admissible) for the result to be optimal, and should be consistent
///   (`h(n) <= c(n, m) + h(m)`) so that each node is expanded once. Use `|_| 0.0` for
///   Dijkstra (or call [`dijkstra`](crate::dijkstra)).
/// - `success(n)`: whether `n` is a goal; the goal is a predicate so that a goal region
///   works as well as a single node.
///
/// Open-list ties on `f = g + h` are broken toward the larger `g`.
///
/// # Errors
///
/// [`NotFound::Exhausted`] when every node reachable from `start` was expanded without
/// meeting the goal: this proves that no path exists (on a finite graph).
///
/// # Example
///
/// A knight's shortest route on an unbounded board, once with an explicit node type and once
/// with bare tuples:
///
/// ```
/// use search::astar;
///
/// #[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
/// struct Pos(i32, i32);
/// const MOVES: [(i32, i32); 8] = [(1, 2), (2, 1), (2, -1), (1, -2), (-1, -2), (-2, -1), (-2, 1), (-1, 2)];
/// let goal = Pos(4, 6);
/// let found = astar(
///     &Pos(1, 1),
///     |&Pos(x, y)| MOVES.map(|(dx, dy)| (Pos(x + dx, y + dy), 1.0)),
///     |&Pos(x, y)| f64::from((goal.0 - x).abs() + (goal.1 - y).abs()) / 3.0,
///     |&p| p == goal,
/// )?;
/// assert_eq!(found.cost, 4.0);
/// assert_eq!(found.path.first(), Some(&Pos(1, 1)));
/// assert_eq!(found.path.last(), Some(&goal));
///
/// let tuples = astar(
///     &(1, 1),
///     |&(x, y): &(i32, i32)| MOVES.map(|(dx, dy)| ((x + dx, y + dy), 1.0)),
///     |&(x, y)| f64::from((4 - x).abs() + (6 - y).abs()) / 3.0,
///     |&p| p == (4, 6),
/// )?;
/// assert_eq!(tuples.cost, 4.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn astar<N: Eq + Hash + Clone, IN: IntoIterator<Item = (N, f64)>>(
    start: &N,
    mut successors: impl FnMut(&N) -> IN,
    mut heuristic: impl FnMut(&N) -> f64,
    mut success: impl FnMut(&N) -> bool,
) -> Result<SearchResult<N>, NotFound> {
    // Nodes live in a vector addressed by index; the map finds a node's index.
    struct Slot<N> {
        node: N,
        parent: usize,
        g: f64,
        closed: bool,
    }
    let mut stats = SearchStats::default();
    let mut index: HashMap<N, usize> = HashMap::new();
    let mut slots: Vec<Slot<N>> = vec![Slot {
        node: start.clone(),
        parent: usize::MAX,
        g: 0.0,
        closed: false,
    }];
    index.insert(start.clone(), 0);
    let mut open = BinaryHeap::new();
    open.push(Entry {
        f: heuristic(start),
        g: 0.0,
        item: 0usize,
    });
    stats.pushes += 1;

    while let Some(Entry { g, item: i, .. }) = open.pop() {
        // A node can sit in the heap several times (each time its g improved); only the
        // entry carrying its current g is live, the others are stale and skipped.
        if slots[i].closed || g > slots[i].g {
            continue;
        }
        if success(&slots[i].node) {
            stats.reached = slots.len() as u64;
            return Ok(build(&slots, i, |s| (&s.node, s.parent), g, stats));
        }
        slots[i].closed = true;
        stats.expansions += 1;
        let here = slots[i].node.clone();
        for (next, cost) in successors(&here) {
            let g_next = g + cost;
            let j = match index.entry(next) {
                MapEntry::Occupied(e) => {
                    let j = *e.get();
                    if slots[j].closed || g_next >= slots[j].g {
                        continue;
                    }
                    slots[j].g = g_next;
                    slots[j].parent = i;
                    j
                }
                MapEntry::Vacant(e) => {
                    let j = slots.len();
                    slots.push(Slot {
                        node: e.key().clone(),
                        parent: i,
                        g: g_next,
                        closed: false,
                    });
                    e.insert(j);
                    j
                }
            };
            let h = heuristic(&slots[j].node);
            open.push(Entry {
                f: g_next + h,
                g: g_next,
                item: j,
            });
            stats.pushes += 1;
        }
    }
    stats.reached = slots.len() as u64;
    Err(NotFound::Exhausted { stats })
}

/// Walks parent links back from `last` and returns the path from the root.
pub(crate) fn build<S, N: Clone>(
    slots: &[S],
    last: usize,
    link: impl Fn(&S) -> (&N, usize),
    cost: f64,
    stats: SearchStats,
) -> SearchResult<N> {
    let mut path = Vec::new();
    let mut i = last;
    while i != usize::MAX {
        let (node, parent) = link(&slots[i]);
        path.push(node.clone());
        i = parent;
    }
    path.reverse();
    SearchResult { path, cost, stats }
}
