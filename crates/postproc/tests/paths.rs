//! Random paths for the curve properties.

use std::ops::Range;

use hyplan_core::Point2;
use proptest::prelude::*;

/// Paths of `nodes` points with both coordinates in `-extent..extent`, consecutive
/// repeats dropped (the fits refuse them).
pub fn any_path(extent: f64, nodes: Range<usize>) -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((-extent..extent, -extent..extent), nodes).prop_map(|pts| {
        let mut out: Vec<Point2> = pts.iter().map(|&(x, y)| Point2::new(x, y)).collect();
        out.dedup();
        out
    })
}
