//! The tutorial profile and the reference's exploration behaviours: detector compute
//! time, the filter's pool, the assigner's re-targeting, stopping at a coverage.

use std::path::{Path, PathBuf};

use hyplan_core::{Bounds, Point2};
use sim::{
    Assigner, AssignerMode, DetectorCost, FREE, Filter, FilterPool, GoalEnd, Mapping, OCCUPIED,
    OccupancyGrid, Profile, Scenario, Strategy,
};

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

fn explore_22m() -> (Scenario, sim::World) {
    let path: PathBuf =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim/explore-22m.ron");
    Scenario::load(&path).unwrap()
}

#[test]
fn profiles_set_their_keys_and_leave_the_rest() {
    let (mut sc, _) = explore_22m();
    let before = sc.clone();
    Profile::Tutorial.apply(&mut sc);
    assert_eq!(sc.controller.rate_hz, 5.0);
    assert_eq!(sc.mapping.resolution, 0.1);
    assert_eq!(sc.mapping.max_range, 50.0);
    assert_eq!(sc.mapping.period, 2.0);
    assert!((sc.robot.body_radius + sc.costmap.padding - 0.21).abs() < 1e-12);
    let r = sc.local_planner.rollout().unwrap();
    assert_eq!(
        (r.acc_lim_x, r.max_vel_x, r.window, r.resolution, r.sim_time),
        (0.05, 0.3, 1.5, 0.01, 1.7)
    );
    assert_eq!(sc.exploration.filter_pool, FilterPool::Reference);
    assert_eq!(sc.exploration.assigner_mode, AssignerMode::Reference);
    assert!(sc.exploration.detector_cost.is_some());
    // Not a profile's key.
    assert_eq!(sc.exploration.eta_global, before.exploration.eta_global);
    assert_eq!(sc.world, before.world);
    // Back to our defaults: the file says nothing of these keys, so it is the file again.
    Profile::Hyplan.apply(&mut sc);
    assert_eq!(sc, before);
}

#[test]
fn detector_cost_slows_the_trees() {
    let (mut sc, world) = explore_22m();
    sc.time_limit = 20.0;
    let free = sim::explore(&sc, &world, 1, Strategy::Both).unwrap();
    // 100 Hz for 20 s, each detector (after the first look round the detectors run too).
    assert!(
        free.detector_iterations
            .iter()
            .all(|&n| (1990..=2010).contains(&n)),
        "{:?}",
        free.detector_iterations
    );
    assert_eq!(free.detector_busy, 0.0);
    // A map copy of 0.1 us per cell: 440 x 440 cells, about 19 ms a copy.
    sc.exploration.detector_cost = Some(DetectorCost {
        cell: 1e-7,
        ..DetectorCost::reference()
    });
    let slow = sim::explore(&sc, &world, 1, Strategy::Both).unwrap();
    for k in 0..2 {
        assert!(
            slow.detector_iterations[k] * 20 < free.detector_iterations[k],
            "{:?} vs {:?}",
            slow.detector_iterations,
            free.detector_iterations
        );
    }
    // The detectors were busy most of the time: no idle period between iterations.
    assert!(slow.detector_busy > 2.0 * 19.0, "{}", slow.detector_busy);
    // The reference's constants on this small map: the loop's ceiling decides.
    sc.exploration.detector_cost = Some(DetectorCost::reference());
    let reference = sim::explore(&sc, &world, 1, Strategy::Both).unwrap();
    assert!(reference.detector_iterations[1] > 1900);
}

#[test]
fn the_reference_pool_keeps_failed_centres() {
    let mut map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(4.0, 4.0)), Mapping::default());
    // An obstacle cell under the first cluster makes its centre fail the cost test.
    map.set_value(20, 20, OCCUPIED);
    let published = [p(1.0, 1.0), p(1.05, 1.0), p(3.0, 3.0)];
    let cost = |m: &OccupancyGrid, q: Point2| {
        if q.x < 2.0 && m.value(20, 20) == OCCUPIED {
            100
        } else {
            0
        }
    };
    for (pool, kept_after) in [(FilterPool::Passed, 1), (FilterPool::Reference, 2)] {
        let mut m = map.clone();
        let mut f = Filter::new(0.3, 70, 0.5, 0.2).with_pool(pool);
        assert_eq!(f.update(&published, &m, |q| cost(&m, q), 0.5).len(), 1);
        // The obstacle is gone: a centre still in the pool passes now.
        m.set_value(20, 20, FREE);
        let again = f.update(&[], &m, |q| cost(&m, q), 0.5).len();
        assert_eq!(again, kept_after, "{pool:?}");
    }
}

#[test]
fn the_reference_assigner_prefers_frontiers_near_its_goal_while_driving() {
    let map = OccupancyGrid::new(Bounds::new(p(0.0, 0.0), p(20.0, 20.0)), Mapping::default());
    let a = Assigner {
        info_radius: 1.0,
        info_multiplier: 3.0,
        hysteresis_radius: 3.0,
        hysteresis_gain: 2.0,
        ..Default::default()
    };
    let (near_goal, near_robot) = (p(15.0, 15.0), p(7.0, 5.0));
    let robot = p(5.0, 5.0);
    // Idle: the nearer frontier wins (same gain, shorter distance, and doubled).
    assert_eq!(
        a.ranked(robot, &[near_goal, near_robot], &map)[0],
        near_robot
    );
    // Driving to (15, 14.5): the frontier by the goal scores its doubled gain.
    let driving = Some((p(15.0, 14.5), true));
    let ranked = a.ranked_with(robot, &[near_goal, near_robot], &map, driving);
    // Gains 3.14 m^2 each: near the goal 3 x 6.28 - 14.1 = 4.7; near the robot
    // 3 x 6.28 - 2 = 16.8: the robot's neighbour still wins on distance here.
    assert_eq!(ranked[0], near_robot);
    let far_robot = p(12.0, 5.0);
    let ranked = a.ranked_with(robot, &[near_goal, far_robot], &map, driving);
    // Near the goal 4.7; the other, 7 m away and not doubled: 3 x 3.14 - 7 = 2.4.
    assert_eq!(ranked[0], near_goal);
}

#[test]
fn tutorial_exploration_is_deterministic_and_stops_at_its_coverage() {
    let (mut sc, world) = explore_22m();
    Profile::Tutorial.apply(&mut sc);
    sc.exploration.stop_at_coverage = Some(0.5);
    let a = sim::explore(&sc, &world, 3, Strategy::Local).unwrap();
    let b = sim::explore(&sc, &world, 3, Strategy::Local).unwrap();
    assert_eq!(a.track, b.track);
    assert_eq!(a.coverage, b.coverage);
    assert!(!a.finished);
    // It stopped at the first map update past 50 %.
    let first = a.coverage.iter().find(|c| c.fraction >= 0.5).unwrap();
    assert!(a.end_time - first.t < 0.1, "{first:?}, end {}", a.end_time);
    assert!(
        a.goal_log
            .iter()
            .all(|g| g.end != GoalEnd::Open || g.t <= a.end_time)
    );
}
