//! What every people model that reacts does alike (`social-force`, `orca`): people who
//! see a robot standing on their route get round it, people who do not walk into it; the
//! same inputs give the same positions; and the helpers the models' own tests share.

use std::path::Path;

use hyplan_core::Point2;
use sim::{Disc, PeopleModel, PeopleModelKind, Pose, Scenario, ScenarioError, World};

/// The reacting models, by name, seeing the robot and not.
const MODELS: [(&str, &str); 2] = [
    ("social-force", "social-force-blind"),
    ("orca", "orca-blind"),
];

/// A scenario of `world` (RON) and `people` (RON list), with `extra` keys.
pub(crate) fn scenario(world: &str, people: &str, extra: &str) -> (Scenario, World) {
    let text = format!(
        "SimScenario(name: \"people\", world: ({world}), people: [{people}], \
         start: (0.5, 0.5), goal: (1.0, 0.5), {extra})"
    );
    let path = Path::new("people.ron");
    let sc = Scenario::parse(&text, path).unwrap();
    let world = sc.build_world(path).unwrap();
    (sc, world)
}

/// Everyone's discs at every tick up to `seconds`, the robot at `robot(t)`.
pub(crate) fn walk(
    model: &mut dyn PeopleModel,
    seconds: f64,
    robot: impl Fn(f64) -> Pose,
) -> Vec<Vec<Disc>> {
    let ticks = (seconds * sim::TICKS_PER_SECOND as f64) as u64;
    (0..=ticks)
        .map(|k| {
            let t = sim::time_of(k);
            model.people(t, robot(t))
        })
        .collect()
}

/// A robot far from everyone.
pub(crate) fn far(_: f64) -> Pose {
    Pose {
        x: 100.0,
        y: 100.0,
        phi: 0.0,
    }
}

/// The smallest gap between two bodies over all frames, m (negative: overlap).
pub(crate) fn closest_gap(frames: &[Vec<Disc>]) -> f64 {
    let mut closest = f64::INFINITY;
    for f in frames {
        for (i, a) in f.iter().enumerate() {
            for b in &f[i + 1..] {
                closest = closest.min((a.center - b.center).norm() - a.radius - b.radius);
            }
        }
    }
    closest
}

/// The smallest gap between the walker's body and a robot standing on their route, and
/// where the walker ends, with the people model `name`.
fn past_a_standing_robot(name: &str) -> (f64, Point2) {
    let (sc, world) = scenario(
        "size: (12.0, 4.0)",
        "(path: [(1.0, 2.0), (11.0, 2.0)], speed: 1.3)",
        "",
    );
    let r = sc.robot.body_radius;
    let robot = Pose {
        x: 6.0,
        y: 2.0,
        phi: std::f64::consts::PI,
    };
    let mut model = PeopleModelKind::from_name(name).unwrap().build(&world, r);
    let frames = walk(model.as_mut(), 20.0, |_| robot);
    let gap = frames
        .iter()
        .map(|f| (f[0].center - Point2::new(robot.x, robot.y)).norm() - f[0].radius - r)
        .fold(f64::INFINITY, f64::min);
    (gap, frames.last().unwrap()[0].center)
}

/// People who see the robot keep off it and get round it to their goal; people who do
/// not walk into it: the hard case is real.
#[test]
fn a_robot_on_the_route() {
    for (seeing, blind) in MODELS {
        let (seen, end_seen) = past_a_standing_robot(seeing);
        let (unseen, _) = past_a_standing_robot(blind);
        println!("{seeing}: robot on the route: gap {seen:.4} m seen, {unseen:.4} m unseen");
        assert!(
            seen > 0.0,
            "{seeing}: a person who sees the robot touched it: {seen}"
        );
        assert!(
            unseen < 0.0,
            "{blind}: a person who does not see it kept off: {unseen}"
        );
        assert!(
            (end_seen - Point2::new(11.0, 2.0)).norm() < 0.1,
            "{seeing}: ended at {end_seen:?}"
        );
    }
}

/// The same inputs give the same positions, bit for bit: five people crossing, one
/// starting on top of another, a moving robot, walls.
#[test]
fn deterministic() {
    let (sc, world) = scenario(
        "size: (10.0, 10.0), shapes: [Box(center: (5.0, 5.0), size: (1.0, 1.0)), \
         Disc(center: (2.0, 7.0), radius: 0.4)]",
        "(path: [(1.0, 5.0), (9.0, 5.0)], speed: 1.2, walk: BackAndForth), \
         (path: [(5.0, 1.0), (5.0, 9.0)], speed: 1.0, walk: Loop), \
         (path: [(1.0, 1.0), (9.0, 9.0), (1.0, 9.0)], speed: 1.4, walk: Loop), \
         (path: [(9.0, 1.0), (1.0, 9.0)], speed: 0.9, start: 2.0), \
         (path: [(9.0, 1.0), (8.0, 2.0)], speed: 1.3, walk: BackAndForth)",
        "",
    );
    let robot = |t: f64| Pose {
        x: 1.0 + 0.3 * t,
        y: 3.0 + (0.5 * t).sin(),
        phi: 0.0,
    };
    for (name, _) in MODELS {
        let kind = PeopleModelKind::from_name(name).unwrap();
        let bits = || {
            let mut m = kind.build(&world, sc.robot.body_radius);
            walk(m.as_mut(), 30.0, robot)
                .iter()
                .flatten()
                .flat_map(|d| [d.center.x.to_bits(), d.center.y.to_bits()])
                .collect::<Vec<u64>>()
        };
        let a = bits();
        assert_eq!(a, bits(), "{name}");
        // They did move and meet: not a trivially equal pair of standstills.
        assert_ne!(a[..10], a[a.len() - 10..], "{name}");
    }
}

/// `sc` driven with seed 1 reaches its goal, and its people move otherwise than
/// scripted ones would: the engine runs the scenario's people model.
pub(crate) fn drives_among(sc: &Scenario, world: &World) {
    let out = sim::run(sc, world, 1, sim::GlobalPlanner::Dijkstra);
    let m = &out.trace.summary;
    println!(
        "{:?}: reached {} in {:?} s, contacts {} at fault",
        sc.people_model, m.reached, m.travel_time, m.contacts_at_fault
    );
    assert!(m.reached);
    let scripted = Scenario {
        people_model: PeopleModelKind::Scripted,
        ..sc.clone()
    };
    let before = sim::run(&scripted, world, 1, sim::GlobalPlanner::Dijkstra);
    assert_ne!(out.trace.rows, before.trace.rows);
}

/// A `people_model` (RON, e.g. `Orca((time_horizon: -1.0))`) whose `field` is out of
/// range is refused naming the file, the field and the value; the same with the field's
/// name misspelt as `typo` is refused at parsing.
pub(crate) fn bad_parameter_is_named(model: &str, field: &str, typo: &str) {
    let text = format!(
        "SimScenario(name: \"bad\", world: (size: (6.0, 3.0)), start: (0.5, 0.5), \
         goal: (1.0, 0.5), people_model: {model})"
    );
    let path = Path::new("bad.ron");
    let bad = Scenario::parse(&text, path).unwrap();
    match bad.build_world(path) {
        Err(e @ ScenarioError::Field { .. }) => {
            let msg = e.to_string();
            assert!(msg.contains("bad.ron"), "{msg}");
            assert!(
                msg.contains(&format!("people_model.{field}` = -1")),
                "{msg}"
            );
        }
        other => panic!("expected a field error, got {other:?}"),
    }
    let text = text.replace(field, typo);
    assert!(Scenario::parse(&text, path).is_err());
}
