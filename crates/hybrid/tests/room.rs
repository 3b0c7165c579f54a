//! Seed 000's Table 2 room and the four hybrids scaled to it: the one workload of the
//! claim test, `examples/room_timing.rs` and the `hybrid` bench, which include this file
//! (`#[path]`), so that they plan the same problem with the same parameters.
//!
//! The picture goes through `envmap::load_map` with `rectangles: true` and a 20-cell
//! safety radius (world units = pixels). Start and goal are the paper's (74, 1953) and
//! (5501, 1308) mm at 6.34 mm/px, in the picture frame (x = column, y = row from the top).

// Each file that includes this one uses a part of it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use envmap::{GridMap, LoadOptions, load_map};
use hybrid::{HybridRrtAstar, RrtAstarBt, RrtAstarRefine, SafeRrtStar};
use hyplan_core::{Budget, Goal, Planner, Point2, Query};

/// Millimetres per pixel of the room picture.
const MM_PER_PX: f64 = 6.34;

/// The room as planned on: the loaded map (obstacles and the 20 px risk band), the same
/// map with the band blocked, and the paper's start and goal.
pub struct Room {
    /// The map as loaded: Forbidden furniture, a Risk band around it.
    pub map: GridMap,
    /// `map` with the Risk band blocked too.
    pub safe: GridMap,
    /// The paper's start, world units (pixels, y up).
    pub start: Point2,
    /// The paper's goal, world units.
    pub goal: Point2,
    /// From `start` to the point `goal`.
    pub query: Query,
}

impl Room {
    /// The map a planner of [`room_planners`] plans on: `safe` or the three zones.
    pub fn map_for(&self, on_safe: bool) -> &GridMap {
        if on_safe { &self.safe } else { &self.map }
    }
}

/// The room picture, found from the including crate's folder upwards.
fn picture() -> PathBuf {
    let relative = Path::new("scenarios/maps/room_960x640.png");
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .map(|dir| dir.join(relative))
        .find(|path| path.exists())
        .unwrap_or_else(|| relative.to_path_buf())
}

/// Loads the room of seed 000's Table 2.
///
/// # Errors
///
/// The picture cannot be read or loaded.
pub fn room() -> Result<Room, Box<dyn std::error::Error>> {
    let options = LoadOptions {
        rectangles: true,
        safety_radius: Some(20.0),
        ..LoadOptions::default()
    };
    let loaded = load_map(&picture(), &options)?;
    let start = loaded.frame.to_world(74.0 / MM_PER_PX, 1953.0 / MM_PER_PX);
    let goal = loaded
        .frame
        .to_world(5501.0 / MM_PER_PX, 1308.0 / MM_PER_PX);
    let safe = loaded.map.clone().avoiding_risk();
    Ok(Room {
        map: loaded.map,
        safe,
        start,
        goal,
        query: Query::new(start, Goal::Point(goal)),
    })
}

/// The four hybrids on the room, each with a label of its parameters and whether it plans
/// on the safe map (`true`) or on the three zones: `rrt-astar-bt` with the paper's pixel
/// defaults, the other three with their papers' parameters scaled to the room's pixels
/// (their papers' maps are 50-100 cells wide).
pub fn room_planners() -> Vec<(&'static str, Box<dyn Planner>, bool)> {
    vec![
        (
            "rrt-astar-bt (paper defaults, safe map)",
            Box::new(RrtAstarBt::default()),
            true,
        ),
        (
            "rrt-astar-refine (step 20, near 30, safe map)",
            Box::new(RrtAstarRefine {
                step: 20.0,
                near_radius: 30.0,
                ..RrtAstarRefine::default()
            }),
            true,
        ),
        (
            "hybrid-rrt-astar (step 10, T 130, D 70, 1500 visited, safe map)",
            Box::new(HybridRrtAstar {
                step: 10.0,
                goal_threshold: 130.0,
                astar_spacing: 70.0,
                astar_max_visited: 1500,
                ..HybridRrtAstar::default()
            }),
            true,
        ),
        (
            "safe-rrt-star (step 40, goal 20, gamma 1000, r<=100, d_cp 50, three zones)",
            Box::new(SafeRrtStar {
                step: 40.0,
                goal_radius: 20.0,
                gamma: 1000.0,
                max_radius: 100.0,
                spline_max_spacing: 50.0,
                curve_spacing: 1.0,
                budget: Budget::iterations(3000),
                ..SafeRrtStar::default()
            }),
            false,
        ),
    ]
}
