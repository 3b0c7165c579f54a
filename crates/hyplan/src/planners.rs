//! The planner registry: a name on the command line -> `Box<dyn Planner>`.
//!
//! One table, [`NAMES`], lists what `--planner` accepts; [`build`] turns a name and the
//! shared flags into a planner: the sampling planners of the `sampling` crate and the grid
//! searches of the `search` crate (8-connected, no corner cutting; they ignore the step,
//! goal bias and budget, and prove "no path").

use hyplan_core::{Budget, Planner};
use sampling::{BiRrt, Rrt, RrtConnect, RrtStar};

/// Names accepted by `--planner`.
pub const NAMES: &[&str] = &[
    "rrt",
    "rrt-star",
    "bi-rrt",
    "rrt-connect",
    "astar",
    "dijkstra",
    "theta-star",
];

/// The planner flags shared by every planner; each planner takes what it uses.
#[derive(Debug, Clone, Copy)]
pub struct PlannerFlags {
    /// Maximum edge length, world units.
    pub step: f64,
    /// Goal bias, a probability (RRT and RRT* only).
    pub goal_bias: f64,
    /// Iteration and time budget.
    pub budget: Budget,
}

/// The planner called `name`, configured from `flags`.
///
/// RRT* runs to its first solution (OMPL's default without `--optimize`). Parameters are
/// validated by the planner itself on its first `plan` call (typed errors).
///
/// # Errors
///
/// An unknown name, listing the known ones.
pub fn build(name: &str, flags: &PlannerFlags) -> anyhow::Result<Box<dyn Planner>> {
    let PlannerFlags {
        step,
        goal_bias,
        budget,
    } = *flags;
    Ok(match name {
        "rrt" => Box::new(Rrt {
            step,
            goal_bias,
            budget,
        }),
        "rrt-star" => Box::new(RrtStar {
            step,
            goal_bias,
            budget,
            ..RrtStar::default()
        }),
        "bi-rrt" => Box::new(BiRrt { step, budget }),
        "rrt-connect" => Box::new(RrtConnect { step, budget }),
        "astar" => Box::new(search::GridAstar::default()),
        "dijkstra" => Box::new(search::GridDijkstra::default()),
        "theta-star" => Box::new(search::ThetaStar::default()),
        other => anyhow::bail!(
            "unknown planner {other:?}; known planners: {}",
            NAMES.join(", ")
        ),
    })
}

/// Whether the planner called `name` uses `--goal-bias`.
#[must_use]
pub fn uses_goal_bias(name: &str) -> bool {
    matches!(name, "rrt" | "rrt-star")
}

/// The seed of run `run` for base seed `seed`: output number `run + 1` of a SplitMix64
/// generator started at `seed`, i.e. `mix(seed + (run + 1) * 0x9E3779B97F4A7C15)` with
/// SplitMix64's finaliser. Runs get well-spread, independent seeds, and run k's seed does
/// not depend on how many runs there are.
#[must_use]
pub fn run_seed(seed: u64, run: u64) -> u64 {
    let mut z = seed.wrapping_add(run.wrapping_add(1).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// SplitMix64's published first outputs for seed 0 (Vigna's reference implementation).
    #[test]
    fn run_seed_is_splitmix64() {
        assert_eq!(run_seed(0, 0), 0xE220_A839_7B1D_CDAF);
        assert_eq!(run_seed(0, 1), 0x6E78_9E6A_A1B9_65F4);
    }

    #[test]
    fn every_name_builds() {
        let flags = PlannerFlags {
            step: 1.0,
            goal_bias: 0.05,
            budget: Budget::default(),
        };
        for name in NAMES {
            assert_eq!(build(name, &flags).unwrap().info().name, *name);
        }
        assert!(build("nope", &flags).is_err());
    }
}
