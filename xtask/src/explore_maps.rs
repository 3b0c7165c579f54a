//! `cargo xtask explore-maps`: issue 27's exploration benchmark. `sim::explore` on the
//! exploration scenario of every real-building map of `data/ros_maps/`, a generated
//! 60 m building and the two drawn or small worlds, for every detector and seed; writes
//! what each run reached (coverage of the reachable free area, how it ended, simulated
//! and wall time) as a Markdown table (`table.md`, also `table.csv`) and JSON
//! (`results.json`; `runs.jsonl` grows a line per run as runs finish).
//!
//! Runs are independent and bit-identical per seed, so they run in parallel (rayon), the
//! largest worlds first, and are reported in a fixed order. Wall times are measured with
//! the runs sharing the cores: the simulated / wall ratio of a run alone is higher on a
//! loaded machine; the thread's CPU time is recorded beside it.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Instant;

use anyhow::{Context, bail};
use rayon::prelude::*;
use serde::Serialize;
use sim::{Scenario, Strategy, World};
use viz::{Align, Table};

/// The maps: the name `--maps` takes, and the scenario file under `scenarios/sim/`.
pub const MAPS: [(&str, &str); 8] = [
    ("22m", "explore-22m.ron"),
    ("tb3", "explore-tb3.ron"),
    ("aws_small_house", "explore-aws_small_house.ron"),
    ("yujin_rnd_hokuyo", "explore-yujin_rnd_hokuyo.ron"),
    ("uos_avz5floor_open", "explore-uos_avz5floor_open.ron"),
    ("mit_building_31", "explore-mit_building_31.ron"),
    ("mit_stata_basement", "explore-mit_stata_basement.ron"),
    ("building-60m", "explore-building-60m.ron"),
];

/// The coverage issue 27 asks of every run.
pub const TARGET: f64 = 0.99;

/// Options of `cargo xtask explore-maps`.
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Maps, comma-separated (default: all): 22m, tb3, aws_small_house,
    /// yujin_rnd_hokuyo, uos_avz5floor_open, mit_building_31, mit_stata_basement,
    /// building-60m.
    #[arg(long, value_delimiter = ',')]
    pub maps: Vec<String>,
    /// Detectors, comma-separated: local, global, both, frontier (default: all four).
    #[arg(long, value_delimiter = ',')]
    pub detectors: Vec<String>,
    /// Seeds, comma-separated.
    #[arg(long, value_delimiter = ',', default_values_t = [0u64, 1, 2])]
    pub seeds: Vec<u64>,
    /// Output folder (default `target/explore-maps` in the workspace).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Runs at a time (default: one per core).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Cap on every scenario's time limit, simulated seconds (quick checks; default: the
    /// scenarios' own limits).
    #[arg(long)]
    pub max_time: Option<f64>,
    /// Print each run's coverage every this many simulated seconds on stderr (0: only
    /// when a run starts and ends).
    #[arg(long, default_value_t = 500.0)]
    pub progress_every: f64,
    /// The conformance check: fail (exit 1) naming every run below 99 % coverage.
    #[arg(long)]
    pub check: bool,
}

/// One run: what it measured.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunRecord {
    /// The map's name (as `--maps` takes it).
    pub map: String,
    /// The scenario file, relative to the workspace.
    pub scenario: String,
    /// The detector.
    pub detector: String,
    /// The seed.
    pub seed: u64,
    /// Known free / reachable free area of the true world at the end.
    pub coverage: f64,
    /// Reachable free area of the true world, m^2.
    pub reachable_m2: f64,
    /// Reachable free area not known free at the end, m^2.
    pub missed_m2: f64,
    /// Simulated time coverage first reached 99 %, s.
    pub t99_s: Option<f64>,
    /// Whether the exploration ended by itself (no frontier left); false: the time limit.
    pub finished: bool,
    /// Simulated time at the end, s.
    pub end_time_s: f64,
    /// The run's time limit, s.
    pub time_limit_s: f64,
    /// Wall-clock time of the run, s.
    pub wall_s: f64,
    /// CPU time of the run's thread, s (NaN where the platform has no thread clock).
    pub cpu_s: f64,
    /// Simulated / wall time.
    pub sim_per_wall: f64,
    /// Goals sent to the navigator.
    pub goals: usize,
    /// Frontiers given up on.
    pub blacklisted: usize,
    /// Distance driven, m.
    pub distance_m: f64,
    /// Laser ticks with the robot's body overlapping the world.
    pub contact_ticks: usize,
}

impl RunRecord {
    /// Whether the run reached [`TARGET`].
    #[must_use]
    pub fn reached(&self) -> bool {
        self.coverage >= TARGET
    }

    /// How the run ended, in words.
    #[must_use]
    pub fn ended(&self) -> &'static str {
        if self.finished {
            "no frontier left"
        } else {
            "time limit"
        }
    }
}

/// Everything `results.json` holds.
#[derive(Debug, Serialize)]
struct Results<'a> {
    target: f64,
    maps: Vec<&'a str>,
    detectors: Vec<&'static str>,
    seeds: &'a [u64],
    max_time: Option<f64>,
    jobs: usize,
    wall_s: f64,
    runs: &'a [RunRecord],
}

/// One map, loaded.
struct Map {
    name: &'static str,
    file: &'static str,
    scenario: Scenario,
    world: World,
}

/// The maps named (all when none), in [`MAPS`] order.
///
/// # Errors
///
/// A name not in [`MAPS`].
pub fn pick_maps(names: &[String]) -> anyhow::Result<Vec<(&'static str, &'static str)>> {
    for n in names {
        if !MAPS.iter().any(|(m, _)| m == n) {
            let known: Vec<&str> = MAPS.iter().map(|(m, _)| *m).collect();
            bail!("unknown map `{n}`: the maps are {}", known.join(", "));
        }
    }
    Ok(MAPS
        .into_iter()
        .filter(|(m, _)| names.is_empty() || names.iter().any(|n| n == m))
        .collect())
}

/// The detectors named (all four when none), in [`Strategy::ALL`] order.
///
/// # Errors
///
/// A name that is not a detector.
pub fn pick_detectors(names: &[String]) -> anyhow::Result<Vec<Strategy>> {
    for n in names {
        if Strategy::parse(n).is_none() {
            bail!("unknown detector `{n}`: local, global, both or frontier");
        }
    }
    Ok(Strategy::ALL
        .into_iter()
        .filter(|s| names.is_empty() || names.iter().any(|n| n == s.name()))
        .collect())
}

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

/// Runs the benchmark and writes its outputs.
///
/// # Errors
///
/// A bad option, a scenario that does not load, a run that fails, an output that cannot
/// be written.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let root = workspace_root();
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| root.join("target/explore-maps"));
    let records = run_in(&root.join("scenarios/sim"), &out, args)?;
    let reached = records.iter().filter(|r| r.reached()).count();
    println!(
        "{reached} of {} runs reached {:.0} % coverage; wrote {}",
        records.len(),
        100.0 * TARGET,
        out.join("table.md").display()
    );
    let short: Vec<String> = records
        .iter()
        .filter(|r| !r.reached())
        .map(|r| {
            format!(
                "{} {} seed {}: {:.1} % ({}, {:.0} s)",
                r.map,
                r.detector,
                r.seed,
                100.0 * r.coverage,
                r.ended(),
                r.end_time_s
            )
        })
        .collect();
    if args.check && !short.is_empty() {
        bail!(
            "{} runs below {:.0} % coverage:\n  {}",
            short.len(),
            100.0 * TARGET,
            short.join("\n  ")
        );
    }
    Ok(())
}

/// [`run`] with the scenarios of `dir`, writing to `out`; returns the runs in order.
fn run_in(dir: &Path, out: &Path, args: &Args) -> anyhow::Result<Vec<RunRecord>> {
    let maps = pick_maps(&args.maps)?;
    let detectors = pick_detectors(&args.detectors)?;
    if args.seeds.is_empty() {
        bail!("no seeds");
    }
    if let Some(t) = args.max_time
        && !(t.is_finite() && t > 0.0)
    {
        bail!("--max-time {t}: must be finite and > 0");
    }
    let loaded: Vec<Map> = maps
        .iter()
        .map(|&(name, file)| {
            let path = dir.join(file);
            let (mut scenario, world) =
                Scenario::load(&path).with_context(|| format!("loading map `{name}`"))?;
            if let Some(t) = args.max_time {
                scenario.time_limit = scenario.time_limit.min(t);
            }
            Ok(Map {
                name,
                file,
                scenario,
                world,
            })
        })
        .collect::<anyhow::Result<_>>()?;
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let jsonl_path = out.join("runs.jsonl");
    let jsonl = Mutex::new(
        std::fs::File::create(&jsonl_path)
            .with_context(|| format!("creating {}", jsonl_path.display()))?,
    );
    // (map index, detector, seed), the largest worlds first so that the longest runs do
    // not start last.
    let mut specs: Vec<(usize, Strategy, u64)> = (0..loaded.len())
        .flat_map(|m| {
            detectors
                .iter()
                .flat_map(move |&d| args.seeds.iter().map(move |&s| (m, d, s)))
        })
        .collect();
    let area = |m: usize| loaded[m].world.bounds.width() * loaded[m].world.bounds.height();
    specs.sort_by(|a, b| area(b.0).total_cmp(&area(a.0)));
    let jobs = args.jobs.unwrap_or_else(rayon::current_num_threads).max(1);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .context("starting the worker threads")?;
    let total = specs.len();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let started = Instant::now();
    eprintln!(
        "explore-maps: {total} runs ({} maps x {} detectors x {} seeds) on {jobs} threads",
        loaded.len(),
        detectors.len(),
        args.seeds.len()
    );
    let mut records: Vec<RunRecord> = pool.install(|| {
        specs
            .par_iter()
            .map(|&(m, detector, seed)| {
                let record = one_run(&loaded[m], detector, seed, args.progress_every)?;
                let k = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
                eprintln!(
                    "explore-maps: [{k}/{total}] {} {} seed {seed}: {:.2} % of {:.1} m^2, {} at {:.0} s, {:.1} s wall ({:.0}x)",
                    record.map,
                    record.detector,
                    100.0 * record.coverage,
                    record.reachable_m2,
                    record.ended(),
                    record.end_time_s,
                    record.wall_s,
                    record.sim_per_wall
                );
                let line = serde_json::to_string(&record)?;
                let mut f = jsonl.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
                writeln!(f, "{line}").context("writing runs.jsonl")?;
                Ok(record)
            })
            .collect::<anyhow::Result<_>>()
    })?;
    let order = |r: &RunRecord| {
        (
            maps.iter().position(|(n, _)| *n == r.map),
            detectors.iter().position(|d| d.name() == r.detector),
            r.seed,
        )
    };
    records.sort_by_key(order);
    let results = Results {
        target: TARGET,
        maps: maps.iter().map(|(n, _)| *n).collect(),
        detectors: detectors.iter().map(|d| d.name()).collect(),
        seeds: &args.seeds,
        max_time: args.max_time,
        jobs,
        wall_s: started.elapsed().as_secs_f64(),
        runs: &records,
    };
    let write = |name: &str, text: String| {
        let p = out.join(name);
        std::fs::write(&p, text).with_context(|| format!("writing {}", p.display()))
    };
    write("results.json", serde_json::to_string_pretty(&results)?)?;
    let table = table(&records);
    write("table.csv", table.to_csv())?;
    write("table.md", report(&records, &table, &results))?;
    Ok(records)
}

/// One exploration, timed.
fn one_run(
    map: &Map,
    detector: Strategy,
    seed: u64,
    progress_every: f64,
) -> anyhow::Result<RunRecord> {
    let label = format!("{} {} seed {seed}", map.name, detector.name());
    eprintln!("explore-maps: {label}: started");
    let mut next = progress_every;
    let mut progress = |c: &sim::Coverage| {
        if progress_every > 0.0 && c.t >= next {
            eprintln!(
                "explore-maps: {label}: t {:.0} s, coverage {:.1} %",
                c.t,
                100.0 * c.fraction
            );
            while next <= c.t {
                next += progress_every;
            }
        }
    };
    let cpu = cpu_time::ThreadTime::try_now().ok();
    let clock = Instant::now();
    let out = sim::explore_with(&map.scenario, &map.world, seed, detector, &mut progress)
        .with_context(|| label.clone())?;
    let wall_s = clock.elapsed().as_secs_f64();
    let cpu_s = cpu.map_or(f64::NAN, |t| t.elapsed().as_secs_f64());
    Ok(RunRecord {
        map: map.name.to_string(),
        scenario: format!("scenarios/sim/{}", map.file),
        detector: detector.name().to_string(),
        seed,
        coverage: out.final_coverage(),
        reachable_m2: out.reachable_area,
        missed_m2: out.missed_area(),
        t99_s: out.time_to(TARGET),
        finished: out.finished,
        end_time_s: out.end_time,
        time_limit_s: map.scenario.time_limit,
        wall_s,
        cpu_s,
        sim_per_wall: out.end_time / wall_s.max(1e-9),
        goals: out.goals.len(),
        blacklisted: out.blacklisted.len(),
        distance_m: out.distance,
        contact_ticks: out.contact_ticks,
    })
}

/// The runs as a table, a row each.
fn table(records: &[RunRecord]) -> Table {
    let mut t = Table::new([
        "map",
        "detector",
        "seed",
        "reachable (m^2)",
        "coverage (%)",
        "99 % at (s)",
        "ended",
        "end (s)",
        "wall (s)",
        "sim / wall",
        "goals",
        "blacklisted",
    ])
    .align([
        Align::Left,
        Align::Left,
        Align::Right,
        Align::Right,
        Align::Right,
        Align::Right,
        Align::Left,
        Align::Right,
        Align::Right,
        Align::Right,
        Align::Right,
        Align::Right,
    ]);
    for r in records {
        let coverage = format!("{:.2}", 100.0 * r.coverage);
        t.row([
            r.map.clone(),
            r.detector.clone(),
            r.seed.to_string(),
            format!("{:.1}", r.reachable_m2),
            if r.reached() {
                coverage
            } else {
                format!("**{coverage}**")
            },
            r.t99_s.map_or("-".into(), |t| format!("{t:.0}")),
            r.ended().to_string(),
            format!("{:.0}", r.end_time_s),
            format!("{:.1}", r.wall_s),
            format!("{:.0}x", r.sim_per_wall),
            r.goals.to_string(),
            r.blacklisted.to_string(),
        ]);
    }
    t
}

/// `table.md`: what ran, how many runs reached the target, the table, the runs that did
/// not.
fn report(records: &[RunRecord], table: &Table, results: &Results<'_>) -> String {
    let reached = records.iter().filter(|r| r.reached()).count();
    let mut s = format!(
        "# Exploration of the building maps (`cargo xtask explore-maps`)\n\n\
         Maps {}; detectors {}; seeds {:?}{}. {} runs on {} threads in {:.0} s of wall time. \
         Coverage: known free / reachable free area of the true world at the end; times are \
         simulated seconds except `wall`, measured with the runs sharing the cores.\n\n\
         **{reached} of {} runs reached {:.0} %.**\n\n",
        results.maps.join(", "),
        results.detectors.join(", "),
        results.seeds,
        results
            .max_time
            .map_or(String::new(), |t| format!("; time limits capped at {t} s")),
        records.len(),
        results.jobs,
        results.wall_s,
        records.len(),
        100.0 * TARGET,
    );
    s.push_str(&table.to_markdown());
    let short: Vec<&RunRecord> = records.iter().filter(|r| !r.reached()).collect();
    if !short.is_empty() {
        s.push_str(&format!("\nBelow {:.0} %:\n\n", 100.0 * TARGET));
        for r in short {
            s.push_str(&format!(
                "- {} {} seed {}: {:.2} %, {:.1} m^2 of {:.1} missed; {} at {:.0} s after {} goals ({} blacklisted)\n",
                r.map,
                r.detector,
                r.seed,
                100.0 * r.coverage,
                r.missed_m2,
                r.reachable_m2,
                r.ended(),
                r.end_time_s,
                r.goals,
                r.blacklisted
            ));
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args() -> Args {
        Args {
            maps: vec!["tb3".into()],
            detectors: vec!["frontier".into()],
            seeds: vec![0],
            out: None,
            jobs: Some(1),
            max_time: Some(5.0),
            progress_every: 0.0,
            check: false,
        }
    }

    #[test]
    fn every_scenario_loads_and_names_are_checked() {
        let dir = workspace_root().join("scenarios/sim");
        for (name, file) in MAPS {
            let path = dir.join(file);
            let (scenario, _) = Scenario::load(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert!(!scenario.known_map, "{name}");
            assert!(scenario.time_limit >= 900.0, "{name}");
        }
        assert_eq!(pick_maps(&[]).unwrap().len(), MAPS.len());
        let two = pick_maps(&["tb3".into(), "22m".into()]).unwrap();
        assert_eq!(two, vec![MAPS[0], MAPS[1]]);
        let e = pick_maps(&["nowhere".into()]).unwrap_err().to_string();
        assert!(
            e.contains("unknown map `nowhere`") && e.contains("building-60m"),
            "{e}"
        );
        assert_eq!(pick_detectors(&[]).unwrap(), Strategy::ALL.to_vec());
        assert!(pick_detectors(&["rrt".into()]).is_err());
    }

    /// A short run writes the table, the CSV and the JSON, one record per run.
    #[test]
    fn a_short_run_writes_every_output() {
        let out = std::env::temp_dir().join(format!("explore-maps-{}", std::process::id()));
        let a = args();
        let records = run_in(&workspace_root().join("scenarios/sim"), &out, &a).unwrap();
        assert_eq!(records.len(), 1);
        let r = &records[0];
        assert_eq!(
            (r.map.as_str(), r.detector.as_str(), r.seed),
            ("tb3", "frontier", 0)
        );
        assert_eq!(r.time_limit_s, 5.0);
        assert!(!r.finished && r.end_time_s <= 5.0 + 1e-9, "{r:?}");
        assert!(r.coverage > 0.0 && r.coverage < TARGET, "{r:?}");
        let md = std::fs::read_to_string(out.join("table.md")).unwrap();
        assert!(md.contains("| map | detector | seed |"), "{md}");
        assert!(md.contains("**0 of 1 runs reached 99 %.**"), "{md}");
        assert!(md.contains("- tb3 frontier seed 0:"), "{md}");
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap())
                .unwrap();
        assert_eq!(json["runs"].as_array().unwrap().len(), 1);
        assert_eq!(json["runs"][0]["detector"], "frontier");
        let lines = std::fs::read_to_string(out.join("runs.jsonl")).unwrap();
        assert_eq!(lines.lines().count(), 1);
        assert!(
            std::fs::read_to_string(out.join("table.csv"))
                .unwrap()
                .starts_with("map,")
        );
        std::fs::remove_dir_all(&out).unwrap();
        let bad = Args {
            max_time: Some(-1.0),
            ..args()
        };
        assert!(run_in(&workspace_root().join("scenarios/sim"), &out, &bad).is_err());
    }
}
