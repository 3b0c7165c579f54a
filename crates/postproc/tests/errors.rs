//! Bad input gives typed errors, never a panic.

use hyplan_core::Point2;
use nalgebra::point;
use postproc::{
    BSpline, Limits, Pchip, PostprocError, Smoothing, smooth_checked, time_curve, time_polyline,
};
use proptest::prelude::*;

#[test]
fn too_few_nodes() {
    for path in [vec![], vec![point![1.0, 1.0]]] {
        let n = path.len();
        let want = PostprocError::TooFewNodes { nodes: n };
        assert_eq!(Pchip::new(&path).unwrap_err(), want);
        assert_eq!(BSpline::from_control_points(&path).unwrap_err(), want);
        assert_eq!(BSpline::interpolating(&path).unwrap_err(), want);
        assert_eq!(
            smooth_checked(&path, Smoothing::Pchip, 0.25, |_, _| true).unwrap_err(),
            want
        );
        let l = Limits::new(1.0, 1.0, 1.0).unwrap();
        assert_eq!(time_polyline(&path, &l).unwrap_err(), want);
        assert_eq!(time_curve(&path, &l).unwrap_err(), want);
    }
}

#[test]
fn repeated_and_nan_nodes() {
    let repeated = [[0.0, 0.0], [1.0, 1.0], [1.0, 1.0], [2.0, 0.0]].map(Point2::from);
    assert_eq!(
        Pchip::new(&repeated).unwrap_err(),
        PostprocError::RepeatedNode {
            index: 1,
            x: 1.0,
            y: 1.0
        }
    );
    let nan = [point![0.0, 0.0], point![1.0, f64::NAN], point![2.0, 0.0]];
    let e = smooth_checked(&nan, Smoothing::BSpline, 0.25, |_, _| true).unwrap_err();
    assert!(
        matches!(e, PostprocError::NonFinite { index: 1, .. }),
        "{e}"
    );
    assert!(e.to_string().contains("node 1"));
    let inf = [point![0.0, 0.0], point![f64::INFINITY, 0.0]];
    assert!(matches!(
        BSpline::from_control_points(&inf),
        Err(PostprocError::NonFinite { index: 1, .. })
    ));
}

#[test]
fn bad_limits_and_spacing() {
    for (v, w, a, name) in [
        (0.0, 1.0, 1.0, "v_max"),
        (1.0, -1.0, 1.0, "omega_max"),
        (1.0, 1.0, f64::NAN, "a_max"),
        (f64::INFINITY, 1.0, 1.0, "v_max"),
    ] {
        match Limits::new(v, w, a) {
            Err(PostprocError::InvalidLimit { name: got, .. }) => assert_eq!(got, name),
            other => panic!("{other:?}"),
        }
    }
    let path = [point![0.0, 0.0], point![1.0, 0.0]];
    let bad = Limits {
        v_max: 1.0,
        omega_max: 1.0,
        a_max: 0.0,
    };
    assert!(matches!(
        time_polyline(&path, &bad),
        Err(PostprocError::InvalidLimit { name: "a_max", .. })
    ));
    for spacing in [0.0, -1.0, f64::NAN, 1e-300] {
        assert!(matches!(
            smooth_checked(&path, Smoothing::Pchip, spacing, |_, _| true),
            Err(PostprocError::InvalidSpacing { .. })
        ));
    }
    assert!(matches!(
        "cubic".parse::<Smoothing>(),
        Err(PostprocError::UnknownMethod { .. })
    ));
}

#[test]
fn colliding_input_refused() {
    let path = [point![0.0, 0.0], point![1.0, 0.0], point![2.0, 0.0]];
    let e = smooth_checked(&path, Smoothing::None, 0.25, |a, _| a.x < 0.5).unwrap_err();
    assert!(
        matches!(e, PostprocError::SegmentNotFree { index: 1, .. }),
        "{e}"
    );
}

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(1e300),
        -10.0f64..10.0,
    ]
}

proptest! {
    #[test]
    fn never_panics(pts in prop::collection::vec((wild(), wild()), 0..12), spacing in wild(), v in wild(), w in wild(), a in wild()) {
        let path: Vec<Point2> = pts.iter().map(|&(x, y)| point![x, y]).collect();
        for m in Smoothing::ALL {
            if let Ok(s) = smooth_checked(&path, m, spacing, |a, b| a.x + b.y < 5.0) {
                let _ = s.time(&Limits { v_max: v, omega_max: w, a_max: a });
            }
        }
        let l = Limits { v_max: v, omega_max: w, a_max: a };
        let _ = time_curve(&path, &l);
        let _ = time_polyline(&path, &l);
        let _ = Pchip::new(&path).map(|c| c.eval(v));
        let _ = BSpline::interpolating(&path).map(|c| c.eval(w));
    }
}
