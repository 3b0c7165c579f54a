//! `cargo xtask crowd`: the robot among generated crowds (issue 29), over densities,
//! controllers and people models; a Markdown table of the figures crowd-navigation work
//! reports, and every run as JSON lines.
//!
//! Run `k` of a cell is `sim::crowd(flow, density, seed, k)` driven with seed `k`: the
//! same rooms and people for every controller and people model, so cells compare paired.

use std::io::Write as _;
use std::path::PathBuf;
use std::sync::Mutex;
use std::time::Instant;

use anyhow::{Context as _, bail};
use harness::stats::median;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde::Serialize;
use sim::{CrowdCell, CrowdFlow, CrowdMetrics, GlobalPlanner, LocalPlanner, PeopleModelKind};
use viz::{Align, Table};

/// Options of `cargo xtask crowd`.
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Runs per cell.
    #[arg(long, default_value_t = 20)]
    pub runs: u64,
    /// Densities, people per 100 m^2, comma-separated.
    #[arg(long, value_delimiter = ',', default_values_t = [0.0, 0.5, 1.0, 2.0])]
    pub densities: Vec<f64>,
    /// Flows, comma-separated: doors, corridor, crossing.
    #[arg(long, value_delimiter = ',', default_values_t = [CrowdFlow::Doors, CrowdFlow::Corridor, CrowdFlow::Crossing])]
    pub flows: Vec<CrowdFlow>,
    /// Local planners, comma-separated: rpp, trajectory, dwa.
    #[arg(long, value_delimiter = ',', default_values_t = ["rpp".to_string(), "trajectory".to_string()])]
    pub controllers: Vec<String>,
    /// People models, comma-separated (see `sim::PeopleModelKind::NAMES`). Default: both
    /// reacting models, people who see the robot and people who do not.
    #[arg(long, value_delimiter = ',', default_values_t = ["social-force".to_string(), "social-force-blind".to_string(), "orca".to_string(), "orca-blind".to_string()])]
    pub models: Vec<String>,
    /// Seed of the generated scenarios.
    #[arg(long, default_value_t = 2026)]
    pub seed: u64,
    /// Runs at a time (default: one per core).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Output folder (default `target/crowd` in the workspace).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Also the safety soak at walking speed: this many of its generated rooms (seed
    /// 2026), people at 0.8-1.6 m/s, for every controller and every people model of
    /// `--soak-models` (0: none).
    #[arg(long, default_value_t = 0)]
    pub soak: u64,
    /// Write one scenario file per flow (density 1, the first run of `--seed`) into DIR
    /// (`crowd-FLOW.ron`, for `hyplan sim`) and stop.
    #[arg(long, value_name = "DIR")]
    pub write_scenarios: Option<PathBuf>,
    /// Runs the robot without its collision monitor (`sim::CollisionMonitor`, on in
    /// every crowd and soak room by default), to measure what the monitor does.
    #[arg(long)]
    pub no_monitor: bool,
    /// How long the robot waits for people before their blocks count as failures, s
    /// (`navigation.people_patience`; default: `sim::PEOPLE_PATIENCE`, 0 for none).
    #[arg(long, value_name = "S")]
    pub people_patience: Option<f64>,
    /// The laser's field of view for every run, degrees, at the same angle between beams
    /// (default: the crowd rooms' 270, `sim::CROWD_FOV_DEG`; the soak rooms' 180, seed
    /// 004's scanner). `--fov 180` runs the crowd rooms with seed 004's scanner.
    #[arg(long, value_name = "DEG")]
    pub fov: Option<f64>,
    /// People models of the soak, comma-separated. Default: every one.
    #[arg(long, value_delimiter = ',', default_values_t = ["scripted".to_string(), "social-force".to_string(), "social-force-blind".to_string(), "orca".to_string(), "orca-blind".to_string()])]
    pub soak_models: Vec<String>,
}

/// The robot of every crowd and soak run: the collision monitor unless `--no-monitor`,
/// the patience with people, the laser's `--fov`.
fn robot_options(args: &Args, patience: f64, sc: &mut sim::Scenario) {
    sc.navigation.collision_monitor = (!args.no_monitor).then(sim::CollisionMonitor::default);
    sc.navigation.people_patience = patience;
    if let Some(fov) = args.fov {
        sc.laser = sc.laser.with_fov(fov);
    }
}

/// Walking speeds of the soak at walking speed, m/s (issue 29).
const SOAK_SPEEDS: (f64, f64) = (0.8, 1.6);

/// One run, as written to `runs.jsonl`.
#[derive(Debug, Clone, Serialize)]
struct RunRecord<'a> {
    flow: CrowdFlow,
    density: f64,
    controller: &'a str,
    model: &'a str,
    index: u64,
    people: usize,
    #[serde(flatten)]
    metrics: CrowdMetrics,
}

/// Runs the crowd table.
///
/// # Errors
///
/// An unknown controller or people model; outputs that cannot be written.
pub fn run(args: &Args) -> anyhow::Result<()> {
    if let Some(dir) = &args.write_scenarios {
        return write_scenarios(dir, args.seed);
    }
    if let Some(fov) = args.fov
        && !(fov > 0.0 && fov <= 360.0)
    {
        bail!("--fov {fov}: the field of view must be in (0, 360] degrees");
    }
    let patience = args.people_patience.unwrap_or(sim::PEOPLE_PATIENCE);
    if !(patience >= 0.0 && patience.is_finite()) {
        bail!("--people-patience {patience}: must be finite and >= 0 seconds");
    }
    let mut controllers = Vec::new();
    for c in &args.controllers {
        let Some(local) = LocalPlanner::from_name(c, None) else {
            bail!("unknown controller `{c}` (rpp, trajectory, dwa)");
        };
        controllers.push((c.as_str(), local));
    }
    let models = people_models(&args.models)?;
    let soak_models = people_models(&args.soak_models)?;
    if models.is_empty() || controllers.is_empty() {
        bail!("--models and --controllers need at least one name each");
    }
    let out = args.out.clone().unwrap_or_else(|| {
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("..")
            .join("target")
            .join("crowd")
    });
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    let jobs = args.jobs.unwrap_or_else(rayon::current_num_threads).max(1);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .context("starting the worker threads")?;
    if args.soak > 0 {
        soak(args, &controllers, &soak_models, patience, &pool, &out)?;
    }
    if args.runs == 0 {
        return Ok(());
    }
    let mut cells = Vec::new();
    for &flow in &args.flows {
        for &density in &args.densities {
            for (c, local) in &controllers {
                // Without people every model is the same run: one row.
                let ms: &[(&str, PeopleModelKind)] =
                    if density > 0.0 { &models } else { &models[..1] };
                for (m, kind) in ms {
                    cells.push((flow, density, *c, *local, *m, *kind));
                }
            }
        }
    }
    let specs: Vec<(usize, u64)> = (0..cells.len())
        .flat_map(|c| (0..args.runs).map(move |k| (c, k)))
        .collect();
    let bar = ProgressBar::new(specs.len() as u64).with_style(
        ProgressStyle::with_template("crowd {bar:40} {pos}/{len} runs, {elapsed} ({eta} left)")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let jsonl =
        Mutex::new(std::fs::File::create(out.join("runs.jsonl")).context("creating runs.jsonl")?);
    let started = Instant::now();
    let results: Vec<(usize, CrowdMetrics, f64)> = pool.install(|| {
        specs
            .par_iter()
            .map(|&(c, k)| {
                let (flow, density, controller, local, model, kind) = cells[c];
                let mut sc = sim::crowd(flow, density, args.seed, k);
                sc.local_planner = local;
                sc.people_model = kind;
                robot_options(args, patience, &mut sc);
                let world = sc
                    .build_world(std::path::Path::new(&sc.name))
                    .with_context(|| format!("building {}", sc.name))?;
                let t0 = Instant::now();
                let m = sim::measure(&sc, &world, k, || GlobalPlanner::Dijkstra);
                let wall = t0.elapsed().as_secs_f64();
                let record = RunRecord {
                    flow,
                    density,
                    controller,
                    model,
                    index: k,
                    people: sc.people.len(),
                    metrics: m.clone(),
                };
                let line = serde_json::to_string(&record)?;
                let mut f = jsonl
                    .lock()
                    .unwrap_or_else(std::sync::PoisonError::into_inner);
                writeln!(f, "{line}").context("writing runs.jsonl")?;
                bar.inc(1);
                Ok((c, m, wall))
            })
            .collect::<anyhow::Result<_>>()
    })?;
    bar.finish_and_clear();
    let mut sums = vec![CrowdCell::default(); cells.len()];
    let mut walls = vec![0.0; cells.len()];
    for (c, m, wall) in &results {
        sums[*c].add(m);
        walls[*c] += wall;
    }
    let mut table = Table::new([
        "flow",
        "density /100 m^2",
        "controller",
        "people",
        "runs",
        "success %",
        "contact %",
        "at-fault %",
        "timeout %",
        "time / alone (median)",
        "path m",
        "min gap m (median)",
        "personal space s/run",
        "people delay s/person",
        "track error m",
        "missed %",
        "false tracks /scan",
    ])
    .align(std::iter::repeat_n(Align::Left, 4).chain(std::iter::repeat_n(Align::Right, 13)));
    let pct = |a: usize, n: usize| format!("{:.1}", 100.0 * a as f64 / n.max(1) as f64);
    let opt = |v: Option<f64>, d: usize| v.map_or("-".into(), |x| format!("{x:.d$}"));
    for ((flow, density, controller, _, model, _), s) in cells.iter().zip(&sums) {
        let people = if *density > 0.0 { *model } else { "none" };
        table.row([
            flow.to_string(),
            format!("{density}"),
            (*controller).to_string(),
            people.to_string(),
            s.runs.to_string(),
            pct(s.reached, s.runs),
            pct(s.with_contact, s.runs),
            pct(s.with_at_fault, s.runs),
            pct(s.timed_out, s.runs),
            opt(median(s.time_ratios.iter().copied()), 2),
            opt(s.mean_path_length(), 1),
            opt(median(s.min_person_distance.iter().copied()), 2),
            format!("{:.1}", s.personal_space_time / s.runs.max(1) as f64),
            opt(s.mean_people_delay(), 2),
            opt(s.mean_track_error(), 2),
            opt(s.missed_rate().map(|r| 100.0 * r), 1),
            opt(
                (s.scans_with_people > 0)
                    .then(|| s.false_tracks as f64 / s.scans_with_people as f64),
                2,
            ),
        ]);
    }
    let wall = started.elapsed().as_secs_f64();
    let md = format!(
        "# Crowd table\n\n`cargo xtask crowd --runs {} --seed {}` ({} runs on {jobs} threads, \
         {wall:.0} s of wall time). Each run is measured against the same room without \
         people (time / alone) and against the people walking without the robot (their \
         delay). Success: the goal reached; contact: any contact with a person or a wall; \
         at-fault: a contact while the robot moved toward what it touched; timeout: the \
         time limit (three times the route at top speed) reached.\n\n{}",
        args.runs,
        args.seed,
        specs.len(),
        table.to_markdown()
    );
    std::fs::write(out.join("crowd.md"), &md).context("writing crowd.md")?;
    std::fs::write(out.join("crowd.csv"), table.to_csv()).context("writing crowd.csv")?;
    println!("{md}");
    eprintln!("crowd: wrote {}", out.join("crowd.md").display());
    Ok(())
}

/// The people models named in `names`.
fn people_models(names: &[String]) -> anyhow::Result<Vec<(&str, PeopleModelKind)>> {
    names
        .iter()
        .map(|m| match PeopleModelKind::from_name(m) {
            Some(kind) => Ok((m.as_str(), kind)),
            None => bail!(
                "unknown people model `{m}` ({})",
                PeopleModelKind::NAMES.join(", ")
            ),
        })
        .collect()
}

/// The safety soak at walking speed: `args.soak` rooms for each controller and people
/// model, one soak per thread; writes `soak.md`.
fn soak(
    args: &Args,
    controllers: &[(&str, LocalPlanner)],
    models: &[(&str, PeopleModelKind)],
    patience: f64,
    pool: &rayon::ThreadPool,
    out: &std::path::Path,
) -> anyhow::Result<()> {
    let combos: Vec<(&str, LocalPlanner, &str, PeopleModelKind)> = controllers
        .iter()
        .flat_map(|&(c, local)| models.iter().map(move |&(m, kind)| (c, local, m, kind)))
        .collect();
    eprintln!(
        "crowd: the soak at walking speed, {} rooms x {} controllers x {} people models",
        args.soak,
        controllers.len(),
        models.len()
    );
    let started = Instant::now();
    let results: Vec<(sim::SoakSummary, f64)> = pool.install(|| {
        combos
            .par_iter()
            .map(|&(c, local, m, kind)| {
                let t0 = Instant::now();
                let s = sim::soak_rooms(
                    2026,
                    args.soak,
                    |seed, k| sim::room_at(seed, k, SOAK_SPEEDS),
                    |sc| {
                        sc.local_planner = local;
                        sc.people_model = kind;
                        robot_options(args, patience, sc);
                    },
                );
                let wall = t0.elapsed().as_secs_f64();
                eprintln!(
                    "crowd: soak {c} / {m}: {} of {} reached, {} at-fault contacts, {wall:.0} s",
                    s.reached, s.rooms, s.contacts_at_fault
                );
                (s, wall)
            })
            .collect()
    });
    let mut table = Table::new([
        "controller",
        "people",
        "rooms",
        "reached %",
        "at-fault contacts",
        "contacts, robot stopped",
        "contacts, not approaching",
        "rooms with an at-fault contact",
        "simulated s",
    ])
    .align(std::iter::repeat_n(Align::Left, 2).chain(std::iter::repeat_n(Align::Right, 7)));
    for ((c, _, m, _), (s, _)) in combos.iter().zip(&results) {
        let rooms: Vec<String> = s
            .at_fault_rooms
            .iter()
            .take(8)
            .map(u64::to_string)
            .collect();
        table.row([
            (*c).to_string(),
            (*m).to_string(),
            s.rooms.to_string(),
            format!("{:.1}", 100.0 * s.reached as f64 / s.rooms.max(1) as f64),
            s.contacts_at_fault.to_string(),
            s.contacts_robot_stopped.to_string(),
            s.contacts_not_approaching.to_string(),
            if rooms.is_empty() {
                "-".into()
            } else {
                rooms.join(" ")
            },
            format!("{:.0}", s.simulated_s),
        ]);
    }
    let md = format!(
        "# The safety soak at walking speed\n\n`cargo xtask crowd --runs 0 --soak {}` \
         ({:.0} s of wall time): `sim::room_at(2026, k, (0.8, 1.6))` for k < {}, people \
         at 0.8-1.6 m/s, each run seeded with its room index.\n\n{}",
        args.soak,
        started.elapsed().as_secs_f64(),
        args.soak,
        table.to_markdown()
    );
    std::fs::write(out.join("soak.md"), &md).context("writing soak.md")?;
    println!("{md}");
    Ok(())
}

/// Writes `crowd-FLOW.ron` into `dir` for every flow: density 1, run 0 of `seed`.
fn write_scenarios(dir: &std::path::Path, seed: u64) -> anyhow::Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    for flow in CrowdFlow::ALL {
        let sc = sim::crowd(flow, 1.0, seed, 0);
        let text = ron::ser::to_string_pretty(&sc, ron::ser::PrettyConfig::default())?;
        let header = format!(
            "// A generated {flow} crowd, 1 person per 100 m^2 on average, people under social \
             forces who see the robot.\n// Written by `cargo xtask crowd --write-scenarios DIR` \
             (sim::crowd({flow}, 1.0, {seed}, 0)); try `hyplan sim FILE --people-model orca-blind`.\n"
        );
        let path = dir.join(format!("crowd-{flow}.ron"));
        std::fs::write(&path, header + &text + "\n")
            .with_context(|| format!("writing {}", path.display()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}
