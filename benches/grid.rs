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

/// Blocks the cells of `map` within `r` of `(cx, cy)` (clipped to the map).
fn disc(map: &mut GridMap, cx: i64, cy: i64, r: i64) {
    let (w, h) = (map.width() as i64, map.height() as i64);
    for y in (cy - r).max(0)..(cy + r + 1).min(h) {
        for x in (cx - r).max(0)..(cx + r + 1).min(w) {
            if (x - cx).pow(2) + (y - cy).pow(2) <= r * r {
                map.set_cell_zone(x as usize, y as usize, Zone::Forbidden);
            }
        }
    }
}

/// Splits `[at, at + len)` into spans of `min..max` cells separated by gaps of `gap`
/// cells (each drawn anew); the last span is cut at the end. Returns `(start, len)`.
fn spans(
    rng: &mut ChaCha8Rng,
    at: usize,
    len: usize,
    span: std::ops::Range<usize>,
    gap: &dyn Fn(&mut ChaCha8Rng) -> usize,
) -> Vec<(usize, usize)> {
    let (mut out, mut x, end) = (Vec::new(), at, at + len);
    while x < end {
        let l = rng.random_range(span.clone()).min(end - x);
        out.push((x, l));
        x += l + gap(rng);
    }
    out
}

/// A `n x n` city imitating MovingAI's street maps (`street/*.map`, cities cut out of
/// OpenStreetMap): blocks 16-64 cells on a side separated by streets 2-5 cells wide (an
/// avenue of 8-13 one time in five), each block split into lots by 1-2 cell alleys, each
/// lot a rectangular building set back 0-2 cells from it; one block in ten is a park
/// (left open).
pub fn streets(n: usize, rng: &mut ChaCha8Rng) -> GridMap {
    let mut map = GridMap::filled(n, n, Zone::Free).expect("size");
    let street = |rng: &mut ChaCha8Rng| {
        if rng.random_bool(0.2) {
            rng.random_range(8..14)
        } else {
            rng.random_range(2..6)
        }
    };
    let alley = |rng: &mut ChaCha8Rng| rng.random_range(1..3);
    let (xs, ys) = (
        spans(rng, 0, n, 16..64, &street),
        spans(rng, 0, n, 16..64, &street),
    );
    for &(bx, bw) in &xs {
        for &(by, bh) in &ys {
            if rng.random_bool(0.1) {
                continue;
            }
            let lots_x = spans(rng, bx, bw, 6..bw.max(7), &alley);
            let lots_y = spans(rng, by, bh, 6..bh.max(7), &alley);
            for &(lx, lw) in &lots_x {
                for &(ly, lh) in &lots_y {
                    let mut inset = || rng.random_range(0..3);
                    let (x0, x1) = (lx + inset(), (lx + lw).saturating_sub(inset()));
                    let (y0, y1) = (ly + inset(), (ly + lh).saturating_sub(inset()));
                    for y in y0..y1 {
                        for x in x0..x1 {
                            map.set_cell_zone(x, y, Zone::Forbidden);
                        }
                    }
                }
            }
        }
    }
    map
}

/// A `n x n` map imitating StarCraft's (MovingAI's `sc1/*.map`): open ground cut into
/// plateaus by three wandering cliffs 3-5 cells thick, crossed by ramps 4-9 cells wide every
/// 50-150 cells, with about `n / 8` irregular obstacles (each a clump of 3-6 overlapping
/// discs of radius 2-15: rocks, water, doodads); about 20 % of the cells blocked.
pub fn game_like(n: usize, rng: &mut ChaCha8Rng) -> GridMap {
    let mut map = GridMap::filled(n, n, Zone::Free).expect("size");
    for c in 0..3 {
        let thick = rng.random_range(3..6);
        let mut off = rng.random_range(n / 8..n - n / 8) as i64;
        let ramps = spans(rng, 0, n, 50..150, &|rng| rng.random_range(4..10));
        for &(from, len) in &ramps {
            for t in from..from + len {
                // The cliff drifts one cell sideways at most per cell along it.
                off = (off + rng.random_range(-1..2)).clamp(8, n as i64 - 8 - thick);
                for k in 0..thick as usize {
                    let o = off as usize + k;
                    let (x, y) = if c % 2 == 0 { (t, o) } else { (o, t) };
                    map.set_cell_zone(x, y, Zone::Forbidden);
                }
            }
        }
    }
    for _ in 0..n / 8 {
        let (cx, cy) = (rng.random_range(0..n) as i64, rng.random_range(0..n) as i64);
        for _ in 0..rng.random_range(3..7) {
            let r = rng.random_range(2..16);
            let (ox, oy) = (
                rng.random_range(-2 * r..2 * r + 1),
                rng.random_range(-r..r + 1),
            );
            disc(&mut map, cx + ox, cy + oy, r);
        }
    }
    map
}

/// A `n x n` map of caverns imitating Dragon Age's (MovingAI's `dao/*.map` caves and
/// dungeons): a cave carved at a quarter of the resolution (47 % of the coarse cells
/// blocked at random, then five rounds of the majority rule: a cell is blocked when 5 or
/// more of its 3 x 3 neighbourhood are, outside the map counting as blocked), scaled up,
/// 8 % of the cells flipped and two rounds of the rule at full resolution to make the walls
/// irregular. What is left is caves tens of cells across joined by winding passages.
pub fn caverns(n: usize, rng: &mut ChaCha8Rng) -> GridMap {
    let majority = |b: &[bool], m: usize| -> Vec<bool> {
        let at = |x: i64, y: i64| {
            x < 0 || y < 0 || x >= m as i64 || y >= m as i64 || b[y as usize * m + x as usize]
        };
        (0..m * m)
            .map(|p| {
                let (x, y) = ((p % m) as i64, (p / m) as i64);
                let around = (-1..2)
                    .flat_map(|dy| (-1..2).map(move |dx| (dx, dy)))
                    .filter(|&(dx, dy)| at(x + dx, y + dy))
                    .count();
                around >= 5
            })
            .collect()
    };
    let m = n / 4;
    let mut coarse: Vec<bool> = (0..m * m).map(|_| rng.random_bool(0.47)).collect();
    for _ in 0..5 {
        coarse = majority(&coarse, m);
    }
    let mut fine: Vec<bool> = (0..n * n)
        .map(|p| {
            coarse[(p / n / 4).min(m - 1) * m + (p % n / 4).min(m - 1)] ^ rng.random_bool(0.08)
        })
        .collect();
    for _ in 0..2 {
        fine = majority(&fine, n);
    }
    let mut map = GridMap::filled(n, n, Zone::Free).expect("size");
    for (p, _) in fine.iter().enumerate().filter(|(_, b)| **b) {
        map.set_cell_zone(p % n, p / n, Zone::Forbidden);
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

/// Queries drawn as MovingAI's benchmark sets spread theirs: between random free cells of
/// `map` (6,000 draws from a stream seeded 7), ten kept per 4-cell bucket of the optimal
/// length, short to long, with our A*'s cost as the reference (`check` compares it with
/// the peer's).
pub fn bucketed_queries(map: &GridMap) -> Vec<Scenario> {
    let (w, h) = (map.width(), map.height());
    let mut search = GridSearch::new(map, GridOptions::default()).expect("grid");
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut buckets: Vec<Vec<Scenario>> = Vec::new();
    for _ in 0..6000 {
        let a = (rng.random_range(0..w), rng.random_range(0..h));
        let b = (rng.random_range(0..w), rng.random_range(0..h));
        if !map.cell_free(a.0, a.1) || !map.cell_free(b.0, b.1) {
            continue;
        }
        if let Ok(p) = search.astar(a, b) {
            let k = (p.cost / 4.0) as usize;
            if buckets.len() <= k {
                buckets.resize(k + 1, Vec::new());
            }
            if buckets[k].len() < 10 {
                buckets[k].push((a, b, p.cost));
            }
        }
    }
    buckets.into_iter().flatten().collect()
}

/// The densities of MovingAI's random-obstacle family (`random512-10` to `random512-40`),
/// one generated 512 x 512 map each (blocked cells drawn from a stream seeded with the
/// percentage), with [`bucketed_queries`] as that family's benchmark sets spread theirs.
pub fn random_family() -> Vec<Suite> {
    const NAMES: [&str; 7] = [
        "random512-10",
        "random512-15",
        "random512-20",
        "random512-25",
        "random512-30",
        "random512-35",
        "random512-40",
    ];
    NAMES
        .iter()
        .zip((10_u32..=40).step_by(5))
        .map(|(&name, percent)| {
            let mut rng = ChaCha8Rng::seed_from_u64(u64::from(percent));
            let map = random(512, f64::from(percent) / 100.0, &mut rng);
            let queries = bucketed_queries(&map);
            Suite { name, map, queries }
        })
        .collect()
}

/// A generator of `n x n` maps.
type MapMaker = fn(usize, &mut ChaCha8Rng) -> GridMap;

/// The generated maps of the second group: mazes, random obstacles and rooms, then city
/// streets, StarCraft-like open ground and Dragon-Age-like caverns.
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
    let mut out: Vec<Suite> = maps
        .into_iter()
        .map(|(name, map)| {
            let queries = queries(&map, &mut rng);
            Suite { name, map, queries }
        })
        .collect();
    // The later families on their own stream of the same seed, so that the maps and
    // queries above stay as they were measured before these were added.
    let mut rng = ChaCha8Rng::seed_from_u64(2026);
    rng.set_stream(1);
    let later: [(&'static str, MapMaker); 3] = [
        ("streets512", streets),
        ("game512", game_like),
        ("caverns512", caverns),
    ];
    for (name, make) in later {
        let map = make(n, &mut rng);
        let queries = queries(&map, &mut rng);
        out.push(Suite { name, map, queries });
    }
    out
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
