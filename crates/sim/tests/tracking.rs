//! People's velocities from successive scans, and the controller's use of them.

use hyplan_core::{Bounds, Point2};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use sim::Disc;
use sim::{Laser, LaserModel, Shape, StaticWorld, Tracker};

fn room() -> (Bounds, StaticWorld) {
    let mut walls = StaticWorld::default();
    walls.add_shape(&Shape::Wall {
        from: (0.1, 0.1),
        to: (9.9, 0.1),
        thickness: 0.2,
    });
    walls.add_shape(&Shape::Box {
        center: (3.0, 7.0),
        size: (0.6, 0.6),
        angle_deg: 0.0,
    });
    let bounds = Bounds::new(Point2::new(0.0, 0.0), Point2::new(10.0, 10.0));
    (bounds, walls)
}

/// A tracker fed a noisy scan every 5 ticks (200 ticks a second) up to `last_tick`, in
/// the room: `scene(t)` gives the scanner's position and the people at `t` s, and
/// `each` looks at the tracker after every update.
fn watch(
    seed: u64,
    last_tick: u64,
    scene: impl Fn(f64) -> (Point2, Vec<Disc>),
    mut each: impl FnMut(&Tracker, u64),
) -> Tracker {
    let (bounds, walls) = room();
    let laser = LaserModel::new(Laser::default());
    let mut tracker = Tracker::new(bounds, &walls, 3.5, 200.0);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for tick in (0..=last_tick).step_by(5) {
        let (origin, people) = scene(tick as f64 / 200.0);
        let mut scan = laser.cast(&walls, &people, origin, std::f64::consts::FRAC_PI_2);
        laser.add_noise(&mut scan, &mut rng);
        tracker.update(&scan, tick);
        each(&tracker, tick);
    }
    tracker
}

#[test]
fn a_walking_person_is_tracked_with_their_velocity() {
    // The person walks right to left across the scanner's view at 0.3 m/s, 2 m ahead.
    let walking = |t: f64| {
        let person = Disc {
            center: Point2::new(6.0 - 0.3 * t, 4.0),
            radius: 0.25,
        };
        (Point2::new(5.0, 2.0), vec![person])
    };
    let tracker = watch(3, 200, walking, |_, _| {});
    let movers = tracker.movers(200);
    assert_eq!(movers.len(), 1, "{movers:?}");
    let m = movers[0];
    assert!(
        (m.velocity.x + 0.3).abs() < 0.05 && m.velocity.y.abs() < 0.05,
        "{m:?}"
    );
    // The centroid of the visible side lies between the surface and the centre.
    assert!((m.center - Point2::new(5.7, 4.0)).norm() < 0.3, "{m:?}");
}

#[test]
fn static_things_are_not_movers() {
    // A pillar off the prior map and a standing person, seen by a scanner that drives
    // past them at 0.3 m/s.
    let still = vec![
        Disc {
            center: Point2::new(4.0, 3.5),
            radius: 0.2,
        },
        Disc {
            center: Point2::new(6.0, 3.0),
            radius: 0.25,
        },
    ];
    let passing = |t: f64| (Point2::new(3.0 + 0.3 * t, 1.5), still.clone());
    let tracker = watch(4, 400, passing, |tracker, tick| {
        // The mapped wall and box never show up as movers.
        assert!(
            tracker
                .movers(tick)
                .iter()
                .all(|m| m.center.y > 2.0 && m.center.y < 6.0),
            "{:?}",
            tracker.movers(tick)
        );
    });
    for m in tracker.movers(400) {
        assert!(m.velocity.norm() < 0.15, "{m:?}");
    }
}

/// Soak rooms whose at-fault contacts (a person walking at the robot's side toward it,
/// seen but not anticipated) led to the tracker: each must now pass without one.
#[test]
fn soak_rooms_that_had_at_fault_contacts() {
    for k in [18, 47, 117, 205] {
        let sc = sim::room(2026, k);
        let world = sc.build_world(std::path::Path::new(&sc.name)).unwrap();
        let out = sim::run(&sc, &world, k, sim::GlobalPlanner::Dijkstra);
        assert_eq!(out.trace.summary.contacts_at_fault, 0, "room {k}");
    }
}
