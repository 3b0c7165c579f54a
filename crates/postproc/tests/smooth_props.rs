//! Checked smoothing never returns a sample pair that crosses a blocked cell.

use hyplan_core::Point2;
use postproc::{PathMetrics, Smoothing, smooth_checked};
use proptest::prelude::*;

use crate::grid::grid_and_path;

/// A quarter cell, as the CLI passes.
const SPACING: f64 = 0.25;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn smoothed_curves_are_free((grid, path) in grid_and_path()) {
        for method in Smoothing::ALL {
            let s = smooth_checked(&path, method, SPACING, |a, b| grid.segment_free(a, b))
                .map_err(|e| TestCaseError::fail(format!("{method}: {e}")))?;
            prop_assert_eq!(s.points[0], path[0], "{} start", method);
            prop_assert_eq!(s.points.last(), path.last(), "{} goal", method);
            for w in s.points.windows(2) {
                prop_assert!(grid.segment_free(w[0], w[1]), "{}: {} -> {} collides", method, w[0], w[1]);
                prop_assert!(nalgebra::distance(&w[0], &w[1]) <= SPACING, "{}: gap", method);
            }
            prop_assert!(s.points.iter().all(|&p| !grid.point_blocked(p)), "{}: sample in a blocked cell", method);
            // Turns are counted at inner nodes only, and no curve is shorter than its chord.
            let m = s.metrics();
            let chord = nalgebra::distance(&path[0], &path[path.len() - 1]);
            prop_assert!(m.length >= chord - 1e-9, "{}: {} < chord {}", method, m.length, chord);
            prop_assert!(m.nodes >= 2 && m.turns + 2 <= m.nodes, "{}: {:?}", method, m);
        }
    }
}

#[test]
fn repairs_reported_round_a_pillar() {
    // Seed 003's setting: the control-point B-spline of a path hugging a pillar cuts the
    // corner into it and must be repaired.
    let mut blocked = vec![false; 100];
    for j in 0..6 {
        for i in 4..6 {
            blocked[j * 10 + i] = true;
        }
    }
    let grid = crate::grid::Grid::new(10, 10, &blocked);
    let path = [
        Point2::new(1.0, 1.0),
        Point2::new(3.9, 6.1),
        Point2::new(6.1, 6.1),
        Point2::new(9.0, 1.0),
    ];
    for method in [
        Smoothing::Pchip,
        Smoothing::BSpline,
        Smoothing::BSplineInterpolating,
    ] {
        let s = smooth_checked(&path, method, SPACING, |a, b| grid.segment_free(a, b)).unwrap();
        // PCHIP keeps y flat on the top leg (shape preservation) and the interpolating
        // spline bulges outwards; the control-point spline cuts the corners into the pillar.
        assert_eq!(
            s.repairs.is_empty(),
            method != Smoothing::BSpline,
            "{method}: {:?}",
            s.repairs
        );
        assert!(s.points.windows(2).all(|w| grid.segment_free(w[0], w[1])));
    }
    // Turns are counted on the nodes: the pruned polyline turns twice.
    let s = smooth_checked(&path, Smoothing::Prune, SPACING, |a, b| {
        grid.segment_free(a, b)
    })
    .unwrap();
    assert_eq!(s.metrics().turns, 2);
    assert_eq!(PathMetrics::of(&path).turns, 2);
}
