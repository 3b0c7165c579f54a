//! Clamped B-splines start and end at the path's end points.

use postproc::{BSpline, Curve};
use proptest::prelude::*;

use crate::paths::any_path;

proptest! {
    #[test]
    fn clamped_ends(path in any_path(1e4, 2..40)) {
        prop_assume!(path.len() >= 2);
        let n = path.len();
        for b in [BSpline::from_control_points(&path).unwrap(), BSpline::interpolating(&path).unwrap()] {
            let (u0, u1) = b.domain();
            prop_assert_eq!(b.eval(u0), path[0]);
            prop_assert_eq!(b.eval(u1), path[n - 1]);
            let samples = Curve::BSpline(b).resample(50.0).unwrap();
            prop_assert_eq!(samples[0], path[0]);
            prop_assert_eq!(samples[samples.len() - 1], path[n - 1]);
            prop_assert!(samples.windows(2).all(|w| nalgebra::distance(&w[0], &w[1]) <= 50.0));
        }
    }

    #[test]
    fn control_spline_stays_in_hull_box(path in any_path(1e4, 2..40)) {
        prop_assume!(path.len() >= 2);
        // Convex hull property, checked against the bounding box of the control points.
        let b = BSpline::from_control_points(&path).unwrap();
        let (lo_x, hi_x) = path.iter().fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p.x), h.max(p.x)));
        let (lo_y, hi_y) = path.iter().fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p.y), h.max(p.y)));
        let (u0, u1) = b.domain();
        for i in 0..=100 {
            let q = b.eval(u0 + (u1 - u0) * f64::from(i) / 100.0);
            prop_assert!(q.x >= lo_x - 1e-6 && q.x <= hi_x + 1e-6 && q.y >= lo_y - 1e-6 && q.y <= hi_y + 1e-6);
        }
    }
}
