//! Shared seeds and planner lists (the random maps are `random_map.rs`'s).

use hyplan_core::{Budget, Planner};
use sampling::{BiRrt, RewireRadius, Rrt, RrtConnect, RrtStar};

/// A fixed seed for deterministic tests.
pub const SEED_1: u64 = 0x5eed_0001;

/// Every planner with a given step and iteration budget.
pub fn all_planners(step: f64, iterations: u64) -> Vec<Box<dyn Planner>> {
    planners_with(step, Budget::iterations(iterations))
}

/// Every planner with a given step and budget.
pub fn planners_with(step: f64, budget: Budget) -> Vec<Box<dyn Planner>> {
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
