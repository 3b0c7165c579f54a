//! Invariants on random grids (proptest).

use envmap::GridMap;
use hyplan_core::{Goal, Point2, Query, Workspace, Zone};
use proptest::prelude::*;
use search::{Connectivity, GridAstar, GridOptions, GridSearch, ThetaStar, astar};

use crate::common::{flipped, legal_moves, octile_length, random_map};

/// A random map (up to 24 x 24, about a third blocked) and two cells.
fn scenario() -> impl Strategy<Value = (GridMap, (usize, usize), (usize, usize))> {
    (2usize..24, 2usize..24).prop_flat_map(|(w, h)| {
        (
            proptest::collection::vec(prop::bool::weighted(0.3), w * h),
            0..w,
            0..h,
            0..w,
            0..h,
        )
            .prop_map(move |(blocked, si, sj, gi, gj)| {
                let zones = blocked
                    .iter()
                    .map(|&b| if b { Zone::Forbidden } else { Zone::Free })
                    .collect();
                let mut map = GridMap::from_zones(w, h, 1.0, Point2::origin(), zones).unwrap();
                map.set_cell_zone(si, sj, Zone::Free);
                map.set_cell_zone(gi, gj, Zone::Free);
                (map, (si, sj), (gi, gj))
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn astar_equals_dijkstra_and_moves_are_legal((map, s, g) in scenario(), four in any::<bool>()) {
        let options = GridOptions {
            connectivity: if four { Connectivity::Four } else { Connectivity::Eight },
            corner_cutting: false,
        };
        let mut search = GridSearch::new(&map, options).unwrap();
        let a = search.astar(s, g);
        let d = search.dijkstra(s, g);
        match (&a, &d) {
            (Ok(a), Ok(d)) => {
                prop_assert!((a.cost - d.cost).abs() < 1e-9, "A* {} Dijkstra {}", a.cost, d.cost);
                if !four {
                    prop_assert!(legal_moves(&map, &a.cells));
                    prop_assert!((octile_length(&a.cells) - a.cost).abs() < 1e-9);
                }
                prop_assert_eq!(a.cells.first(), Some(&s));
                prop_assert_eq!(a.cells.last(), Some(&g));
            }
            (Err(_), Err(_)) => {}
            _ => prop_assert!(false, "A* {:?} vs Dijkstra {:?}", a, d),
        }
    }

    #[test]
    fn grid_astar_matches_generic_astar((map, s, g) in scenario()) {
        let mut search = GridSearch::new(&map, GridOptions::default()).unwrap();
        let grid = search.astar(s, g).ok().map(|p| p.cost);
        let (w, h) = (map.width() as i64, map.height() as i64);
        let free = |i: i64, j: i64| i >= 0 && j >= 0 && i < w && j < h && map.cell_free(i as usize, j as usize);
        let generic = astar(
            &(s.0 as i64, s.1 as i64),
            |&(i, j)| {
                let mut v = Vec::new();
                for (di, dj) in [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)] {
                    let ok = free(i + di, j + dj) && (di == 0 || dj == 0 || (free(i + di, j) && free(i, j + dj)));
                    if ok {
                        v.push(((i + di, j + dj), if di != 0 && dj != 0 { std::f64::consts::SQRT_2 } else { 1.0 }));
                    }
                }
                v
            },
            |_| 0.0,
            |&(i, j)| (i as usize, j as usize) == g,
        ).ok().map(|r| r.cost);
        match (grid, generic) {
            (Some(a), Some(b)) => prop_assert!((a - b).abs() < 1e-9),
            (None, None) => {}
            other => prop_assert!(false, "{:?}", other),
        }
    }

    #[test]
    fn any_angle_paths_are_free_and_cost_their_length((map, s, g) in scenario()) {
        let mut search = GridSearch::new(&map, GridOptions::default()).unwrap();
        let a = search.astar(s, g).ok().map(|p| p.cost);
        // Both variants must find a path exactly when A* does; Theta* is also held to be
        // no longer than A*, Lazy Theta* is not.
        for (name, lazy, weight) in [("Theta*", false, 1.0), ("Lazy Theta*", true, 1.0), ("weighted Lazy Theta*", true, 1.3)] {
            let t = match (lazy, weight) {
                (false, _) => search.theta_star(&map, s, g),
                (true, 1.0) => search.lazy_theta_star(&map, s, g),
                (true, w) => search.lazy_theta_star_weighted(&map, s, g, w),
            };
            let (t, a) = match (t, a) {
                (Ok(t), Some(a)) => (t, a),
                (Err(_), None) => continue,
                (t, a) => return Err(TestCaseError::fail(format!("{name} {t:?} vs A* {a:?}"))),
            };
            prop_assert_eq!(t.cells.first(), Some(&s));
            prop_assert_eq!(t.cells.last(), Some(&g));
            let mut length = 0.0;
            for w in t.cells.windows(2) {
                let (p, q) = (map.cell_center(w[0].0, w[0].1), map.cell_center(w[1].0, w[1].1));
                prop_assert!(map.segment_free(p, q), "{} {:?}", name, w);
                length += (q - p).norm();
            }
            prop_assert!((length - t.cost).abs() < 1e-6, "{} length {} cost {}", name, length, t.cost);
            prop_assert!(lazy || t.cost <= a + 1e-9, "{} {} > A* {}", name, t.cost, a);
        }
        // Weight 1 is Lazy Theta* itself.
        let plain = search.lazy_theta_star(&map, s, g).ok().map(|p| p.cells);
        let one = search.lazy_theta_star_weighted(&map, s, g, 1.0).ok().map(|p| p.cells);
        prop_assert_eq!(&plain, &one);
        // A search whose lines of sight were prepared first answers as one that made them
        // in its first query.
        let mut prepared = GridSearch::new(&map, GridOptions::default()).unwrap();
        prepared.prepare_lines_of_sight(&map);
        prop_assert_eq!(prepared.lazy_theta_star(&map, s, g).ok().map(|p| p.cells), plain);
    }

    #[test]
    fn planner_paths_pass_segment_free((map, s, g) in scenario(), dx in 0.05f64..0.95, dy in 0.05f64..0.95) {
        let start = Point2::new(s.0 as f64 + dx, s.1 as f64 + dy);
        let goal = Point2::new(g.0 as f64 + 1.0 - dx, g.1 as f64 + 1.0 - dy);
        let query = Query::new(start, Goal::Point(goal));
        for plan in [
            GridAstar::default().plan(&map, &query, &mut rand::rng()),
            ThetaStar::default().plan(&map, &query, &mut rand::rng()),
        ].into_iter().flatten() {
            prop_assert_eq!(plan.path.first(), Some(&start));
            prop_assert_eq!(plan.path.last(), Some(&goal));
            for w in plan.path.windows(2) {
                prop_assert!(map.segment_free(w[0], w[1]), "{:?}", w);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// A search brought up to date by `update_window` over the changed cells answers
    /// every later query as one built afresh on the changed map; `connected` says
    /// whether Dijkstra finds a path.
    #[test]
    fn update_window_and_connected_agree_with_a_fresh_search(
        (map, s, g) in scenario(),
        flips in proptest::collection::vec((0usize..24, 0usize..24), 1..12),
        corner_cutting in any::<bool>(),
        four in any::<bool>(),
    ) {
        let options = GridOptions {
            connectivity: if four { Connectivity::Four } else { Connectivity::Eight },
            corner_cutting,
        };
        let mut kept = GridSearch::new(&map, options).unwrap();
        // A first query leaves words of an older generation behind.
        let _ = kept.dijkstra(s, g);
        let (changed, columns, rows) = flipped(&map, &flips, &[]);
        kept.update_window(&changed, columns, rows).unwrap();
        let mut fresh = GridSearch::new(&changed, options).unwrap();
        let (a, b) = (kept.dijkstra(s, g), fresh.dijkstra(s, g));
        prop_assert_eq!(a.as_ref().ok().map(|p| (&p.cells, p.cost)), b.as_ref().ok().map(|p| (&p.cells, p.cost)));
        prop_assert_eq!(kept.astar(g, s).map(|p| p.cells), fresh.astar(g, s).map(|p| p.cells));
        match kept.connected(s, g) {
            Ok(joined) => prop_assert_eq!(joined, b.is_ok(), "connected {} vs Dijkstra {:?}", joined, b),
            Err(_) => prop_assert!(b.is_err()),
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Dijkstra bounded by any cost at least the optimum finds Dijkstra's own path, cell
    /// for cell, under every move rule, on open maps (the most ties between equal
    /// costs) to cluttered ones; bounded below the optimum it finds none. Fails when a
    /// cell within the bound is left out, or one beyond it is taken as a path cell.
    #[test]
    fn dijkstra_within_a_bound_keeps_dijkstras_path(
        (w, h, density) in (2usize..40, 2usize..40, 0.0f64..0.4),
        seed in any::<u64>(),
        (si, sj, gi, gj) in (0usize..40, 0usize..40, 0usize..40, 0usize..40),
        (four, corner_cutting) in (any::<bool>(), any::<bool>()),
        extra in prop_oneof![Just(0.0), 0.0f64..3.0],
    ) {
        let (s, g) = ((si % w, sj % h), (gi % w, gj % h));
        let map = random_map(w, h, density, seed, &[s, g]);
        let options = GridOptions {
            connectivity: if four { Connectivity::Four } else { Connectivity::Eight },
            corner_cutting,
        };
        let mut search = GridSearch::new(&map, options).unwrap();
        let Ok(full) = search.dijkstra(s, g) else {
            prop_assert!(search.dijkstra_within(s, g, f64::INFINITY).is_err());
            return Ok(());
        };
        let within = search.dijkstra_within(s, g, full.cost + extra).unwrap();
        prop_assert_eq!(&within.cells, &full.cells);
        prop_assert_eq!(within.cost, full.cost);
        prop_assert!(within.stats.expansions <= full.stats.expansions);
        if full.cost > 0.0 {
            prop_assert!(search.dijkstra_within(s, g, full.cost - 0.01).is_err());
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// On maps wider than a word of the connectivity flood's bit rows (runs crossing
    /// words, from sparse to dense obstacles), `connected` says whether Dijkstra finds a
    /// path, before and after a change brought in by `update_window`.
    #[test]
    fn connected_agrees_with_dijkstra_on_wide_maps(
        (w, h, density) in (60usize..200, 2usize..14, 0.02f64..0.5),
        seed in any::<u64>(),
        (si, sj, gi, gj) in (0usize..200, 0usize..14, 0usize..200, 0usize..14),
        flips in proptest::collection::vec((0usize..200, 0usize..14), 1..40),
    ) {
        let (s, g) = ((si % w, sj % h), (gi % w, gj % h));
        let map = random_map(w, h, density, seed, &[s, g]);
        let mut kept = GridSearch::new(&map, GridOptions::default()).unwrap();
        prop_assert_eq!(kept.connected(s, g).unwrap(), kept.dijkstra(s, g).is_ok());
        prop_assert_eq!(kept.connected(g, s).unwrap(), kept.dijkstra(s, g).is_ok());
        let (changed, columns, rows) = flipped(&map, &flips, &[s, g]);
        if !columns.is_empty() {
            kept.update_window(&changed, columns, rows).unwrap();
        }
        let mut fresh = GridSearch::new(&changed, GridOptions::default()).unwrap();
        prop_assert_eq!(kept.connected(s, g).unwrap(), fresh.dijkstra(s, g).is_ok());
    }
}

/// One random query on `w x h`: (start, goal) cells from `k`.
fn cell_query(map: &GridMap, (a, b, c, d): (usize, usize, usize, usize)) -> Query {
    let (w, h) = (map.width(), map.height());
    let at = |i: usize, j: usize| map.cell_center(i % w, j % h);
    Query::new(at(a, b), Goal::Point(at(c, d)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Plans through the `Planner` trait on one map, which keeps each planner's prepared
    /// search between calls (and drops it when a zone changes or is given another
    /// `blocked_from`), equal plans on a fresh copy of the map each time: what a call
    /// leaves behind never changes the next one's answer.
    #[test]
    fn a_kept_search_plans_as_a_fresh_one(
        (map, _, _) in scenario(),
        steps in proptest::collection::vec(
            (0u8..5, (0usize..24, 0usize..24, 0usize..24, 0usize..24), 0u8..4, any::<bool>(), (0usize..24, 0usize..24)),
            1..12,
        ),
    ) {
        use hyplan_core::Planner;
        use search::{GridDijkstra, Jps, LazyThetaStar};
        let mut map = map;
        let mut rng = rand::rng();
        for (which, cells, change, toggle, (ci, cj)) in steps {
            // Now and then the map changes between plans: a cell, or what blocks.
            match change {
                0 => {
                    let (i, j) = (ci % map.width(), cj % map.height());
                    let zone = if map.cell_zone(i, j) == Zone::Free { Zone::Forbidden } else { Zone::Free };
                    map.set_cell_zone(i, j, zone);
                }
                1 if toggle => map.set_cell_zone(ci % map.width(), cj % map.height(), Zone::Risk),
                2 => map.blocked_from = if toggle { Zone::Risk } else { Zone::Forbidden },
                _ => {}
            }
            let planner: Box<dyn Planner> = match which {
                0 => Box::new(GridAstar::default()),
                1 => Box::new(GridDijkstra::default()),
                2 => Box::new(Jps::default()),
                3 => Box::new(LazyThetaStar::default()),
                _ => Box::new(ThetaStar::default()),
            };
            if toggle {
                let _ = planner.prepare(&map);
            }
            let query = cell_query(&map, cells);
            let kept = planner.plan(&map, &query, &mut rng).map(|p| p.path).map_err(|e| e.to_string());
            let fresh = planner.plan(&map.clone(), &query, &mut rng).map(|p| p.path).map_err(|e| e.to_string());
            // The error texts carry elapsed times; their kind is what must agree.
            match (&kept, &fresh) {
                (Ok(a), Ok(b)) => prop_assert_eq!(a, b),
                (Err(a), Err(b)) => prop_assert_eq!(a.split(':').next(), b.split(':').next()),
                _ => prop_assert!(false, "kept {:?} fresh {:?}", kept, fresh),
            }
        }
    }
}
