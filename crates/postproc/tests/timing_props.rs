//! Transfer time is at least length / v_max and analytic on a straight segment.

use hyplan_core::{Point2, path_length};
use postproc::{Limits, Smoothing, smooth_checked, straight_time, time_curve, time_polyline};
use proptest::prelude::*;

use crate::grid::grid_and_path;

fn limits() -> impl Strategy<Value = Limits> {
    (0.05f64..5.0, 0.1f64..3.0, 0.05f64..5.0).prop_map(|(v, w, a)| Limits::new(v, w, a).unwrap())
}

/// Rest-to-rest time on a straight line, written out independently of the crate.
fn analytic(len: f64, l: &Limits) -> f64 {
    let d_ramp = l.v_max * l.v_max / (2.0 * l.a_max); // distance to reach v_max
    if len >= 2.0 * d_ramp {
        2.0 * l.v_max / l.a_max + (len - 2.0 * d_ramp) / l.v_max
    } else {
        2.0 * (len / l.a_max).sqrt()
    }
}

proptest! {
    #[test]
    fn straight_segment_is_analytic(len in 0.01f64..100.0, n in 1usize..60, l in limits(), angle in 0.0f64..std::f64::consts::TAU) {
        let dir = nalgebra::Vector2::new(angle.cos(), angle.sin());
        let a = Point2::new(1.0, -2.0);
        let b = a + dir * len;
        let expected = analytic(nalgebra::distance(&a, &b), &l);
        let poly = time_polyline(&[a, b], &l).unwrap();
        prop_assert!((poly.transfer_time - expected).abs() <= 1e-9 * expected.max(1.0));
        prop_assert!((straight_time(nalgebra::distance(&a, &b), &l).unwrap() - expected).abs() <= 1e-9 * expected.max(1.0));
        // The same line, sampled in n uneven pieces, timed as a curve.
        let samples: Vec<Point2> = (0..=n).map(|i| {
            let t = (i as f64 / n as f64).powf(1.3);
            a + (b - a) * t
        }).collect();
        let curve = time_curve(&samples, &l).unwrap();
        prop_assert!((curve.transfer_time - expected).abs() <= 1e-6 * expected.max(1.0),
            "curve {} vs {}", curve.transfer_time, expected);
        prop_assert!(curve.max_speed() <= l.v_max * (1.0 + 1e-12));
    }

    #[test]
    fn at_least_length_over_vmax((grid, path) in grid_and_path(), l in limits()) {
        for method in Smoothing::ALL {
            let s = smooth_checked(&path, method, 0.25, |a, b| grid.segment_free(a, b)).unwrap();
            let t = s.time(&l).unwrap();
            prop_assert!(t.transfer_time >= s.length() / l.v_max * (1.0 - 1e-12), "{}", method);
            let driven = if method.is_polyline() { path_length(&s.nodes) } else { s.length() };
            prop_assert!((t.length - driven).abs() < 1e-9, "{}", method);
            prop_assert!(t.max_speed() <= l.v_max * (1.0 + 1e-12), "{}", method);
            prop_assert!(t.max_omega() <= l.omega_max * (1.0 + 1e-9), "{} omega {}", method, t.max_omega());
            let first = t.profile[0];
            let last = t.profile[t.profile.len() - 1];
            prop_assert_eq!((first.t, first.v), (0.0, 0.0));
            prop_assert_eq!(last.v, 0.0);
            prop_assert!((last.t - t.transfer_time).abs() < 1e-12);
            prop_assert!(t.profile.windows(2).all(|w| w[1].t >= w[0].t));
        }
    }
}

#[test]
fn seed000_straight_numbers() {
    // 6009.30 mm at 150 mm/s with a = 150 mm/s^2: 40.062 s cruise + 1 s of ramps.
    let l = Limits::new(150.0, 1.0, 150.0).unwrap();
    let t = time_polyline(&[Point2::new(0.0, 0.0), Point2::new(6009.30, 0.0)], &l).unwrap();
    assert!((t.transfer_time - (6009.30 / 150.0 + 1.0)).abs() < 1e-9);
}
