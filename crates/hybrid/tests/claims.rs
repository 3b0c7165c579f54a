//! The papers' qualitative claims, each on a map of its paper's kind, as means over at
//! least 100 fixed seeds. The measured numbers are printed (`cargo test -p hybrid --
//! --nocapture claims`) and recorded in `docs/papers/00{0,1,2,3}-*.md`, "What we
//! measured".

use envmap::GridMap;
use hybrid::{HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{Budget, Goal, Point2, Query, Zone};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use sampling::{RewireRadius, Rrt, RrtStar};

use crate::fixtures::mean;
use crate::room::{Room, room};

const RUNS: u64 = 100;

fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(0xc1a1_0000 + seed)
}

/// Seed 000 (Tables 2 and 3): RRT-A*-BT gives a shorter path with fewer path nodes than
/// plain RRT (same step 40 px, goal joined from within one step, no goal bias, same safe map,
/// raw path), on the 960 x 640 room of Table 2.
#[test]
fn seed000_rrt_astar_bt_shorter_with_fewer_nodes_than_rrt() {
    let Room {
        safe,
        start,
        goal,
        query,
        ..
    } = room().unwrap();
    let bt = RrtAstarBt::default();
    let rrt = Rrt {
        step: 40.0,
        goal_bias: 0.0,
        budget: Budget::iterations(10_000),
    };
    let (mut bt_len, mut bt_path_nodes, mut bt_tree) = (vec![], vec![], vec![]);
    let (mut repairs, mut refused) = (0, 0);
    let (mut rrt_len, mut rrt_path_nodes, mut rrt_tree) = (vec![], vec![], vec![]);
    for seed in 0..RUNS {
        let s = bt.plan_detailed(&safe, &query, &mut rng(seed)).unwrap();
        bt_len.push(s.plan.length());
        bt_path_nodes.push((s.reduced.len() - 2) as f64);
        bt_tree.push(s.plan.stats.nodes as f64);
        repairs += s.smoothing_repairs;
        refused += usize::from(s.smoothing_refused);
        let p = rrt.plan(&safe, &query, &mut rng(seed)).unwrap();
        rrt_len.push(p.length());
        rrt_path_nodes.push((p.path.len() - 2) as f64);
        rrt_tree.push(p.stats.nodes as f64);
    }
    eprintln!(
        "seed 000 room, {RUNS} runs: RRT-A*-BT length {:.1} px, path nodes {:.1}, tree {:.1}; \
         {repairs} PCHIP repairs, {refused} refused; RRT length {:.1} px, path nodes {:.1}, \
         tree {:.1}; straight {:.1}",
        mean(&bt_len),
        mean(&bt_path_nodes),
        mean(&bt_tree),
        mean(&rrt_len),
        mean(&rrt_path_nodes),
        mean(&rrt_tree),
        (goal - start).norm()
    );
    assert!(mean(&bt_len) < mean(&rrt_len));
    // The paper's "nodes" are the path's nodes (Table 2: 20 nodes, 21 segments).
    assert!(mean(&bt_path_nodes) < mean(&rrt_path_nodes));
    // Not claimed, and it does not hold: A* order explores more of the room than RRT does
    // (measured: 830.8 tree nodes against 205.8 for RRT, 100 runs).
}

/// Rasterises the seed-001 reconstruction (docs/papers/001, 3.2): 100 x 100 cells, eight
/// obstacles; a cell is occupied when the shape overlaps it (rectangles, circles) or
/// holds its centre (polygons).
fn grid100() -> GridMap {
    let mut map = GridMap::filled(100, 100, Zone::Free).unwrap();
    let rects = [
        (20, 10, 35, 40),
        (45, 30, 55, 70),
        (65, 60, 90, 68),
        (60, 80, 70, 95),
    ];
    let circles = [((30.0, 65.0), 8.0), ((75.0, 30.0), 10.0)];
    let polys: [&[(f64, f64)]; 2] = [
        &[
            (10.0, 75.0),
            (25.0, 75.0),
            (25.0, 80.0),
            (15.0, 80.0),
            (15.0, 95.0),
            (10.0, 95.0),
        ],
        &[(78.0, 40.0), (92.0, 40.0), (85.0, 52.0)],
    ];
    let inside = |poly: &[(f64, f64)], x: f64, y: f64| {
        let mut c = false;
        let n = poly.len();
        for k in 0..n {
            let (a, b) = (poly[k], poly[(k + n - 1) % n]);
            if (a.1 > y) != (b.1 > y) && x < (b.0 - a.0) * (y - a.1) / (b.1 - a.1) + a.0 {
                c = !c;
            }
        }
        c
    };
    for j in 0..100 {
        for i in 0..100 {
            let (x, y) = (i as f64, j as f64);
            let rect = rects
                .iter()
                .any(|&(x0, y0, x1, y1)| i >= x0 && i < x1 && j >= y0 && j < y1);
            let circle = circles.iter().any(|&((cx, cy), r)| {
                let dx = (cx - (x + 0.5)).abs() - 0.5;
                let dy = (cy - (y + 0.5)).abs() - 0.5;
                dx.max(0.0).hypot(dy.max(0.0)) < r
            });
            let poly = polys.iter().any(|p| inside(p, x + 0.5, y + 0.5));
            if rect || circle || poly {
                map.set_cell_zone(i, j, Zone::Forbidden);
            }
        }
    }
    map
}

/// Seed 001 (section 4): the hybrid's mean length is below plain RRT's and its mean turn
/// count (> 10 degrees) is lower, on the 100 x 100 grid.
#[test]
fn seed001_refined_paths_shorter_with_fewer_turns_than_rrt() {
    let map = grid100();
    let query = Query::new(Point2::new(5.0, 5.0), Goal::Point(Point2::new(95.0, 95.0)));
    let hybrid = RrtAstarRefine::default();
    let rrt = Rrt {
        step: 3.0,
        goal_bias: 0.05,
        budget: Budget::iterations(10_000),
    };
    let turns = |p: &[Point2]| postproc::count_turns(p, 10f64.to_radians()) as f64;
    let (mut h_len, mut h_turns, mut r_len, mut r_turns) = (vec![], vec![], vec![], vec![]);
    let mut runs = 0;
    for seed in 0..RUNS {
        let s = hybrid.plan_detailed(&map, &query, &mut rng(seed)).unwrap();
        h_len.push(s.plan.length());
        h_turns.push(turns(&s.plan.path));
        runs += s.astar_runs;
        let p = rrt.plan(&map, &query, &mut rng(seed)).unwrap();
        r_len.push(p.length());
        r_turns.push(turns(&p.path));
    }
    eprintln!(
        "seed 001 grid, {RUNS} runs: hybrid length {:.2}, turns {:.2} ({runs} A* stretches); \
         RRT length {:.2}, turns {:.2}",
        mean(&h_len),
        mean(&h_turns),
        mean(&r_len),
        mean(&r_turns)
    );
    assert!(mean(&h_len) < mean(&r_len));
    assert!(mean(&h_turns) < mean(&r_turns));
}

/// Seed 002's Map-1 reconstruction (docs/papers/002, 3.4): 75 x 75 cells, 18 rectangles
/// (x, y, w, h), each padded by one cell (3 x 3 dilation).
fn map1() -> GridMap {
    let rects: [(usize, usize, usize, usize); 18] = [
        (30, 22, 13, 2),
        (27, 10, 2, 12),
        (33, 12, 2, 2),
        (40, 17, 2, 2),
        (44, 8, 3, 3),
        (60, 60, 5, 4),
        (50, 66, 4, 5),
        (64, 45, 6, 3),
        (52, 50, 3, 6),
        (40, 55, 5, 5),
        (25, 60, 6, 4),
        (10, 50, 4, 6),
        (15, 35, 5, 3),
        (55, 30, 4, 4),
        (62, 20, 3, 7),
        (40, 38, 7, 3),
        (8, 15, 4, 4),
        (20, 5, 3, 3),
    ];
    let mut map = GridMap::filled(75, 75, Zone::Free).unwrap();
    for (x, y, w, h) in rects {
        let (x0, y0) = (x.saturating_sub(1), y.saturating_sub(1));
        crate::fixtures::fill(
            &mut map,
            x0,
            y0,
            (x + w + 1).min(75),
            (y + h + 1).min(75),
            Zone::Forbidden,
        );
    }
    map
}

/// Seed 002 (Table I): the hybrid visits fewer nodes (tree + sub-search expansions) than
/// plain RRT with step 1 and goal bias 0.25.
#[test]
fn seed002_hybrid_visits_fewer_nodes_than_rrt() {
    let map = map1();
    let query = Query::new(
        Point2::new(74.5, 74.5),
        Goal::Point(Point2::new(37.5, 15.5)),
    );
    let hybrid = HybridRrtAstar::default();
    let rrt = Rrt {
        step: 1.0,
        goal_bias: 0.25,
        budget: Budget::iterations(30_000),
    };
    let (mut h_nodes, mut r_nodes) = (vec![], vec![]);
    let (mut runs, mut gave_up, mut h_ok, mut r_ok) = (0, 0, 0, 0);
    for seed in 0..RUNS {
        if let Ok(s) = hybrid.plan_detailed(&map, &query, &mut rng(seed)) {
            h_nodes.push(s.plan.stats.nodes as f64);
            runs += s.astar_runs;
            gave_up += s.astar_failures;
            h_ok += 1;
        }
        if let Ok(p) = rrt.plan(&map, &query, &mut rng(seed)) {
            r_nodes.push(p.stats.nodes as f64);
            r_ok += 1;
        }
    }
    eprintln!(
        "seed 002 map 1, {RUNS} runs: hybrid nodes {:.1} (solved {h_ok}, {runs} sub-searches, \
         {gave_up} gave up); RRT nodes {:.1} (solved {r_ok})",
        mean(&h_nodes),
        mean(&r_nodes)
    );
    assert_eq!(h_ok, RUNS);
    assert_eq!(r_ok, RUNS);
    assert!(mean(&h_nodes) < mean(&r_nodes));
}

/// Seed 003's scenario 1 (docs/papers/003, 3.4): [0, 50]^2 at 0.1 units per cell, five
/// rectangles, a risk band 2 units wide. Returns the map and the obstacles.
fn scenario1() -> (GridMap, Vec<(f64, f64, f64, f64)>) {
    let rects = vec![
        (8.0, 4.0, 16.0, 14.0),
        (22.0, 20.0, 30.0, 32.0),
        (34.0, 36.0, 44.0, 42.0),
        (4.0, 28.0, 14.0, 36.0),
        (30.0, 6.0, 42.0, 14.0),
    ];
    let n = 500;
    let mut zones = vec![Zone::Free; n * n];
    for j in 0..n {
        for i in 0..n {
            let (x0, y0) = (i as f64 * 0.1, j as f64 * 0.1);
            // Distance from the cell square to each rectangle.
            let d = rects
                .iter()
                .map(|&(a, b, c, e)| {
                    let dx = (a - (x0 + 0.1)).max(x0 - c).max(0.0);
                    let dy = (b - (y0 + 0.1)).max(y0 - e).max(0.0);
                    dx.hypot(dy)
                })
                .fold(f64::INFINITY, f64::min);
            let overlap = rects
                .iter()
                .any(|&(a, b, c, e)| x0 + 0.1 > a && x0 < c && y0 + 0.1 > b && y0 < e);
            zones[j * n + i] = if overlap {
                Zone::Forbidden
            } else if d < 2.0 {
                Zone::Risk
            } else {
                Zone::Free
            };
        }
    }
    let map = GridMap::from_zones(n, n, 0.1, Point2::origin(), zones).unwrap();
    (map, rects)
}

/// Minimum distance from a polyline (sampled every 0.05) to the rectangles.
fn min_clearance(path: &[Point2], rects: &[(f64, f64, f64, f64)]) -> f64 {
    let dist = |p: Point2| {
        rects
            .iter()
            .map(|&(a, b, c, e)| {
                (a - p.x)
                    .max(p.x - c)
                    .max(0.0)
                    .hypot((b - p.y).max(p.y - e).max(0.0))
            })
            .fold(f64::INFINITY, f64::min)
    };
    let mut best = f64::INFINITY;
    for w in path.windows(2) {
        let k = ((w[1] - w[0]).norm() / 0.05).ceil().max(1.0) as usize;
        for t in 0..=k {
            best = best.min(dist(w[0] + (w[1] - w[0]) * (t as f64 / k as f64)));
        }
    }
    best
}

/// Seed 003 (section 3): safe-rrt-star keeps a larger minimum clearance than plain RRT*
/// (lambda = 0, Forbidden only, same step, bias, N), at a comparable length (ratio <= 1.10).
#[test]
fn seed003_safe_rrt_star_keeps_more_clearance_than_rrt_star() {
    let (map, rects) = scenario1();
    let query = Query::new(Point2::new(0.0, 0.0), Goal::Point(Point2::new(50.0, 50.0)));
    let safe = SafeRrtStar::default();
    let plain = RrtStar {
        step: 2.0,
        goal_bias: 0.05,
        budget: Budget::iterations(3000),
        rewire: RewireRadius::Gamma(62.0),
        stop_at_first_solution: true,
    };
    let (mut s_clear, mut s_len, mut p_clear, mut p_len, mut p_pruned) =
        (vec![], vec![], vec![], vec![], vec![]);
    let (mut forbidden_hits, mut repairs, mut refused) = (0, 0, 0);
    for seed in 0..RUNS {
        if let Ok(staged) = safe.plan_detailed(&map, &query, &mut rng(seed)) {
            let s = &staged.plan;
            s_clear.push(min_clearance(&s.path, &rects));
            s_len.push(s.length());
            forbidden_hits += s
                .path
                .iter()
                .filter(|&&p| map.zone_at(p) == Zone::Forbidden)
                .count();
            repairs += staged.smoothing_repairs;
            refused += usize::from(staged.smoothing_refused);
        }
        if let Ok(p) = plain.plan(&map, &query, &mut rng(seed)) {
            p_clear.push(min_clearance(&p.path, &rects));
            p_len.push(p.length());
            let pruned = postproc::shortcut_greedy(&p.path, |a, b| {
                hyplan_core::Workspace::segment_free(&map, a, b)
            });
            p_pruned.push(hyplan_core::path_length(&pruned));
        }
    }
    eprintln!(
        "seed 003 scenario 1, {RUNS} runs: safe-rrt-star min clearance {:.3}, length {:.2} \
         (solved {}, {repairs} spline repairs, {refused} refused); RRT* min clearance {:.3}, \
         raw length {:.2}, pruned length {:.2} (solved {})",
        mean(&s_clear),
        mean(&s_len),
        s_len.len(),
        mean(&p_clear),
        mean(&p_len),
        mean(&p_pruned),
        p_len.len()
    );
    assert_eq!(forbidden_hits, 0);
    assert!(s_len.len() as u64 >= RUNS * 95 / 100);
    assert!(mean(&s_clear) > mean(&p_clear));
    assert!(mean(&s_len) / mean(&p_len) <= 1.10);
}
