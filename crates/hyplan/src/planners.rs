//! `--planner NAME` and the shared flags -> a planner from `harness`'s registry.
//!
//! The command line and the scenario files share one registry,
//! [`harness::build_planner`]: here the flags become a [`harness::PlannerSpec`], passing
//! each planner only the parameters it has (the grid searches take none; the papers'
//! hybrids keep their papers' defaults unless `--step` is given).

use hyplan_core::{Budget, Planner};

/// The planner flags shared by every planner; each planner takes what it uses.
#[derive(Debug, Clone, Copy)]
pub struct PlannerFlags {
    /// Maximum edge length, world units, when given (or the CLI's default for the plain
    /// sampling planners).
    pub step: Option<f64>,
    /// Goal bias, a probability.
    pub goal_bias: f64,
    /// Goal radius, world units (0: the exact goal point).
    pub goal_radius: f64,
    /// Iteration and time budget.
    pub budget: Budget,
}

/// Whether `name` is a grid search (no step, bias or budget).
fn is_grid_search(name: &str) -> bool {
    matches!(name, "astar" | "dijkstra" | "theta-star")
}

/// Whether the planner called `name` uses `--goal-bias`.
#[must_use]
pub fn uses_goal_bias(name: &str) -> bool {
    matches!(
        name,
        "rrt" | "rrt-star" | "rrt-astar-refine" | "hybrid-rrt-astar" | "safe-rrt-star"
    )
}

/// The planner called `name`, configured from `flags`.
///
/// RRT* runs to its first solution (OMPL's default without `--optimize`). Parameter values
/// are validated by the planner itself on its first `plan` call (typed errors).
///
/// # Errors
///
/// An unknown name, listing the known ones.
pub fn build(name: &str, flags: &PlannerFlags) -> anyhow::Result<Box<dyn Planner>> {
    let mut params = std::collections::BTreeMap::new();
    if !is_grid_search(name) {
        // GA-PCHIP has no step: its segments join via-points anywhere on the map.
        if let Some(step) = flags.step.filter(|_| name != "ga-pchip") {
            params.insert("step".to_string(), step);
            // RRT-A*-BT's closed list is a radius around grown nodes, a quarter step by
            // default (10 px for 40 px steps): keep that ratio for another step.
            if name == "rrt-astar-bt" {
                params.insert("closed_radius".to_string(), step / 4.0);
            }
        }
        if uses_goal_bias(name) {
            params.insert("goal_bias".to_string(), flags.goal_bias);
        }
        // The planners whose own goal region is a parameter get the query's radius.
        if matches!(name, "rrt-astar-bt" | "safe-rrt-star") && flags.goal_radius > 0.0 {
            params.insert("goal_radius".to_string(), flags.goal_radius);
        }
        // u64::MAX stands for "no iteration cap" (a time limit ends the run); as f64 it
        // rounds up, and the conversion back saturates to u64::MAX.
        params.insert(
            "max_iterations".to_string(),
            flags.budget.max_iterations as f64,
        );
        if let Some(t) = flags.budget.max_time {
            params.insert("time_limit_s".to_string(), t.as_secs_f64());
        }
    }
    let spec = harness::PlannerSpec {
        name: name.to_string(),
        label: None,
        params,
        smoothing: None,
    };
    harness::build_planner(&spec).map_err(|e| anyhow::anyhow!("--planner {name}: {e}"))
}

/// Whether the plain sampling planners (whose library default step is 1 world unit) should
/// get the CLI's map-sized default step.
#[must_use]
pub fn wants_default_step(name: &str) -> bool {
    matches!(name, "rrt" | "rrt-star" | "bi-rrt" | "rrt-connect")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_builds() {
        let flags = PlannerFlags {
            step: Some(1.0),
            goal_bias: 0.05,
            goal_radius: 1.0,
            budget: Budget::default(),
        };
        for name in harness::PLANNER_NAMES {
            assert_eq!(build(name, &flags).unwrap().info().name, *name);
        }
        assert!(build("nope", &flags).is_err());
    }
}
