//! Jump point search: A*'s costs on random grids (proptest), hand cases, MovingAI maps.

use envmap::GridMap;
use hyplan_core::{Goal, PlanError, Point2, Query, Zone};
use proptest::prelude::*;
use search::{
    Connectivity, GridAstar, GridOptions, GridSearch, GridSearchError, Jps, JpsError,
    JumpPointSearch, ScenEntry, read_scen,
};

use crate::common::{data_dir, flipped, legal_moves, load_movingai, octile_length, peer_maps_dir};

/// Start and goal cells.
type Pair = ((usize, usize), (usize, usize));

/// A random `w x h` map with obstacle density `density` and `queries` pairs of free cells.
fn scenario(
    widths: std::ops::Range<usize>,
    heights: std::ops::Range<usize>,
    density: f64,
) -> impl Strategy<Value = (GridMap, Vec<Pair>)> {
    (widths, heights).prop_flat_map(move |(w, h)| {
        (
            proptest::collection::vec(prop::bool::weighted(density), w * h),
            proptest::collection::vec((0..w, 0..h, 0..w, 0..h), 1..6),
        )
            .prop_map(move |(blocked, queries)| {
                let zones = blocked
                    .iter()
                    .map(|&b| if b { Zone::Forbidden } else { Zone::Free })
                    .collect();
                let mut map = GridMap::from_zones(w, h, 1.0, Point2::origin(), zones).unwrap();
                let queries: Vec<_> = queries
                    .into_iter()
                    .map(|(si, sj, gi, gj)| ((si, sj), (gi, gj)))
                    .collect();
                for &(s, g) in &queries {
                    map.set_cell_zone(s.0, s.1, Zone::Free);
                    map.set_cell_zone(g.0, g.1, Zone::Free);
                }
                (map, queries)
            })
    })
}

/// Runs every query with JPS (one prepared search, reused) and A*; checks that they agree
/// on whether a path exists and on its cost, and that JPS's path is legal.
fn agree(map: &GridMap, queries: &[Pair]) -> Result<(), TestCaseError> {
    let mut astar = GridSearch::new(map, GridOptions::default()).unwrap();
    let mut jps = JumpPointSearch::new(map, GridOptions::default()).unwrap();
    for &(s, g) in queries {
        let a = astar.astar(s, g);
        let j = jps.search(s, g);
        match (&a, &j) {
            (Ok(a), Ok(j)) => {
                prop_assert!(
                    (a.cost - j.cost).abs() <= 1e-9 * a.cost.max(1.0),
                    "{s:?} -> {g:?}: A* {} JPS {}",
                    a.cost,
                    j.cost
                );
                prop_assert!(legal_moves(map, &j.cells), "{s:?} -> {g:?}: {:?}", j.cells);
                prop_assert!((octile_length(&j.cells) - j.cost).abs() < 1e-9);
                prop_assert_eq!(j.cells.first(), Some(&s));
                prop_assert_eq!(j.cells.last(), Some(&g));
            }
            (Err(GridSearchError::NoPath { .. }), Err(GridSearchError::NoPath { .. })) => {}
            _ => prop_assert!(false, "{s:?} -> {g:?}: A* {a:?} vs JPS {j:?}"),
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn jps_finds_astars_cost_on_small_random_grids(
        (map, queries) in scenario(1..24, 1..24, 0.3),
    ) {
        agree(&map, &queries)?;
    }

    /// Wider than a word: the scans cross 64-bit boundaries both ways, in rows and
    /// columns.
    #[test]
    fn jps_finds_astars_cost_on_wide_sparse_grids(
        (map, queries) in scenario(60..200, 60..140, 0.08),
    ) {
        agree(&map, &queries)?;
    }

    /// Nearly open and wider than a word: the diagonal jumps' straight scans run past the
    /// windows they carry from step to step and go on block by block, both ways.
    #[test]
    fn jps_finds_astars_cost_on_open_wide_grids(
        (map, queries) in scenario(64..300, 64..200, 0.01),
    ) {
        agree(&map, &queries)?;
    }

    #[test]
    fn jps_finds_astars_cost_on_dense_grids(
        (map, queries) in scenario(20..90, 20..90, 0.4),
    ) {
        agree(&map, &queries)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// A search brought up to date by `update_window` answers as one built on the
    /// changed map: cells flipped both ways, in a window that crosses the bit lines'
    /// words. Fails when a newly blocked cell is left free in the rows or the columns.
    #[test]
    fn an_updated_window_answers_as_a_fresh_search(
        (map, queries) in scenario(60..150, 20..80, 0.15),
        flips in proptest::collection::vec((0usize..150, 0usize..80), 1..60),
    ) {
        let mut kept = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
        let (changed, columns, rows) = flipped(&map, &flips, &[]);
        kept.update_window(&changed, columns, rows).unwrap();
        let mut fresh = JumpPointSearch::new(&changed, GridOptions::default()).unwrap();
        for &(s, g) in &queries {
            prop_assert_eq!(kept.search(s, g), fresh.search(s, g));
        }
    }
}

fn ascii(text: &str) -> GridMap {
    GridMap::from_ascii(text).unwrap()
}

#[test]
fn open_grid_expands_few_jump_points() {
    let map = GridMap::filled(300, 200, Zone::Free).unwrap();
    let mut jps = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
    let p = jps.search((3, 5), (290, 180)).unwrap();
    let (dx, dy) = (287.0, 175.0);
    assert!((p.cost - (dx - dy + dy * std::f64::consts::SQRT_2)).abs() < 1e-9);
    assert_eq!(p.cells.len(), 288);
    assert!(legal_moves(&map, &p.cells));
    assert!(p.stats.expansions <= 2, "{:?}", p.stats);
}

#[test]
fn corridor_and_turns() {
    let map = ascii(
        "
        ..........
        #########.
        ..........
        .#########
        ..........
        ",
    );
    let mut jps = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
    let a = GridSearch::new(&map, GridOptions::default())
        .unwrap()
        .astar((0, 4), (9, 0))
        .unwrap();
    let p = jps.search((0, 4), (9, 0)).unwrap();
    assert_eq!(p.cost, a.cost);
    assert!(legal_moves(&map, &p.cells));
    assert_eq!(p.cells.first(), Some(&(0, 4)));
    assert_eq!(p.cells.last(), Some(&(9, 0)));
}

#[test]
fn no_path_is_an_error_with_stats() {
    let map = ascii(
        "
        ..#..
        ..#..
        ..#..
        ",
    );
    let mut jps = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
    let e = jps.search((0, 0), (4, 2)).unwrap_err();
    assert!(matches!(e, GridSearchError::NoPath { stats } if stats.expansions >= 1));
    // Two cells meeting at a corner do not let a diagonal through.
    let map = ascii(
        "
        .#
        #.
        ",
    );
    let mut jps = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
    assert!(matches!(
        jps.search((0, 1), (1, 0)),
        Err(GridSearchError::NoPath { .. })
    ));
}

#[test]
fn start_equals_goal() {
    let map = ascii("...\n...\n");
    let mut jps = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
    let p = jps.search((1, 1), (1, 1)).unwrap();
    assert_eq!(p.cells, vec![(1, 1)]);
    assert_eq!(p.cost, 0.0);
    assert_eq!(p.stats.expansions, 0);
}

#[test]
fn bad_start_and_goal_are_typed_errors() {
    let map = ascii(
        "
        .#.
        ...
        ",
    );
    let mut jps = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
    assert_eq!(
        jps.search((1, 1), (0, 0)),
        Err(GridSearchError::StartBlocked { i: 1, j: 1 })
    );
    assert_eq!(
        jps.search((0, 0), (1, 1)),
        Err(GridSearchError::GoalBlocked { i: 1, j: 1 })
    );
    assert!(matches!(
        jps.search((3, 0), (0, 0)),
        Err(GridSearchError::StartOutside { i: 3, .. })
    ));
    assert!(matches!(
        jps.search((0, 0), (0, 2)),
        Err(GridSearchError::GoalOutside { j: 2, .. })
    ));
}

#[test]
fn other_move_rules_are_refused_naming_astar() {
    let map = ascii("...\n");
    for options in [
        GridOptions {
            connectivity: Connectivity::Four,
            corner_cutting: false,
        },
        GridOptions {
            connectivity: Connectivity::Eight,
            corner_cutting: true,
        },
    ] {
        let e = JumpPointSearch::new(&map, options).unwrap_err();
        assert!(matches!(e, JpsError::NotApplicable { .. }));
        assert!(e.to_string().contains("astar"), "{e}");
        let planner = Jps {
            options,
            ..Jps::default()
        };
        let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(2.5, 0.5)));
        let e = planner.plan(&map, &query, &mut rand::rng()).unwrap_err();
        assert!(
            matches!(
                e,
                PlanError::InvalidParameter {
                    name: "options",
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains("astar"), "{e}");
    }
}

#[test]
fn planner_matches_grid_astar() {
    let map = ascii(
        "
        ........
        .######.
        ......#.
        .####.#.
        ........
        ",
    );
    let query = Query::new(Point2::new(0.5, 0.5), Goal::Point(Point2::new(5.5, 2.5)));
    let j = Jps::default().plan(&map, &query, &mut rand::rng()).unwrap();
    let a = GridAstar::default()
        .plan(&map, &query, &mut rand::rng())
        .unwrap();
    assert!((j.cost - a.cost).abs() < 1e-9);
    assert_eq!(j.path.first(), Some(&query.start));
    assert_eq!(j.path.last(), Some(&Point2::new(5.5, 2.5)));
    assert!(j.stats.expansions <= a.stats.expansions);
}

/// Every scenario of a MovingAI pair: JPS's cost is A*'s (and the `.scen`'s), and JPS
/// expands fewer nodes in total.
fn movingai_agrees(map_path: &std::path::Path, scen_path: &std::path::Path) {
    let map = load_movingai(map_path);
    let scen = read_scen(scen_path).unwrap();
    let mut astar = GridSearch::new(&map, GridOptions::default()).unwrap();
    let mut jps = JumpPointSearch::new(&map, GridOptions::default()).unwrap();
    let (mut astar_expanded, mut jps_expanded) = (0, 0);
    for (id, s) in scen.iter().enumerate() {
        let start = ScenEntry::to_cell(s.start, map.height()).unwrap();
        let goal = ScenEntry::to_cell(s.goal, map.height()).unwrap();
        let a = astar.astar(start, goal).unwrap();
        let j = jps.search(start, goal).unwrap();
        assert!(
            (a.cost - j.cost).abs() <= 1e-9 * a.cost.max(1.0),
            "scenario {id}: A* {} JPS {}",
            a.cost,
            j.cost
        );
        assert!((j.cost - s.optimal).abs() <= f64::max(1e-3, 1e-5 * s.optimal));
        assert!(legal_moves(&map, &j.cells), "scenario {id}: illegal move");
        assert_eq!(j.cells.first(), Some(&start));
        assert_eq!(j.cells.last(), Some(&goal));
        astar_expanded += a.stats.expansions;
        jps_expanded += j.stats.expansions;
    }
    assert!(
        jps_expanded < astar_expanded,
        "JPS {jps_expanded} expansions, A* {astar_expanded}"
    );
}

#[test]
fn arena_scenarios_agree_with_fewer_expansions() {
    let dir = data_dir().join("movingai");
    movingai_agrees(&dir.join("arena.map"), &dir.join("arena.map.scen"));
}

#[test]
fn peers_maze_scenarios_agree() {
    let dir = peer_maps_dir();
    movingai_agrees(&dir.join("maze.map"), &dir.join("maze.scen"));
}

/// A map large enough for the open list's wide (`u128`) keys: random queries agree with
/// A*.
#[test]
fn large_map_agrees_with_astar() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(crate::common::SEED);
    let (w, h) = (900, 700);
    let zones = (0..w * h)
        .map(|_| {
            if rng.random_bool(0.15) {
                Zone::Forbidden
            } else {
                Zone::Free
            }
        })
        .collect();
    let mut map = GridMap::from_zones(w, h, 1.0, Point2::origin(), zones).unwrap();
    let mut queries = Vec::new();
    for _ in 0..6 {
        let s = (rng.random_range(0..w), rng.random_range(0..h));
        let g = (rng.random_range(0..w), rng.random_range(0..h));
        map.set_cell_zone(s.0, s.1, Zone::Free);
        map.set_cell_zone(g.0, g.1, Zone::Free);
        queries.push((s, g));
    }
    agree(&map, &queries).unwrap();
}
