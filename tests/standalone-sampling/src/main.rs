//! A user's program: convex polygon obstacles in a 20 x 10 hall, planned through with
//! `sampling` only (no grid map, no other hyplan crate).

use rand_chacha::ChaCha8Rng;
use sampling::rand::SeedableRng;
use sampling::{Bounds, Budget, Goal, Point2, Query, RrtConnect, RrtStar, Workspace};

/// Convex polygons, counter-clockwise; a point on an edge counts as inside (closed).
struct Hall {
    polygons: Vec<Vec<Point2>>,
}

fn cross(o: Point2, a: Point2, b: Point2) -> f64 {
    (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x)
}

fn inside(poly: &[Point2], p: Point2) -> bool {
    (0..poly.len()).all(|i| cross(poly[i], poly[(i + 1) % poly.len()], p) >= 0.0)
}

/// Whether closed segments ab and cd share a point.
fn segments_meet(a: Point2, b: Point2, c: Point2, d: Point2) -> bool {
    let (d1, d2) = (cross(a, b, c), cross(a, b, d));
    let (d3, d4) = (cross(c, d, a), cross(c, d, b));
    let on = |p: Point2, q: Point2, r: Point2| {
        r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    (d1 * d2 < 0.0 && d3 * d4 < 0.0)
        || (d1 == 0.0 && on(a, b, c))
        || (d2 == 0.0 && on(a, b, d))
        || (d3 == 0.0 && on(c, d, a))
        || (d4 == 0.0 && on(c, d, b))
}

impl Workspace for Hall {
    fn bounds(&self) -> Bounds {
        Bounds::new(Point2::new(0.0, 0.0), Point2::new(20.0, 10.0))
    }

    fn is_free(&self, p: Point2) -> bool {
        self.bounds().contains(p) && !self.polygons.iter().any(|poly| inside(poly, p))
    }

    fn segment_free(&self, a: Point2, b: Point2) -> bool {
        self.is_free(a)
            && self.is_free(b)
            && !self.polygons.iter().any(|poly| {
                (0..poly.len()).any(|i| segments_meet(a, b, poly[i], poly[(i + 1) % poly.len()]))
            })
    }
}

fn main() {
    let square = |x: f64, y: f64, w: f64, h: f64| {
        vec![
            Point2::new(x, y),
            Point2::new(x + w, y),
            Point2::new(x + w, y + h),
            Point2::new(x, y + h),
        ]
    };
    let hall = Hall {
        polygons: vec![
            square(4.0, 0.0, 1.0, 7.0),
            square(9.0, 3.0, 1.0, 7.0),
            square(14.0, 0.0, 1.0, 7.0),
            vec![
                Point2::new(17.0, 6.0),
                Point2::new(19.0, 7.0),
                Point2::new(17.5, 8.5),
            ],
        ],
    };
    let query = Query::new(
        Point2::new(1.0, 1.0),
        Goal::disc(Point2::new(19.0, 1.0), 0.5),
    );
    let connect = RrtConnect {
        step: 0.5,
        ..RrtConnect::default()
    };
    let star = RrtStar {
        step: 0.5,
        budget: Budget::iterations(20_000),
        ..RrtStar::default()
    };
    for (name, result) in [
        (
            "rrt-connect",
            connect.plan(&hall, &query, &mut ChaCha8Rng::seed_from_u64(1)),
        ),
        (
            "rrt-star",
            star.plan(&hall, &query, &mut ChaCha8Rng::seed_from_u64(1)),
        ),
    ] {
        let plan = result.unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(plan.path[0], query.start, "{name} keeps the start");
        assert!(
            plan.path.windows(2).all(|w| hall.segment_free(w[0], w[1])),
            "{name} returned a colliding path"
        );
        // Round the three walls the shortest path is about 28.2 (tangents at their ends), 18
        // for the straight line.
        assert!(plan.cost > 25.0, "{name}: {} is too short", plan.cost);
        println!(
            "{name}: length {:.2}, {} waypoints",
            plan.cost,
            plan.path.len()
        );
    }
}
