//! Shared seeds, maps and planner lists.

use envmap::GridMap;
use hyplan_core::{Budget, Planner, Zone};
use sampling::{BiRrt, RewireRadius, Rrt, RrtConnect, RrtStar};

/// A fixed seed for deterministic tests.
pub const SEED_1: u64 = 0x5eed_0001;

/// A random `w x h` grid: each cell forbidden with probability `density`, drawn from the
/// bits of `cells` (one byte per cell; 255 * density is the threshold).
pub fn random_map(w: usize, h: usize, density: f64, cells: &[u8]) -> GridMap {
    let threshold = (density * 256.0) as u32;
    let zones = (0..w * h)
        .map(|k| {
            if u32::from(cells[k % cells.len()]) < threshold {
                Zone::Forbidden
            } else {
                Zone::Free
            }
        })
        .collect();
    GridMap::from_zones(w, h, 1.0, hyplan_core::Point2::origin(), zones).unwrap()
}

/// Every planner with a given step and iteration budget.
pub fn all_planners(step: f64, iterations: u64) -> Vec<Box<dyn Planner>> {
    let budget = Budget::iterations(iterations);
    vec![
        Box::new(Rrt {
            step,
            budget,
            goal_bias: 0.1,
        }),
        Box::new(RrtStar {
            step,
            budget,
            goal_bias: 0.1,
            ..RrtStar::default()
        }),
        Box::new(RrtStar {
            step,
            budget,
            goal_bias: 0.1,
            rewire: RewireRadius::KNearest(8),
            stop_at_first_solution: false,
        }),
        Box::new(BiRrt { step, budget }),
        Box::new(RrtConnect { step, budget }),
    ]
}
