//! Crowd scenarios and their figures.

use std::path::Path;

use sim::{CrowdFlow, GlobalPlanner, PeopleModelKind, Pose, SocialForceParams, Walk};

/// Every flow fills its room to about the density asked for: the time-averaged count of
/// people on stage inside the room, over the run, is within 35 % of density x area / 100
/// (a Poisson stream over ten seeds).
#[test]
fn rooms_hold_the_density_asked_for() {
    for flow in CrowdFlow::ALL {
        let density = 2.0;
        let (mut sum, mut samples) = (0.0, 0.0);
        for seed in 0..10 {
            let sc = sim::crowd(flow, density, seed, 0);
            let world = sc.build_world(Path::new(&sc.name)).unwrap();
            assert!(sc.people.iter().all(|p| p.walk == Walk::Through));
            let mut model = PeopleModelKind::Scripted.build(&world, 0.2);
            let (w, h) = sc.world.size.unwrap();
            let lobby = if flow == CrowdFlow::Corridor {
                0.0
            } else {
                2.0
            };
            for k in 0..(sc.time_limit as usize) {
                let people = model.people(k as f64, Pose::default());
                sum += people
                    .iter()
                    .filter(|d| {
                        let c = d.center;
                        c.x > 0.0 && c.x < w && c.y > lobby && c.y < h - lobby
                    })
                    .count() as f64;
                samples += 1.0;
            }
        }
        let mean = sum / samples;
        let want = density * flow.area() / 100.0;
        assert!(
            (mean - want).abs() < 0.35 * want,
            "{flow}: {mean:.2} people on average, want {want:.2}"
        );
    }
}

/// A person who walks through leaves the world at the end of the route, and the meter
/// counts the arrival; the people model alone (no robot) arrives too.
#[test]
fn through_walkers_arrive_and_are_counted() {
    let sc = sim::crowd(CrowdFlow::Crossing, 1.0, 3, 0);
    let world = sc.build_world(Path::new(&sc.name)).unwrap();
    let alone = sim::people_alone(&sc, &world, 40.0).arrivals;
    let arrived = alone.iter().flatten().count();
    assert!(arrived >= 3, "{alone:?}");
    // Everyone who set off before 20 s with a clear crossing (about 14 m at >= 0.8 m/s)
    // is gone by 40 s.
    for (p, a) in sc.people.iter().zip(&alone) {
        let len: f64 = p
            .path
            .windows(2)
            .map(|s| ((s[1].0 - s[0].0).powi(2) + (s[1].1 - s[0].1).powi(2)).sqrt())
            .sum();
        if p.start + 1.5 * len / p.speed + 3.0 < 40.0 {
            assert!(a.is_some(), "{p:?}");
        }
    }
}

/// A person pushing toward a way-point behind a wall is held in place and counted; one
/// walking the corridor back and forth, or waiting to set off, is not; scripted walkers,
/// who go through walls, are never held.
#[test]
fn people_held_by_the_walls_are_counted() {
    let mut sc = sim::crowd(CrowdFlow::Corridor, 0.0, 1, 0);
    let (w, h) = sc.world.size.unwrap();
    let walker = |from: (f64, f64), to: (f64, f64), start: f64| sim::Person {
        path: vec![from, to],
        speed: 1.3,
        start,
        radius: 0.25,
        walk: Walk::BackAndForth,
        group: None,
    };
    sc.people = vec![
        walker((w - 3.0, h / 2.0), (w + 2.0, h / 2.0), 0.0),
        walker((2.0, h / 2.0 + 0.8), (w - 4.0, h / 2.0 + 0.8), 0.0),
        walker((2.0, h / 2.0 - 0.8), (w - 4.0, h / 2.0 - 0.8), 50.0),
    ];
    sc.people_model = PeopleModelKind::SocialForce(SocialForceParams {
        sees_robot: false,
        ..Default::default()
    });
    let world = sc.build_world(Path::new(&sc.name)).unwrap();
    assert_eq!(world.people.len(), 3);
    assert_eq!(sim::people_alone(&sc, &world, 60.0).held, 1);
    // Not for as long as HELD_FOR.
    assert_eq!(sim::people_alone(&sc, &world, sim::HELD_FOR - 1.0).held, 0);
    sc.people_model = PeopleModelKind::Scripted;
    let world = sc.build_world(Path::new(&sc.name)).unwrap();
    assert_eq!(sim::people_alone(&sc, &world, 60.0).held, 0);
}

/// A run among people who see the robot: reached, no at-fault contact, the figures
/// filled in and consistent (the time alone is the time of the empty room).
#[test]
fn a_run_among_people_is_measured() {
    let sc = sim::crowd(CrowdFlow::Doors, 1.0, 1, 0);
    let world = sc.build_world(Path::new(&sc.name)).unwrap();
    let m = sim::measure(&sc, &world, 0, || GlobalPlanner::Dijkstra);
    assert!(m.reached, "{m:?}");
    assert_eq!(m.contacts_at_fault, 0, "{m:?}");
    let empty = sim::crowd(CrowdFlow::Doors, 0.0, 1, 0);
    let world0 = empty.build_world(Path::new(&empty.name)).unwrap();
    let alone = sim::run(&empty, &world0, 0, GlobalPlanner::Dijkstra);
    assert_eq!(m.travel_time_alone, alone.trace.summary.travel_time);
    assert!(m.time_ratio().unwrap() >= 0.99, "{m:?}");
    assert!(m.path_length > 13.0, "{m:?}");
    assert!(m.sightings > 0 && m.missed <= m.sightings, "{m:?}");
}

/// Members of a group under social forces stay within a couple of metres of each other
/// while they walk.
#[test]
fn groups_keep_together() {
    let mut sc = sim::crowd(CrowdFlow::Corridor, 2.0, 5, 0);
    sc.people_model = PeopleModelKind::SocialForce(SocialForceParams::default());
    let world = sc.build_world(Path::new(&sc.name)).unwrap();
    let pairs: Vec<(usize, usize)> = (0..sc.people.len())
        .flat_map(|i| (i + 1..sc.people.len()).map(move |j| (i, j)))
        .filter(|&(i, j)| sc.people[i].group.is_some() && sc.people[i].group == sc.people[j].group)
        .collect();
    assert!(!pairs.is_empty());
    let mut model = sc.people_model.build(&world, 0.2);
    let far = Pose {
        x: 1e6,
        y: 1e6,
        phi: 0.0,
    };
    let mut worst: f64 = 0.0;
    for tick in 0..(40 * 200) {
        let people = model.people(tick as f64 * 0.005, far);
        for &(i, j) in &pairs {
            let (a, b) = (people[i].center, people[j].center);
            if a.x > -1e5 && b.x > -1e5 {
                worst = worst.max((a - b).norm());
            }
        }
    }
    assert!(worst < 2.5, "group members {worst:.2} m apart");
}

/// ORCA people come in, cross and leave too, and a run among them is measured: reached,
/// no at-fault contact, people who left in both runs.
#[test]
fn orca_crowds_walk_through() {
    let mut sc = sim::crowd(CrowdFlow::Crossing, 1.0, 2, 0);
    sc.people_model = PeopleModelKind::from_name("orca").unwrap();
    let world = sc.build_world(Path::new(&sc.name)).unwrap();
    let m = sim::measure(&sc, &world, 0, || GlobalPlanner::Dijkstra);
    assert!(m.reached, "{m:?}");
    assert_eq!(m.contacts_at_fault, 0, "{m:?}");
    assert!(m.people_arrived >= 2, "{m:?}");
}

/// Doors room `index` of `cargo xtask crowd` (seed 2026, density 1) with people who do
/// not look (social forces), run at `fov` degrees with or without the collision monitor:
/// the run's at-fault contacts, after checking that it reached the goal when there are
/// none.
fn blind_doors_at_fault(index: u64, fov: f64, monitor: bool) -> usize {
    let mut sc = sim::crowd(CrowdFlow::Doors, 1.0, 2026, index);
    assert!(sc.navigation.collision_monitor.is_some());
    sc.laser = sc.laser.with_fov(fov);
    if !monitor {
        sc.navigation.collision_monitor = None;
    }
    sc.people_model = PeopleModelKind::from_name("social-force-blind").unwrap();
    let world = sc.build_world(Path::new(&sc.name)).unwrap();
    let out = sim::run(&sc, &world, index, GlobalPlanner::Dijkstra);
    let at_fault = out.trace.summary.contacts_at_fault;
    assert!(
        at_fault > 0 || out.trace.summary.reached,
        "{:?}",
        out.trace.contacts
    );
    at_fault
}

/// A person who does not look walks into the robot's side from behind it, seen at the
/// edge of a 180-degree laser's view a moment before contact (doors room 149, regulated
/// pure pursuit). Without the collision monitor the robot still creeps toward them at
/// contact (at fault); with it (the crowd scenarios' default) it has stopped.
#[test]
fn the_collision_monitor_stops_before_a_blind_walker_arrives() {
    assert_eq!(blind_doors_at_fault(149, 180.0, true), 0);
    assert!(blind_doors_at_fault(149, 180.0, false) > 0);
}

/// A person who does not look comes from behind beside the moving robot (doors room 5):
/// seed 004's 180-degree laser sees them level with the robot, too late to stop, and the
/// contact is the robot's fault even with the collision monitor; the crowd robot's
/// 270-degree scanner ([`sim::CROWD_FOV_DEG`]) sees them in time.
#[test]
fn the_crowd_robot_sees_a_walker_coming_from_behind() {
    assert_eq!(blind_doors_at_fault(5, sim::CROWD_FOV_DEG, true), 0);
    assert!(blind_doors_at_fault(5, 180.0, true) > 0);
}

/// People who see the robot crowd round it in the corridor (crowd 2026 / 230, social
/// forces, regulated pure pursuit): counted as failures, their blocks make the navigator
/// give up after eight in a row; waited for (the crowd scenarios' `people_patience`),
/// they walk on and the robot arrives.
#[test]
fn the_robot_waits_for_people_instead_of_giving_up() {
    let mut sc = sim::crowd(CrowdFlow::Corridor, 1.0, 2026, 230);
    assert_eq!(sc.navigation.people_patience, sim::PEOPLE_PATIENCE);
    let world = sc.build_world(Path::new(&sc.name)).unwrap();
    let waited = sim::run(&sc, &world, 230, GlobalPlanner::Dijkstra);
    assert!(waited.trace.summary.reached);
    sc.navigation.people_patience = 0.0;
    let counted = sim::run(&sc, &world, 230, GlobalPlanner::Dijkstra);
    assert!(!counted.trace.summary.reached);
    assert!(
        counted
            .trace
            .events
            .iter()
            .any(|e| e.kind == sim::EventKind::Nav(sim::NavEvent::GaveUp))
    );
}

/// The crowd scenarios in `scenarios/sim/` are the generator's, unchanged: written by
/// `cargo xtask crowd --write-scenarios scenarios/sim`, read back equal.
#[test]
fn the_shipped_crowd_files_are_the_generators() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim");
    for flow in CrowdFlow::ALL {
        let path = dir.join(format!("crowd-{flow}.ron"));
        let text = std::fs::read_to_string(&path).unwrap();
        let read = sim::Scenario::parse(&text, &path).unwrap();
        assert_eq!(read, sim::crowd(flow, 1.0, 2026, 0), "{}", path.display());
    }
}
