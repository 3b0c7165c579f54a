//! Plan among round pillars with no grid map at all: the `Workspace` is four discs in a
//! 10 x 10 room, implemented here in a few lines, and `sampling` is the only hyplan crate
//! used.
//!
//! Run with `cargo run -p sampling --example discs`.

use rand::SeedableRng;
use sampling::{Bounds, Budget, Goal, Planner, Point2, Query, Rrt, RrtConnect, RrtStar, Workspace};

/// A room with round pillars; `segment_free` is exact (distance from each centre to the
/// segment), not sampled.
struct Pillars {
    size: f64,
    discs: Vec<(Point2, f64)>,
}

impl Workspace for Pillars {
    fn bounds(&self) -> Bounds {
        Bounds::new(Point2::origin(), Point2::new(self.size, self.size))
    }

    fn is_free(&self, p: Point2) -> bool {
        self.bounds().contains(p) && self.discs.iter().all(|&(c, r)| (p - c).norm() > r)
    }

    fn segment_free(&self, a: Point2, b: Point2) -> bool {
        self.is_free(a)
            && self.is_free(b)
            && self.discs.iter().all(|&(c, r)| {
                let ab = b - a;
                let t = ((c - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
                let nearest = if ab.norm_squared() > 0.0 {
                    a + ab * t
                } else {
                    a
                };
                (nearest - c).norm() > r
            })
    }
}

fn main() {
    let room = Pillars {
        size: 10.0,
        discs: vec![
            (Point2::new(3.0, 3.0), 1.2),
            (Point2::new(6.5, 6.0), 1.5),
            (Point2::new(3.0, 7.5), 1.0),
            (Point2::new(7.5, 2.0), 1.0),
        ],
    };
    let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(9.5, 9.5)));
    let planners: Vec<(&str, Box<dyn Planner>)> = vec![
        (
            "RRT",
            Box::new(Rrt {
                step: 0.5,
                ..Rrt::default()
            }),
        ),
        (
            "RRT-Connect",
            Box::new(RrtConnect {
                step: 0.5,
                ..RrtConnect::default()
            }),
        ),
        (
            "RRT* (whole budget)",
            Box::new(RrtStar {
                step: 0.5,
                budget: Budget::iterations(3_000),
                stop_at_first_solution: false,
                ..RrtStar::default()
            }),
        ),
    ];
    for (name, planner) in planners {
        // One seeded stream per run: the same seed gives the same path, bit for bit.
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        match planner.plan(&room, &query, &mut rng) {
            Ok(plan) => {
                assert!(plan.path.windows(2).all(|w| room.segment_free(w[0], w[1])));
                println!(
                    "{name:>20}: length {:.2} with {} waypoints, {} tree nodes",
                    plan.cost,
                    plan.path.len(),
                    plan.stats.nodes
                );
            }
            Err(e) => println!("{name:>20}: {e}"),
        }
    }
}
