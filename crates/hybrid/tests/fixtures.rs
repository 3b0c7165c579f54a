//! Shared seeds, maps and planner lists.

use envmap::GridMap;
use hybrid::{HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{Budget, Planner, Zone};

// The random maps of `sampling`'s tests, with a risk band added below.
#[path = "../../sampling/tests/random_map.rs"]
mod random_grid;

/// A fixed seed for deterministic tests.
pub const SEED_1: u64 = 0x5eed_0001;

/// How a planner must be handed a three-zone map, and what its path must avoid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Avoids {
    /// Plans on `map.avoiding_risk()`: Risk and Forbidden block.
    RiskAndForbidden,
    /// Plans on the map as it is: Forbidden blocks.
    Forbidden,
}

/// The four planners with parameters sized for maps of a few tens of cells, with a budget
/// of `iterations`, and the zone each must avoid.
pub fn all_planners(iterations: u64) -> Vec<(Box<dyn Planner>, Avoids)> {
    let budget = Budget::iterations(iterations);
    vec![
        (
            Box::new(RrtAstarBt {
                step: 2.0,
                goal_radius: 1.0,
                closed_radius: Some(0.5),
                candidates: 20,
                curve_spacing: 0.25,
                budget,
                ..RrtAstarBt::default()
            }),
            Avoids::RiskAndForbidden,
        ),
        (
            Box::new(RrtAstarRefine {
                step: 1.5,
                near_radius: 1.5,
                budget,
                ..RrtAstarRefine::default()
            }),
            Avoids::Forbidden,
        ),
        (
            Box::new(HybridRrtAstar {
                budget,
                ..HybridRrtAstar::default()
            }),
            Avoids::Forbidden,
        ),
        (
            Box::new(SafeRrtStar {
                step: 1.5,
                goal_radius: 1.0,
                gamma: 20.0,
                max_radius: 3.0,
                spline_max_spacing: 2.0,
                curve_spacing: 0.1,
                budget,
                ..SafeRrtStar::default()
            }),
            Avoids::Forbidden,
        ),
    ]
}

/// Every planner with `iterations`, each with `map` as it plans on it ([`planning_map`]).
pub fn planners_on(map: &GridMap, iterations: u64) -> Vec<(Box<dyn Planner>, GridMap)> {
    all_planners(iterations)
        .into_iter()
        .map(|(planner, avoids)| {
            let ws = planning_map(map, avoids);
            (planner, ws)
        })
        .collect()
}

/// The map a planner plans on, given the three-zone map.
pub fn planning_map(map: &GridMap, avoids: Avoids) -> GridMap {
    match avoids {
        Avoids::RiskAndForbidden => map.clone().avoiding_risk(),
        Avoids::Forbidden => map.clone(),
    }
}

/// A random `w x h` grid: each cell forbidden with probability `density`, drawn from the
/// bytes of `cells`, then a one-cell risk band around the obstacles (8-neighbourhood).
pub fn random_map(w: usize, h: usize, density: f64, cells: &[u8]) -> GridMap {
    let mut map = random_grid::random_map(w, h, density, cells);
    add_band(&mut map, 1);
    map
}

/// Marks every free cell within `r` cells (Chebyshev) of a forbidden cell as Risk.
pub fn add_band(map: &mut GridMap, r: usize) {
    let (w, h) = (map.width(), map.height());
    let src = map.clone();
    for j in 0..h {
        for i in 0..w {
            if src.cell_zone(i, j) != Zone::Free {
                continue;
            }
            let near = (j.saturating_sub(r)..=(j + r).min(h - 1)).any(|jj| {
                (i.saturating_sub(r)..=(i + r).min(w - 1))
                    .any(|ii| src.cell_zone(ii, jj) == Zone::Forbidden)
            });
            if near {
                map.set_cell_zone(i, j, Zone::Risk);
            }
        }
    }
}

/// Fills the cells of the rectangle `[x0, x1) x [y0, y1)` (cells, y up) with `zone`.
pub fn fill(map: &mut GridMap, x0: usize, y0: usize, x1: usize, y1: usize, zone: Zone) {
    for j in y0..y1 {
        for i in x0..x1 {
            map.set_cell_zone(i, j, zone);
        }
    }
}

/// A 40 x 24 room with three blocks and a one-cell risk band.
pub fn small_room() -> GridMap {
    let mut map = GridMap::filled(40, 24, Zone::Free).unwrap();
    fill(&mut map, 10, 0, 13, 15, Zone::Forbidden);
    fill(&mut map, 20, 9, 23, 24, Zone::Forbidden);
    fill(&mut map, 28, 4, 34, 8, Zone::Forbidden);
    add_band(&mut map, 1);
    map
}

/// The mean of `xs`.
pub fn mean(xs: &[f64]) -> f64 {
    xs.iter().sum::<f64>() / xs.len() as f64
}
