//! Every planner on random maps: valid paths, determinism, typed errors, budgets.

use envmap::GridMap;
use hyplan_core::{Budget, Goal, PlanError, Planner, Point2, Query, Workspace};
use proptest::prelude::*;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use sampling::{RewireRadius, Rrt, RrtStar};

use crate::fixtures::{SEED_1, all_planners, planners_with};
use crate::random_map::random_map;

/// The path contract: starts at the start bit for bit, ends in the goal region, every
/// segment free, cost = length.
fn assert_valid(map: &GridMap, query: &Query, plan: &hyplan_core::Plan, name: &str) {
    assert_eq!(
        plan.path[0], query.start,
        "{name}: path must start at the start"
    );
    let last = *plan.path.last().unwrap();
    assert!(
        query.goal.contains(last),
        "{name}: {last:?} not in the goal region"
    );
    if let Goal::Point(g) = query.goal {
        assert_eq!(last, g, "{name}: exact goal");
    }
    for w in plan.path.windows(2) {
        assert!(
            map.segment_free(w[0], w[1]),
            "{name}: segment {:?}-{:?} blocked",
            w[0],
            w[1]
        );
    }
    assert!((plan.cost - plan.length()).abs() <= 1e-9 * (1.0 + plan.cost));
    assert!(plan.stats.collision_checks > 0 || plan.path.len() == 1);
    assert_eq!(
        plan.stats.nodes as usize,
        plan.trees.iter().map(|t| t.len()).sum::<usize>(),
        "{name}: nodes counts every tree node"
    );
}

/// Whether a chain of free cells sharing sides joins the start's cell to a cell whose
/// closed square meets the goal disc (a plain breadth-first search, independent of
/// `envmap::connectivity`).
fn connected(map: &GridMap, query: &Query) -> bool {
    let Some(start) = map.world_to_cell(query.start) else {
        return false;
    };
    let (w, h) = (map.width(), map.height());
    let g = query.goal.center();
    let meets = |i: usize, j: usize| {
        let dx = (i as f64 - g.x).max(g.x - (i as f64 + 1.0)).max(0.0);
        let dy = (j as f64 - g.y).max(g.y - (j as f64 + 1.0)).max(0.0);
        dx.hypot(dy) <= query.goal.radius()
    };
    let mut seen = vec![false; w * h];
    let mut queue = std::collections::VecDeque::from([start]);
    seen[start.1 * w + start.0] = true;
    while let Some((i, j)) = queue.pop_front() {
        if meets(i, j) {
            return true;
        }
        for (a, b) in [
            (i.wrapping_sub(1), j),
            (i + 1, j),
            (i, j.wrapping_sub(1)),
            (i, j + 1),
        ] {
            if a < w && b < h && !seen[b * w + a] && map.cell_free(a, b) {
                seen[b * w + a] = true;
                queue.push_back((a, b));
            }
        }
    }
    false
}

/// A grid map that cannot prove disconnection (it hides `Workspace::disconnection`): the
/// planners must then spend their budget.
struct NoProof<'a>(&'a GridMap);

impl Workspace for NoProof<'_> {
    fn bounds(&self) -> hyplan_core::Bounds {
        self.0.bounds()
    }
    fn is_free(&self, p: Point2) -> bool {
        self.0.is_free(p)
    }
    fn segment_free(&self, a: Point2, b: Point2) -> bool {
        self.0.segment_free(a, b)
    }
}

fn free_cells(map: &GridMap) -> Vec<Point2> {
    let mut out = Vec::new();
    for j in 0..map.height() {
        for i in 0..map.width() {
            if map.cell_free(i, j) {
                out.push(map.cell_center(i, j));
            }
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// On random maps every planner returns a valid path or a spent budget, never anything
    /// else, and the same seed gives the same plan bit for bit.
    #[test]
    fn every_planner_gives_valid_deterministic_paths(
        w in 6_usize..24,
        h in 6_usize..24,
        density in 0.0..0.35_f64,
        cells in prop::collection::vec(any::<u8>(), 64..600),
        picks in (any::<prop::sample::Index>(), any::<prop::sample::Index>()),
        radius in prop_oneof![Just(0.0), 0.3..3.0_f64],
        step in 0.5..4.0_f64,
        seed in any::<u64>(),
    ) {
        let map = random_map(w, h, density, &cells);
        let free = free_cells(&map);
        prop_assume!(free.len() >= 2);
        let start = free[picks.0.index(free.len())];
        let goal_center = free[picks.1.index(free.len())];
        let goal = if radius == 0.0 { Goal::Point(goal_center) } else { Goal::disc(goal_center, radius) };
        let query = Query::new(start, goal);
        for planner in all_planners(step, 1_500) {
            let name = planner.info().name;
            let a = planner.plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(seed));
            let b = planner.plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(seed));
            match (&a, &b) {
                (Ok(pa), Ok(pb)) => {
                    assert_valid(&map, &query, pa, name);
                    prop_assert_eq!(&pa.path, &pb.path);
                    prop_assert_eq!(&pa.trees, &pb.trees);
                }
                (Err(PlanError::BudgetExhausted { stats: sa }), Err(PlanError::BudgetExhausted { stats: sb })) => {
                    prop_assert_eq!(sa.iterations, 1_500);
                    prop_assert_eq!(sa.nodes, sb.nodes);
                    prop_assert!(connected(&map, &query), "{}: gave up on a connected query", name);
                }
                // "No path" before the budget only with a proof: the independent flood
                // fill below agrees that start and goal are not connected.
                (Err(PlanError::Disconnected { stats, .. }), Err(PlanError::Disconnected { .. })) => {
                    prop_assert_eq!(stats.iterations, 0);
                    prop_assert!(!connected(&map, &query), "{}: false proof", name);
                }
                _ => prop_assert!(false, "{}: unexpected or non-deterministic result {:?} / {:?}", name, a.as_ref().err(), b.as_ref().err()),
            }
        }
    }

    /// RRT* with the whole budget: more iterations (same seed) never give a longer path.
    #[test]
    fn rrt_star_never_gets_longer(
        cells in prop::collection::vec(any::<u8>(), 400..401),
        density in 0.0..0.25_f64,
        seed in any::<u64>(),
        knn in any::<bool>(),
    ) {
        let map = random_map(20, 20, density, &cells);
        let free = free_cells(&map);
        prop_assume!(free.len() >= 2);
        let query = Query::new(free[0], Goal::disc(*free.last().unwrap(), 1.0));
        let mut last: Option<f64> = None;
        for iterations in [300_u64, 600, 1200, 2400] {
            let planner = RrtStar {
                step: 2.0,
                budget: Budget::iterations(iterations),
                stop_at_first_solution: false,
                rewire: if knn { RewireRadius::KNearest(10) } else { RewireRadius::Auto },
                ..RrtStar::default()
            };
            match planner.plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(seed)) {
                Ok(plan) => {
                    assert_valid(&map, &query, &plan, "rrt-star");
                    if let Some(prev) = last {
                        prop_assert!(plan.cost <= prev + 1e-9, "{} iterations: {} > {}", iterations, plan.cost, prev);
                    }
                    last = Some(plan.cost);
                }
                Err(e) => prop_assert!(last.is_none() && e.is_no_path(), "lost a solution: {e}"),
            }
        }
    }
}

fn open_map() -> GridMap {
    GridMap::from_ascii(
        "
        ..........
        ..........
        ....#.....
        ....#.....
        ..........
        ",
    )
    .unwrap()
}

/// The generic `plan` and the `dyn Planner` one draw the same numbers.
#[test]
fn dyn_planner_matches_generic_plan() {
    let map = open_map();
    let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(9.5, 4.5)));
    let rrt = Rrt::default();
    let generic = rrt
        .plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(SEED_1))
        .unwrap();
    let boxed: Box<dyn Planner> = Box::new(rrt);
    let dynamic = boxed
        .plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(SEED_1))
        .unwrap();
    assert_eq!(generic.path, dynamic.path);
    assert_eq!(generic.trees, dynamic.trees);
}

/// Bad input is a typed error naming the parameter, before any work.
#[test]
fn bad_parameters_are_typed_errors() {
    let map = open_map();
    let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(9.5, 4.5)));
    let mut rng = ChaCha8Rng::seed_from_u64(SEED_1);
    for step in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        for planner in all_planners(step, 100) {
            match planner.plan(&map, &query, &mut rng) {
                Err(PlanError::InvalidParameter { name: "step", .. }) => {}
                other => panic!("{} step {step}: {other:?}", planner.info().name),
            }
        }
    }
    for bias in [-0.1, 1.5, f64::NAN] {
        let biased: [Box<dyn Planner>; 2] = [
            Box::new(Rrt {
                goal_bias: bias,
                ..Rrt::default()
            }),
            Box::new(RrtStar {
                goal_bias: bias,
                ..RrtStar::default()
            }),
        ];
        for planner in biased {
            assert!(matches!(
                planner.plan(&map, &query, &mut rng),
                Err(PlanError::InvalidParameter {
                    name: "goal_bias",
                    ..
                })
            ));
        }
    }
    for planner in all_planners(1.0, 0) {
        assert!(matches!(
            planner.plan(&map, &query, &mut rng),
            Err(PlanError::InvalidParameter {
                name: "budget.max_iterations",
                ..
            })
        ));
    }
    let zero_time = Rrt {
        budget: Budget::iterations(10).with_time(std::time::Duration::ZERO),
        ..Rrt::default()
    };
    assert!(matches!(
        zero_time.plan(&map, &query, &mut rng),
        Err(PlanError::InvalidParameter {
            name: "budget.max_time",
            ..
        })
    ));
    for rewire in [
        RewireRadius::Gamma(0.0),
        RewireRadius::Gamma(f64::NAN),
        RewireRadius::KNearest(0),
    ] {
        let star = RrtStar {
            rewire,
            ..RrtStar::default()
        };
        assert!(matches!(
            star.plan(&map, &query, &mut rng),
            Err(PlanError::InvalidParameter { .. })
        ));
    }
}

#[test]
fn bad_queries_are_typed_errors() {
    let map = open_map();
    let mut rng = ChaCha8Rng::seed_from_u64(SEED_1);
    let goal = Goal::Point(Point2::new(9.5, 4.5));
    let cases = [
        (Query::new(Point2::new(-1.0, 0.5), goal), "start"),
        (Query::new(Point2::new(f64::NAN, 0.5), goal), "start"),
        (Query::new(Point2::new(4.5, 2.5), goal), "start"),
        (
            Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(4.5, 1.5))),
            "goal",
        ),
        (
            Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(10.5, 1.5))),
            "goal",
        ),
        (
            Query::new(
                Point2::new(0.5, 0.5),
                Goal::disc(Point2::new(9.5, 4.5), -1.0),
            ),
            "goal",
        ),
    ];
    for (query, what) in cases {
        for planner in all_planners(1.0, 100) {
            let r = planner.plan(&map, &query, &mut rng);
            let ok = match what {
                "start" => matches!(r, Err(PlanError::InvalidStart { .. })),
                _ => matches!(r, Err(PlanError::InvalidGoal { .. })),
            };
            assert!(ok, "{} {query:?}: {r:?}", planner.info().name);
        }
    }
}

/// A walled-off goal: every planner proves it at once on the grid map, naming the wall;
/// on a workspace that cannot prove it, every planner spends exactly its iteration budget
/// and says so.
#[test]
fn unreachable_goal_spends_the_budget() {
    let map = GridMap::from_ascii(
        "
        ......#...
        ......#...
        ......#...
        ......#...
        ",
    )
    .unwrap();
    let query = Query::new(
        Point2::new(0.5, 0.5),
        Goal::disc(Point2::new(9.5, 3.5), 0.5),
    );
    for planner in all_planners(1.0, 3_000) {
        match planner.plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(SEED_1)) {
            Err(PlanError::Disconnected { cause, stats }) => {
                assert_eq!(cause, hyplan_core::NoPathCause::Wall);
                assert_eq!(stats.iterations, 0);
            }
            other => panic!("{}: {other:?}", planner.info().name),
        }
        let started = std::time::Instant::now();
        match planner.plan(
            &NoProof(&map),
            &query,
            &mut ChaCha8Rng::seed_from_u64(SEED_1),
        ) {
            Err(PlanError::BudgetExhausted { stats }) => {
                assert_eq!(stats.iterations, 3_000, "{}", planner.info().name);
                assert!(stats.nodes > 10);
            }
            other => panic!("{}: {other:?}", planner.info().name),
        }
        assert!(started.elapsed().as_secs_f64() < 5.0);
    }
}

/// A time limit stops an unreachable search about on time.
#[test]
fn time_limit_stops_the_search() {
    let map = GridMap::from_ascii(
        "
        ......#...
        ......#...
        ",
    )
    .unwrap();
    let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(9.5, 1.5)));
    let limit = std::time::Duration::from_millis(100);
    let budget = Budget::iterations(u64::MAX).with_time(limit);
    for planner in planners_with(1.0, budget) {
        let started = std::time::Instant::now();
        let r = planner.plan(
            &NoProof(&map),
            &query,
            &mut ChaCha8Rng::seed_from_u64(SEED_1),
        );
        let took = started.elapsed();
        assert!(matches!(r, Err(PlanError::BudgetExhausted { .. })));
        assert!(
            took >= limit && took < limit * 5,
            "{}: {took:?}",
            planner.info().name
        );
    }
}

/// Start inside the goal region: a one-point path, no work.
#[test]
fn start_in_goal_region() {
    let map = open_map();
    let query = Query::new(
        Point2::new(0.5, 0.5),
        Goal::disc(Point2::new(1.0, 0.5), 1.0),
    );
    for planner in all_planners(1.0, 10) {
        let plan = planner
            .plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(SEED_1))
            .unwrap();
        assert_eq!(plan.path, vec![query.start], "{}", planner.info().name);
    }
}

/// Seed 002's setting: step 1 from an integer point on a grid, many nodes on shared
/// coordinates; no panic, valid path.
#[test]
fn integer_steps_do_not_panic() {
    let map = GridMap::filled(75, 75, hyplan_core::Zone::Free).unwrap();
    let query = Query::new(
        Point2::new(74.0, 74.0),
        Goal::disc(Point2::new(37.0, 15.0), 13.0),
    );
    for goal_bias in [0.25, 1.0] {
        let rrt = Rrt {
            step: 1.0,
            goal_bias,
            budget: Budget::iterations(30_000),
        };
        let plan = rrt
            .plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(SEED_1))
            .unwrap();
        assert_valid(&map, &query, &plan, "rrt");
    }
    let star = RrtStar {
        step: 1.0,
        goal_bias: 1.0,
        ..RrtStar::default()
    };
    let plan = star
        .plan(&map, &query, &mut ChaCha8Rng::seed_from_u64(SEED_1))
        .unwrap();
    assert_valid(&map, &query, &plan, "rrt-star");
}
