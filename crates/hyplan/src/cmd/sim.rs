//! `hyplan sim`: drive the simulated robot of seed 004 through a scenario (crate `sim`).

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Context;
use registry::PlannerKind;

use crate::planners::SpecParser;

/// Options of `hyplan sim`.
#[derive(clap::Args)]
pub struct Args {
    /// The scenario file (RON, see `scenarios/sim/`), or a ROS map (`map_server` `.yaml`)
    /// to drive across, known in advance, from `--start` to `--goal`.
    pub scenario: PathBuf,
    /// Where the robot starts on a ROS map, `X,Y` in metres (required with a map).
    #[arg(long, value_parser = super::parse_xy, allow_hyphen_values = true)]
    pub start: Option<(f64, f64)>,
    /// The goal on a ROS map, `X,Y` in metres (required with a map).
    #[arg(long, value_parser = super::parse_xy, allow_hyphen_values = true)]
    pub goal: Option<(f64, f64)>,
    /// Simulated seconds before the run is stopped. Default: the scenario's, 600 on a ROS
    /// map.
    #[arg(long)]
    pub time_limit: Option<f64>,
    /// Seed of the run's random streams (laser noise, sampling planners).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Global planner `NAME[:key=value,...]`: `dijkstra` (the paper's Algorithm 3 on the
    /// costmap, default) or any other planner of the registry, as `hyplan plan` runs it.
    #[arg(long, default_value = "dijkstra", value_parser = SpecParser::with_help(SIM_HELP))]
    pub planner: String,
    /// Local planner: `rpp` (regulated pure pursuit), `trajectory` (base_local_planner's
    /// Trajectory Rollout) or `dwa` (its Dynamic Window Approach). Default: the
    /// scenario's `local_planner` (`rpp` when it says nothing); a roll-out keeps the
    /// scenario's roll-out parameters when it has some.
    #[arg(long, value_parser = CONTROLLERS)]
    pub controller: Option<String>,
    /// Navigation-stack profile: `tutorial` (the values of rrt_exploration_tutorials:
    /// trajectory roll-out at 5 Hz, its costmaps, gmapping's range and rate, the reference
    /// detectors' compute time, filter and assigner; each value's source in docs/sim.md)
    /// or `hyplan` (our defaults). It overwrites the scenario's values of those keys;
    /// `--controller` then still chooses the local planner. Default: the scenario as written.
    #[arg(long, value_parser = PROFILES)]
    pub profile: Option<String>,
    /// How the people move: `scripted` (their routes, blind), `social-force` (Helbing and
    /// Molnár's social forces, seeing the robot), `orca` (reciprocal velocity obstacles,
    /// seeing it), or `social-force-blind` / `orca-blind` (not seeing it). Default: the
    /// scenario's `people_model`.
    #[arg(long, value_parser = clap::builder::PossibleValuesParser::new(sim::PeopleModelKind::NAMES))]
    pub people_model: Option<String>,
    /// Add people to the map: `D` per 100 m^2 of the floor the robot can reach, each
    /// walking back and forth at about 1.3 m/s between two points of the floor drawn from
    /// `--seed` (`sim::people_on_map`). They see the
    /// robot under social forces unless `--people-model` says otherwise. The robot is set
    /// up as in `cargo xtask crowd`: collision monitor on (unless `--collision-monitor
    /// off`), waiting up to 30 s for people before giving up, a 270-degree scanner. Needs
    /// a map (a ROS map, or a scenario on a map file).
    #[arg(long, value_name = "D", allow_negative_numbers = true)]
    pub crowd: Option<f64>,
    /// The collision monitor between the navigation stack and the wheels (Nav2's
    /// `collision_monitor`; `sim::CollisionMonitor`): `on` slows and stops the robot before
    /// someone walking straight at it could reach it, `off` drives the bare stack. Default:
    /// the scenario's `navigation.collision_monitor` (off unless the file turns it on).
    #[arg(long, value_parser = ["on", "off"])]
    pub collision_monitor: Option<String>,
    /// Folder for the trace (CSV, JSON), the built map (ROS YAML + PGM, as map_saver
    /// writes it: free 254, occupied 0, unknown 205, `mode: trinary`) and the figures
    /// (trajectory, v and omega, animation; SVG).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write the run as a ROS 2 bag (MCAP) for Foxglove or RViz: /map, /scan, /odom, /tf,
    /// /cmd_vel, /plan, /people, stamped with simulated time (see docs/sim.md).
    #[arg(long, value_name = "FILE")]
    pub mcap: Option<PathBuf>,
    /// Memory limit, cells: the scenario's map file and every grid the run keeps over the
    /// world (the built map, the costmap, the obstacle memory: the world's size over each
    /// grid's resolution) may have at most this many cells; larger ones are refused
    /// before they are allocated.
    #[arg(long, value_name = "N", default_value_t = envmap::DEFAULT_MAX_CELLS)]
    pub max_cells: usize,
}

/// The names `--profile` takes.
pub(crate) const PROFILES: [&str; 2] = ["hyplan", "tutorial"];

/// Applies the profile `name` (one of [`PROFILES`]) to `scenario`.
pub(crate) fn apply_profile(scenario: &mut sim::Scenario, name: &str) -> anyhow::Result<()> {
    let profile = sim::Profile::parse(name).with_context(|| {
        format!(
            "--profile = {name:?}: must be one of {}",
            PROFILES.join(", ")
        )
    })?;
    profile.apply(scenario);
    Ok(())
}

/// The names `--controller` takes.
pub(crate) const CONTROLLERS: [&str; 3] = ["rpp", "trajectory", "dwa"];

/// Sets `scenario`'s local planner to the one `name` names (one of [`CONTROLLERS`]),
/// keeping the scenario's roll-out parameters when it has some.
pub(crate) fn set_local_planner(scenario: &mut sim::Scenario, name: &str) -> anyhow::Result<()> {
    let params = scenario.local_planner.rollout();
    scenario.local_planner = sim::LocalPlanner::from_name(name, params).with_context(|| {
        format!(
            "--controller = {name:?}: must be one of {}",
            CONTROLLERS.join(", ")
        )
    })?;
    Ok(())
}

/// `--planner`'s help lines where the simulator reads a name otherwise than `hyplan plan`.
const SIM_HELP: &[(PlannerKind, &str)] = &[(
    PlannerKind::Dijkstra,
    "the paper's Algorithm 3: Dijkstra on the costmap, re-planned as the robot maps",
)];

/// The global planner `spec` names, read through the registry: the single place where the
/// CLI's planners (`crate::planners`) meet the simulator. `dijkstra` is the paper's
/// Algorithm 3 on the sim's costmap ([`sim::GlobalPlanner::Dijkstra`]), which has no
/// parameters; every other planner runs on the sim's map as `hyplan plan` builds it.
fn global_planner(spec: &str) -> anyhow::Result<sim::GlobalPlanner> {
    let flags = crate::planners::PlannerFlags {
        map_diagonal: None,
        // World units are metres here: 0.25 m steps, like a few costmap cells.
        step: Some(0.25),
        goal_bias: 0.05,
        goal_radius: 0.0,
        // The sim re-plans at every blocked path inside its control loop: a fixed cap.
        max_iterations: Some(20_000),
        time_limit: None,
    };
    let config = crate::planners::configure(spec, &flags)?;
    if config.kind() == PlannerKind::Dijkstra {
        if spec.contains(':') {
            anyhow::bail!(
                "--planner {spec}: the simulator's dijkstra is the paper's Algorithm 3 on the \
                 costmap, which takes no parameters"
            );
        }
        return Ok(sim::GlobalPlanner::Dijkstra);
    }
    Ok(sim::GlobalPlanner::Other(config.build()))
}

/// `--crowd`: people at `density` on the scenario's map ([`sim::add_crowd`]).
fn add_crowd(
    scenario: &mut sim::Scenario,
    world: &mut sim::World,
    density: f64,
    seed: u64,
) -> anyhow::Result<()> {
    let crowd = sim::add_crowd(scenario, world, density, seed)
        .map_err(|e| anyhow::anyhow!("--crowd {density}: {e}"))?;
    outln!(
        "crowd: {} {} on {:.0} m^2 of floor reachable from the start ({density} per 100 m^2{})",
        crowd.people.len(),
        if crowd.people.len() == 1 {
            "person"
        } else {
            "people"
        },
        crowd.floor_m2,
        if crowd.people.len() == sim::MAX_MAP_PEOPLE {
            format!(", at most {}", sim::MAX_MAP_PEOPLE)
        } else {
            String::new()
        }
    )?;
    Ok(())
}

/// Runs `hyplan sim`: a summary on stdout; exit 0 goal reached, 1 not reached, 2 bad input.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    let ros_map = super::is_ros_map(&args.scenario);
    let (mut scenario, mut world) = if ros_map {
        let scenario = scenario_of_map(args)?;
        let world = scenario
            .build_world_limited(&args.scenario, args.max_cells)
            .map_err(|e| super::map_point_error(e, true))?;
        (scenario, world)
    } else {
        sim::Scenario::load_limited(&args.scenario, args.max_cells)
            .map_err(super::sim_scenario_error)?
    };
    super::set_time_limit(&mut scenario, args.time_limit)?;
    if let Some(name) = &args.profile {
        super::sim::apply_profile(&mut scenario, name)?;
    }
    if let Some(name) = &args.controller {
        set_local_planner(&mut scenario, name)?;
    }
    if let Some(density) = args.crowd {
        add_crowd(&mut scenario, &mut world, density, args.seed)?;
    }
    if let Some(name) = &args.people_model {
        scenario.people_model =
            sim::PeopleModelKind::from_name(name).context("--people-model: a known name")?;
    }
    match args.collision_monitor.as_deref() {
        Some("on") => {
            scenario.navigation.collision_monitor =
                Some(scenario.navigation.collision_monitor.unwrap_or_default());
        }
        Some(_) => scenario.navigation.collision_monitor = None,
        None => {}
    }
    if args.crowd.is_some() {
        // After the flags, so that it says what the run does.
        outln!(
            "crowd robot: collision monitor {}, waits up to {} s for people, {}-degree scanner (as `cargo xtask crowd`'s)",
            if scenario.navigation.collision_monitor.is_some() {
                "on"
            } else {
                "off"
            },
            scenario.navigation.people_patience,
            scenario.laser.fov_deg
        )?;
    }
    let planner = global_planner(&args.planner)?;
    let mut meter = sim::CrowdMeter::new(world.people.len());
    let outcome = match &args.mcap {
        None => sim::run_with(&scenario, &world, args.seed, planner, &mut [&mut meter]),
        Some(path) => {
            let mut bag = sim::BagRecorder::create(path)?;
            let outcome = sim::run_with(
                &scenario,
                &world,
                args.seed,
                planner,
                &mut [&mut bag, &mut meter],
            );
            bag.finish()?;
            outcome
        }
    };
    let m = &outcome.trace.summary;
    outln!(
        "{}: {} (planner {}, controller {}, seed {})",
        m.scenario,
        match m.travel_time {
            Some(t) => format!("goal reached in {t:.2} s"),
            None => format!("goal not reached (stopped at {:.2} s)", m.end_time),
        },
        m.planner,
        scenario.local_planner.name(),
        m.seed
    )?;
    outln!(
        "distance {:.2} m, stops {}, re-plans {}, plan failures {}, min gap obstacle {:.3} m, min gap person {}, within {} m of a person {:.2} s",
        m.distance,
        m.stops,
        m.replans,
        m.failures,
        m.min_obstacle_distance,
        m.min_person_distance
            .map_or("-".to_string(), |d| format!("{d:.3} m")),
        sim::PERSONAL_SPACE,
        m.personal_space_time
    )?;
    outln!(
        "contacts: {} at fault, {} with the robot stopped, {} other",
        m.contacts_at_fault,
        m.contacts_robot_stopped,
        m.contacts_not_approaching
    )?;
    // Among people, the crowd figures: the same run without them, and them without the
    // robot (two more runs, the second of the people model alone).
    let crowd = if world.people.is_empty() {
        None
    } else {
        let planner = global_planner(&args.planner)?;
        Some(meter.finish(&scenario, &world, args.seed, &outcome, planner))
    };
    if let Some(c) = &crowd {
        outln!(
            "among people: {}; people's delay {:.2} s over {} who left; held in place without the robot: {} of {}; tracker: {} error, {} of {} sightings missed, {} false tracks",
            match (c.travel_time_alone, c.time_ratio()) {
                (Some(t), Some(r)) => format!("{t:.2} s to the goal without them ({r:.2}x)"),
                (Some(t), None) => format!("{t:.2} s to the goal without them"),
                (None, _) => "goal not reached without them either".to_string(),
            },
            c.people_delay,
            c.people_arrived,
            c.people_held_alone,
            world.people.len(),
            if c.sightings > c.missed {
                format!(
                    "{:.3} m",
                    c.track_error_sum / (c.sightings - c.missed) as f64
                )
            } else {
                "-".to_string()
            },
            c.missed,
            c.sightings,
            c.false_tracks
        )?;
    }
    if let Some(dir) = &args.out {
        let mut files = sim::write_all(&outcome, &world, dir)
            .with_context(|| format!("writing the outputs into {}", dir.display()))?;
        if let Some(c) = &crowd {
            let path = dir.join("crowd.json");
            std::fs::write(&path, serde_json::to_string_pretty(c)?)
                .with_context(|| format!("writing {}", path.display()))?;
            files.push(path);
        }
        for f in files {
            outln!("wrote {}", f.display())?;
        }
    }
    if let Some(path) = &args.mcap {
        outln!("wrote {}", path.display())?;
    }
    Ok(if m.reached {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(crate::EXIT_NO_PATH)
    })
}

/// The drive across the ROS map `args.scenario`, known in advance, from `--start` to
/// `--goal`, with the defaults.
fn scenario_of_map(args: &Args) -> anyhow::Result<sim::Scenario> {
    let (Some(start), Some(goal)) = (args.start, args.goal) else {
        anyhow::bail!(
            "{}: a map needs --start X,Y and --goal X,Y (metres in the map frame)",
            args.scenario.display()
        );
    };
    let on = super::OnMap {
        kind: "nav",
        start,
        goal,
        known_map: true,
        time_limit: 600.0,
    };
    super::scenario_on_map(&args.scenario, &on)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn controller_flag_keeps_the_scenarios_rollout() {
        let text = r#"SimScenario(name: "t", world: (size: (4.0, 4.0)), start: (1.0, 1.0),
            goal: (3.0, 3.0), local_planner: Trajectory((sim_time: 1.7)))"#;
        let mut sc = sim::Scenario::parse(text, std::path::Path::new("t.ron")).unwrap();
        set_local_planner(&mut sc, "dwa").unwrap();
        let want = sim::Rollout {
            sim_time: 1.7,
            ..sim::Rollout::default()
        };
        assert_eq!(sc.local_planner, sim::LocalPlanner::Dwa(want));
        set_local_planner(&mut sc, "rpp").unwrap();
        assert_eq!(sc.local_planner, sim::LocalPlanner::Rpp);
        assert!(set_local_planner(&mut sc, "teb").is_err());
        apply_profile(&mut sc, "tutorial").unwrap();
        assert_eq!(sc.controller.rate_hz, 5.0);
        assert_eq!(sc.local_planner.name(), "trajectory");
        set_local_planner(&mut sc, "dwa").unwrap();
        assert!(matches!(sc.local_planner, sim::LocalPlanner::Dwa(r) if r.acc_lim_x == 0.05));
        let err = apply_profile(&mut sc, "nav2").unwrap_err().to_string();
        assert!(err.contains("--profile = \"nav2\""), "{err}");
    }
}
