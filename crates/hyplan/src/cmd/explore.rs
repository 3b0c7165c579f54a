//! `hyplan explore`: the simulated robot of seed 004 explores an unknown world with the
//! RRT frontier detectors (or the nearest-frontier baseline) and builds its map (crate
//! `sim`, module `explore`).

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, bail};
use hyplan_core::Point2;

/// Options of `hyplan explore`.
#[derive(clap::Args)]
pub struct Args {
    /// The scenario file (RON, see `scenarios/sim/explore-*.ron`), or a ROS map
    /// (`map_server` `.yaml`) to explore with the defaults, nothing known in advance.
    pub scenario: PathBuf,
    /// Where the robot starts on a ROS map, `X,Y` in metres. Default: the map frame's
    /// origin when the robot fits there (a SLAM map's origin is where its robot started),
    /// else the most open spot of the map.
    #[arg(long, value_parser = super::parse_xy, allow_hyphen_values = true)]
    pub start: Option<(f64, f64)>,
    /// Simulated seconds before the run is stopped. Default: the scenario's, 4000 on a
    /// ROS map.
    #[arg(long)]
    pub time_limit: Option<f64>,
    /// Frontier detector: `local` (Algorithm 1), `global` (Algorithm 2), `both` (the
    /// reference's launch) or `frontier` (the nearest-frontier baseline). Default: the
    /// scenario's (`both` when it says nothing).
    #[arg(long)]
    pub detector: Option<String>,
    /// Growth rate eta of both trees, m (default: the scenario's, or the reference's 15
    /// global and 1 local).
    #[arg(long, allow_negative_numbers = true)]
    pub eta: Option<f64>,
    /// Laser field of view, degrees, in (0, 360] (default: the scenario's, 180).
    #[arg(long, allow_negative_numbers = true)]
    pub fov: Option<f64>,
    /// Seed of the run's random streams (laser noise, planner, each detector).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Local planner: `rpp`, `trajectory` or `dwa`, as `hyplan sim --controller`.
    /// Default: the scenario's.
    #[arg(long, value_parser = super::sim::CONTROLLERS)]
    pub controller: Option<String>,
    /// Navigation-stack profile: `tutorial` (the values of rrt_exploration_tutorials:
    /// trajectory roll-out at 5 Hz, its costmaps, gmapping's range and rate, the reference
    /// detectors' compute time, filter and assigner; each value's source in docs/sim.md)
    /// or `hyplan` (our defaults). It overwrites the scenario's values of those keys;
    /// `--controller` then still chooses the local planner. Default: the scenario as written.
    #[arg(long, value_parser = super::sim::PROFILES)]
    pub profile: Option<String>,
    /// Folder for coverage.csv, track.csv, the final map (map.yaml + map.pgm), the
    /// figures (map, track, trees and frontiers at the scenario's snapshot times and at
    /// the end; SVG) and animation.png (the map being built, an animated PNG with a
    /// frame every 10 s of simulated time unless the scenario sets `frame_period`). The
    /// map is written as map_saver writes one: free 254, occupied 0, unknown 205,
    /// `mode: trinary`.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write the run as a ROS 2 bag (MCAP) for Foxglove or RViz: /map, /scan, /odom, /tf,
    /// /cmd_vel, /plan, /frontiers, /rrt_tree, stamped with simulated time (see
    /// docs/sim.md).
    #[arg(long, value_name = "FILE")]
    pub mcap: Option<PathBuf>,
    /// With `--mcap`: write one scan in N on /scan (1: every scan, the laser's rate;
    /// /odom and /tf keep the laser's rate). The noisy ranges are most of a long run's
    /// bag (see docs/measurements/issue-32.md).
    #[arg(long, value_name = "N", default_value_t = 1, requires = "mcap")]
    pub mcap_scan_every: u64,
    /// Memory limit, cells: the scenario's map file and every grid the run keeps over the
    /// world (the built map, the costmap, the obstacle memory: the world's size over each
    /// grid's resolution) may have at most this many cells; larger ones are refused
    /// before they are allocated.
    #[arg(long, value_name = "N", default_value_t = envmap::DEFAULT_MAX_CELLS)]
    pub max_cells: usize,
}

/// Runs `hyplan explore`: progress on stderr, a summary on stdout; exit 0 when the
/// exploration ended by itself (no frontier left), 1 when the time limit stopped it,
/// 2 on bad input.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    let ros_map = super::is_ros_map(&args.scenario);
    let mut scenario = if ros_map {
        scenario_of_map(args)?
    } else {
        sim::Scenario::load_limited(&args.scenario, args.max_cells)
            .map_err(super::sim_scenario_error)?
            .0
    };
    super::set_time_limit(&mut scenario, args.time_limit)?;
    if let Some(name) = &args.profile {
        super::sim::apply_profile(&mut scenario, name)?;
    }
    if let Some(d) = &args.detector {
        scenario.exploration.strategy = sim::Strategy::parse(d).with_context(|| {
            format!("--detector = {d:?}: must be one of local, global, both, frontier")
        })?;
    }
    if let Some(name) = &args.controller {
        super::sim::set_local_planner(&mut scenario, name)?;
    }
    if let Some(eta) = args.eta {
        if !(eta.is_finite() && eta > 0.0) {
            bail!("--eta = {eta}: must be finite and > 0 (metres)");
        }
        scenario.exploration.eta_global = eta;
        scenario.exploration.eta_local = eta;
    }
    if let Some(fov) = args.fov {
        if !(fov.is_finite() && fov > 0.0 && fov <= 360.0) {
            bail!("--fov = {fov}: must be finite, > 0 and at most 360 (degrees)");
        }
        scenario.laser.fov_deg = fov;
    }
    if args.out.is_some() && scenario.exploration.frame_period.is_none() {
        scenario.exploration.frame_period = Some(10.0);
    }
    // The overrides are checked with the rest of the scenario.
    let world = scenario
        .build_world_limited(&args.scenario, args.max_cells)
        .map_err(|e| super::map_point_error(e, ros_map))?;
    let strategy = scenario.exploration.strategy;
    let mut next_line = 0.0;
    let mut progress = |c: &sim::Coverage| {
        if c.t >= next_line {
            eprintln!(
                "explore: t {:6.0} s, coverage {:5.1} %",
                c.t,
                100.0 * c.fraction
            );
            next_line += 60.0;
        }
    };
    let outcome = match &args.mcap {
        None => sim::explore_with(&scenario, &world, args.seed, strategy, &mut progress)?,
        Some(path) => {
            let mut bag = sim::BagRecorder::create(path)?.with_scan_every(args.mcap_scan_every);
            let outcome = sim::explore_observed(
                &scenario,
                &world,
                args.seed,
                strategy,
                &mut progress,
                &mut [&mut bag],
            )?;
            bag.finish()?;
            outcome
        }
    };
    let time = |f: f64| {
        outcome
            .time_to(f)
            .map_or("not reached".to_string(), |t| format!("{t:.0} s"))
    };
    outln!(
        "{}: {} (detector {}, eta {} m global / {} m local, fov {} deg, seed {})",
        outcome.scenario,
        if outcome.finished {
            format!("explored, no frontier left at {:.0} s", outcome.end_time)
        } else {
            format!("stopped by the time limit at {:.0} s", outcome.end_time)
        },
        strategy.name(),
        scenario.exploration.eta_global,
        scenario.exploration.eta_local,
        scenario.laser.fov_deg,
        args.seed
    )?;
    outln!(
        "coverage {:.2} % of {:.1} m^2 reachable free; 95 % at {}, 99 % at {}; missed {:.2} m^2",
        100.0 * outcome.final_coverage(),
        outcome.reachable_area,
        time(0.95),
        time(0.99),
        outcome.missed_area()
    )?;
    outln!(
        "distance {:.1} m, goals {}, blacklisted {}, points published {}, contact ticks {}, tight plans {}",
        outcome.distance,
        outcome.goals.len(),
        outcome.blacklisted.len(),
        outcome.published,
        outcome.contact_ticks,
        outcome.tight_plans
    )?;
    // What is left, and why: "it stopped" always comes with "why".
    let left = sim::left_unknown(&scenario, &world, &outcome);
    let by_cause = sim::left_by_cause(&left);
    if by_cause.is_empty() {
        outln!("left unknown: nothing of the reachable free space")?;
    } else {
        outln!(
            "left unknown: {:.2} m^2 of the reachable free space in {} patches",
            left.iter().map(|r| r.area).sum::<f64>(),
            left.len()
        )?;
        for (cause, area, n) in &by_cause {
            let biggest = left.iter().find(|r| r.cause == *cause);
            outln!(
                "  {area:8.2} m^2 in {n:3} patches: {}{}",
                cause.describe(),
                biggest.map_or(String::new(), |r| format!(
                    " (largest {:.2} m^2 at ({:.2}, {:.2}))",
                    r.area, r.centre.x, r.centre.y
                ))
            )?;
        }
    }
    let [free, occupied, unknown] = outcome.map.counts();
    outln!(
        "built map: {} x {} cells of {} m: {free} free, {occupied} occupied, {unknown} unknown",
        outcome.map.width(),
        outcome.map.height(),
        outcome.map.params.resolution
    )?;
    if let Some(dir) = &args.out {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("creating the folder {}", dir.display()))?;
        let put = |name: &str, text: &str| -> anyhow::Result<()> {
            let p = dir.join(name);
            std::fs::write(&p, text).with_context(|| format!("writing {}", p.display()))?;
            outln!("wrote {}", p.display())?;
            Ok(())
        };
        let summary = serde_json::json!({
            "scenario": outcome.scenario,
            "detector": strategy.name(),
            "seed": args.seed,
            "finished": outcome.finished,
            "end_time_s": outcome.end_time,
            "coverage": outcome.final_coverage(),
            "reachable_free_m2": outcome.reachable_area,
            "missed_m2": outcome.missed_area(),
            "time_to_95_s": outcome.time_to(0.95),
            "time_to_99_s": outcome.time_to(0.99),
            "distance_m": outcome.distance,
            "goals": outcome.goals.len(),
            "blacklisted": outcome.blacklisted.len(),
            "tight_plans": outcome.tight_plans,
            "left_by_cause": by_cause
                .iter()
                .map(|(c, a, n)| serde_json::json!({"cause": c, "area_m2": a, "patches": n}))
                .collect::<Vec<_>>(),
            "left": left,
        });
        put("summary.json", &serde_json::to_string_pretty(&summary)?)?;
        put("coverage.csv", &outcome.coverage_csv())?;
        put("track.csv", &outcome.track_csv())?;
        let yaml = dir.join("map.yaml");
        outcome
            .map
            .write_ros(&yaml)
            .with_context(|| format!("writing {}", yaml.display()))?;
        outln!("wrote {} (+ map.pgm)", yaml.display())?;
        let apng = sim::animation_png(&outcome, 100).map_err(anyhow::Error::msg)?;
        let p = dir.join("animation.png");
        std::fs::write(&p, apng).with_context(|| format!("writing {}", p.display()))?;
        outln!(
            "wrote {} (animated PNG, a frame per {} s)",
            p.display(),
            scenario.exploration.frame_period.unwrap_or(10.0)
        )?;
        for snap in &outcome.snapshots {
            let svg = sim::snapshot_svg(&outcome, snap, &world)?;
            put(&format!("explore-{:04.0}s.svg", snap.t), &svg)?;
        }
    }
    if let Some(path) = &args.mcap {
        outln!("wrote {}", path.display())?;
    }
    Ok(if outcome.finished {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(crate::EXIT_NO_PATH)
    })
}

/// The exploration of the ROS map `args.scenario` with the defaults, nothing known in
/// advance, from `--start` or a start chosen on the map (see [`Args::start`]).
fn scenario_of_map(args: &Args) -> anyhow::Result<sim::Scenario> {
    let start = match args.start {
        Some(s) => s,
        None => {
            // The robot's radius with a margin.
            let clearance = sim::Robot::default().body_radius + 0.2;
            let opts = envmap::LoadOptions {
                max_cells: args.max_cells,
                ..envmap::LoadOptions::default()
            };
            let loaded = super::load_map(&args.scenario, &opts)?;
            let start = open_start(&loaded.map, loaded.frame, clearance).with_context(|| {
                format!(
                    "{}: no free spot {clearance:.2} m from every obstacle to start from",
                    args.scenario.display()
                )
            })?;
            eprintln!(
                "explore: starting at ({:.2}, {:.2}) on {} (--start X,Y to choose)",
                start.0,
                start.1,
                args.scenario
                    .file_name()
                    .unwrap_or_default()
                    .to_string_lossy()
            );
            start
        }
    };
    let on = super::OnMap {
        kind: "explore",
        start,
        goal: start,
        known_map: false,
        time_limit: 4000.0,
    };
    super::scenario_on_map(&args.scenario, &on)
}

/// The map frame's origin when it is at least `clearance` from every blocked cell, else
/// the cell centre farthest from them (the first found among equals), in the map frame
/// (`frame`); `None` when no cell is that far.
fn open_start(
    map: &envmap::GridMap,
    frame: envmap::InputFrame,
    clearance: f64,
) -> Option<(f64, f64)> {
    if map.clearance_at(frame.to_world(0.0, 0.0)) >= clearance {
        return Some((0.0, 0.0));
    }
    let mut best: Option<(f64, Point2)> = None;
    for j in 0..map.height() {
        for i in 0..map.width() {
            let c = map.cell_center(i, j);
            let d = map.clearance_at(c);
            if d >= clearance && best.is_none_or(|(b, _)| d > b) {
                best = Some((d, c));
            }
        }
    }
    best.map(|(_, c)| frame.from_world(c))
}
