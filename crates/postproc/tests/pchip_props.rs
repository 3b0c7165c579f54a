//! PCHIP passes through every node and does not overshoot monotone data.

use hyplan_core::Point2;
use postproc::Pchip;
use proptest::prelude::*;

use crate::paths::any_path;

/// Paths with strictly increasing x and non-decreasing y: both coordinates monotone in s.
fn monotone_path() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((0.01f64..5.0, 0.0f64..5.0), 1..25).prop_map(|steps| {
        let mut p = Point2::new(0.0, 0.0);
        let mut out = vec![p];
        for (dx, dy) in steps {
            p = Point2::new(p.x + dx, p.y + dy);
            out.push(p);
        }
        out
    })
}

proptest! {
    #[test]
    fn passes_through_every_node(path in any_path(100.0, 2..30)) {
        prop_assume!(path.len() >= 2);
        let c = Pchip::new(&path).unwrap();
        for (p, &s) in path.iter().zip(c.knots()) {
            prop_assert_eq!(c.eval(s), *p);
        }
    }

    #[test]
    fn no_overshoot_on_monotone_data(path in monotone_path()) {
        let c = Pchip::new(&path).unwrap();
        let knots = c.knots();
        for k in 0..path.len() - 1 {
            let (a, b) = (path[k], path[k + 1]);
            for i in 0..=32 {
                let s = knots[k] + (knots[k + 1] - knots[k]) * f64::from(i) / 32.0;
                let q = c.eval(s);
                let tol = 1e-9;
                prop_assert!(q.x >= a.x - tol && q.x <= b.x + tol, "x {} outside [{}, {}]", q.x, a.x, b.x);
                prop_assert!(q.y >= a.y - tol && q.y <= b.y + tol, "y {} outside [{}, {}]", q.y, a.y, b.y);
            }
        }
    }
}
