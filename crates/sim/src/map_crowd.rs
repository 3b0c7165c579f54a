//! People on a loaded map ([`people_on_map`]): walkers going back and forth between
//! far-apart points of a building's floor, at a chosen density, so that a robot can be
//! tried among people on any map, not only in the generated halls of [`crate::crowd`].

use envmap::{Connectivity, GridMap, Mask, flood_fill, nearest_passable};
use hyplan_core::{Point2, Zone};
use rand::Rng;
use search::{GridOptions, GridSearch};

use crate::crowd::{crowd_robot, walking_speed};
use crate::engine::{PEOPLE_STREAM, stream};
use crate::scenario::Scenario;
use crate::social_force::{PeopleModelKind, SocialForceParams};
use crate::world::{Person, Walk, World};

/// How far a cell of a person's floor is from every blocked cell at least, m: a body's
/// radius (0.25 m) and 10 cm, so that people walk the corridors and doorways a person
/// fits through, not along the walls' faces.
pub const PERSON_CLEARANCE: f64 = 0.35;

/// The clearances a walker's route keeps from every wall where the floor allows, widest
/// first, m: a route is planned on the floor at least this far from the walls, else at
/// the next, else anywhere on the floor; its ends are drawn from the widest floor.
/// Social-force people walking at 1.3 m/s are held about 0.59 m from a wall they walk
/// toward, so a route that grazes a pillar or a wall's bump at `PERSON_CLEARANCE` can
/// hold them in place for good.
pub const ROUTE_CLEARANCES: [f64; 2] = [0.6, 0.45];

/// Way-points of a route are at most this far apart, m: a person pushed off a leg heads
/// back to it a step ahead, not straight for a corner that may lie behind a wall.
const ROUTE_STEP: f64 = 1.0;

/// The most people [`people_on_map`] places, whatever the density and the floor (ORCA
/// and social forces cost the square of the crowd each step).
pub const MAX_MAP_PEOPLE: usize = 500;

/// How far apart a walker's two ends are at least, in a straight line, m (fewer when the
/// floor is smaller: then as far as twenty draws found).
const MIN_ROUTE: f64 = 4.0;

/// No one starts nearer the robot than this, m (as in the crowd halls).
const CLEAR_OF_ROBOT: f64 = 1.5;

/// No two people start nearer each other than this, centre to centre, m.
const APART: f64 = 0.6;

/// Body radius of the people placed, m.
const RADIUS: f64 = 0.25;

/// The people [`people_on_map`] placed, and the floor they walk.
#[derive(Debug, Clone)]
pub struct MapCrowd {
    /// The walkers, each going back and forth along an any-angle path of the floor.
    pub people: Vec<Person>,
    /// Area of the floor people walk (the part reachable from the robot's start), m^2.
    pub floor_m2: f64,
}

/// Why no crowd was placed on a map.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MapCrowdError {
    /// The density is negative or not finite.
    #[error("density = {0}: must be finite and >= 0 (people per 100 m^2)")]
    Density(f64),
    /// The scenario's world has no map to place people on.
    #[error(
        "the scenario {0:?} has no map to place people on (a ROS map, or a world whose map is a file)"
    )]
    NoMap(String),
    /// No floor a person fits on is connected to the robot's start.
    #[error(
        "no floor a person fits on ({PERSON_CLEARANCE} m from every wall) is connected to the \
         robot's start ({x:.3}, {y:.3})"
    )]
    NoFloor {
        /// The robot's start, m.
        x: f64,
        /// The robot's start, m.
        y: f64,
    },
}

/// `density` people per 100 m^2 on the floor of `map` that the robot starting at `robot`
/// can reach (cells at least [`PERSON_CLEARANCE`] from any blocked cell, 8-connected),
/// at most [`MAX_MAP_PEOPLE`], each walking back and forth, from time 0, between two
/// points of that floor drawn at random at least 4 m apart (where the floor is at least
/// the first of [`ROUTE_CLEARANCES`] from the walls, if it is anywhere): along the map's
/// Lazy Theta* path between them (straight where the floor allows, a way-point at each
/// corner and at least every metre) on the part of the floor farthest from the walls that
/// joins them, of [`ROUTE_CLEARANCES`] and [`PERSON_CLEARANCE`].
/// They start at their first point, none within 1.5 m of the robot nor 0.6 m of each
/// other, at speeds of [`crate::WALKING_SPEED`] cut to [`crate::SPEED_LIMITS`], with a
/// body radius of 0.25 m. Drawn from `rng`; the same generator state gives the same
/// people.
///
/// ```
/// use hyplan_core::Point2;
/// use hyplan_core::Zone;
/// // A 20 x 10 m hall, walled.
/// let mut map = envmap::GridMap::filled(200, 100, Zone::Free)?.with_frame(0.1, Point2::origin())?;
/// for i in 0..200 {
///     map.set_cell_zone(i, 0, Zone::Forbidden);
///     map.set_cell_zone(i, 99, Zone::Forbidden);
/// }
/// for j in 0..100 {
///     map.set_cell_zone(0, j, Zone::Forbidden);
///     map.set_cell_zone(199, j, Zone::Forbidden);
/// }
/// let mut rng = sim::stream(7, sim::PEOPLE_STREAM);
/// let crowd = sim::people_on_map(&map, 1.0, Point2::new(1.0, 5.0), &mut rng)?;
/// assert!((150.0..200.0).contains(&crowd.floor_m2));
/// assert_eq!(crowd.people.len(), (crowd.floor_m2 / 100.0).round() as usize);
/// assert!(crowd.people.iter().all(|p| p.walk == sim::Walk::BackAndForth));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`MapCrowdError`]: a bad density, or no floor connected to the robot.
pub fn people_on_map<R: Rng>(
    map: &GridMap,
    density: f64,
    robot: Point2,
    rng: &mut R,
) -> Result<MapCrowd, MapCrowdError> {
    if !(density.is_finite() && density >= 0.0) {
        return Err(MapCrowdError::Density(density));
    }
    let no_floor = MapCrowdError::NoFloor {
        x: robot.x,
        y: robot.y,
    };
    let (w, h, res) = (map.width(), map.height(), map.resolution());
    let clear_cells_sq = (PERSON_CLEARANCE / res).powi(2);
    let walls = map.blocked_distance();
    let fits = |i: usize, j: usize| {
        map.cell_zone(i, j) != Zone::Forbidden
            && walls.is_none_or(|d| f64::from(d.cell_dist_sq(i, j)) >= clear_cells_sq)
    };
    let room = Mask::from_cells(
        w,
        h,
        (0..h)
            .flat_map(|j| (0..w).map(move |i| (i, j)))
            .map(|(i, j)| fits(i, j))
            .collect(),
    )
    .ok_or_else(|| no_floor.clone())?;
    let near_robot = map
        .world_to_cell(robot)
        .and_then(|c| {
            nearest_passable((w, h), c, (1.0 / res).ceil() as usize, |i, j| {
                room.get(i, j)
            })
        })
        .ok_or_else(|| no_floor.clone())?;
    let floor = flood_fill(&room, near_robot, Connectivity::Eight);
    let cells: Vec<(usize, usize)> = (0..h)
        .flat_map(|j| (0..w).map(move |i| (i, j)))
        .filter(|&(i, j)| floor.get(i, j))
        .collect();
    let floor_m2 = cells.len() as f64 * res * res;
    let wanted = ((density * floor_m2 / 100.0).round() as usize).min(MAX_MAP_PEOPLE);
    let mut people = Vec::with_capacity(wanted);
    if wanted == 0 {
        return Ok(MapCrowd { people, floor_m2 });
    }
    // The floor at each clearance a route may keep, widest first; the last is the whole
    // floor.
    let mut levels: Vec<(GridMap, GridSearch)> = ROUTE_CLEARANCES
        .iter()
        .chain(&[PERSON_CLEARANCE])
        .map(|&clearance| {
            let clear_sq = (clearance / res).powi(2);
            let zones = (0..h)
                .flat_map(|j| (0..w).map(move |i| (i, j)))
                .map(|(i, j)| {
                    let clear = walls.is_none_or(|d| f64::from(d.cell_dist_sq(i, j)) >= clear_sq);
                    if floor.get(i, j) && clear {
                        Zone::Free
                    } else {
                        Zone::Forbidden
                    }
                })
                .collect();
            let level = GridMap::from_zones(w, h, res, map.origin(), zones)
                .expect("the size and frame of a valid map");
            let search = GridSearch::new(&level, GridOptions::default())
                .expect("a map the grid search takes");
            (level, search)
        })
        .collect();
    // Routes end where the widest floor is, if there is any: a way-point within a wall's
    // reach may be one a person is held short of.
    let (widest, _) = &levels[0];
    let ends: Vec<(usize, usize)> = cells
        .iter()
        .copied()
        .filter(|&(i, j)| widest.cell_free(i, j))
        .collect();
    let ends = if ends.is_empty() { &cells } else { &ends };
    let mut route = |a: (usize, usize), b: (usize, usize)| {
        levels.iter_mut().find_map(|(level, search)| {
            // A two-sided test first: a search that fails floods all it reaches.
            if !search.connected(a, b).ok()? {
                return None;
            }
            Some(search.lazy_theta_star(level, a, b).ok()?.cells)
        })
    };
    let at = |c: (usize, usize)| map.cell_center(c.0, c.1);
    let draw = |rng: &mut R| ends[rng.random_range(0..ends.len())];
    // Bounded draws, so that a floor too small or too full for the rules places fewer.
    for _ in 0..wanted * 20 {
        if people.len() == wanted {
            break;
        }
        let a = draw(rng);
        let pa = at(a);
        if (pa - robot).norm() < CLEAR_OF_ROBOT
            || people
                .iter()
                .any(|p: &Person| (Point2::new(p.path[0].0, p.path[0].1) - pa).norm() < APART)
        {
            continue;
        }
        // The farthest of a few draws when none is MIN_ROUTE away.
        let mut b = draw(rng);
        for _ in 0..20 {
            if (at(b) - pa).norm() >= MIN_ROUTE {
                break;
            }
            let c = draw(rng);
            if (at(c) - pa).norm() > (at(b) - pa).norm() {
                b = c;
            }
        }
        let Some(cells) = route(a, b) else {
            continue;
        };
        if cells.len() < 2 {
            continue;
        }
        let corners: Vec<Point2> = cells.iter().map(|&c| at(c)).collect();
        people.push(Person {
            path: postproc::densify(&corners, ROUTE_STEP)
                .iter()
                .map(|p| (p.x, p.y))
                .collect(),
            speed: walking_speed(rng),
            start: 0.0,
            radius: RADIUS,
            walk: Walk::BackAndForth,
            group: None,
        });
    }
    Ok(MapCrowd { people, floor_m2 })
}

/// Adds `density` people per 100 m^2 to a scenario on a map and its world, as `hyplan sim
/// --crowd` does: placed by [`people_on_map`] from the robot's start, drawn from
/// `seed`'s [`PEOPLE_STREAM`]; under social forces who see the robot if the scenario's
/// people were scripted (else its model); the robot set up as the crowd rooms'
/// ([`crowd_robot`]). Returns what was placed.
///
/// ```
/// let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
///     .join("../../scenarios/sim/nav-aws_small_house.ron");
/// let (mut scenario, mut world) = sim::Scenario::load(&path)?;
/// let crowd = sim::add_crowd(&mut scenario, &mut world, 2.0, 7)?;
/// assert_eq!(world.people, crowd.people);
/// assert_eq!(scenario.people, crowd.people);
/// assert_eq!(scenario.navigation.people_patience, sim::PEOPLE_PATIENCE);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`MapCrowdError`]: a bad density, a world without a map, no floor at the start.
pub fn add_crowd(
    scenario: &mut Scenario,
    world: &mut World,
    density: f64,
    seed: u64,
) -> Result<MapCrowd, MapCrowdError> {
    let map = world
        .statics
        .grid
        .as_ref()
        .ok_or_else(|| MapCrowdError::NoMap(scenario.name.clone()))?;
    let start = Point2::new(scenario.start.0, scenario.start.1);
    let crowd = people_on_map(map, density, start, &mut stream(seed, PEOPLE_STREAM))?;
    if scenario.people_model == PeopleModelKind::Scripted {
        scenario.people_model = PeopleModelKind::SocialForce(SocialForceParams::default());
    }
    crowd_robot(scenario);
    scenario.people.extend(crowd.people.iter().cloned());
    world.people.extend(crowd.people.iter().cloned());
    Ok(crowd)
}
