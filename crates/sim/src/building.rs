//! Generated multi-room buildings as a scenario's map ([`MapSpec::Building`]): envmap's
//! [`floor_plan`](envmap::floor_plan) drawn at [`BUILDING_RESOLUTION`], for explorations of
//! buildings larger than any public map.
//!
//! [`MapSpec::Building`]: crate::MapSpec::Building

use std::path::Path;

use envmap::GridMap;
use hyplan_core::Point2;
use rand::SeedableRng;

use crate::scenario::ScenarioError;

/// Cell side of a generated building, m: the built map's and the costmap's default cell,
/// so that walls and doors fall on whole cells of the robot's own grids.
///
/// ```
/// use sim::{BUILDING_RESOLUTION, Scenario};
/// let text = r#"SimScenario(name: "b", world: (map: Some(Building(size: (20.0, 15.0)))),
///     start: (2.5, 2.5), goal: (17.5, 12.5), known_map: false)"#;
/// let path = std::path::Path::new("b.ron");
/// let world = Scenario::parse(text, path)?.build_world(path)?;
/// let grid = world.statics.grid.as_ref().expect("the building's grid");
/// assert_eq!(grid.resolution(), BUILDING_RESOLUTION);
/// assert_eq!((grid.width(), grid.height()), (400, 300)); // 20 m x 15 m
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub const BUILDING_RESOLUTION: f64 = 0.05;

/// The floor plan's smallest room side, cells: `floor_plan` never splits a room below
/// `max(4 door, 100)` cells, and a door plus a wall at each end must fit in its side.
const SMALLEST_ROOM: usize = 100;

/// The building of a [`crate::MapSpec::Building`]: `size` (m) of rooms and corridors,
/// walls `wall` thick with doors `door` wide, laid out by `seed`; its lower-left corner at
/// (0, 0). Lengths must be whole cells of [`BUILDING_RESOLUTION`]; the grid may have at
/// most `max_cells` cells (checked before it is allocated). `path` names the scenario in
/// errors.
pub(crate) fn building(
    (width, height): (f64, f64),
    door: f64,
    wall: f64,
    seed: u64,
    path: &Path,
    max_cells: usize,
) -> Result<GridMap, ScenarioError> {
    let field = |name: &str, value: String, reason: String| ScenarioError::Field {
        path: path.to_path_buf(),
        field: format!("world.map.{name}"),
        value,
        reason,
    };
    let show_size = format!("({width}, {height})");
    let (columns, rows) = (width / BUILDING_RESOLUTION, height / BUILDING_RESOLUTION);
    let cells = columns.round() * rows.round();
    if cells > max_cells as f64 {
        return Err(ScenarioError::TooLarge {
            path: path.to_path_buf(),
            field: "world.map.size".into(),
            value: show_size,
            what: format!(
                "the building at {BUILDING_RESOLUTION} m per cell would be {:.0} x {:.0} = {cells:.0} cells",
                columns.round(),
                rows.round()
            ),
            cells,
            limit: max_cells,
        });
    }
    let whole = |name: &str, v: f64| -> Result<usize, ScenarioError> {
        let n = v / BUILDING_RESOLUTION;
        if n.round() >= 1.0 && (n - n.round()).abs() <= 1e-6 {
            Ok(n.round() as usize)
        } else {
            Err(field(
                name,
                v.to_string(),
                format!("must be a whole number (at least 1) of {BUILDING_RESOLUTION} m cells"),
            ))
        }
    };
    let (w_cells, h_cells) = (whole("size.width", width)?, whole("size.height", height)?);
    let d = whole("door", door)?;
    let w = whole("wall", wall)?;
    if d + 2 * w >= SMALLEST_ROOM {
        let most = (SMALLEST_ROOM - 1) as f64 * BUILDING_RESOLUTION;
        return Err(field(
            "wall",
            wall.to_string(),
            format!(
                "a door and two walls ({door} + 2 x {wall} m) must be under {most} m, the smallest room's side"
            ),
        ));
    }
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let plan = envmap::floor_plan(w_cells, h_cells, d, w, &mut rng);
    let (got_w, got_h) = (plan.map.width(), plan.map.height());
    if (got_w, got_h) != (w_cells, h_cells) {
        // The floor plan grows a side that cannot hold one room and its walls.
        return Err(field(
            "size",
            show_size,
            format!(
                "too small for one room with these doors and walls: at least ({}, {}) m",
                got_w as f64 * BUILDING_RESOLUTION,
                got_h as f64 * BUILDING_RESOLUTION
            ),
        ));
    }
    Ok(plan
        .map
        .with_frame(BUILDING_RESOLUTION, Point2::origin())
        .unwrap_or_else(|_| unreachable!("a positive resolution and the origin")))
}
