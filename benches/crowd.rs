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
