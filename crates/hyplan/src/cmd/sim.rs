//! `hyplan sim`: drive the simulated robot of seed 004 through a scenario (crate `sim`).

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Context;

/// Options of `hyplan sim`.
#[derive(clap::Args)]
pub struct Args {
    /// The scenario file (RON, see `scenarios/sim/`).
    pub scenario: PathBuf,
    /// Seed of the run's random streams (laser noise, sampling planners).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Global planner: `dijkstra` (the paper's Algorithm 3, default) or any planner of
    /// `hyplan plan` (astar, theta-star, rrt, rrt-star, rrt-connect, the hybrids, ...).
    #[arg(long, default_value = "dijkstra")]
    pub planner: String,
    /// Folder for the trace (CSV, JSON), the built map (ROS YAML + PGM, as map_saver
    /// writes it: free 254, occupied 0, unknown 205, `mode: trinary`) and the figures
    /// (trajectory, v and omega, animation; SVG).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Memory limit, cells: the scenario's map file and every grid the run keeps over the
    /// world (the built map, the costmap, the obstacle memory: the world's size over each
    /// grid's resolution) may have at most this many cells; larger ones are refused
    /// before they are allocated.
    #[arg(long, value_name = "N", default_value_t = envmap::DEFAULT_MAX_CELLS)]
    pub max_cells: usize,
}

/// The global planner called `name`: the single place where the CLI's planner registry
/// (`crate::planners`, over `harness::build_planner`) meets the simulator.
fn global_planner(name: &str) -> anyhow::Result<sim::GlobalPlanner> {
    if name == "dijkstra" {
        return Ok(sim::GlobalPlanner::Dijkstra);
    }
    let flags = crate::planners::PlannerFlags {
        // World units are metres here: 0.25 m steps, like a few costmap cells.
        step: Some(0.25),
        goal_bias: 0.05,
        goal_radius: 0.0,
        // The sim re-plans at every blocked path inside its control loop: a fixed cap.
        max_iterations: Some(20_000),
        time_limit: None,
    };
    Ok(sim::GlobalPlanner::Other(crate::planners::build(
        name, &flags,
    )?))
}

/// Runs `hyplan sim`: a summary on stdout; exit 0 goal reached, 1 not reached, 2 bad input.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    let (scenario, world) = sim::Scenario::load_limited(&args.scenario, args.max_cells)
        .map_err(super::sim_scenario_error)?;
    let planner = global_planner(&args.planner)?;
    let outcome = sim::run(&scenario, &world, args.seed, planner);
    let m = &outcome.trace.summary;
    outln!(
        "{}: {} (planner {}, seed {})",
        m.scenario,
        match m.travel_time {
            Some(t) => format!("goal reached in {t:.2} s"),
            None => format!("goal not reached (stopped at {:.2} s)", m.end_time),
        },
        m.planner,
        m.seed
    )?;
    outln!(
        "distance {:.2} m, stops {}, re-plans {}, plan failures {}, min gap obstacle {:.3} m, min gap person {}",
        m.distance,
        m.stops,
        m.replans,
        m.failures,
        m.min_obstacle_distance,
        m.min_person_distance
            .map_or("-".to_string(), |d| format!("{d:.3} m"))
    )?;
    outln!(
        "contacts: {} at fault, {} with the robot stopped, {} other",
        m.contacts_at_fault,
        m.contacts_robot_stopped,
        m.contacts_not_approaching
    )?;
    if let Some(dir) = &args.out {
        let files = sim::write_all(&outcome, &world, dir)
            .with_context(|| format!("writing the outputs into {}", dir.display()))?;
        for f in files {
            outln!("wrote {}", f.display())?;
        }
    }
    Ok(if m.reached {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(crate::EXIT_NO_PATH)
    })
}
