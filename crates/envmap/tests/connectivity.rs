//! The run-based connectivity proof against its slow cell-by-cell reference
//! (`disconnection_reference`, `disconnection_hopping_reference`): the same verdict and the same cause, to the bit, on small
//! random maps with a consistent band (zones from the distance transform) and with
//! high-risk cells drawn at random.

use envmap::Moves;
use envmap::{GridMap, Mask, distance_transform, zones};
use hyplan_core::{Goal, Point2, Query, Zone};
use proptest::prelude::*;

/// A map of up to `max` x `max` cells: obstacles of a random density, and either the
/// band of a random radius or random high-risk cells.
fn map_strategy(max: usize) -> impl Strategy<Value = GridMap> {
    (
        1..=max,
        1..=max,
        0.0..0.5f64,
        0.0..4.0f64,
        any::<bool>(),
        any::<u64>(),
    )
        .prop_flat_map(|(w, h, density, radius, banded, _)| {
            (
                proptest::collection::vec(proptest::bool::weighted(density.max(0.01)), w * h),
                proptest::collection::vec(proptest::bool::weighted(0.3), w * h),
            )
                .prop_map(move |(cells, risky)| {
                    let mask = Mask::from_cells(w, h, cells).unwrap();
                    let z = if banded {
                        zones(&mask, &distance_transform(&mask), radius)
                    } else {
                        mask.cells()
                            .iter()
                            .zip(&risky)
                            .map(|(&f, &r)| match (f, r) {
                                (true, _) => Zone::Forbidden,
                                (false, true) => Zone::Risk,
                                _ => Zone::Free,
                            })
                            .collect()
                    };
                    GridMap::from_zones(w, h, 0.5, Point2::new(-1.0, 2.0), z).unwrap()
                })
        })
}

/// A query with start and goal anywhere in the map (free or not: the check must agree
/// with the reference either way) and a goal disc of radius 0 to 2.
fn query_strategy() -> impl Strategy<Value = (f64, f64, f64, f64, f64)> {
    (
        0.0..1.0f64,
        0.0..1.0f64,
        0.0..1.0f64,
        0.0..1.0f64,
        0.0..2.0f64,
    )
}

fn query(map: &GridMap, q: (f64, f64, f64, f64, f64)) -> Query {
    let b = hyplan_core::Workspace::bounds(map);
    let at = |u: f64, v: f64| Point2::new(b.min.x + u * b.width(), b.min.y + v * b.height());
    let goal = if q.4 < 0.5 {
        Goal::Point(at(q.2, q.3))
    } else {
        Goal::disc(at(q.2, q.3), q.4 - 0.5)
    };
    Query::new(at(q.0, q.1), goal)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn runs_agree_with_the_reference(
        map in map_strategy(24),
        q in query_strategy(),
        safe in any::<bool>(),
        eight in any::<bool>(),
        hop in 0.1..12.0f64,
    ) {
        let map = if safe { map.avoiding_risk() } else { map };
        let query = query(&map, q);
        let moves = if eight { Moves::Eight } else { Moves::Four };
        prop_assert_eq!(
            envmap::disconnection(&map, &query, moves),
            envmap::disconnection_reference(&map, &query, moves)
        );
        let mut plain = map.clone();
        plain.blocked_from = Zone::Forbidden;
        prop_assert_eq!(
            envmap::disconnection_hopping(&plain, &query, hop),
            envmap::disconnection_hopping_reference(&plain, &query, hop)
        );
    }
}

/// A 400 x 300 map whose tunnel the band closes: the same cause as the reference, and
/// the cached components survive a clone.
#[test]
fn large_band_case_matches_the_reference() {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    let g = envmap::narrow_passage(400, 300, 6, 8, &mut rng);
    let map = envmap::with_risk_band(&g.map, 5.0).avoiding_risk();
    let query = Query::new(g.start, Goal::disc(g.goal, 2.0));
    let fast = envmap::disconnection(&map, &query, Moves::Four);
    assert!(
        matches!(fast, Some(hyplan_core::NoPathCause::RiskBand { .. })),
        "{fast:?}"
    );
    assert_eq!(
        fast,
        envmap::disconnection_reference(&map, &query, Moves::Four)
    );
    assert_eq!(
        envmap::disconnection(&map.clone(), &query, Moves::Four),
        fast
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// A flood grown level by level in arbitrary increments, after a restart that reuses
    /// the last flood's buffers, holds the whole flood's steps for every cell within the
    /// level it reached, and no cell beyond; grown to the end it equals the whole flood.
    #[test]
    fn a_flood_grown_on_demand_agrees_with_the_whole_one(
        w in 1usize..30,
        h in 1usize..30,
        bits in proptest::collection::vec(any::<bool>(), 900),
        seeds in proptest::collection::vec((0usize..32, 0usize..32), 1..4),
        first in proptest::collection::vec((0usize..32, 0usize..32), 1..3),
        levels in proptest::collection::vec(0u32..12, 1..6),
        eight in any::<bool>(),
    ) {
        let conn = if eight { envmap::Connectivity::Eight } else { envmap::Connectivity::Four };
        let open: Vec<bool> = bits[..w * h].to_vec();
        let mask = Mask::from_cells(w, h, open.clone()).unwrap();
        let whole = envmap::steps_from_cells(&mask, seeds.iter().copied(), conn);
        prop_assert_eq!(&whole, &breadth_first(w, h, &open, &seeds, eight));
        let mut flood = envmap::StepsFlood::new(w, h, conn);
        flood.restart(first.iter().copied());
        flood.grow_to(u32::MAX, |c| open[c]);
        flood.restart(seeds.iter().copied());
        let mut level = 0;
        for step in levels {
            level += step;
            flood.grow_to(level, |c| open[c]);
            let from = flood.unreached_from();
            for (c, (&s, &full)) in flood.steps().iter().zip(&whole).enumerate() {
                if full <= level {
                    prop_assert_eq!(s, full, "cell {} at level {}", c, level);
                }
                if s == u32::MAX && full != u32::MAX {
                    prop_assert!(full >= from, "cell {}: {} steps, reported at least {}", c, full, from);
                }
            }
        }
        flood.grow_to(u32::MAX, |c| open[c]);
        prop_assert!(flood.finished());
        prop_assert_eq!(flood.steps(), &whole[..]);
    }
}

/// Steps by a plain breadth-first search with a double-ended queue and bounds tests, the
/// reference the flood is checked against: seeds at 0 (inside the grid, open or not),
/// then open cells only.
fn breadth_first(
    w: usize,
    h: usize,
    open: &[bool],
    seeds: &[(usize, usize)],
    eight: bool,
) -> Vec<u32> {
    let mut steps = vec![u32::MAX; w * h];
    let mut queue = std::collections::VecDeque::new();
    for &(i, j) in seeds {
        if i < w && j < h && steps[j * w + i] != 0 {
            steps[j * w + i] = 0;
            queue.push_back((i, j));
        }
    }
    while let Some((i, j)) = queue.pop_front() {
        for dj in -1i64..=1 {
            for di in -1i64..=1 {
                if (di, dj) == (0, 0) || (!eight && di != 0 && dj != 0) {
                    continue;
                }
                let (a, b) = (i as i64 + di, j as i64 + dj);
                if a < 0 || b < 0 || a >= w as i64 || b >= h as i64 {
                    continue;
                }
                let n = b as usize * w + a as usize;
                if steps[n] == u32::MAX && open[n] {
                    steps[n] = steps[j * w + i] + 1;
                    queue.push_back((a as usize, b as usize));
                }
            }
        }
    }
    steps
}
