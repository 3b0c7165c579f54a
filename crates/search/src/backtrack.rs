//! Back-tracking: depth-first search with undo, children tried best-first.
//!
//! This is the search seed 000 (`000_9b224721fe327833.txt`, the "BT" of RRT-A*-BT) runs to
//! escape a blockage: go deeper along the most promising child, and when a node has no
//! child left, undo the step and try the parent's next child.

use std::collections::HashSet;
use std::hash::Hash;

use crate::{NotFound, SearchResult, SearchStats};

/// Limits of a [`backtrack`] search.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BacktrackLimits {
    /// Longest path tried, in edges. Children deeper than this are not entered.
    pub max_depth: usize,
    /// Most nodes expanded before giving up.
    pub max_expansions: u64,
}

impl Default for BacktrackLimits {
    /// No depth cap (`usize::MAX`) and one million expansions.
    fn default() -> Self {
        Self {
            max_depth: usize::MAX,
            max_expansions: 1_000_000,
        }
    }
}

/// Finds **a** path (not necessarily the cheapest) from `start` to a node satisfying
/// `success`, by depth-first search with undo.
///
/// At each node the children are sorted by `f = g + h` (the cost so far plus the heuristic)
/// and tried best first; ties keep the order `successors` gave. Every node entered is
/// remembered for the rest of the search: a node is never entered twice, so the current
/// path never loops and a dead end (a node all of whose children failed) is never tried
/// again from another parent.
///
/// # Guarantees
///
/// - The returned path is simple (no node twice), starts at `start`, ends at a node
///   satisfying `success`, uses only edges given by `successors`, and `cost` is the sum of
///   their costs.
/// - **Not optimal**: the first path found is returned; the best-first child order only
///   makes a good one likely.
/// - **Complete on finite graphs when neither limit bites**: with `max_depth` at least the
///   number of reachable nodes and a large enough `max_expansions`, it expands every
///   reachable node before reporting [`NotFound::Exhausted`], which is then a proof that no
///   path exists (each node is expanded at most once, so it stops after at most as many
///   expansions as there are reachable nodes).
/// - With a smaller `max_depth`, a node first entered along a long route is remembered as
///   dead even if its subtree was only cut by the depth cap, so a path may be missed; the
///   search then reports [`NotFound::BudgetExhausted`], never `Exhausted`.
/// - Memory: the set of entered nodes plus the children of the nodes on the current path.
///
/// # Errors
///
/// [`NotFound::Exhausted`] when the reachable graph holds no goal (proof);
/// [`NotFound::BudgetExhausted`] when `max_expansions` was reached or the depth cap cut a
/// branch.
///
/// # Example
///
/// ```
/// use search::{BacktrackLimits, backtrack};
/// // A 5 x 5 grid with a wall x = 2 for y < 4: the walk must climb over it.
/// let free = |x: i32, y: i32| (0..5).contains(&x) && (0..5).contains(&y) && !(x == 2 && y < 4);
/// let found = backtrack(
///     &(0, 0),
///     |&(x, y): &(i32, i32)| {
///         [(1, 0), (-1, 0), (0, 1), (0, -1)]
///             .into_iter()
///             .map(move |(dx, dy)| (x + dx, y + dy))
///             .filter(|&(x, y)| free(x, y))
///             .map(|p| (p, 1.0))
///     },
///     |&(x, y)| f64::from((4 - x).abs() + (0 - y).abs()),
///     |&p| p == (4, 0),
///     BacktrackLimits::default(),
/// )?;
/// assert_eq!(found.path.first(), Some(&(0, 0)));
/// assert_eq!(found.path.last(), Some(&(4, 0)));
/// assert!(found.path.contains(&(2, 4)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn backtrack<N: Eq + Hash + Clone, IN: IntoIterator<Item = (N, f64)>>(
    start: &N,
    mut successors: impl FnMut(&N) -> IN,
    mut heuristic: impl FnMut(&N) -> f64,
    mut success: impl FnMut(&N) -> bool,
    limits: BacktrackLimits,
) -> Result<SearchResult<N>, NotFound> {
    /// One node of the current path and the children it has not tried yet, sorted so that
    /// the best (smallest f) is at the end, ready to `pop`.
    struct Frame<N> {
        node: N,
        g: f64,
        untried: Vec<(N, f64)>,
    }
    let mut stats = SearchStats {
        reached: 1,
        ..SearchStats::default()
    };
    if success(start) {
        return Ok(SearchResult {
            path: vec![start.clone()],
            cost: 0.0,
            stats,
        });
    }
    let mut entered: HashSet<N> = HashSet::new();
    let mut depth_cut = false;
    let mut expand = |node: &N, g: f64, stats: &mut SearchStats| -> Vec<(N, f64)> {
        stats.expansions += 1;
        let mut children: Vec<(N, f64, f64)> = successors(node)
            .into_iter()
            .map(|(n, c)| {
                let f = g + c + heuristic(&n);
                (n, c, f)
            })
            .collect();
        stats.pushes += children.len() as u64;
        // Ascending f, ties in the given order (stable sort), then reversed so that the best
        // child, and among equals the first given, is at the end for `pop`.
        children.sort_by(|a, b| a.2.total_cmp(&b.2));
        children.into_iter().rev().map(|(n, c, _)| (n, c)).collect()
    };
    entered.insert(start.clone());
    let first = expand(start, 0.0, &mut stats);
    let mut path: Vec<Frame<N>> = vec![Frame {
        node: start.clone(),
        g: 0.0,
        untried: first,
    }];

    while let Some(top) = path.last_mut() {
        let top_g = top.g;
        let Some((child, cost)) = top.untried.pop() else {
            // Dead end: every child of this node failed. Undo the step.
            path.pop();
            continue;
        };
        if entered.contains(&child) {
            continue;
        }
        if path.len() > limits.max_depth {
            // The child would sit deeper than the cap: not entered, not remembered.
            depth_cut = true;
            continue;
        }
        let g = top_g + cost;
        if success(&child) {
            stats.reached = entered.len() as u64 + 1;
            let mut nodes: Vec<N> = path.iter().map(|f| f.node.clone()).collect();
            nodes.push(child);
            return Ok(SearchResult {
                path: nodes,
                cost: g,
                stats,
            });
        }
        if stats.expansions >= limits.max_expansions {
            stats.reached = entered.len() as u64;
            return Err(NotFound::BudgetExhausted { stats });
        }
        entered.insert(child.clone());
        let untried = expand(&child, g, &mut stats);
        path.push(Frame {
            node: child,
            g,
            untried,
        });
    }
    stats.reached = entered.len() as u64;
    if depth_cut {
        Err(NotFound::BudgetExhausted { stats })
    } else {
        Err(NotFound::Exhausted { stats })
    }
}
