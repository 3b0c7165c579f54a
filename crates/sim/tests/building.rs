//! Generated buildings (`MapSpec::Building`): the 60 m scenario's doors are 0.8 m, every
//! room is reachable by the robot, the layout follows the seed, bad values are refused.

use std::path::{Path, PathBuf};

use envmap::{Connectivity, GridMap, Mask, distance_transform, flood_fill, label_components};
use hyplan_core::{Point2, Zone};
use sim::{BUILDING_RESOLUTION, MapSpec, Scenario, ScenarioError};

fn building_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim/explore-building-60m.ron")
}

/// The scenario's building, as the world holds it.
fn building() -> (Scenario, GridMap) {
    let path = building_path();
    let (scenario, world) =
        Scenario::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let grid = world.statics.grid.expect("a generated building is a grid");
    (scenario, grid)
}

/// How many cells in a row are blocked from `(i, j)` on, stepping `(di, dj)`.
fn blocked_run(blocked: &Mask, (i, j): (usize, usize), (di, dj): (isize, isize)) -> usize {
    let (mut i, mut j, mut n) = (i as isize, j as isize, 0);
    while i >= 0
        && j >= 0
        && (i as usize) < blocked.width()
        && (j as usize) < blocked.height()
        && blocked.get(i as usize, j as usize)
    {
        n += 1;
        i += di;
        j += dj;
    }
    n
}

/// The widths, in cells, of the door openings cut across one direction: maximal runs of
/// free cells along rows (`along_rows`) or columns whose two end cells (the jambs) are
/// blocked over exactly `wall` cells across the run. Only a door's jambs are that short:
/// a corridor's or a room's sides are walls seen lengthwise.
fn door_runs(blocked: &Mask, wall: usize, along_rows: bool) -> Vec<usize> {
    let (w, h) = (blocked.width(), blocked.height());
    let (lines, len) = if along_rows { (h, w) } else { (w, h) };
    let at = |line: usize, k: usize| if along_rows { (k, line) } else { (line, k) };
    let across = |c: (usize, usize)| {
        let (up, down) = if along_rows {
            ((0, 1), (0, -1))
        } else {
            ((1, 0), (-1, 0))
        };
        blocked_run(blocked, c, up) + blocked_run(blocked, c, down) - 1
    };
    let mut out = Vec::new();
    for line in 0..lines {
        let mut k = 0;
        while k < len {
            if blocked.get(at(line, k).0, at(line, k).1) {
                k += 1;
                continue;
            }
            let start = k;
            while k < len && !blocked.get(at(line, k).0, at(line, k).1) {
                k += 1;
            }
            if start == 0 || k == len {
                continue;
            }
            let (a, b) = (across(at(line, start - 1)), across(at(line, k)));
            assert_eq!(
                a == wall,
                b == wall,
                "a free run at line {line}, cells {start}..{k}, with one short jamb only"
            );
            if a == wall {
                out.push(k - start);
            }
        }
    }
    out
}

/// Every door of the 60 m building is 0.8 m (16 cells) wide, and there is one per room
/// boundary at least: the runs across door openings, `wall` of them per door.
#[test]
fn doors_are_0_8_m() {
    let (scenario, grid) = building();
    let Some(MapSpec::Building {
        size, door, wall, ..
    }) = scenario.world.map
    else {
        panic!("the scenario's map is not a building");
    };
    assert_eq!(size, (60.0, 60.0));
    assert_eq!(grid.resolution(), BUILDING_RESOLUTION);
    assert_eq!((grid.width(), grid.height()), (1200, 1200));
    let door_cells = (door / BUILDING_RESOLUTION).round() as usize;
    let wall_cells = (wall / BUILDING_RESOLUTION).round() as usize;
    assert_eq!((door_cells, wall_cells), (16, 3));
    let blocked = Mask::from_zones_at_least(&grid, Zone::Forbidden);
    let mut doors = 0;
    for along_rows in [true, false] {
        let runs = door_runs(&blocked, wall_cells, along_rows);
        assert!(
            runs.iter().all(|&n| n == door_cells),
            "door widths in cells: {runs:?}"
        );
        assert_eq!(runs.len() % wall_cells, 0, "{runs:?}");
        doors += runs.len() / wall_cells;
    }
    assert!(doors >= 30, "{doors} doors");
}

/// Every room (a region of free cells more than 0.5 m from any wall: doors, 0.8 m wide,
/// separate them) is reachable from the start by the robot's disc, which keeps its centre
/// `body_radius` plus half a cell diagonal from every wall cell's centre.
#[test]
fn every_room_is_reachable() {
    let (scenario, grid) = building();
    let blocked = Mask::from_zones_at_least(&grid, Zone::Forbidden);
    let dist = distance_transform(&blocked);
    let (w, h) = (grid.width(), grid.height());
    let res = grid.resolution();
    let clear = scenario.robot.body_radius / res + 0.5_f64.sqrt();
    let fits: Vec<bool> = dist
        .dist_sq()
        .iter()
        .map(|&d| f64::from(d) >= clear * clear)
        .collect();
    let fits = Mask::from_cells(w, h, fits).unwrap();
    let start = grid
        .world_to_cell(Point2::new(scenario.start.0, scenario.start.1))
        .unwrap();
    assert!(fits.get(start.0, start.1));
    let reach = flood_fill(&fits, start, Connectivity::Four);
    let core = (0.5 / res).powi(2);
    let rooms: Vec<bool> = dist
        .dist_sq()
        .iter()
        .map(|&d| f64::from(d) > core)
        .collect();
    let rooms = Mask::from_cells(w, h, rooms).unwrap();
    let labels = label_components(&rooms);
    assert!(
        labels.components.len() >= 30,
        "{} rooms",
        labels.components.len()
    );
    let mut missed = vec![0usize; labels.components.len()];
    for (k, &l) in labels.labels.iter().enumerate() {
        if l > 0 && !reach.cells()[k] {
            missed[l as usize - 1] += 1;
        }
    }
    let unreached: Vec<_> = labels
        .components
        .iter()
        .zip(&missed)
        .filter(|(_, m)| **m > 0)
        .map(|(c, m)| (c.rect, *m))
        .collect();
    assert!(unreached.is_empty(), "rooms not reached: {unreached:?}");
}

fn with_map(map: &str) -> Result<sim::World, ScenarioError> {
    let text = format!(
        "SimScenario(name: \"b\", world: (map: Some({map})), start: (2.5, 2.5), goal: (2.5, 3.5), known_map: false)"
    );
    let path = Path::new("b.ron");
    Scenario::parse(&text, path)?.build_world(path)
}

/// Same seed, same building; another seed, another; defaults: 0.8 m doors, 0.15 m walls.
#[test]
fn the_seed_picks_the_layout() {
    let grid = |map: &str| with_map(map).unwrap().statics.grid.unwrap();
    let a = grid("Building(size: (20.0, 15.0), seed: 3)");
    assert_eq!((a.width(), a.height()), (400, 300));
    assert_eq!(
        a,
        grid("Building(size: (20.0, 15.0), door: 0.8, wall: 0.15, seed: 3)")
    );
    assert_ne!(a, grid("Building(size: (20.0, 15.0), seed: 4)"));
}

/// Bad values are refused naming the field: not whole cells, a wall too thick for a
/// room, a building too small for one room, not positive, above the memory limit.
#[test]
fn bad_buildings_are_refused() {
    let field = |map: &str| match with_map(map) {
        Err(ScenarioError::Field { field, .. }) => field,
        other => panic!("{map}: expected a field error, got {other:?}"),
    };
    assert_eq!(
        field("Building(size: (20.0, 20.0), door: 0.83)"),
        "world.map.door"
    );
    assert_eq!(
        field("Building(size: (20.02, 20.0))"),
        "world.map.size.width"
    );
    assert_eq!(
        field("Building(size: (20.0, 20.0), wall: 2.5)"),
        "world.map.wall"
    );
    assert_eq!(field("Building(size: (4.0, 20.0))"), "world.map.size");
    assert_eq!(
        field("Building(size: (20.0, -1.0))"),
        "world.map.size.height"
    );
    assert_eq!(
        field("Building(size: (20.0, 20.0), door: 0.0)"),
        "world.map.door"
    );
    match with_map("Building(size: (1e6, 1e6))") {
        Err(ScenarioError::TooLarge { field, .. }) => assert_eq!(field, "world.map.size"),
        other => panic!("expected TooLarge, got {other:?}"),
    }
}
