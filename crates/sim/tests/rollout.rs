//! The trajectory roll-out local planner (`base_local_planner`'s Trajectory Rollout and
//! DWA) on seed 004's three navigation scenarios.

use std::path::PathBuf;

use sim::{GlobalPlanner, LocalPlanner, Rollout, Scenario};

fn scenarios() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim")
}

const FILES: [&str; 3] = ["1-free.ron", "2-static.ron", "3-person.ron"];

fn with(planner: &str, file: &str) -> (Scenario, sim::World) {
    let (mut sc, world) = Scenario::load(&scenarios().join(file)).unwrap();
    sc.local_planner = LocalPlanner::from_name(planner, None).unwrap();
    (sc, world)
}

/// Time to goal, omega peak and stops of a run, for the report.
fn figures(out: &sim::Outcome) -> (Option<f64>, f64, usize) {
    let m = &out.trace.summary;
    let peak = out
        .trace
        .rows
        .iter()
        .map(|r| r.omega.abs())
        .fold(0.0, f64::max);
    (m.travel_time, peak, m.stops)
}

#[test]
fn rollout_reaches_the_goal_without_fault_within_limits() {
    // Regulated pure pursuit too, for the figures beside the roll-out's.
    for planner in ["rpp", "trajectory", "dwa"] {
        for file in FILES {
            let (sc, world) = with(planner, file);
            let started = std::time::Instant::now();
            let out = sim::run(&sc, &world, 1, GlobalPlanner::Dijkstra);
            let wall = started.elapsed().as_secs_f64();
            let m = &out.trace.summary;
            let (time, peak, stops) = figures(&out);
            println!(
                "{planner} {}: goal {time:?} s, omega peak {peak:.3} rad/s, stops {stops}, \
                 at fault {}, wall {wall:.3} s",
                sc.name, m.contacts_at_fault
            );
            assert!(m.reached, "{planner} {}", sc.name);
            assert_eq!(m.contacts_at_fault, 0, "{planner} {}", sc.name);
            let dt = 1.0 / sc.controller.rate_hz;
            let mut prev: Option<&sim::Row> = None;
            for r in &out.trace.rows {
                assert!(r.v >= 0.0 && r.v <= sc.robot.v_max + 1e-12);
                assert!(r.omega.abs() <= sc.robot.omega_max + 1e-12);
                assert!(r.wheel_right.abs() <= sc.robot.max_wheel_speed + 1e-9);
                assert!(r.wheel_left.abs() <= sc.robot.max_wheel_speed + 1e-9);
                if let Some(p) = prev {
                    assert!(
                        (r.v - p.v).abs() <= sc.robot.acc_v * dt + 1e-9,
                        "{planner} {} at {}",
                        sc.name,
                        r.t
                    );
                    assert!(
                        (r.omega - p.omega).abs() <= sc.robot.acc_omega * dt + 1e-9,
                        "{planner} {} at {}",
                        sc.name,
                        r.t
                    );
                }
                prev = Some(r);
            }
        }
    }
}

/// Selecting regulated pure pursuit by name drives exactly as a file that names no
/// local planner.
#[test]
fn rpp_selected_is_the_default() {
    let (plain, world) = Scenario::load(&scenarios().join("3-person.ron")).unwrap();
    assert_eq!(plain.local_planner, LocalPlanner::Rpp);
    let (chosen, _) = with("rpp", "3-person.ron");
    let a = sim::run(&plain, &world, 1, GlobalPlanner::Dijkstra);
    let b = sim::run(&chosen, &world, 1, GlobalPlanner::Dijkstra);
    assert_eq!(bits(&a), bits(&b));
}

fn bits(o: &sim::Outcome) -> Vec<u64> {
    o.trace
        .rows
        .iter()
        .flat_map(|r| [r.t, r.x, r.y, r.phi, r.v, r.omega].map(f64::to_bits))
        .collect()
}

#[test]
fn rollout_runs_are_deterministic() {
    for planner in ["trajectory", "dwa"] {
        let (sc, world) = with(planner, "3-person.ron");
        let a = sim::run(&sc, &world, 3, GlobalPlanner::Dijkstra);
        let b = sim::run(&sc, &world, 3, GlobalPlanner::Dijkstra);
        assert_eq!(bits(&a), bits(&b), "{planner}");
        assert_eq!(a.trace.events.len(), b.trace.events.len());
    }
}

#[test]
fn scenario_files_choose_the_local_planner() {
    let base = r#"SimScenario(name: "hall", world: (size: (6.0, 3.0)),
        start: (0.5, 1.5), goal: (5.5, 1.5)"#;
    let path = std::path::Path::new("hall.ron");
    let plain = Scenario::parse(&format!("{base})"), path).unwrap();
    assert_eq!(plain.local_planner, LocalPlanner::Rpp);
    let dwa = Scenario::parse(
        &format!("{base}, local_planner: Dwa((sim_time: 1.7, vx_samples: 6)))"),
        path,
    )
    .unwrap();
    let want = Rollout {
        sim_time: 1.7,
        vx_samples: 6,
        ..Rollout::default()
    };
    assert_eq!(dwa.local_planner, LocalPlanner::Dwa(want));
    let traj = Scenario::parse(&format!("{base}, local_planner: Trajectory(()))"), path).unwrap();
    assert_eq!(
        traj.local_planner,
        LocalPlanner::Trajectory(Rollout::default())
    );
    assert!(Scenario::parse(&format!("{base}, local_planner: Dwa((speed: 1.0)))"), path).is_err());
    // Values out of range are refused with the field's name.
    let bad = Scenario::parse(
        &format!("{base}, local_planner: Dwa((sim_time: 0.0)))"),
        path,
    )
    .unwrap();
    let err = bad.build_world(path).unwrap_err().to_string();
    assert!(err.contains("local_planner.sim_time"), "{err}");
    // The roll-out drives the hall to its goal.
    let mut sc = plain;
    sc.local_planner = LocalPlanner::Trajectory(Rollout::default());
    let world = sc.build_world(path).unwrap();
    let out = sim::run(&sc, &world, 7, GlobalPlanner::Dijkstra);
    assert!(out.trace.summary.reached);
}
