//! `NearestIndex` against a linear scan.

use hyplan_core::Point2;
use proptest::prelude::*;
use sampling::NearestIndex;

fn linear_nearest(points: &[Point2], q: Point2) -> f64 {
    points
        .iter()
        .map(|p| (p - q).norm())
        .fold(f64::INFINITY, f64::min)
}

fn linear_within(points: &[Point2], q: Point2, r: f64) -> Vec<usize> {
    (0..points.len())
        .filter(|&i| (points[i] - q).norm() <= r)
        .collect()
}

/// The planners' index (leaves of 64 points) and the exploration detectors' (256), and
/// leaves of 8, the smallest, for deep trees.
fn check_against_scan(points: &[Point2], queries: &[(Point2, f64)]) {
    check_in_buckets::<8>(points, queries);
    check_in_buckets::<64>(points, queries);
    check_in_buckets::<256>(points, queries);
}

fn check_in_buckets<const B: usize>(points: &[Point2], queries: &[(Point2, f64)]) {
    let mut index = NearestIndex::<B>::with_bucket_capacity(0);
    for (i, &p) in points.iter().enumerate() {
        assert_eq!(index.insert(p), i);
    }
    assert_eq!(index.len(), points.len());
    for &(q, r) in queries {
        let (id, d) = index.nearest(q).unwrap();
        assert_eq!(d, (points[id] - q).norm());
        assert!(
            (d - linear_nearest(points, q)).abs() <= 1e-12,
            "nearest {d} vs scan {}",
            linear_nearest(points, q)
        );
        let mut got: Vec<usize> = index.within(q, r).into_iter().map(|(i, _)| i).collect();
        got.sort_unstable();
        assert_eq!(got, linear_within(points, q, r), "within {r} of {q:?}");
        let k = 5.min(points.len());
        let knn = index.nearest_k(q, k);
        assert_eq!(knn.len(), k);
        let mut scan: Vec<f64> = points.iter().map(|p| (p - q).norm()).collect();
        scan.sort_by(f64::total_cmp);
        let mut kd: Vec<f64> = knn.iter().map(|&(_, d)| d).collect();
        kd.sort_by(f64::total_cmp);
        for (a, b) in kd.iter().zip(&scan[..k]) {
            assert!((a - b).abs() <= 1e-12);
        }
    }
}

/// Nodes on integer cells with step 1: hundreds of points share x (and y) coordinates.
/// (kiddo 5's mutable tree, used before, panicked here: "Too many items with the same
/// position on one axis".)
#[test]
fn many_points_on_one_axis() {
    let mut points = Vec::new();
    for x in 0..5 {
        for y in 0..200 {
            points.push(Point2::new(f64::from(x), f64::from(y)));
        }
    }
    // A column of 500 points on x = 7.
    points.extend((0..500).map(|y| Point2::new(7.0, f64::from(y) * 0.5)));
    let queries: Vec<_> = (0..50)
        .map(|k| (Point2::new(f64::from(k) * 0.17, f64::from(k) * 3.9), 2.0))
        .collect();
    check_against_scan(&points, &queries);
}

/// More than a leaf of identical points, which no split separates: the index keeps the
/// duplicates aside and reports all of them.
#[test]
fn many_identical_points() {
    let mut points = vec![Point2::new(3.0, 3.0); 100];
    points.extend(vec![Point2::new(4.0, 3.0); 40]);
    points.push(Point2::new(-0.0, 0.0));
    points.push(Point2::new(0.0, -0.0));
    let queries = [
        (Point2::new(3.1, 3.0), 0.5),
        (Point2::new(3.5, 3.0), 0.5),
        (Point2::new(0.0, 0.0), 0.0),
    ];
    check_against_scan(&points, &queries);
    let mut index = NearestIndex::new();
    for &p in &points {
        index.insert(p);
    }
    assert_eq!(index.within(Point2::new(3.0, 3.0), 0.0).len(), 100);
}

/// Coordinates so large that squared distances overflow to infinity: the queries still
/// report points (every distance ties at infinity).
#[test]
fn overflowing_distances_still_answer() {
    let mut index = NearestIndex::<8>::with_bucket_capacity(0);
    for k in 0..20 {
        index.insert(Point2::new(1e200 * f64::from(k), -1e200));
    }
    let q = Point2::new(-1e200, 1e200);
    let (id, d) = index.nearest(q).unwrap();
    assert!(id < 20 && d.is_infinite(), "{id} {d}");
    assert_eq!(index.nearest_k(q, 5).len(), 5);
    assert_eq!(index.within(q, f64::INFINITY).len(), 20);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random points (on a coarse lattice half the time, so that many share coordinates)
    /// answer as a linear scan does.
    #[test]
    fn matches_linear_scan(
        raw in prop::collection::vec((0.0..50.0_f64, 0.0..50.0_f64), 1..400),
        lattice in any::<bool>(),
        queries in prop::collection::vec((-5.0..55.0_f64, -5.0..55.0_f64, 0.0..10.0_f64), 1..20),
    ) {
        let points: Vec<Point2> = raw
            .iter()
            .map(|&(x, y)| if lattice { Point2::new(x.floor(), (y / 10.0).floor()) } else { Point2::new(x, y) })
            .collect();
        let queries: Vec<_> = queries.iter().map(|&(x, y, r)| (Point2::new(x, y), r)).collect();
        check_against_scan(&points, &queries);
    }
}
