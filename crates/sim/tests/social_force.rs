//! Helbing and Molnár's social force model (`sim::SocialForce`): people who pass each
//! other, keep off walls and (when they look) off the robot, deterministically.

use std::path::Path;

use hyplan_core::Point2;

use crate::reacting::{bad_parameter_is_named, drives_among, far, scenario, walk};
use sim::{PeopleModelKind, Person, Scenario, Scripted, SocialForce, SocialForceParams};

/// Seconds per engine tick.
const TICK: f64 = 1.0 / sim::TICKS_PER_SECOND as f64;

fn params(sees_robot: bool) -> SocialForceParams {
    SocialForceParams {
        sees_robot,
        ..SocialForceParams::default()
    }
}

/// Two people walking head-on along the middle of a 3 m corridor step aside, pass each
/// other without their bodies touching, and both reach their goals.
#[test]
fn head_on_in_a_corridor() {
    let walls = "Wall(from: (0.0, 0.1), to: (12.0, 0.1), thickness: 0.2), \
                 Wall(from: (0.0, 3.3), to: (12.0, 3.3), thickness: 0.2)";
    let (_, world) = scenario(
        &format!("size: (12.0, 3.4), shapes: [{walls}]"),
        "(path: [(1.0, 1.7), (11.0, 1.7)], speed: 1.3), \
         (path: [(11.0, 1.7), (1.0, 1.7)], speed: 1.3)",
        "",
    );
    let mut model = SocialForce::new(&world.people, &world.statics, 0.2, params(true));
    let frames = walk(&mut model, 20.0, far);
    let mut closest = f64::INFINITY;
    let mut apart_when_level = None;
    for (f, next) in frames.iter().zip(&frames[1..]) {
        let gap = (f[0].center - f[1].center).norm() - f[0].radius - f[1].radius;
        closest = closest.min(gap);
        if (f[0].center.x < f[1].center.x) != (next[0].center.x < next[1].center.x) {
            apart_when_level = Some((f[0].center.y - f[1].center.y).abs());
        }
        for d in f {
            let (wall, _) = world.statics.nearest(d.center);
            assert!(wall > d.radius, "a body touches a wall at {:?}", d.center);
        }
    }
    println!("head-on: closest gap {closest:.3} m, {apart_when_level:?} m apart when level");
    assert!(closest > 0.0, "bodies overlap: gap {closest}");
    let apart = apart_when_level.expect("they never passed each other");
    assert!(apart > 0.5, "{apart}");
    let last = frames.last().unwrap();
    assert!(
        (last[0].center - Point2::new(11.0, 1.7)).norm() < 0.1,
        "{last:?}"
    );
    assert!(
        (last[1].center - Point2::new(1.0, 1.7)).norm() < 0.1,
        "{last:?}"
    );
}

/// Without the side preference (`keep_right: 0`, the paper's forces alone and no
/// fluctuations) the same two people in the open stop face to face: why it exists.
#[test]
fn exactly_head_on_needs_a_side_preference() {
    let (_, world) = scenario(
        "size: (12.0, 3.4)",
        "(path: [(1.0, 1.7), (11.0, 1.7)], speed: 1.3), \
         (path: [(11.0, 1.7), (1.0, 1.7)], speed: 1.3)",
        "",
    );
    let stuck = |keep_right| {
        let p = SocialForceParams {
            keep_right,
            ..params(true)
        };
        let mut model = SocialForce::new(&world.people, &world.statics, 0.2, p);
        let last = walk(&mut model, 20.0, far).pop().unwrap();
        (last[0].center - Point2::new(11.0, 1.7)).norm() > 1.0
    };
    assert!(stuck(0.0));
    assert!(!stuck(sim::KEEP_RIGHT));
}

/// A route 0.2 m from a box's side (closer than the body's 0.25 m radius): the scripted
/// walker's body cuts into the box, the social force walker's does not, and still
/// arrives.
#[test]
fn a_grazed_box_is_not_entered() {
    let (_, world) = scenario(
        "size: (12.0, 4.0), shapes: [Box(center: (6.0, 1.0), size: (2.0, 1.0))]",
        "(path: [(1.0, 1.7), (11.0, 1.7)], speed: 1.3)",
        "",
    );
    let scripted = walk(&mut Scripted::new(&world.people), 12.0, far);
    let body_in_box = |f: &Vec<sim::Disc>| {
        let d = f[0];
        world.statics.inside(d.center) || world.statics.nearest(d.center).0 < d.radius
    };
    assert!(
        scripted.iter().any(body_in_box),
        "the test's route must graze"
    );
    let mut model = SocialForce::new(&world.people, &world.statics, 0.2, params(true));
    let frames = walk(&mut model, 12.0, far);
    let clearance = frames
        .iter()
        .map(|f| world.statics.nearest(f[0].center).0 - f[0].radius)
        .fold(f64::INFINITY, f64::min);
    println!("grazed box: smallest body clearance {clearance:.3} m");
    assert!(!frames.iter().any(body_in_box), "clearance {clearance}");
    let last = frames.last().unwrap();
    assert!(
        (last[0].center - Point2::new(11.0, 1.7)).norm() < 0.1,
        "{last:?}"
    );
}

/// Alone on a one-segment route, a person walks at their desired speed (within 5 %), as
/// the scripted model does.
#[test]
fn alone_at_the_desired_speed() {
    let people = [Person {
        path: vec![(0.0, 0.0), (30.0, 0.0)],
        speed: 1.2,
        start: 1.0,
        radius: 0.25,
        walk: sim::Walk::Once,
        group: None,
    }];
    let statics = sim::StaticWorld::default();
    let mut model = SocialForce::new(&people, &statics, 0.2, params(true));
    let frames = walk(&mut model, 12.0, far);
    let at = |t: f64| frames[(t / TICK).round() as usize][0].center;
    let social = (at(11.0) - at(4.0)).norm() / 7.0;
    let scripted_at = |t| people[0].position(t);
    let scripted = (scripted_at(11.0) - scripted_at(4.0)).norm() / 7.0;
    println!("alone: {social:.4} m/s, scripted {scripted:.4} m/s");
    assert!((social - 1.2).abs() < 0.05 * 1.2, "{social}");
    assert!((scripted - 1.2).abs() < 1e-9);
    // Standing before their start time.
    assert!(frames[(0.9 / TICK) as usize][0].center.coords.norm() < 1e-9);
}

/// A call at an earlier time than the last starts over (an episode restarted).
#[test]
fn time_going_back_starts_over() {
    let people = [Person {
        path: vec![(0.0, 0.0), (5.0, 0.0)],
        speed: 1.0,
        start: 0.0,
        radius: 0.25,
        walk: sim::Walk::Once,
        group: None,
    }];
    let statics = sim::StaticWorld::default();
    let mut model = SocialForce::new(&people, &statics, 0.2, params(true));
    let first = walk(&mut model, 3.0, far);
    let again = walk(&mut model, 3.0, far);
    assert_eq!(first, again);
    assert!(first.last().unwrap()[0].center.x > 2.0);
}

/// The scenario key: `Scripted` by default, `SocialForce(( .. ))` parsed and checked,
/// and a navigation run among social force people.
#[test]
fn chosen_by_the_scenario() {
    let person = "(path: [(4.0, 0.5), (4.0, 2.5)], speed: 1.2, walk: BackAndForth)";
    let (sc, _) = scenario("size: (6.0, 3.0)", person, "");
    assert_eq!(sc.people_model, PeopleModelKind::Scripted);
    let text = format!(
        "SimScenario(name: \"sf\", world: (size: (6.0, 3.0)), people: [{person}], \
         start: (0.5, 1.5), goal: (5.5, 1.5), \
         people_model: SocialForce((sees_robot: true, view_deg: 180.0)))"
    );
    let path = Path::new("sf.ron");
    let sc = Scenario::parse(&text, path).unwrap();
    let world = sc.build_world(path).unwrap();
    let PeopleModelKind::SocialForce(p) = sc.people_model else {
        panic!("{:?}", sc.people_model)
    };
    assert!(p.sees_robot);
    assert_eq!((p.view_deg, p.person_strength), (180.0, 2.1));
    // The engine moves them: the trace's people are the social force model's.
    drives_among(&sc, &world);
    bad_parameter_is_named(
        "SocialForce((person_range: -1.0))",
        "person_range",
        "speeed",
    );
}

/// A driven episode restarted ([`sim::Driven::reset`]) replays the social force people
/// exactly: the model starts over when time goes back.
#[test]
fn a_reset_episode_replays() {
    let text = "SimScenario(name: \"sf\", world: (size: (6.0, 3.0)), \
                people: [(path: [(4.0, 0.5), (1.0, 2.5)], speed: 1.2, walk: BackAndForth)], \
                start: (0.5, 1.5), goal: (5.5, 1.5), people_model: SocialForce(()))";
    let path = Path::new("sf.ron");
    let sc = Scenario::parse(text, path).unwrap();
    let world = sc.build_world(path).unwrap();
    let mut robot = sim::Driven::new(&sc, &world, 3);
    let command = sim::Twist { v: 0.3, omega: 0.1 };
    let episode = |robot: &mut sim::Driven<'_>| {
        (0..40)
            .map(|_| robot.step(command).people.clone())
            .collect::<Vec<_>>()
    };
    let first = episode(&mut robot);
    robot.reset(3);
    let again = episode(&mut robot);
    assert_eq!(first, again);
    // They walked: not a standstill replayed.
    let (start, end) = (first[0][0].center, first[39][0].center);
    assert!((end - start).norm() > 2.0, "{start} {end}");
}
