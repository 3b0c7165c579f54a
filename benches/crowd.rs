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

/// The cost of a crowd run against the empty run, per simulated second, from `pairs` runs
/// of each in turn (one of each first, unmeasured): each run timed on its thread's CPU
/// clock. The host's bursts of load and the first runs' cold caches fall on both sides,
/// where separate rounds of each (as criterion's groups are) let them fall on one.
///
/// `empty` and `crowd` each run once and return their simulated time, s.
///
/// ```no_run
/// # fn run() -> f64 { 36.2 }
/// let paired = hyplan_benches::crowd::Paired::measure(9, run, run);
/// println!("{:.2}x", paired.ratio);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Paired {
    /// Median over the pairs of the crowd run's CPU per simulated second over the empty
    /// run's.
    pub ratio: f64,
    /// Median CPU of the empty run, ms per simulated second.
    pub empty_ms: f64,
    /// Median CPU of the crowd run, ms per simulated second.
    pub crowd_ms: f64,
}

impl Paired {
    /// Times `pairs` (at least one) pairs of runs; see [`Paired`].
    pub fn measure(
        pairs: usize,
        mut empty: impl FnMut() -> f64,
        mut crowd: impl FnMut() -> f64,
    ) -> Self {
        let per_second = |run: &mut dyn FnMut() -> f64| {
            let t = cpu_time::ThreadTime::now();
            let simulated = std::hint::black_box(run());
            t.elapsed().as_secs_f64() * 1e3 / simulated
        };
        per_second(&mut empty);
        per_second(&mut crowd);
        let (mut ratios, mut alone, mut among) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..pairs.max(1) {
            let a = per_second(&mut empty);
            let c = per_second(&mut crowd);
            ratios.push(c / a);
            alone.push(a);
            among.push(c);
        }
        Self {
            ratio: median(ratios),
            empty_ms: median(alone),
            crowd_ms: median(among),
        }
    }
}

/// The middle value (the upper of the two middle ones).
fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}
