//! Pruning keeps the ends, never lengthens and keeps every segment free.

use hyplan_core::{Point2, path_length};
use postproc::{prune_pairwise, shortcut_farthest, shortcut_greedy};
use proptest::prelude::*;

use crate::grid::grid_and_path;

fn is_subsequence(sub: &[Point2], of: &[Point2]) -> bool {
    let mut it = of.iter();
    sub.iter().all(|p| it.any(|q| q == p))
}

proptest! {
    #[test]
    fn pruning_is_valid((grid, path) in grid_and_path()) {
        let free = |a, b| grid.segment_free(a, b);
        for (name, pruned) in [
            ("pairwise", prune_pairwise(&path, free)),
            ("greedy", shortcut_greedy(&path, free)),
            ("farthest", shortcut_farthest(&path, free)),
        ] {
            prop_assert_eq!(pruned[0], path[0], "{} start", name);
            prop_assert_eq!(pruned.last(), path.last(), "{} goal", name);
            prop_assert!(path_length(&pruned) <= path_length(&path) + 1e-9, "{} longer", name);
            prop_assert!(pruned.windows(2).all(|w| grid.segment_free(w[0], w[1])), "{} collides", name);
            prop_assert!(is_subsequence(&pruned, &path), "{} not a subsequence", name);
        }
    }

    #[test]
    fn pruning_an_empty_world_gives_the_chord(pts in prop::collection::vec((-50.0f64..50.0, -50.0f64..50.0), 2..30)) {
        let path: Vec<Point2> = pts.iter().map(|&(x, y)| Point2::new(x, y)).collect();
        prop_assert_eq!(shortcut_greedy(&path, |_, _| true), vec![path[0], path[path.len() - 1]]);
        prop_assert_eq!(prune_pairwise(&path, |_, _| true), vec![path[0], path[path.len() - 1]]);
        prop_assert_eq!(shortcut_farthest(&path, |_, _| true), vec![path[0], path[path.len() - 1]]);
    }
}

#[test]
fn pairwise_on_staircase() {
    // A staircase where only two-step shortcuts are free: pairwise halves it.
    let path: Vec<Point2> = (0..7)
        .map(|i| Point2::new(f64::from(i), f64::from(i % 2)))
        .collect();
    let free = |a: Point2, b: Point2| (b.x - a.x).abs() <= 2.0;
    let pruned = prune_pairwise(&path, free);
    assert_eq!(pruned, vec![path[0], path[2], path[4], path[6]]);
}
