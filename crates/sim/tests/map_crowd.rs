//! People placed on a loaded map, and people models walking on one.

use std::path::Path;

use hyplan_core::{Point2, Zone};
use sim::{MapCrowdError, PERSON_CLEARANCE, PeopleModelKind, Pose, Walk, people_on_map};

/// The AWS small house (a ROS map of a real house) as a navigation scenario's world.
fn house() -> (sim::Scenario, sim::World) {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim/nav-aws_small_house.ron");
    sim::Scenario::load(&path).unwrap()
}

fn robot(sc: &sim::Scenario) -> Point2 {
    Point2::new(sc.start.0, sc.start.1)
}

/// Every walker keeps to the floor a person fits on: their way-points are on it, each
/// leg between them is free of every cell off it (so of every wall by the clearance),
/// they start apart and away from the robot, and the count follows the density.
#[test]
fn walkers_keep_to_the_floor_a_person_fits_on() {
    let (sc, world) = house();
    let map = world.statics.grid.as_ref().unwrap();
    let walls = map.blocked_distance().unwrap();
    let res = map.resolution();
    for (seed, density) in [(1, 1.0), (2, 5.0), (3, 20.0)] {
        let mut rng = sim::stream(seed, sim::PEOPLE_STREAM);
        let crowd = people_on_map(map, density, robot(&sc), &mut rng).unwrap();
        let want = (density * crowd.floor_m2 / 100.0).round() as usize;
        assert!(crowd.floor_m2 > 50.0, "{}", crowd.floor_m2);
        // The rules (apart, away from the robot) may leave a full floor short.
        assert!(
            crowd.people.len() <= want,
            "{} > {want}",
            crowd.people.len()
        );
        assert!(
            crowd.people.len() * 10 >= want * 9,
            "{} of {want}",
            crowd.people.len()
        );
        for p in &crowd.people {
            assert_eq!(p.walk, Walk::BackAndForth);
            assert!((0.8..=1.8).contains(&p.speed), "{}", p.speed);
            assert!(p.path.len() >= 2);
            for w in p.path.windows(2) {
                let (a, b) = (Point2::new(w[0].0, w[0].1), Point2::new(w[1].0, w[1].1));
                map.segment_cells(a, b, |i, j| {
                    let clear = walls.cell_dist(i, j) * res;
                    assert!(
                        map.cell_zone(i, j) != Zone::Forbidden && clear >= PERSON_CLEARANCE,
                        "seed {seed}: leg {a} -> {b} crosses cell ({i}, {j}), {clear:.3} m from a wall"
                    );
                    true
                });
            }
            let first = Point2::new(p.path[0].0, p.path[0].1);
            assert!((first - robot(&sc)).norm() >= 1.5);
            for q in &crowd.people {
                let other = Point2::new(q.path[0].0, q.path[0].1);
                assert!(std::ptr::eq(p, q) || (first - other).norm() >= 0.6);
            }
        }
        // The same stream state, the same people.
        let again = people_on_map(
            map,
            density,
            robot(&sc),
            &mut sim::stream(seed, sim::PEOPLE_STREAM),
        )
        .unwrap();
        assert_eq!(again.people, crowd.people);
    }
}

#[test]
fn bad_densities_and_robots_in_walls_are_refused() {
    let (sc, world) = house();
    let map = world.statics.grid.as_ref().unwrap();
    let mut rng = sim::stream(0, sim::PEOPLE_STREAM);
    for d in [-1.0, f64::NAN, f64::INFINITY] {
        let e = people_on_map(map, d, robot(&sc), &mut rng).unwrap_err();
        assert!(matches!(e, MapCrowdError::Density(_)), "{e}");
        assert!(e.to_string().contains("density"), "{e}");
    }
    let none = people_on_map(map, 0.0, robot(&sc), &mut rng).unwrap();
    assert!(none.people.is_empty() && none.floor_m2 > 50.0);
    // Far outside the map: no floor to reach.
    let e = people_on_map(map, 1.0, Point2::new(1e4, 1e4), &mut rng).unwrap_err();
    assert!(matches!(e, MapCrowdError::NoFloor { .. }), "{e}");
}

/// People under ORCA on a real house's map keep their bodies out of its walls (the loaded
/// map's cell edges they avoid are those near them and those their rays find): at every
/// tenth of a second over two minutes each person is at least their radius, less 2 cm,
/// from every wall.
#[test]
fn orca_people_on_a_map_keep_out_of_its_walls() {
    let (closest, walked, alone) = orca_in_the_house(4);
    assert!(closest >= -0.02, "a person {closest:.3} m into a wall");
    // They walked, not stood: a fifth of the way they would go alone, at least (ORCA
    // people meeting head-on in the house's narrow passages hold each other up).
    assert!(walked > 0.2 * alone, "{walked:.1} m of {alone:.1} m");
}

/// The same walk for people placed with seeds 1 to 12, printed: how near the walls they
/// come and how far they walk (a measurement: `cargo test -p sim --release --test main
/// -- --ignored --nocapture orca_people_near_the_walls`).
#[test]
#[ignore = "measurement, run by hand"]
fn orca_people_near_the_walls() {
    for seed in 1..=12 {
        let (closest, walked, alone) = orca_in_the_house(seed);
        println!(
            "seed {seed}: nearest a wall {closest:.4} m beyond the radius, walked {walked:.1} m of {alone:.1} m"
        );
        assert!(closest >= -0.02, "seed {seed}: {closest:.3} m into a wall");
    }
}

/// ORCA people placed in the AWS house (5 per 100 m^2, seed `seed`) for 120 s, the robot
/// far away: the least gap between a person and a wall less their radius, sampled every
/// 0.1 s, the way they walked, and the way they would walk alone, m.
fn orca_in_the_house(seed: u64) -> (f64, f64, f64) {
    let (sc, mut world) = house();
    let map = world.statics.grid.clone().unwrap();
    let crowd = people_on_map(
        &map,
        5.0,
        robot(&sc),
        &mut sim::stream(seed, sim::PEOPLE_STREAM),
    )
    .unwrap();
    assert!(crowd.people.len() >= 4, "{}", crowd.people.len());
    world.people = crowd.people;
    let mut model = PeopleModelKind::from_name("orca")
        .unwrap()
        .build(&world, 0.2);
    let far = Pose {
        x: -100.0,
        y: -100.0,
        phi: 0.0,
    };
    let mut closest = f64::INFINITY;
    let mut walked = 0.0;

    let mut last = model.people(0.0, far);
    for tick in 1..=24_000 {
        let t = tick as f64 * 0.005;
        let now = model.people(t, far);
        if tick % 20 == 0 {
            for (d, before) in now.iter().zip(&last) {
                let (gap, _) = world.statics.nearest(d.center);
                closest = closest.min(gap - d.radius);
                walked += (d.center - before.center).norm();
            }
            last = now;
        }
    }
    let alone: f64 = world.people.iter().map(|p| p.speed * 120.0).sum();
    (closest, walked, alone)
}

/// A drawn room, 5 cm cells, top row first: `#` walls, `.` floor.
fn drawn(rows: &[String]) -> envmap::GridMap {
    envmap::GridMap::from_ascii(&rows.join("\n"))
        .and_then(|m| m.with_frame(0.05, Point2::origin()))
        .unwrap()
}

/// The least clearance (centre of the nearest blocked cell to the cell's centre) along
/// every leg of every walker's route, m.
fn least_clearance(map: &envmap::GridMap, people: &[sim::Person]) -> f64 {
    let walls = map.blocked_distance().unwrap();
    let mut least = f64::INFINITY;
    for p in people {
        for w in p.path.windows(2) {
            let (a, b) = (Point2::new(w[0].0, w[0].1), Point2::new(w[1].0, w[1].1));
            map.segment_cells(a, b, |i, j| {
                least = least.min(walls.cell_dist(i, j) * map.resolution());
                true
            });
        }
    }
    least
}

/// Routes keep the widest clearance that joins their ends: in a 6 x 4 m room with a
/// 0.3 m pillar in its middle, every leg stays 0.6 m from the pillar and the walls (a
/// route planned on the whole floor grazes the pillar at 0.35 m); across a 1 m door
/// between two such rooms, 0.45 m.
#[test]
fn routes_keep_the_widest_clearance_the_floor_offers() {
    let room = |i: usize, j: usize| {
        let wall = i == 0 || j == 0 || i == 119 || j == 79;
        let pillar = (57..63).contains(&i) && (37..43).contains(&j);
        wall || pillar
    };
    let rows: Vec<String> = (0..80)
        .map(|j| {
            (0..120)
                .map(|i| if room(i, j) { '#' } else { '.' })
                .collect()
        })
        .collect();
    let map = drawn(&rows);
    let start = Point2::new(0.6, 0.6);
    let mut people = Vec::new();
    for seed in 0..10 {
        let mut rng = sim::stream(seed, sim::PEOPLE_STREAM);
        people.extend(people_on_map(&map, 30.0, start, &mut rng).unwrap().people);
    }
    assert!(people.len() >= 50, "{}", people.len());
    let least = least_clearance(&map, &people);
    assert!(least >= sim::ROUTE_CLEARANCES[0], "{least:.3}");

    // Two such rooms side by side, a 1 m door (20 cells) through the walls between them.
    let rows: Vec<String> = (0..80)
        .map(|j| {
            (0..241)
                .map(|i| {
                    let door = (119..=120).contains(&i) && (30..50).contains(&j);
                    let wall = !door && (i == 240 || room(i % 120, j));
                    if wall { '#' } else { '.' }
                })
                .collect()
        })
        .collect();
    let map = drawn(&rows);
    let mut through = 0;
    let mut people = Vec::new();
    for seed in 0..10 {
        let mut rng = sim::stream(seed, sim::PEOPLE_STREAM);
        let crowd = people_on_map(&map, 15.0, start, &mut rng).unwrap();
        through += crowd
            .people
            .iter()
            .filter(|p| (p.path[0].0 - 6.0) * (p.path.last().unwrap().0 - 6.0) < 0.0)
            .count();
        people.extend(crowd.people);
    }
    assert!(through >= 10, "{through} routes through the door");
    let least = least_clearance(&map, &people);
    assert!(
        (sim::ROUTE_CLEARANCES[1]..sim::ROUTE_CLEARANCES[0]).contains(&least),
        "{least:.3}"
    );
}

/// People held in place by a building's walls, not by the robot: on each building map of
/// `data/ros_maps`, density 1 (20 on the small TurtleBot3 world), seeds 1 to 3, people
/// who do not look walking 120 s with no robot ([`sim::people_alone`]), the count of those
/// held in place (within `HELD_WITHIN` of one place for `HELD_FOR` or more).
#[test]
#[ignore = "a measurement, not a check"]
fn people_held_in_place_on_the_building_maps() {
    let (mut held_all, mut people_all) = ([0; 2], 0);
    for (scenario, density) in [
        ("explore-tb3.ron", 20.0),
        ("explore-aws_small_house.ron", 1.0),
        ("explore-yujin_rnd_hokuyo.ron", 1.0),
        ("explore-uos_avz5floor_open.ron", 1.0),
        ("explore-mit_building_31.ron", 1.0),
        ("explore-mit_stata_basement.ron", 1.0),
    ] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../scenarios/sim")
            .join(scenario);
        let (mut sc, mut world) = sim::Scenario::load(&path).unwrap();
        let map = world.statics.grid.clone().unwrap();
        let (mut held, mut people) = ([0; 2], 0);
        for seed in 1..=3 {
            let mut rng = sim::stream(seed, sim::PEOPLE_STREAM);
            world.people = people_on_map(&map, density, robot(&sc), &mut rng)
                .unwrap()
                .people;
            people += world.people.len();
            let models = [
                PeopleModelKind::SocialForce(sim::SocialForceParams {
                    sees_robot: false,
                    ..Default::default()
                }),
                PeopleModelKind::Orca(sim::OrcaParams {
                    sees_robot: false,
                    ..Default::default()
                }),
            ];
            for (m, kind) in models.into_iter().enumerate() {
                sc.people_model = kind;
                held[m] += sim::people_alone(&sc, &world, 120.0).held;
            }
        }
        println!(
            "{scenario}: {people} people, held 20 s or more: social forces {}, ORCA {}",
            held[0], held[1]
        );
        people_all += people;
        held_all[0] += held[0];
        held_all[1] += held[1];
    }
    println!(
        "all: {people_all} people, held: social forces {}, ORCA {}",
        held_all[0], held_all[1]
    );
}
