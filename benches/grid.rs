//! Grid A* and JPS workloads shared by the `grid_search` bench and the `grid_astar_rounds`
//! and `grid_jps_rounds` examples: the MovingAI suites, the generated 512 x 512 maps, and the peer
//! (`pathfinding::directed::astar::astar` written as the stand-alone `pathfinding-astar`
//! peer writes it).

use std::path::{Path, PathBuf};

use envmap::GridMap;
use hyplan_core::Zone;
use ordered_float::OrderedFloat;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use search::{GridOptions, GridSearch, JumpPointSearch, ScenEntry, SearchStats, read_scen};

const SQRT2: f64 = std::f64::consts::SQRT_2;

/// One scenario: start cell, goal cell `(i, j)` (row from the bottom), optimal length.
pub type Scenario = ((usize, usize), (usize, usize), f64);

/// A map and its queries.
pub struct Suite {
    /// Name in the bench ids.
    pub name: &'static str,
    /// The grid.
    pub map: GridMap,
    /// The queries, with their optimal lengths.
    pub queries: Vec<Scenario>,
}

/// The repository's `data` folder (public maps with their licences).
pub fn data() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../data")
}

/// A MovingAI map and every scenario of its `.scen` file.
pub fn suite(name: &'static str, map: &Path, scen: &Path) -> Suite {
    let map = envmap::read_movingai(map).unwrap_or_else(|e| panic!("{e}"));
    let h = map.height();
    let queries = read_scen(scen)
        .unwrap_or_else(|e| panic!("{e}"))
        .iter()
        .map(|s| {
            let cell = |p| ScenEntry::to_cell(p, h).expect("scenario inside the map");
            (cell(s.start), cell(s.goal), s.optimal)
        })
        .collect();
    Suite { name, map, queries }
}

/// The peer: `pathfinding::directed::astar::astar` on the same grid and rules, as the
/// stand-alone `pathfinding-astar` peer (outside this repository) runs it.
pub fn peer_astar(map: &GridMap, start: (usize, usize), goal: (usize, usize)) -> Option<f64> {
    let (w, h) = (map.width() as i64, map.height() as i64);
    let free = |x: i64, y: i64| {
        x >= 0 && y >= 0 && x < w && y < h && map.cell_free(x as usize, y as usize)
    };
    let id = |x: i64, y: i64| (y * w + x) as u32;
    let (gx, gy) = (goal.0 as i64, goal.1 as i64);
    let goal_id = id(gx, gy);
    let octile = |x: i64, y: i64| {
        let (dx, dy) = ((x - gx).abs() as f64, (y - gy).abs() as f64);
        let (lo, hi) = if dx < dy { (dx, dy) } else { (dy, dx) };
        (hi - lo) + SQRT2 * lo
    };
    pathfinding::directed::astar::astar(
        &id(start.0 as i64, start.1 as i64),
        |&n| {
            let (x, y) = (i64::from(n) % w, i64::from(n) / w);
            let mut out = [(0u32, OrderedFloat(0.0)); 8];
            let mut k = 0;
            let (e, wst, nth, s) = (
                free(x + 1, y),
                free(x - 1, y),
                free(x, y + 1),
                free(x, y - 1),
            );
            let mut push = |nx: i64, ny: i64, c: f64| {
                out[k] = (id(nx, ny), OrderedFloat(c));
                k += 1;
            };
            if e {
                push(x + 1, y, 1.0);
            }
            if wst {
                push(x - 1, y, 1.0);
            }
            if nth {
                push(x, y + 1, 1.0);
            }
            if s {
                push(x, y - 1, 1.0);
            }
            if e && nth && free(x + 1, y + 1) {
                push(x + 1, y + 1, SQRT2);
            }
            if e && s && free(x + 1, y - 1) {
                push(x + 1, y - 1, SQRT2);
            }
            if wst && nth && free(x - 1, y + 1) {
                push(x - 1, y + 1, SQRT2);
            }
            if wst && s && free(x - 1, y - 1) {
                push(x - 1, y - 1, SQRT2);
            }
            out.into_iter().take(k)
        },
        |&n| OrderedFloat(octile(i64::from(n) % w, i64::from(n) / w)),
        |&n| n == goal_id,
    )
    .map(|(_, c)| c.0)
}

/// A `n x n` maze of `corridor`-wide passages and 1-cell walls, carved by a depth-first
/// walk (the recursive backtracker) over the grid of rooms.
pub fn maze(n: usize, corridor: usize, rng: &mut ChaCha8Rng) -> GridMap {
    let mut map = GridMap::filled(n, n, Zone::Forbidden).expect("size");
    let k = (n - 1) / (corridor + 1);
    let corner = |r: usize| 1 + r * (corridor + 1);
    let carve = |map: &mut GridMap, x0: usize, y0: usize, w: usize, h: usize| {
        for j in y0..y0 + h {
            for i in x0..x0 + w {
                map.set_cell_zone(i, j, Zone::Free);
            }
        }
    };
    let mut seen = vec![false; k * k];
    let mut stack = vec![(0, 0)];
    seen[0] = true;
    carve(&mut map, corner(0), corner(0), corridor, corridor);
    while let Some(&(ci, cj)) = stack.last() {
        let next: Vec<(usize, usize)> = [(1i64, 0i64), (-1, 0), (0, 1), (0, -1)]
            .iter()
            .map(|&(di, dj)| (ci as i64 + di, cj as i64 + dj))
            .filter(|&(i, j)| i >= 0 && j >= 0 && i < k as i64 && j < k as i64)
            .map(|(i, j)| (i as usize, j as usize))
            .filter(|&(i, j)| !seen[j * k + i])
            .collect();
        if next.is_empty() {
            stack.pop();
            continue;
        }
        let (ni, nj) = next[rng.random_range(0..next.len())];
        seen[nj * k + ni] = true;
        carve(&mut map, corner(ni), corner(nj), corridor, corridor);
        // The wall between the two rooms.
        let (x0, y0) = (corner(ci.min(ni)), corner(cj.min(nj)));
        if ni != ci {
            carve(&mut map, x0 + corridor, y0, 1, corridor);
        } else {
            carve(&mut map, x0, y0 + corridor, corridor, 1);
        }
        stack.push((ni, nj));
    }
    map
}

/// A `n x n` map whose cells are blocked with probability `p`.
pub fn random(n: usize, p: f64, rng: &mut ChaCha8Rng) -> GridMap {
    let mut map = GridMap::filled(n, n, Zone::Free).expect("size");
    for j in 0..n {
        for i in 0..n {
            if rng.random_bool(p) {
                map.set_cell_zone(i, j, Zone::Forbidden);
            }
        }
    }
    map
}

/// A `n x n` map of `room`-sized rooms with 1-cell walls and two doors in each wall.
pub fn rooms(n: usize, room: usize, rng: &mut ChaCha8Rng) -> GridMap {
    let mut map = GridMap::filled(n, n, Zone::Free).expect("size");
    for j in 0..n {
        for i in 0..n {
            if i % room == 0 || j % room == 0 {
                map.set_cell_zone(i, j, Zone::Forbidden);
            }
        }
    }
    for ry in (0..n).step_by(room) {
        for rx in (0..n).step_by(room) {
            for _ in 0..2 {
                let door = 1 + rng.random_range(0..room - 1);
                if rx + room < n && ry + door < n {
                    map.set_cell_zone(rx + room, ry + door, Zone::Free);
                }
                if ry + room < n && rx + door < n {
                    map.set_cell_zone(rx + door, ry + room, Zone::Free);
                }
            }
        }
    }
    map
}

/// Ten queries between random free cells of `map` at least `n / 4` apart (by the optimal
/// length), with our Dijkstra's cost as the reference.
pub fn queries(map: &GridMap, rng: &mut ChaCha8Rng) -> Vec<Scenario> {
    let (w, h) = (map.width(), map.height());
    let mut search = GridSearch::new(map, GridOptions::default()).expect("grid");
    let mut out = Vec::new();
    while out.len() < 10 {
        let a = (rng.random_range(0..w), rng.random_range(0..h));
        let b = (rng.random_range(0..w), rng.random_range(0..h));
        if !map.cell_free(a.0, a.1) || !map.cell_free(b.0, b.1) {
            continue;
        }
        if let Ok(p) = search.dijkstra(a, b)
            && p.cost >= w as f64 / 4.0
        {
            out.push((a, b, p.cost));
        }
    }
    out
}

/// The generated maps of the second group.
pub fn generated() -> Vec<Suite> {
    let n = 512;
    let mut rng = ChaCha8Rng::seed_from_u64(2026);
    let maps: [(&'static str, GridMap); 6] = [
        ("maze512-1", maze(n, 1, &mut rng)),
        ("maze512-4", maze(n, 4, &mut rng)),
        ("maze512-16", maze(n, 16, &mut rng)),
        ("random512-20", random(n, 0.20, &mut rng)),
        ("random512-35", random(n, 0.35, &mut rng)),
        ("rooms512-32", rooms(n, 32, &mut rng)),
    ];
    maps.into_iter()
        .map(|(name, map)| {
            let queries = queries(&map, &mut rng);
            Suite { name, map, queries }
        })
        .collect()
}

/// The two MovingAI suites of the main group: `data/movingai`'s arena pair (160 scenarios)
/// and the peers' 101 x 101 maze (`data/generated`) (101 scenarios).
pub fn movingai() -> [Suite; 2] {
    [
        suite(
            "arena",
            &data().join("movingai/arena.map"),
            &data().join("movingai/arena.map.scen"),
        ),
        suite(
            "maze",
            &data().join("generated/maze.map"),
            &data().join("generated/maze.scen"),
        ),
    ]
}

/// Solves every query of `s` once with `ours` and with the peer and asserts both costs are
/// within `max(1e-3, 1e-5 len)` of the optimum; returns our summed counters.
pub fn check(s: &Suite, ours: &mut GridSearch) -> SearchStats {
    let mut total = SearchStats::default();
    for (k, &(a, b, opt)) in s.queries.iter().enumerate() {
        let tol = f64::max(1e-3, 1e-5 * opt);
        let mine = ours.astar(a, b).ok();
        let peer = peer_astar(&s.map, a, b);
        let name = s.name;
        assert!(
            mine.as_ref().is_some_and(|p| (p.cost - opt).abs() <= tol),
            "{name} #{k}: ours {:?} vs {opt}",
            mine.map(|p| p.cost)
        );
        assert!(
            peer.is_some_and(|c| (c - opt).abs() <= tol),
            "{name} #{k}: peer {peer:?} vs {opt}"
        );
        if let Some(p) = mine {
            total.expansions += p.stats.expansions;
            total.pushes += p.stats.pushes;
        }
    }
    total
}

/// Every query of `s` by our A* on `ours`; the summed costs (so nothing is optimised away).
pub fn run_ours(s: &Suite, ours: &mut GridSearch) -> f64 {
    s.queries
        .iter()
        .map(|&(a, b, _)| {
            let p = ours.astar(std::hint::black_box(a), std::hint::black_box(b));
            p.map_or(0.0, |p| p.cost)
        })
        .sum()
}

/// Every query of `s` by the peer; the summed costs.
pub fn run_peer(s: &Suite) -> f64 {
    s.queries
        .iter()
        .map(|&(a, b, _)| {
            peer_astar(&s.map, std::hint::black_box(a), std::hint::black_box(b)).unwrap_or(0.0)
        })
        .sum()
}

/// Solves every query of `s` once by jump point search on `jps` and asserts each cost is
/// within `max(1e-3, 1e-5 len)` of the optimum; returns the summed counters (expansions:
/// jump points).
pub fn check_jps(s: &Suite, jps: &mut JumpPointSearch) -> SearchStats {
    let mut total = SearchStats::default();
    for (k, &(a, b, opt)) in s.queries.iter().enumerate() {
        let tol = f64::max(1e-3, 1e-5 * opt);
        let found = jps.search(a, b).ok();
        assert!(
            found.as_ref().is_some_and(|p| (p.cost - opt).abs() <= tol),
            "{} #{k}: JPS {:?} vs {opt}",
            s.name,
            found.map(|p| p.cost)
        );
        if let Some(p) = found {
            total.expansions += p.stats.expansions;
            total.pushes += p.stats.pushes;
        }
    }
    total
}

/// Every query of `s` by jump point search on `jps`; the summed costs.
pub fn run_jps(s: &Suite, jps: &mut JumpPointSearch) -> f64 {
    s.queries
        .iter()
        .map(|&(a, b, _)| {
            let p = jps.search(std::hint::black_box(a), std::hint::black_box(b));
            p.map_or(0.0, |p| p.cost)
        })
        .sum()
}
