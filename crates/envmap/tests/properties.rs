//! Property tests: EDT vs brute force, segment_free vs an independent exact cell test,
//! rectangles hold their obstacles, zones respect the safety radius.

use envmap::{GridMap, Mask, Picture, Pipeline, distance_transform, label_components, zones};
use hyplan_core::{Point2, Workspace, Zone};
use proptest::prelude::*;

fn mask_strategy(max: usize) -> impl Strategy<Value = Mask> {
    (1..=max, 1..=max, 0.0..0.6f64).prop_flat_map(|(w, h, density)| {
        proptest::collection::vec(proptest::bool::weighted(density.max(0.01)), w * h)
            .prop_map(move |cells| Mask::from_cells(w, h, cells).unwrap())
    })
}

fn brute_dist_sq(mask: &Mask, i: usize, j: usize) -> Option<u64> {
    let mut best = None;
    for b in 0..mask.height() {
        for a in 0..mask.width() {
            if mask.get(a, b) {
                let d = (a as i64 - i as i64).pow(2) as u64 + (b as i64 - j as i64).pow(2) as u64;
                best = Some(best.map_or(d, |x: u64| x.min(d)));
            }
        }
    }
    best
}

/// Whether the closed segment a-b meets the closed square [i, i+1] x [j, j+1] (world =
/// cell units). Separating axis test: the axes x and y, and the segment's normal. Exact
/// for the dyadic coordinates the strategies produce.
fn segment_meets_cell(a: (f64, f64), b: (f64, f64), i: usize, j: usize) -> bool {
    let (x0, x1, y0, y1) = (i as f64, i as f64 + 1.0, j as f64, j as f64 + 1.0);
    if a.0.max(b.0) < x0 || a.0.min(b.0) > x1 || a.1.max(b.1) < y0 || a.1.min(b.1) > y1 {
        return false;
    }
    let side = |px: f64, py: f64| (b.0 - a.0) * (py - a.1) - (b.1 - a.1) * (px - a.0);
    let s = [side(x0, y0), side(x1, y0), side(x0, y1), side(x1, y1)];
    !(s.iter().all(|&v| v > 0.0) || s.iter().all(|&v| v < 0.0))
}

/// Coordinates on a 1/8 grid, slightly beyond the map on each side.
fn coord(n: usize) -> impl Strategy<Value = f64> {
    (-4i64..=(n as i64 * 8 + 4)).prop_map(|k| k as f64 / 8.0)
}

fn zone_map(mask: &Mask, risk: &[bool]) -> GridMap {
    let zones = mask
        .cells()
        .iter()
        .zip(risk.iter().cycle())
        .map(|(&f, &r)| {
            if f {
                Zone::Forbidden
            } else if r {
                Zone::Risk
            } else {
                Zone::Free
            }
        })
        .collect();
    GridMap::from_zones(mask.width(), mask.height(), 1.0, Point2::origin(), zones).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn edt_equals_brute_force(mask in mask_strategy(14)) {
        let d = distance_transform(&mask);
        for j in 0..mask.height() {
            for i in 0..mask.width() {
                let want = brute_dist_sq(&mask, i, j).map_or(u32::MAX, |d| d as u32);
                prop_assert_eq!(d.cell_dist_sq(i, j), want, "cell ({}, {})", i, j);
            }
        }
    }

    #[test]
    fn segment_free_matches_exact_cell_test(
        (mask, risk, a, b, avoid) in mask_strategy(8).prop_flat_map(|m| {
            let (w, h) = (m.width(), m.height());
            (Just(m), proptest::collection::vec(any::<bool>(), 8),
             (coord(w), coord(h)), (coord(w), coord(h)), any::<bool>())
        })
    ) {
        let mut map = zone_map(&mask, &risk);
        if avoid {
            map = map.avoiding_risk();
        }
        let (w, h) = (map.width() as f64, map.height() as f64);
        let inside = |p: (f64, f64)| (0.0..=w).contains(&p.0) && (0.0..=h).contains(&p.1);
        let mut touched = Vec::new();
        for j in 0..map.height() {
            for i in 0..map.width() {
                if segment_meets_cell(a, b, i, j) {
                    touched.push((i, j));
                }
            }
        }
        touched.sort_unstable();
        let mut visited = Vec::new();
        map.segment_cells(Point2::new(a.0, a.1), Point2::new(b.0, b.1), |i, j| {
            visited.push((i, j));
            true
        });
        visited.sort_unstable();
        visited.dedup();
        if inside(a) && inside(b) {
            prop_assert_eq!(&visited, &touched);
        }
        let want = inside(a) && inside(b) && touched.iter().all(|&(i, j)| map.cell_free(i, j));
        prop_assert_eq!(
            map.segment_free(Point2::new(a.0, a.1), Point2::new(b.0, b.1)), want,
            "{:?} -> {:?} touched {:?}", a, b, touched
        );
    }

    #[test]
    fn segment_free_never_crosses_a_blocked_cell(
        (mask, a, b) in mask_strategy(10).prop_flat_map(|m| {
            let (w, h) = (m.width() as f64, m.height() as f64);
            (Just(m), (0.0..=w, 0.0..=h), (0.0..=w, 0.0..=h))
        })
    ) {
        let map = zone_map(&mask, &[false]);
        let (pa, pb) = (Point2::new(a.0, a.1), Point2::new(b.0, b.1));
        if map.segment_free(pa, pb) {
            for k in 0..=2000 {
                let t = f64::from(k) / 2000.0;
                let p = pa + (pb - pa) * t;
                let (i, j) = (p.x.floor() as usize, p.y.floor() as usize);
                // Points on a cell border belong to both cells; check the open interior.
                if p.x.fract() != 0.0 && p.y.fract() != 0.0 && i < map.width() && j < map.height() {
                    prop_assert!(map.cell_free(i, j), "t = {} at ({}, {}) in blocked cell", t, p.x, p.y);
                }
            }
        }
    }

    #[test]
    fn every_obstacle_cell_lies_in_its_rectangle(mask in mask_strategy(16)) {
        let labels = label_components(&mask);
        prop_assert_eq!(labels.components.iter().map(|c| c.cells).sum::<usize>(), mask.count());
        for j in 0..mask.height() {
            for i in 0..mask.width() {
                let l = labels.labels[j * mask.width() + i];
                prop_assert_eq!(l != 0, mask.get(i, j));
                if l != 0 {
                    prop_assert!(labels.components[l as usize - 1].rect.contains(i, j));
                    // 8-neighbours that are obstacles share the label.
                    for (di, dj) in [(1i64, 0i64), (0, 1), (1, 1), (-1, 1)] {
                        let (ni, nj) = (i as i64 + di, j as i64 + dj);
                        if ni >= 0 && nj >= 0 && mask.get(ni as usize, nj as usize) {
                            prop_assert_eq!(labels.labels[nj as usize * mask.width() + ni as usize], l);
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn zones_respect_the_safety_radius(mask in mask_strategy(14), r in 0.0..6.0f64) {
        let z = zones(&mask, &distance_transform(&mask), r);
        for j in 0..mask.height() {
            for i in 0..mask.width() {
                let zone = z[j * mask.width() + i];
                let d = brute_dist_sq(&mask, i, j).map(|d| (d as f64).sqrt());
                match zone {
                    Zone::Forbidden => prop_assert!(mask.get(i, j)),
                    Zone::Risk => prop_assert!(!mask.get(i, j) && d.is_some_and(|d| d <= r)),
                    Zone::Free => prop_assert!(d.is_none_or(|d| d > r)),
                }
            }
        }
    }

    #[test]
    fn pipeline_rectangles_cover_the_mask(
        (w, h, px) in (4usize..40, 4usize..40).prop_flat_map(|(w, h)|
            (Just(w), Just(h), proptest::collection::vec(any::<u8>(), w * h)))
    ) {
        let pic = Picture::grey(w, h, px).unwrap();
        let out = Pipeline { rectangles: true, safety_radius: 1.5, ..Pipeline::default() }.run(&pic).unwrap();
        for j in 0..h {
            for i in 0..w {
                if out.mask.get(i, j) {
                    prop_assert!(out.rectangles.iter().any(|r| r.contains(i, j)));
                    prop_assert_eq!(out.map.cell_zone(i, j), Zone::Forbidden);
                }
                prop_assert_eq!(out.obstacles.get(i, j), out.rectangles.iter().any(|r| r.contains(i, j)));
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// `clearance` is a lower bound on the exact distance to the nearest blocked closed
    /// cell (the border is not an obstacle), at most 2.2 cells below it.
    #[test]
    fn clearance_is_a_tight_lower_bound(
        (mask, p) in mask_strategy(10).prop_flat_map(|m| {
            let (w, h) = (m.width() as f64, m.height() as f64);
            (Just(m), (0.0..=w, 0.0..=h))
        })
    ) {
        let map = zone_map(&mask, &[false]);
        let p = Point2::new(p.0, p.1);
        let c = map.clearance(p).unwrap();
        let mut exact = f64::INFINITY;
        for j in 0..map.height() {
            for i in 0..map.width() {
                if !map.cell_free(i, j) {
                    let dx = (i as f64 - p.x).max(p.x - (i as f64 + 1.0)).max(0.0);
                    let dy = (j as f64 - p.y).max(p.y - (j as f64 + 1.0)).max(0.0);
                    exact = exact.min(dx.hypot(dy));
                }
            }
        }
        if !map.is_free(p) {
            prop_assert_eq!(c, 0.0);
        } else if exact.is_infinite() {
            prop_assert!(c.is_infinite());
        } else {
            prop_assert!(c <= exact + 1e-12, "clearance {} > exact {}", c, exact);
            prop_assert!(c >= exact - 2.2, "clearance {} << exact {}", c, exact);
        }
    }
}

#[test]
fn clearance_cache_follows_zone_edits() {
    let mut map = GridMap::filled(9, 9, Zone::Free).unwrap();
    let p = Point2::new(4.5, 4.5);
    assert_eq!(map.clearance(p), Some(f64::INFINITY)); // no obstacle: the border does not count
    map.set_cell_zone(5, 4, Zone::Forbidden);
    let c = map.clearance(p).unwrap();
    assert!((0.0..=0.5).contains(&c), "{c}");
    map.set_cell_zone(5, 4, Zone::Risk);
    assert_eq!(map.clearance(p), Some(f64::INFINITY));
    let risky = map.clone().avoiding_risk();
    assert!(risky.clearance(p).unwrap() <= 0.5);
}

/// A sparse mask (obstacles about one cell in `1 / density`), so that most cells are
/// beyond the inflation radius of every obstacle, some within it.
fn sparse_mask_strategy(max: usize) -> impl Strategy<Value = Mask> {
    (1..=max, 1..=max, 2u32..40).prop_flat_map(|(w, h, density)| {
        proptest::collection::vec(0..density, w * h).prop_map(move |draws| {
            Mask::from_cells(w, h, draws.into_iter().map(|d| d == 0).collect()).unwrap()
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// The bounded inflation is the full one: the same cost in every cell, for any mask,
    /// radii and resolution (including radii past the bounded path's 64-cell reach).
    #[test]
    fn inflate_equals_the_costs_of_the_full_transform(
        mask in sparse_mask_strategy(48),
        inscribed in 0.0f64..0.6,
        extra in 0.0f64..1.2,
        scaling in 0.0f64..25.0,
        resolution in prop_oneof![Just(0.05), Just(0.1), 0.01f64..0.5],
    ) {
        let inf = envmap::Inflation {
            inscribed_radius: inscribed,
            inflation_radius: inscribed + extra,
            cost_scaling_factor: scaling,
        };
        let full = inf.costs(&distance_transform(&mask), resolution).unwrap();
        prop_assert_eq!(inf.inflate(&mask, resolution).unwrap(), full);
    }
}

#[test]
fn inflate_refuses_what_costs_refuses() {
    let mask = Mask::new(4, 4);
    let bad = envmap::Inflation {
        inscribed_radius: 0.5,
        inflation_radius: 0.2,
        cost_scaling_factor: 1.0,
    };
    assert!(bad.inflate(&mask, 0.1).is_err());
    let ok = envmap::Inflation::default();
    for res in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = ok.inflate(&mask, res).unwrap_err().to_string();
        assert!(e.contains("resolution"), "{e}");
    }
}

/// A map up to 60 x 60 with a few blocked cells in open space (where the strides run up
/// to them) or up to 30 % blocked, some of the rest high-risk.
fn open_map_strategy() -> impl Strategy<Value = (Mask, Vec<bool>)> {
    let density = prop_oneof![0.0..0.006f64, 0.0..0.3f64];
    (4usize..60, 4usize..60, density).prop_flat_map(|(w, h, density)| {
        (
            proptest::collection::vec(proptest::bool::weighted(density), w * h)
                .prop_map(move |cells| Mask::from_cells(w, h, cells).unwrap()),
            proptest::collection::vec(proptest::bool::weighted(0.01), 64),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// With the stride table made, `segment_free` still answers exactly which closed
    /// cells the segment touches (corners and grid lines included: end points on a 1/8
    /// grid), against the brute-force test of every cell; segments across the map and
    /// within 5 cells (which one look at a stride may accept).
    #[test]
    fn strided_segment_free_matches_exact_cell_test(
        ((mask, risk), segments, short, avoid) in open_map_strategy().prop_flat_map(|(m, r)| {
            let (w, h) = (m.width(), m.height());
            let point = ((0..=w * 8).prop_map(|k| k as f64 / 8.0), (0..=h * 8).prop_map(|k| k as f64 / 8.0));
            let offset = (-40..=40i32, -40..=40i32);
            (
                Just((m, r)),
                proptest::collection::vec((point.clone(), point.clone()), 1..24),
                proptest::collection::vec((point, offset), 1..24),
                any::<bool>(),
            )
        })
    ) {
        let mut map = zone_map(&mask, &risk);
        if avoid {
            map = map.avoiding_risk();
        }
        prop_assert!(map.blocked_strides().is_some());
        let (w, h) = (map.width() as f64, map.height() as f64);
        // From `a` by the offset, and centred on `a` (half the offset each way).
        let short = short.into_iter().flat_map(|(a, (du, dv))| {
            let at = |p: (f64, f64), k: f64| {
                ((p.0 + k * f64::from(du) / 8.0).clamp(0.0, w), (p.1 + k * f64::from(dv) / 8.0).clamp(0.0, h))
            };
            [(a, at(a, 1.0)), (at(a, -0.5), at(a, 0.5))]
        });
        for (a, b) in segments.into_iter().chain(short) {
            let want = (0..map.height()).all(|j| {
                (0..map.width()).all(|i| !segment_meets_cell(a, b, i, j) || map.cell_free(i, j))
            });
            prop_assert_eq!(
                map.segment_free(Point2::new(a.0, a.1), Point2::new(b.0, b.1)), want,
                "{:?} -> {:?}", a, b
            );
        }
    }

    /// In a world frame whose cell edges are not exact in binary (0.05 m cells, origin
    /// (-3.3, 7.1)), the strided check equals the plain sweep on a map that has no table.
    #[test]
    fn strided_segment_free_equals_the_sweep_in_a_world_frame(
        ((mask, risk), segments) in open_map_strategy().prop_flat_map(|(m, r)| {
            let (w, h) = (m.width() as f64, m.height() as f64);
            let point = (0.0..=w, 0.0..=h);
            (Just((m, r)), proptest::collection::vec((point.clone(), point), 1..24))
        })
    ) {
        let plain = zone_map(&mask, &risk).with_frame(0.05, Point2::new(-3.3, 7.1)).unwrap();
        let strided = plain.clone();
        prop_assert!(strided.blocked_strides().is_some());
        let world = |p: (f64, f64)| Point2::new(-3.3 + p.0 * 0.05, 7.1 + p.1 * 0.05);
        for (a, b) in segments {
            let (a, b) = (world(a), world(b));
            let want = plain.bounds().contains(a)
                && plain.bounds().contains(b)
                && plain.segment_cells(a, b, |i, j| plain.cell_free(i, j));
            prop_assert_eq!(strided.segment_free_cells(a, b), want, "{:?} -> {:?}", a, b);
        }
    }
}

/// Every segment of up to 5 cells centred on a 1/8 grid point about one obstacle (which
/// one look at the stride table of its middle may accept) answers as the brute-force test
/// of every cell, on all sides of the obstacle and at every distance from it.
#[test]
fn short_segments_about_an_obstacle_match_the_exact_cell_test() {
    let mut mask = Mask::new(9, 9);
    mask.set(6, 6, true);
    let map = zone_map(&mask, &[false]);
    assert!(map.blocked_strides().is_some());
    let eighths = |from: i32, to: i32| (from..=to).map(|k| f64::from(k) / 8.0);
    for mx in eighths(8, 52) {
        for my in eighths(8, 52) {
            for hx in eighths(-20, 20) {
                for hy in eighths(-20, 20) {
                    let (a, b) = ((mx - hx, my - hy), (mx + hx, my + hy));
                    if [a.0, a.1, b.0, b.1]
                        .iter()
                        .any(|&c| !(0.0..=9.0).contains(&c))
                    {
                        continue;
                    }
                    let want = (0..9).all(|j| {
                        (0..9).all(|i| !segment_meets_cell(a, b, i, j) || map.cell_free(i, j))
                    });
                    assert_eq!(
                        map.segment_free(Point2::new(a.0, a.1), Point2::new(b.0, b.1)),
                        want,
                        "{a:?} -> {b:?}"
                    );
                }
            }
        }
    }
}
