//! The conformance suite every hybrid planner passes: valid paths against the zone it must
//! avoid, start and goal kept, determinism, budgets, "no path", typed errors; proptest on
//! random maps.

use envmap::GridMap;
use hybrid::{HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{
    Budget, Goal, NoPathCause, Plan, PlanError, Planner, Point2, Query, Workspace, Zone,
};
use proptest::prelude::*;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::fixtures::{self, Avoids, SEED_1};

#[path = "../../search/tests/open_square.rs"]
mod open_square;

use open_square::OpenSquare;

/// Checks a plan against the contract: starts at the start, ends at the goal (a point
/// goal) or in it, every segment free on the planning map, never in Forbidden.
fn assert_valid(plan: &Plan, ws: &GridMap, query: &Query, name: &str) {
    assert_eq!(plan.path[0], query.start, "{name}: start moved");
    let last = *plan.path.last().unwrap();
    assert!(
        query.goal.contains(last),
        "{name}: ends at {last:?}, not in the goal"
    );
    for w in plan.path.windows(2) {
        assert!(
            ws.segment_free(w[0], w[1]),
            "{name}: segment {:?} not free",
            w
        );
        assert!(
            ws.zone(w[0]) != Zone::Forbidden,
            "{name}: node in Forbidden"
        );
    }
    assert!(
        plan.cost.is_finite() && plan.cost >= plan.length() - 1e-9,
        "{name}"
    );
    assert!(plan.stats.nodes >= 1, "{name}");
    assert!(!plan.trees.is_empty(), "{name}");
}

fn room_query() -> Query {
    Query::new(Point2::new(2.5, 12.5), Goal::Point(Point2::new(37.5, 12.5)))
}

#[test]
fn names_are_the_registry_names() {
    let names: Vec<&str> = fixtures::all_planners(10)
        .iter()
        .map(|(p, _)| p.info().name)
        .collect();
    assert_eq!(
        names,
        [
            "rrt-astar-bt",
            "rrt-astar-refine",
            "hybrid-rrt-astar",
            "safe-rrt-star"
        ]
    );
    assert!(RrtAstarRefine::default().info().grid_only);
    assert!(HybridRrtAstar::default().info().grid_only);
    assert!(!RrtAstarBt::default().info().grid_only);
    assert!(!SafeRrtStar::default().info().grid_only);
}

#[test]
fn paths_are_valid_on_the_small_room() {
    let map = fixtures::small_room();
    let query = room_query();
    for (planner, avoids) in fixtures::all_planners(20_000) {
        let ws = fixtures::planning_map(&map, avoids);
        let name = planner.info().name;
        for seed in 0..10 {
            let plan = planner
                .plan(&ws, &query, &mut ChaCha8Rng::seed_from_u64(SEED_1 + seed))
                .unwrap_or_else(|e| panic!("{name}, seed {seed}: {e}"));
            assert_valid(&plan, &ws, &query, name);
            assert_eq!(*plan.path.last().unwrap(), query.goal.center(), "{name}");
            if avoids == Avoids::RiskAndForbidden {
                assert!(
                    plan.path.iter().all(|&p| map.zone(p) == Zone::Free),
                    "{name}"
                );
            }
        }
    }
}

#[test]
fn goal_disc_is_reached() {
    let map = fixtures::small_room();
    let query = Query::new(
        Point2::new(2.5, 12.5),
        Goal::disc(Point2::new(37.5, 12.5), 1.5),
    );
    for (planner, ws) in fixtures::planners_on(&map, 20_000) {
        let plan = planner
            .plan(&ws, &query, &mut ChaCha8Rng::seed_from_u64(SEED_1))
            .unwrap();
        assert_valid(&plan, &ws, &query, planner.info().name);
    }
}

#[test]
fn same_seed_same_plan() {
    let map = fixtures::small_room();
    let query = room_query();
    for (planner, ws) in fixtures::planners_on(&map, 20_000) {
        let a = planner
            .plan(&ws, &query, &mut ChaCha8Rng::seed_from_u64(7))
            .unwrap();
        let b = planner
            .plan(&ws, &query, &mut ChaCha8Rng::seed_from_u64(7))
            .unwrap();
        let name = planner.info().name;
        assert_eq!(a.path, b.path, "{name}");
        assert_eq!(a.trees, b.trees, "{name}");
        assert_eq!(a.cost.to_bits(), b.cost.to_bits(), "{name}");
        assert_eq!(a.stats.nodes, b.stats.nodes, "{name}");
        assert_eq!(a.stats.collision_checks, b.stats.collision_checks, "{name}");
        let c = planner
            .plan(&ws, &query, &mut ChaCha8Rng::seed_from_u64(8))
            .unwrap();
        assert!(
            c.trees != a.trees,
            "{name}: another seed gave the same tree"
        );
    }
}

#[test]
fn budgets_are_honoured() {
    let map = fixtures::small_room();
    let query = room_query();
    for (planner, ws) in fixtures::planners_on(&map, 3) {
        let name = planner.info().name;
        let err = planner
            .plan(&ws, &query, &mut ChaCha8Rng::seed_from_u64(1))
            .expect_err(name);
        let PlanError::BudgetExhausted { stats } = err else {
            panic!("{name}: {err}")
        };
        assert!(
            stats.iterations <= 3,
            "{name}: {} iterations",
            stats.iterations
        );
    }
    // A time budget stops a run whose iteration budget is huge.
    let mut walled = fixtures::small_room();
    fixtures::fill(&mut walled, 24, 0, 25, 24, Zone::Forbidden);
    let slow = SafeRrtStar {
        budget: Budget::iterations(u64::MAX).with_time(std::time::Duration::from_millis(30)),
        step: 1.5,
        ..SafeRrtStar::default()
    };
    let t = std::time::Instant::now();
    let err = slow
        .plan(&walled, &room_query(), &mut ChaCha8Rng::seed_from_u64(1))
        .unwrap_err();
    assert!(err.is_no_path());
    assert!(t.elapsed() < std::time::Duration::from_secs(2));
}

#[test]
fn walled_off_goal_gives_no_path() {
    let mut map = fixtures::small_room();
    // A wall across the room at x = 25.
    fixtures::fill(&mut map, 25, 0, 26, 24, Zone::Forbidden);
    fixtures::add_band(&mut map, 1);
    let query = room_query();
    // Every planner proves it at once, names the wall, and samples nothing.
    for (planner, ws) in fixtures::planners_on(&map, 2_000) {
        let name = planner.info().name;
        let err = planner
            .plan(&ws, &query, &mut ChaCha8Rng::seed_from_u64(SEED_1))
            .expect_err(name);
        assert!(err.is_no_path(), "{name}: {err}");
        assert_eq!(err.cause(), Some(&NoPathCause::Wall), "{name}: {err}");
        assert_eq!(err.stats().unwrap().iterations, 0, "{name}");
    }
}

/// `P`'s defaults with one `change`, as a boxed planner.
fn tweaked<P: Planner + Default + 'static>(change: fn(&mut P)) -> Box<dyn Planner> {
    let mut planner = P::default();
    change(&mut planner);
    Box::new(planner)
}

#[test]
fn bad_input_is_a_typed_error() {
    let map = fixtures::small_room();
    let query = room_query();
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let param = |e: PlanError| match e {
        PlanError::InvalidParameter { name, .. } => name,
        other => panic!("{other}"),
    };
    let bad: [(Box<dyn Planner>, &str); 5] = [
        (tweaked::<RrtAstarBt>(|p| p.step = 0.0), "step"),
        (tweaked::<RrtAstarBt>(|p| p.candidates = 0), "candidates"),
        (tweaked::<RrtAstarRefine>(|p| p.step = f64::NAN), "step"),
        (
            tweaked::<HybridRrtAstar>(|p| p.goal_bias = 1.5),
            "goal_bias",
        ),
        (
            tweaked::<SafeRrtStar>(|p| p.safety_weight = -1.0),
            "safety_weight",
        ),
    ];
    for (planner, name) in bad {
        assert_eq!(
            param(planner.plan(&map, &query, &mut rng).unwrap_err()),
            name
        );
    }
    for (planner, _) in fixtures::all_planners(0) {
        assert_eq!(
            param(planner.plan(&map, &query, &mut rng).unwrap_err()),
            "budget.max_iterations"
        );
    }
    // Start inside an obstacle, goal outside the map.
    for (planner, _) in fixtures::all_planners(100) {
        let bad_start = Query::new(Point2::new(11.5, 5.5), query.goal);
        assert!(matches!(
            planner.plan(&map, &bad_start, &mut rng),
            Err(PlanError::InvalidStart { .. })
        ));
        let bad_goal = Query::new(query.start, Goal::Point(Point2::new(99.0, 5.0)));
        assert!(matches!(
            planner.plan(&map, &bad_goal, &mut rng),
            Err(PlanError::InvalidGoal { .. })
        ));
    }
}

#[test]
fn grid_planners_refuse_other_workspaces_and_the_others_accept_them() {
    let query = Query::new(Point2::new(1.0, 1.0), Goal::Point(Point2::new(19.0, 19.0)));
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    for (planner, _) in fixtures::all_planners(5_000) {
        let result = planner.plan(&OpenSquare(20.0), &query, &mut rng);
        if planner.info().grid_only {
            assert!(matches!(
                result,
                Err(PlanError::InvalidParameter {
                    name: "workspace",
                    ..
                })
            ));
        } else {
            let plan = result.unwrap();
            assert_eq!(plan.path[0], query.start);
            assert_eq!(*plan.path.last().unwrap(), query.goal.center());
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, .. ProptestConfig::default() })]

    /// On random 24 x 24 maps every returned path is valid against the zone its planner
    /// must avoid, and failures are "no path" outcomes, never panics or bad-input errors.
    #[test]
    fn random_maps_give_valid_paths_or_no_path(
        cells in prop::collection::vec(any::<u8>(), 576),
        seed in any::<u64>(),
    ) {
        let mut map = fixtures::random_map(24, 24, 0.12, &cells);
        // Keep start and goal corners free of obstacles and band.
        fixtures::fill(&mut map, 0, 0, 3, 3, Zone::Free);
        fixtures::fill(&mut map, 21, 21, 24, 24, Zone::Free);
        let query = Query::new(Point2::new(1.5, 1.5), Goal::Point(Point2::new(22.5, 22.5)));
        for (planner, ws) in fixtures::planners_on(&map, 3_000) {
            let name = planner.info().name;
            match planner.plan(&ws, &query, &mut ChaCha8Rng::seed_from_u64(seed)) {
                Ok(plan) => assert_valid(&plan, &ws, &query, name),
                Err(e) => prop_assert!(e.is_no_path(), "{}: {}", name, e),
            }
        }
    }
}
