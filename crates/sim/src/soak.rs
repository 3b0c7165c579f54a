//! The safety soak: generated rooms with people crossing the robot's way.
//!
//! Room `k` of a soak with seed `s` is generated from its own ChaCha8 stream
//! (`seed_from_u64(s)`, stream `k`), so any room can be replayed alone:
//! - a rectangle of 8-14 m by 6-10 m with boundary walls;
//! - 2-5 boxes or pillars (0.3-1.2 m), kept 1 m away from the start and the goal;
//! - start 1 m from the left wall, goal 1 m from the right wall, at random heights;
//! - 1-3 people walking across the room (bottom to top or back) at 0.1 m/s up to the
//!   robot's top speed, setting off within the first 20 s, once or back and forth.
//!
//! Every default of the robot, laser (720 beams at 40 Hz), map, costmap, controller and
//! navigator applies; the local planner is regulated pure pursuit unless [`soak_with`]
//! is given another.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use crate::kinematics::Robot;
use crate::planner::GlobalPlanner;
use crate::rollout::LocalPlanner;
use crate::scenario::Scenario;
use crate::world::{Person, Shape, Walk};

/// The generated room `index` of a soak seeded `seed`, its people walking at 0.1 m/s up
/// to the robot's top speed: [`room_at`].
#[must_use]
pub fn room(seed: u64, index: u64) -> Scenario {
    room_at(seed, index, (0.1, Robot::default().v_max))
}

/// The generated room `index` of a soak seeded `seed`, each person's walking speed drawn
/// uniformly from `speeds` (low, high), m/s: [`room`]'s rooms, but for the people's
/// speeds (the same draws, so the same geometry and routes).
///
/// ```
/// let walking = sim::room_at(7, 3, (0.8, 1.6));
/// let slow = sim::room(7, 3);
/// assert_eq!(walking.world.shapes, slow.world.shapes);
/// assert!(walking.people.iter().all(|p| (0.8..=1.6).contains(&p.speed)));
/// ```
#[must_use]
pub fn room_at(seed: u64, index: u64, speeds: (f64, f64)) -> Scenario {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index);
    let w: f64 = rng.random_range(8.0..14.0);
    let h: f64 = rng.random_range(6.0..10.0);
    let t = 0.2;
    let mut shapes = vec![
        Shape::Wall {
            from: (0.1, 0.1),
            to: (w - 0.1, 0.1),
            thickness: t,
        },
        Shape::Wall {
            from: (w - 0.1, 0.1),
            to: (w - 0.1, h - 0.1),
            thickness: t,
        },
        Shape::Wall {
            from: (w - 0.1, h - 0.1),
            to: (0.1, h - 0.1),
            thickness: t,
        },
        Shape::Wall {
            from: (0.1, h - 0.1),
            to: (0.1, 0.1),
            thickness: t,
        },
    ];
    let start = (1.0, rng.random_range(1.0..h - 1.0));
    let goal = (w - 1.0, rng.random_range(1.0..h - 1.0));
    let n_obstacles = rng.random_range(2..=5);
    let mut placed = 0;
    for _ in 0..100 {
        if placed == n_obstacles {
            break;
        }
        let c: (f64, f64) = (
            rng.random_range(1.5..w - 1.5),
            rng.random_range(0.8..h - 0.8),
        );
        let size: (f64, f64) = (rng.random_range(0.3..1.2), rng.random_range(0.3..1.2));
        let far = |p: (f64, f64)| {
            ((c.0 - p.0).powi(2) + (c.1 - p.1).powi(2)).sqrt() > 1.0 + size.0.max(size.1)
        };
        if !(far(start) && far(goal)) {
            continue;
        }
        shapes.push(if rng.random_bool(0.3) {
            Shape::Disc {
                center: c,
                radius: size.0 / 2.0,
            }
        } else {
            Shape::Box {
                center: c,
                size,
                angle_deg: rng.random_range(0.0..90.0),
            }
        });
        placed += 1;
    }
    let people = (0..rng.random_range(1..=3))
        .map(|_| {
            let x = rng.random_range(2.5..w - 2.5);
            let (a, b) = ((x, 0.5), (x, h - 0.5));
            let path = if rng.random_bool(0.5) {
                vec![a, b]
            } else {
                vec![b, a]
            };
            Person {
                path,
                speed: rng.random_range(speeds.0..=speeds.1),
                start: rng.random_range(0.0..20.0),
                radius: 0.25,
                walk: if rng.random_bool(0.5) {
                    Walk::Once
                } else {
                    Walk::BackAndForth
                },
                group: None,
            }
        })
        .collect();
    Scenario::generated(
        (format!("soak-{seed}-{index}"), "generated room".into()),
        ((w, h), shapes),
        people,
        (start, rng.random_range(-180.0..180.0), goal),
        90.0,
    )
}

/// Totals of a soak.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct SoakSummary {
    /// Rooms run.
    pub rooms: u64,
    /// Rooms refused by validation (a person or a box on the start), not run.
    pub invalid: u64,
    /// Goals reached.
    pub reached: u64,
    /// Contacts the robot caused (moving toward the obstacle).
    pub contacts_at_fault: u64,
    /// Contacts while the robot stood still.
    pub contacts_robot_stopped: u64,
    /// Contacts while the robot moved, but not toward the obstacle.
    pub contacts_not_approaching: u64,
    /// Rooms with an at-fault contact (`room` index).
    pub at_fault_rooms: Vec<u64>,
    /// Simulated seconds.
    pub simulated_s: f64,
}

/// Runs rooms `0..n` of a soak seeded `seed` (each run seeded with its index), driven by
/// regulated pure pursuit: [`soak_with`] and [`LocalPlanner::Rpp`].
#[must_use]
pub fn soak(seed: u64, n: u64) -> SoakSummary {
    soak_with(seed, n, LocalPlanner::Rpp)
}

/// Runs rooms `0..n` of a soak seeded `seed` (each run seeded with its index), each room's
/// `local_planner` replaced by `local`.
///
/// ```no_run
/// let s = sim::soak_with(2026, 12, sim::LocalPlanner::Trajectory(Default::default()));
/// println!("{} of {} reached, {} at-fault contacts", s.reached, s.rooms, s.contacts_at_fault);
/// ```
#[must_use]
pub fn soak_with(seed: u64, n: u64, local: LocalPlanner) -> SoakSummary {
    soak_each(seed, n, |sc| sc.local_planner = local)
}

/// Runs rooms `0..n` of a soak seeded `seed`, each room's scenario changed by `set` first
/// (a [`Profile`](crate::Profile), a local planner...).
///
/// ```no_run
/// let s = sim::soak_each(2026, 12, |sc| sim::Profile::Tutorial.apply(sc));
/// println!("{} of {} reached, {} at-fault contacts", s.reached, s.rooms, s.contacts_at_fault);
/// ```
#[must_use]
pub fn soak_each(seed: u64, n: u64, set: impl Fn(&mut Scenario)) -> SoakSummary {
    soak_rooms(seed, n, room, set)
}

/// Runs rooms `0..n` of a soak seeded `seed`, each made by `make(seed, index)` ([`room`],
/// or [`room_at`] with other walking speeds) and changed by `set`.
///
/// ```no_run
/// // The soak at walking speed, people under social forces who do not see the robot.
/// let s = sim::soak_rooms(2026, 12, |s, k| sim::room_at(s, k, (0.8, 1.6)), |sc| {
///     sc.people_model = sim::PeopleModelKind::SocialForce(sim::SocialForceParams {
///         sees_robot: false,
///         ..Default::default()
///     });
/// });
/// println!("{} of {} reached", s.reached, s.rooms);
/// ```
#[must_use]
pub fn soak_rooms(
    seed: u64,
    n: u64,
    make: impl Fn(u64, u64) -> Scenario,
    set: impl Fn(&mut Scenario),
) -> SoakSummary {
    let mut s = SoakSummary::default();
    for k in 0..n {
        let mut sc = make(seed, k);
        set(&mut sc);
        let Ok(world) = sc.build_world(std::path::Path::new(&sc.name)) else {
            s.invalid += 1;
            continue;
        };
        let out = crate::run(&sc, &world, k, GlobalPlanner::Dijkstra);
        let m = &out.trace.summary;
        s.rooms += 1;
        s.reached += u64::from(m.reached);
        s.contacts_at_fault += m.contacts_at_fault as u64;
        s.contacts_robot_stopped += m.contacts_robot_stopped as u64;
        s.contacts_not_approaching += m.contacts_not_approaching as u64;
        if m.contacts_at_fault > 0 {
            s.at_fault_rooms.push(k);
        }
        s.simulated_s += m.end_time;
    }
    s
}
