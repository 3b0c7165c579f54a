//! The navigation scenarios on the map the robot built itself: the paper explores first,
//! then navigates on the result (section III); here a navigation scenario's mapped world
//! (its `shapes` and map, without the obstacles placed later and without people) is
//! explored, and the scenario is then run twice, on its true prior map and on the built
//! one.

use std::path::Path;

use crate::explore::params::Strategy;
use crate::explore::run::{ExploreOutcome, explore};
use crate::planner::GlobalPlanner;
use crate::run::{Outcome, run};
use crate::scenario::{Scenario, ScenarioError};
use crate::world::StaticWorld;

/// An exploration and the navigation runs on both maps.
#[derive(Debug)]
pub struct SelfMapped {
    /// The exploration of the scenario's mapped world.
    pub exploration: ExploreOutcome,
    /// The scenario on its true prior map.
    pub on_true: Outcome,
    /// The scenario on the built map (unknown cells passable, as NavFn allows).
    pub on_built: Outcome,
}

/// Explores `scenario`'s mapped world (file `path`) with `strategy` and seed `seed`
/// (time limit `explore_limit` s), then runs the scenario on both maps with Dijkstra.
///
/// # Errors
///
/// The scenario's [`ScenarioError`]; an invalid region as [`ScenarioError::Field`].
pub fn explore_then_navigate(
    scenario: &Scenario,
    path: &Path,
    seed: u64,
    strategy: Strategy,
    explore_limit: f64,
) -> Result<SelfMapped, ScenarioError> {
    let mut unknown = scenario.clone();
    unknown.world.unmapped.clear();
    unknown.people.clear();
    unknown.known_map = false;
    unknown.time_limit = explore_limit;
    let unknown_world = unknown.build_world(path)?;
    let exploration =
        explore(&unknown, &unknown_world, seed, strategy).map_err(|e| ScenarioError::Field {
            path: path.to_path_buf(),
            field: "exploration.region".into(),
            value: format!("{:?}", unknown.exploration.region),
            reason: e.to_string(),
        })?;
    let world = scenario.build_world(path)?;
    let on_true = run(scenario, &world, seed, GlobalPlanner::Dijkstra);
    let mut mapped = StaticWorld::default();
    mapped.add_grid(exploration.map.to_grid_map());
    let built_world = crate::world::World {
        mapped,
        ..world.clone()
    };
    let on_built = run(scenario, &built_world, seed, GlobalPlanner::Dijkstra);
    Ok(SelfMapped {
        exploration,
        on_true,
        on_built,
    })
}
