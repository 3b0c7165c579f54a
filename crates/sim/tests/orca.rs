//! ORCA people (`sim::Orca`): head-on passes, RVO2's circle, walls, the robot seen or
//! not, determinism, and the scenario key.

use std::path::Path;

use hyplan_core::Point2;

use crate::reacting::{bad_parameter_is_named, closest_gap, drives_among, far, scenario, walk};
use sim::{
    Disc, Orca, OrcaParams, PeopleModel, PeopleModelKind, Person, Scenario, SocialForce,
    SocialForceParams, StaticWorld, Walk,
};

fn params(sees_robot: bool) -> OrcaParams {
    OrcaParams {
        sees_robot,
        ..OrcaParams::default()
    }
}

/// Two people walking head-on along one line in an open space pass each other without
/// their bodies touching, and both reach their goals.
#[test]
fn head_on_in_the_open() {
    let (_, world) = scenario(
        "size: (12.0, 4.0)",
        "(path: [(1.0, 2.0), (11.0, 2.0)], speed: 1.3), \
         (path: [(11.0, 2.0), (1.0, 2.0)], speed: 1.3)",
        "",
    );
    let mut model = Orca::new(&world.people, &world.statics, 0.2, params(true));
    let frames = walk(&mut model, 20.0, far);
    let closest = closest_gap(&frames);
    println!("ORCA head-on: closest gap {closest:.4} m");
    assert!(closest > 0.0, "bodies overlap: gap {closest}");
    let last = frames.last().unwrap();
    assert!(
        (last[0].center - Point2::new(11.0, 2.0)).norm() < 0.05,
        "{last:?}"
    );
    assert!(
        (last[1].center - Point2::new(1.0, 2.0)).norm() < 0.05,
        "{last:?}"
    );
}

/// RVO2's `Circle` example (its `examples/Circle.cpp`: agents evenly on a circle, each
/// bound for the antipodal point), scaled to people: 12 people of radius 0.25 m at 1 m/s
/// on a circle of radius 2 m (RVO2: 250 agents of 1.5 m on 200 m). Every body stays off
/// every other at every 5 ms tick, to within 1e-3 m (ORCA avoids contact exactly in
/// continuous time; the `f32` half-planes and the discrete step leave at most that), and
/// everyone ends at their antipode.
#[test]
fn rvo2_circle() {
    let n = 12;
    let people: Vec<Person> = (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            let (x, y) = (2.0 * a.cos(), 2.0 * a.sin());
            Person {
                path: vec![(x, y), (-x, -y)],
                speed: 1.0,
                start: 0.0,
                radius: 0.25,
                walk: Walk::Once,
                group: None,
            }
        })
        .collect();
    let statics = StaticWorld::default();
    let mut model = Orca::new(&people, &statics, 0.2, params(true));
    let frames = walk(&mut model, 30.0, far);
    let closest = closest_gap(&frames);
    println!("ORCA circle of {n}: closest gap {closest:.5} m");
    assert!(closest > -1e-3, "bodies overlap: gap {closest}");
    let last = frames.last().unwrap();
    for (d, p) in last.iter().zip(&people) {
        let goal = Point2::new(p.path[1].0, p.path[1].1);
        assert!(
            (d.center - goal).norm() < 0.05,
            "{:?} short of {goal}",
            d.center
        );
    }
    // They did have to avoid each other: the straight lines all cross at the centre.
    assert!(closest < 0.5, "{closest}");
}

/// A straight route blocked by a slanting wall: the person slides along it and goes
/// around its end without their body touching it, and arrives; the scripted walker walks
/// through it. The same wall square across the route holds them in front of it (ORCA is
/// local, see `Orca`'s doc), still without touching it.
#[test]
fn around_a_wall() {
    let run = |wall: &str| {
        let (_, world) = scenario(
            &format!("size: (12.0, 6.0), shapes: [{wall}]"),
            "(path: [(1.0, 2.0), (11.0, 2.0)], speed: 1.3)",
            "",
        );
        let touches = |d: &Disc| {
            world.statics.inside(d.center) || world.statics.nearest(d.center).0 < d.radius
        };
        let scripted = walk(&mut sim::Scripted::new(&world.people), 12.0, far);
        assert!(
            scripted.iter().any(|f| touches(&f[0])),
            "the route must be blocked"
        );
        let mut model = Orca::new(&world.people, &world.statics, 0.2, params(true));
        let frames = walk(&mut model, 20.0, far);
        let clearance = frames
            .iter()
            .map(|f| world.statics.nearest(f[0].center).0 - f[0].radius)
            .fold(f64::INFINITY, f64::min);
        println!("ORCA {wall}: smallest body clearance {clearance:.4} m");
        assert!(
            !frames.iter().any(|f| touches(&f[0])),
            "clearance {clearance}"
        );
        frames.last().unwrap()[0].center
    };
    let end = run("Wall(from: (5.5, 0.5), to: (6.5, 3.0), thickness: 0.2)");
    assert!(
        (end - Point2::new(11.0, 2.0)).norm() < 0.05,
        "ended at {end:?}"
    );
    let held = run("Wall(from: (6.0, 0.5), to: (6.0, 3.0), thickness: 0.2)");
    assert!(held.x < 6.0, "ended at {held:?}");
}

/// A call at an earlier time than the last starts over (an episode restarted).
#[test]
fn time_going_back_starts_over() {
    let people = [Person {
        path: vec![(0.0, 0.0), (5.0, 0.0)],
        speed: 1.0,
        start: 0.0,
        radius: 0.25,
        walk: Walk::Once,
        group: None,
    }];
    let statics = StaticWorld::default();
    let mut model = Orca::new(&people, &statics, 0.2, params(true));
    let first = walk(&mut model, 3.0, far);
    let again = walk(&mut model, 3.0, far);
    assert_eq!(first, again);
    assert!(first.last().unwrap()[0].center.x > 2.5);
    // Standing before their start, then at the scripted pace.
    let late = [Person {
        start: 1.0,
        ..people[0].clone()
    }];
    let mut model = Orca::new(&late, &statics, 0.2, params(true));
    let frames = walk(&mut model, 3.0, far);
    assert_eq!(frames[150][0].center, Point2::origin());
    assert!(
        (frames[600][0].center.x - 2.0).abs() < 0.02,
        "{:?}",
        frames[600]
    );
}

/// The scenario key: `Orca(( .. ))` parsed and checked, and a navigation run among ORCA
/// people.
#[test]
fn chosen_by_the_scenario() {
    let person = "(path: [(4.0, 0.5), (4.0, 2.5)], speed: 1.2, walk: BackAndForth)";
    let text = format!(
        "SimScenario(name: \"orca\", world: (size: (6.0, 3.0)), people: [{person}], \
         start: (0.5, 1.5), goal: (5.5, 1.5), people_model: Orca((sees_robot: false)))"
    );
    let path = Path::new("orca.ron");
    let sc = Scenario::parse(&text, path).unwrap();
    let world = sc.build_world(path).unwrap();
    let PeopleModelKind::Orca(p) = sc.people_model else {
        panic!("{:?}", sc.people_model)
    };
    assert!(!p.sees_robot);
    assert_eq!(
        p,
        OrcaParams {
            sees_robot: false,
            ..OrcaParams::default()
        }
    );
    drives_among(&sc, &world);
    bad_parameter_is_named("Orca((time_horizon: -1.0))", "time_horizon", "time_horizn");
    bad_parameter_is_named("Orca((step: -1.0))", "step", "stepp");
}

/// The cost of one `people` call (one 5 ms tick) with 20 people crossing an open 10 m
/// room, ORCA against social forces. Run it with
/// `cargo test -p sim --release --test main -- --ignored --nocapture orca::cost`.
#[test]
#[ignore = "a timing, not a check"]
fn cost_of_twenty_people() {
    let people: Vec<Person> = (0..20)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 20.0;
            let (x, y) = (5.0 + 4.0 * a.cos(), 5.0 + 4.0 * a.sin());
            Person {
                path: vec![(x, y), (10.0 - x, 10.0 - y)],
                speed: 1.0 + 0.02 * k as f64,
                start: 0.0,
                radius: 0.25,
                walk: Walk::BackAndForth,
                group: None,
            }
        })
        .collect();
    let text = "SimScenario(name: \"room\", world: (size: (10.0, 10.0), shapes: [\
                Wall(from: (0.0, 0.0), to: (10.0, 0.0), thickness: 0.1), \
                Wall(from: (10.0, 0.0), to: (10.0, 10.0), thickness: 0.1), \
                Wall(from: (10.0, 10.0), to: (0.0, 10.0), thickness: 0.1), \
                Wall(from: (0.0, 10.0), to: (0.0, 0.0), thickness: 0.1)]), \
                start: (0.5, 0.5), goal: (1.0, 0.5))";
    let path = Path::new("room.ron");
    let world = Scenario::parse(text, path)
        .unwrap()
        .build_world(path)
        .unwrap();
    let ticks = 4000_u64;
    let time = |model: &mut dyn PeopleModel| {
        let started = std::time::Instant::now();
        for k in 0..=ticks {
            std::hint::black_box(model.people(sim::time_of(k), far(0.0)));
        }
        started.elapsed().as_secs_f64() / (ticks + 1) as f64
    };
    let mut orca = Orca::new(&people, &world.statics, 0.2, params(true));
    let mut social = SocialForce::new(&people, &world.statics, 0.2, SocialForceParams::default());
    let (o, s) = (time(&mut orca), time(&mut social));
    println!(
        "20 people, one call (5 ms tick): ORCA {:.1} us, social force {:.1} us ({:.2}x)",
        o * 1e6,
        s * 1e6,
        o / s
    );
    // The same people on a loaded map of 0.05 m cells, 20 m x 20 m, scattered with
    // 0.2 m pillars every 0.6 m outside the middle 10 m: thousands of cell edges, of
    // which ORCA's buckets hand each person those within reach.
    let side = 400;
    let rows: Vec<String> = (0..side)
        .map(|j| {
            (0..side)
                .map(|i| {
                    let centre = (100..300).contains(&i) && (100..300).contains(&j);
                    if !centre && i % 12 < 4 && j % 12 < 4 {
                        '#'
                    } else {
                        '.'
                    }
                })
                .collect()
        })
        .collect();
    let map = envmap::GridMap::from_ascii(&rows.join("\n"))
        .unwrap()
        .with_frame(0.05, Point2::new(-5.0, -5.0))
        .unwrap();
    let mut statics = StaticWorld::default();
    statics.add_grid(map);
    let mut orca = Orca::new(&people, &statics, 0.2, params(true));
    let mut social = SocialForce::new(&people, &statics, 0.2, SocialForceParams::default());
    let (o, s) = (time(&mut orca), time(&mut social));
    println!(
        "20 people among {} cell edges: ORCA {:.1} us, social force {:.1} us ({:.2}x)",
        statics.grid_segments.len(),
        o * 1e6,
        s * 1e6,
        o / s
    );
}
