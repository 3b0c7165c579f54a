//! Redundant-node pruning: seed 000's pairwise reduction and the greedy shortcut of
//! seeds 001/003.

use hyplan_core::Point2;

/// Drops redundant nodes by testing each node against the node after next (seed 000,
/// section 4.5, "Reduction of the number of nodes").
///
/// One pass walks the path from the start: if the segment from node `i` to node `i + 2` is
/// free, node `i + 1` is dropped and the walk goes on from `i + 2`; otherwise both edges
/// are kept and the walk goes on from `i + 1`. Passes repeat until one drops nothing.
///
/// # Arguments
///
/// - `path`: the nodes, start first. Paths of fewer than three nodes come back unchanged.
/// - `segment_free`: the oracle, true when the closed segment between its two arguments
///   is free (for a grid map, `|a, b| map.segment_free(a, b)`).
///
/// # Returns
///
/// A subsequence of `path` that keeps the first and the last node bit for bit. Each new
/// segment was accepted by the oracle, and every other segment is one of the input's, so a
/// free input gives a free output. By the triangle inequality it is never longer.
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::prune_pairwise;
/// let zigzag = [
///     Point2::new(0.0, 0.0),
///     Point2::new(1.0, 0.1),
///     Point2::new(2.0, 0.0),
///     Point2::new(3.0, 0.1),
///     Point2::new(4.0, 0.0),
/// ];
/// let pruned = prune_pairwise(&zigzag, |_, _| true); // an empty world
/// assert_eq!(pruned, vec![zigzag[0], zigzag[4]]);
/// ```
#[must_use]
pub fn prune_pairwise(
    path: &[Point2],
    segment_free: impl FnMut(Point2, Point2) -> bool,
) -> Vec<Point2> {
    prune_pairwise_passes(path, usize::MAX, segment_free)
}

/// [`prune_pairwise`] for at most `passes` passes (fewer when a pass removes nothing):
/// seed 000's node reduction (4.5) is one pass.
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::prune_pairwise_passes;
/// let zigzag: Vec<Point2> = (0..5).map(|i| Point2::new(f64::from(i), 0.1 * f64::from(i % 2))).collect();
/// // One pass joins every other node; the second pass joins the ends.
/// assert_eq!(prune_pairwise_passes(&zigzag, 1, |_, _| true).len(), 3);
/// assert_eq!(prune_pairwise_passes(&zigzag, 2, |_, _| true).len(), 2);
/// ```
#[must_use]
pub fn prune_pairwise_passes(
    path: &[Point2],
    passes: usize,
    mut segment_free: impl FnMut(Point2, Point2) -> bool,
) -> Vec<Point2> {
    let mut current = path.to_vec();
    for _ in 0..passes {
        let n = current.len();
        let next = anchor_walk(&current, |i| {
            // Node i + 1 is redundant when i sees i + 2: join them directly.
            if i + 2 < n && segment_free(current[i], current[i + 2]) {
                i + 2
            } else {
                i + 1
            }
        });
        if next.len() == n {
            return next;
        }
        current = next;
    }
    current
}

/// Drops redundant nodes greedily from the start (seed 003, section 2.3; seed 001,
/// section 3.2, "path smoothing").
///
/// From the current anchor (first the start) the path is connected to the following nodes
/// one after the other as long as the straight segment from the anchor stays free; at the
/// first node that is not visible, the last visible one becomes the next anchor. This is
/// the forward scan the seed describes, so it costs about one oracle call per node.
///
/// # Arguments
///
/// - `path`: the nodes, start first. Paths of fewer than three nodes come back unchanged.
/// - `segment_free`: the oracle, true when the closed segment is free.
///
/// # Returns
///
/// A subsequence of `path` that keeps the first and the last node bit for bit, never
/// longer, whose new segments were all accepted by the oracle.
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::shortcut_greedy;
/// // A wall on x = 2 for y < 2: the path must go round its top.
/// let free = |a: Point2, b: Point2| {
///     let t = (2.0 - a.x) / (b.x - a.x);
///     !(0.0..=1.0).contains(&t) || a.y + t * (b.y - a.y) > 2.0
/// };
/// let path = [
///     Point2::new(0.0, 0.0),
///     Point2::new(1.0, 1.5),
///     Point2::new(1.5, 3.0),
///     Point2::new(3.5, 3.0),
///     Point2::new(4.0, 0.0),
/// ];
/// let pruned = shortcut_greedy(&path, free);
/// assert_eq!(pruned, vec![path[0], path[2], path[4]]);
/// ```
#[must_use]
pub fn shortcut_greedy(
    path: &[Point2],
    mut segment_free: impl FnMut(Point2, Point2) -> bool,
) -> Vec<Point2> {
    anchor_walk(path, |anchor| {
        // The neighbour is always kept: its segment belongs to the input.
        let mut reach = anchor + 1;
        while reach + 1 < path.len() && segment_free(path[anchor], path[reach + 1]) {
            reach += 1;
        }
        reach
    })
}

/// Drops redundant nodes by connecting each anchor to the farthest node it sees, searching
/// back from the goal (the "farthest visible node" reading of the greedy shortcut).
///
/// Unlike [`shortcut_greedy`], which stops at the first node hidden from the anchor, this
/// looks past hidden nodes, so it can skip a detour that comes back into view. It costs up
/// to `n^2 / 2` oracle calls instead of about `n`.
///
/// # Arguments
///
/// - `path`: the nodes, start first. Paths of fewer than three nodes come back unchanged.
/// - `segment_free`: the oracle, true when the closed segment is free.
///
/// # Returns
///
/// A subsequence of `path` that keeps the first and the last node bit for bit, never
/// longer, whose new segments were all accepted by the oracle.
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::{shortcut_farthest, shortcut_greedy};
/// // Node 2 is hidden from the start, node 3 is visible again.
/// let path: Vec<Point2> = (0..5).map(|i| Point2::new(f64::from(i), 0.0)).collect();
/// let free = |a: Point2, b: Point2| !(a.x == 0.0 && b.x == 2.0);
/// assert_eq!(shortcut_greedy(&path, free), vec![path[0], path[1], path[4]]);
/// assert_eq!(shortcut_farthest(&path, free), vec![path[0], path[4]]);
/// ```
#[must_use]
pub fn shortcut_farthest(
    path: &[Point2],
    mut segment_free: impl FnMut(Point2, Point2) -> bool,
) -> Vec<Point2> {
    anchor_walk(path, |anchor| {
        // The neighbour is the fallback: its segment belongs to the input.
        (anchor + 2..path.len())
            .rev()
            .find(|&j| segment_free(path[anchor], path[j]))
            .unwrap_or(anchor + 1)
    })
}

/// The walk every pruning pass shares: from the start, `reach(anchor)` names the node (after
/// `anchor`) that the anchor joins, which is kept and becomes the next anchor, until the
/// last node is kept. Paths of fewer than three nodes come back unchanged.
fn anchor_walk(path: &[Point2], mut reach: impl FnMut(usize) -> usize) -> Vec<Point2> {
    if path.len() < 3 {
        return path.to_vec();
    }
    let mut out = vec![path[0]];
    let mut anchor = 0;
    while anchor + 1 < path.len() {
        anchor = reach(anchor);
        out.push(path[anchor]);
    }
    out
}

#[cfg(test)]
mod tests {
    use nalgebra::point;

    use super::*;

    #[test]
    fn pairwise_keeps_blocked_corner() {
        let path = [point![0.0, 0.0], point![0.0, 1.0], point![1.0, 1.0]];
        assert_eq!(prune_pairwise(&path, |_, _| false), path.to_vec());
        assert_eq!(prune_pairwise(&path, |_, _| true), vec![path[0], path[2]]);
    }

    #[test]
    fn short_paths_unchanged() {
        assert!(prune_pairwise(&[], |_, _| true).is_empty());
        assert_eq!(
            shortcut_greedy(&[point![1.0, 2.0]], |_, _| true),
            vec![point![1.0, 2.0]]
        );
    }

    #[test]
    fn greedy_jumps_to_last_visible() {
        let path: Vec<_> = (0..6).map(|i| point![f64::from(i), 0.0]).collect();
        // Only segments spanning at most two nodes are free.
        let free = |a: Point2, b: Point2| (b.x - a.x).abs() <= 2.0;
        assert_eq!(
            shortcut_greedy(&path, free),
            vec![path[0], path[2], path[4], path[5]]
        );
    }
}
