//! The crowd bench's workload: scenario 3's hall of seed 004, empty and with 20 people
//! walking back and forth across it, shared by the criterion group `crowd` (seed 0) and
//! the example `crowd_seeds` (any seed).

use std::path::{Path, PathBuf};

use sim::{PeopleModelKind, Scenario};

/// Scenario 3's file (the hall).
#[must_use]
pub fn hall_file() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenarios/sim/3-person.ron")
}

/// Scenario 3's hall with nobody in it, and the same hall with 20 people under `model`:
/// ten lanes each way across it below the dividing wall, staggered in time, at 1.3 m/s.
///
/// # Panics
///
/// If the scenario file does not load.
#[must_use]
pub fn hall(model: PeopleModelKind) -> (Scenario, Scenario) {
    let (mut empty, _) = Scenario::load(&hall_file()).expect("scenario 3 loads");
    empty.people.clear();
    let mut crowd = empty.clone();
    crowd.people = (0..20)
        .map(|k| {
            let x = 1.0 + 1.0 * f64::from(k % 10) + 0.5 * f64::from(k / 10);
            let (a, b) = if k % 2 == 0 { (1.0, 10.0) } else { (10.0, 1.0) };
            sim::Person {
                path: vec![(x, a), (x, b)],
                speed: 1.3,
                start: 0.3 * f64::from(k),
                radius: 0.25,
                walk: sim::Walk::BackAndForth,
                group: None,
            }
        })
        .collect();
    crowd.people_model = model;
    (empty, crowd)
}

/// MIT building 31's map (a real floor's SLAM map, `data/ros_maps/`).
#[must_use]
pub fn building_file() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../data/ros_maps/mit_building_31/building_31.yaml")
}

/// A run across MIT building 31's map, known in advance (from (0, 0) to (-14.83, 10.61),
/// 21 m), with nobody, and the same run among 20 people under `model`, placed as `hyplan
/// sim --crowd` places them (`sim::people_on_map`, seed 1, at the density that puts 20
/// on the floor the robot reaches); the robot set up as the crowd rooms'
/// (`sim::crowd_robot`) in both.
///
/// # Panics
///
/// If the map does not load.
#[must_use]
pub fn building(model: PeopleModelKind) -> (Scenario, Scenario, sim::World) {
    let file = building_file();
    let text = "SimScenario(name: \"mit_building_31\", world: (map: Some(Ros(\"building_31.yaml\"))), \
                start: (0.0, 0.0), goal: (-14.83, 10.61), known_map: true, time_limit: 600.0)";
    let mut empty = Scenario::parse(text, &file).expect("the scenario parses");
    sim::crowd_robot(&mut empty);
    let world = empty.build_world(&file).expect("building 31's map loads");
    let map = world.statics.grid.as_ref().expect("a map");
    let robot = hyplan_core::Point2::new(empty.start.0, empty.start.1);
    let place = |density: f64| {
        sim::people_on_map(map, density, robot, &mut sim::stream(1, sim::PEOPLE_STREAM))
            .expect("floor around the start")
    };
    let floor = place(0.0).floor_m2;
    let mut crowd = empty.clone();
    crowd.people = place(20.0 * 100.0 / floor).people;
    crowd.people_model = model;
    (empty, crowd, world)
}
