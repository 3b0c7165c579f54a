//! Grid searches on small hand-made maps.

use envmap::GridMap;
use hyplan_core::Zone;
use search::{Connectivity, GridOptions, GridSearch, GridSearchError};

use crate::common::{legal_moves, octile_length};

const SQRT2: f64 = std::f64::consts::SQRT_2;

/// An 8-connected search on `map` that may cut corners.
fn cutting_corners(map: &GridMap) -> GridSearch {
    let options = GridOptions {
        corner_cutting: true,
        ..GridOptions::default()
    };
    GridSearch::new(map, options).unwrap()
}

#[test]
fn no_corner_cutting_by_default() {
    // The tiny.map case of the peers: (0,0)->(1,1) in file coordinates costs 2, because the
    // diagonal would cut the blocked cell beside it.
    let map = GridMap::from_ascii(
        "
        #.
        ..
    ",
    )
    .unwrap();
    let mut s = GridSearch::new(&map, GridOptions::default()).unwrap();
    let p = s.astar((0, 0), (1, 1)).unwrap();
    assert_eq!(p.cost, 2.0);
    assert_eq!(p.cells, vec![(0, 0), (1, 0), (1, 1)]);
    let mut cut = cutting_corners(&map);
    assert_eq!(cut.astar((0, 0), (1, 1)).unwrap().cost, SQRT2);
}

#[test]
fn corner_cutting_never_squeezes_between_two_blocks() {
    let map = GridMap::from_ascii(
        "
        #.
        .#
    ",
    )
    .unwrap();
    let mut cut = cutting_corners(&map);
    assert!(matches!(
        cut.astar((0, 0), (1, 1)),
        Err(GridSearchError::NoPath { .. })
    ));
}

#[test]
fn four_connected_costs_manhattan() {
    let map = GridMap::filled(6, 4, Zone::Free).unwrap();
    let mut s = GridSearch::new(
        &map,
        GridOptions {
            connectivity: Connectivity::Four,
            corner_cutting: false,
        },
    )
    .unwrap();
    let p = s.astar((0, 0), (5, 3)).unwrap();
    assert_eq!(p.cost, 8.0);
    assert!(
        p.cells
            .windows(2)
            .all(|w| w[0].0.abs_diff(w[1].0) + w[0].1.abs_diff(w[1].1) == 1)
    );
    assert_eq!(s.dijkstra((0, 0), (5, 3)).unwrap().cost, 8.0);
}

#[test]
fn octile_on_open_map_and_scratch_reuse() {
    let map = GridMap::filled(20, 10, Zone::Free).unwrap();
    let mut s = GridSearch::new(&map, GridOptions::default()).unwrap();
    for _ in 0..3 {
        let p = s.astar((0, 0), (19, 9)).unwrap();
        assert!((p.cost - (10.0 + 9.0 * SQRT2)).abs() < 1e-12);
        assert!(legal_moves(&map, &p.cells));
        assert!((octile_length(&p.cells) - p.cost).abs() < 1e-12);
        // A* with the octile heuristic on an open map expands little more than the path
        // (rounding in f = g + h can break a few ties the other way).
        assert!((p.stats.expansions as usize) < 2 * p.cells.len());
        let q = s.astar((19, 9), (0, 9)).unwrap();
        assert_eq!(q.cost, 19.0);
    }
}

#[test]
fn unreachable_goal_exhausts_the_reachable_cells() {
    // The left region has 6 free cells; the goal is walled off on the right.
    let map = GridMap::from_ascii(
        "
        ..#..
        ..#..
        ..#..
    ",
    )
    .unwrap();
    let mut s = GridSearch::new(&map, GridOptions::default()).unwrap();
    for r in [s.astar((0, 0), (4, 2)), s.dijkstra((0, 0), (4, 2))] {
        match r {
            Err(GridSearchError::NoPath { stats }) => {
                assert_eq!(stats.expansions, 6);
                assert_eq!(stats.reached, 6);
            }
            other => panic!("{other:?}"),
        }
    }
    match s.theta_star(&map, (0, 0), (4, 2)) {
        Err(GridSearchError::NoPath { stats }) => assert!(stats.expansions >= 6),
        other => panic!("{other:?}"),
    }
}

#[test]
fn bad_cells_are_typed_errors() {
    let map = GridMap::from_ascii(
        "
        .#
        ..
    ",
    )
    .unwrap();
    let mut s = GridSearch::new(&map, GridOptions::default()).unwrap();
    assert!(matches!(
        s.astar((2, 0), (0, 0)),
        Err(GridSearchError::StartOutside { i: 2, .. })
    ));
    assert!(matches!(
        s.astar((0, 0), (0, 5)),
        Err(GridSearchError::GoalOutside { j: 5, .. })
    ));
    assert!(matches!(
        s.astar((1, 1), (0, 0)),
        Err(GridSearchError::StartBlocked { i: 1, j: 1 })
    ));
    assert!(matches!(
        s.dijkstra((0, 0), (1, 1)),
        Err(GridSearchError::GoalBlocked { .. })
    ));
    assert!(s.cost_to_go((1, 1)).is_err());
    let p = s.astar((0, 0), (0, 0)).unwrap();
    assert_eq!((p.cells.clone(), p.cost), (vec![(0, 0)], 0.0));
}

#[test]
fn risk_zone_blocks_only_when_asked() {
    let map = GridMap::from_ascii(
        "
        ...
        .~.
        ...
    ",
    )
    .unwrap();
    let mut s = GridSearch::new(&map, GridOptions::default()).unwrap();
    assert_eq!(s.astar((0, 1), (2, 1)).unwrap().cost, 2.0);
    let safe = map.avoiding_risk();
    let mut s = GridSearch::new(&safe, GridOptions::default()).unwrap();
    let p = s.astar((0, 1), (2, 1)).unwrap();
    assert!(!p.cells.contains(&(1, 1)));
    assert!(p.cost > 2.0);
}

#[test]
fn cost_to_go_matches_point_to_point_dijkstra() {
    let map = GridMap::from_ascii(
        "
        ........
        .######.
        .#....#.
        .#.##.#.
        ...#....
    ",
    )
    .unwrap();
    let mut s = GridSearch::new(&map, GridOptions::default()).unwrap();
    let goal = (4, 2);
    let field = s.cost_to_go(goal).unwrap();
    assert_eq!(field.goal(), goal);
    assert_eq!(field.cost(goal.0, goal.1), Some(0.0));
    assert_eq!(field.next(goal.0, goal.1), None);
    for j in 0..map.height() {
        for i in 0..map.width() {
            let direct = s.dijkstra((i, j), goal);
            match (field.cost(i, j), direct) {
                (Some(c), Ok(p)) => {
                    assert!((c - p.cost).abs() < 1e-9, "({i},{j}): {c} vs {}", p.cost);
                    let cells = field.path_from(i, j).unwrap();
                    assert_eq!(cells.last(), Some(&goal));
                    assert!(legal_moves(&map, &cells));
                    assert!((octile_length(&cells) - c).abs() < 1e-9);
                }
                (None, Err(_)) => {}
                (a, b) => panic!("({i},{j}): field {a:?}, search {b:?}"),
            }
        }
    }
}

#[test]
fn theta_star_goes_straight_where_it_can() {
    let map = GridMap::filled(10, 5, Zone::Free).unwrap();
    let mut s = GridSearch::new(&map, GridOptions::default()).unwrap();
    let p = s.theta_star(&map, (0, 0), (9, 4)).unwrap();
    assert_eq!(p.cells, vec![(0, 0), (9, 4)]);
    assert!((p.cost - 97f64.sqrt()).abs() < 1e-12);
}

#[test]
fn memory_per_cell_is_as_documented() {
    assert_eq!(GridSearch::BYTES_PER_CELL, 14);
}

#[test]
fn update_rereads_the_map_and_refuses_another_size() {
    let mut map = GridMap::filled(5, 3, Zone::Free).unwrap();
    let mut s = GridSearch::new(&map, GridOptions::default()).unwrap();
    assert_eq!(s.astar((0, 1), (4, 1)).unwrap().cost, 4.0);
    for j in 0..3 {
        map.set_cell_zone(2, j, Zone::Forbidden);
    }
    s.update(&map).unwrap();
    assert!(matches!(
        s.astar((0, 1), (4, 1)),
        Err(GridSearchError::NoPath { .. })
    ));
    let other = GridMap::filled(4, 3, Zone::Free).unwrap();
    assert!(matches!(
        s.update(&other),
        Err(GridSearchError::SizeMismatch {
            width: 5,
            got_width: 4,
            ..
        })
    ));
}

/// A deterministic pseudo-random sequence for the tests below.
fn xorshift(mut state: u64) -> impl FnMut(usize) -> usize {
    move |n| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % n as u64) as usize
    }
}

#[test]
fn one_search_answers_many_queries_like_fresh_ones() {
    // 700 queries on one `GridSearch` wrap its generation counter (254 queries) twice;
    // every answer must match a search built for that query alone.
    let map = GridMap::from_ascii(
        "
        ..........#.........
        ..######..#..####...
        ..#.......#.....#...
        ..#..########...#...
        ..#.............#...
        ..##########....#...
        ...........#........
        ####..#....#..#####.
        ......#.............
        ......#######.......
    ",
    )
    .unwrap();
    let mut reused = GridSearch::new(&map, GridOptions::default()).unwrap();
    let mut pick = xorshift(0x5eed);
    let free: Vec<(usize, usize)> = (0..map.height())
        .flat_map(|j| (0..map.width()).map(move |i| (i, j)))
        .filter(|&(i, j)| map.cell_free(i, j))
        .collect();
    for k in 0..700 {
        let (a, b) = (free[pick(free.len())], free[pick(free.len())]);
        let mut fresh = GridSearch::new(&map, GridOptions::default()).unwrap();
        let (got, want) = if k % 2 == 0 {
            (reused.astar(a, b), fresh.astar(a, b))
        } else {
            (reused.dijkstra(a, b), fresh.dijkstra(a, b))
        };
        match (got, want) {
            (Ok(g), Ok(w)) => {
                assert_eq!(g.cost, w.cost, "query {k}: {a:?} -> {b:?}");
                assert_eq!(g.cells, w.cells, "query {k}");
                assert!(legal_moves(&map, &g.cells));
            }
            (Err(g), Err(w)) => assert_eq!(g.to_string(), w.to_string(), "query {k}"),
            (g, w) => panic!("query {k}: {g:?} vs {w:?}"),
        }
    }
}

#[test]
fn large_grids_use_wide_keys_and_stay_optimal() {
    // 800 x 800 (642,404 padded cells) is past the 64-bit keys: the 128-bit path runs.
    // On an open map the optimum is the octile distance; a wall with one gap forces a
    // detour whose length Dijkstra confirms.
    let (w, h) = (800, 800);
    let mut zones = vec![Zone::Free; w * h];
    for j in 0..h - 1 {
        zones[j * w + 400] = Zone::Forbidden;
    }
    let map = GridMap::from_zones(w, h, 1.0, hyplan_core::Point2::new(0.0, 0.0), zones).unwrap();
    let mut s = GridSearch::new(&map, GridOptions::default()).unwrap();
    let octile = |a: (usize, usize), b: (usize, usize)| {
        let (dx, dy) = (a.0.abs_diff(b.0) as f64, a.1.abs_diff(b.1) as f64);
        dx.max(dy) + (SQRT2 - 1.0) * dx.min(dy)
    };
    // Same side of the wall: straight octile distance.
    let p = s.astar((10, 20), (390, 700)).unwrap();
    assert!((p.cost - octile((10, 20), (390, 700))).abs() < 1e-9);
    assert!((octile_length(&p.cells) - p.cost).abs() < 1e-9);
    // Across the wall, through the gap at the top row.
    let (a, b) = ((100, 100), (700, 100));
    let p = s.astar(a, b).unwrap();
    let d = s.dijkstra(a, b).unwrap();
    assert!((p.cost - d.cost).abs() < 1e-9);
    assert!(p.cells.contains(&(400, h - 1)));
    assert!(legal_moves(&map, &p.cells));
    // No corner cutting: the gap cell is entered and left by straight moves.
    let via_gap = octile(a, (399, h - 1)) + 2.0 + octile((401, h - 1), b);
    assert!((p.cost - via_gap).abs() < 1e-9, "{} vs {via_gap}", p.cost);
}
