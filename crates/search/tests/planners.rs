//! The `Planner` implementations on world points.

use envmap::GridMap;
use std::time::Duration;

use hyplan_core::{Budget, Goal, PlanError, Planner, Point2, Query, Workspace};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use search::{GridAstar, GridDijkstra, ThetaStar};

use crate::common::SEED;

#[path = "open_square.rs"]
mod open_square;

use open_square::OpenSquare;

fn room() -> GridMap {
    GridMap::from_ascii(
        "
        ..........
        ..........
        ....##....
        ....##....
        ....##....
        ..........
    ",
    )
    .unwrap()
    .with_frame(0.5, Point2::new(-1.0, 2.0))
    .unwrap()
}

fn planners() -> Vec<Box<dyn Planner>> {
    vec![
        Box::new(GridAstar::default()),
        Box::new(GridDijkstra::default()),
        Box::new(ThetaStar::default()),
    ]
}

#[test]
fn paths_start_and_end_exactly_and_every_segment_is_free() {
    let map = room();
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    let query = Query::new(Point2::new(-0.9, 2.1), Goal::Point(Point2::new(3.77, 4.8)));
    let mut costs = Vec::new();
    for p in planners() {
        let plan = p.plan(&map, &query, &mut rng).unwrap();
        assert_eq!(plan.path.first(), Some(&query.start), "{}", p.info().name);
        assert_eq!(
            plan.path.last(),
            Some(&query.goal.center()),
            "{}",
            p.info().name
        );
        for w in plan.path.windows(2) {
            assert!(map.segment_free(w[0], w[1]), "{}: {w:?}", p.info().name);
        }
        assert!((plan.cost - plan.length()).abs() < 1e-12);
        assert!(plan.stats.expansions > 0);
        costs.push(plan.cost);
    }
    assert!(
        (costs[0] - costs[1]).abs() < 1e-9,
        "A* {} vs Dijkstra {}",
        costs[0],
        costs[1]
    );
    assert!(
        costs[2] <= costs[0] + 1e-9,
        "Theta* {} vs A* {}",
        costs[2],
        costs[0]
    );
}

#[test]
fn goal_disc_ends_inside_the_disc() {
    let map = room();
    let goal = Goal::disc(Point2::new(3.5, 4.75), 1.2);
    let query = Query::new(Point2::new(-0.75, 2.25), goal);
    let plan = GridAstar::default()
        .plan(&map, &query, &mut rand::rng())
        .unwrap();
    assert!(goal.contains(*plan.path.last().unwrap()));
    assert!(
        plan.path[..plan.path.len() - 1]
            .iter()
            .all(|&p| !goal.contains(p))
    );
}

#[test]
fn bad_queries_are_typed_errors() {
    let map = room();
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    let inside_block = Point2::new(1.25, 3.75);
    for p in planners() {
        let q = Query::new(Point2::new(-5.0, 2.5), Goal::Point(Point2::new(0.0, 3.0)));
        assert!(matches!(
            p.plan(&map, &q, &mut rng),
            Err(PlanError::InvalidStart { .. })
        ));
        let q = Query::new(Point2::new(0.0, 3.0), Goal::Point(inside_block));
        assert!(matches!(
            p.plan(&map, &q, &mut rng),
            Err(PlanError::InvalidGoal { .. })
        ));
        let q = Query::new(
            Point2::new(f64::NAN, 3.0),
            Goal::Point(Point2::new(0.0, 3.0)),
        );
        assert!(matches!(
            p.plan(&map, &q, &mut rng),
            Err(PlanError::InvalidStart { .. })
        ));
    }
}

#[test]
fn unreachable_goal_is_no_path_with_stats() {
    let map = GridMap::from_ascii(
        "
        ..#..
        ..#..
    ",
    )
    .unwrap();
    let q = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(4.5, 1.5)));
    for p in planners() {
        match p.plan(&map, &q, &mut rand::rng()) {
            // Proved by the flood fill before any search, with the cause.
            Err(PlanError::Disconnected { cause, stats }) => {
                assert_eq!(cause, hyplan_core::NoPathCause::Wall);
                assert_eq!(stats.expansions, 0);
            }
            other => panic!("{}: {other:?}", p.info().name),
        }
    }
}

#[test]
fn non_grid_workspace_is_refused() {
    let q = Query::new(Point2::new(0.1, 0.1), Goal::Point(Point2::new(0.9, 0.9)));
    for p in planners() {
        match p.plan(&OpenSquare(1.0), &q, &mut rand::rng()) {
            Err(PlanError::InvalidParameter {
                name: "workspace", ..
            }) => {}
            other => panic!("{other:?}"),
        }
        assert!(p.info().grid_only && p.info().proves_no_path);
    }
}

#[test]
fn a_lazy_theta_star_weight_below_one_is_refused() {
    let q = Query::new(
        Point2::new(-0.75, 2.25),
        Goal::Point(Point2::new(3.75, 4.75)),
    );
    for weight in [0.5, f64::NAN, f64::INFINITY] {
        let p = search::LazyThetaStar {
            weight,
            ..Default::default()
        };
        match p.plan(&room(), &q, &mut rand::rng()) {
            Err(PlanError::InvalidParameter { name: "weight", .. }) => {}
            other => panic!("{weight}: {other:?}"),
        }
    }
    let weighted = search::LazyThetaStar {
        weight: 1.5,
        ..Default::default()
    };
    assert!(weighted.plan(&room(), &q, &mut rand::rng()).is_ok());
}

/// Theta* with a time limit does not make the map's stride table, whose cost grows with
/// the map outside the limit's checks (60 ms on 2,000 x 2,000 cells); without a limit it
/// does, and `prepare` makes it ahead of timed plans. The paths are the same either way.
#[test]
fn theta_star_under_a_time_limit_leaves_the_stride_table_to_prepare() {
    let query = Query::new(
        Point2::new(-0.75, 2.25),
        Goal::Point(Point2::new(3.75, 4.75)),
    );
    let limited = ThetaStar {
        budget: Budget::iterations(u64::MAX).with_time(Duration::from_secs(60)),
        ..ThetaStar::default()
    };
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);

    let map = room();
    let timed = limited.plan(&map, &query, &mut rng).unwrap();
    assert!(map.made_blocked_strides().is_none());

    let map = room();
    let untimed = ThetaStar::default().plan(&map, &query, &mut rng).unwrap();
    assert!(map.made_blocked_strides().is_some());
    assert_eq!(timed.path, untimed.path);

    let map = room();
    limited.prepare(&map).unwrap();
    assert!(map.made_blocked_strides().is_some());
    assert_eq!(
        limited.plan(&map, &query, &mut rng).unwrap().path,
        untimed.path
    );
}
