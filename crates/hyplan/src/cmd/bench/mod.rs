//! `hyplan bench`: which planner, with which parameters, for my map? Runs planners on
//! one or more problems (a map and a query), many times each, spread over threads, and
//! writes every run (CSV, JSON), a summary with pairwise rank tests (Markdown), box plots
//! and a success-rate chart (SVG) and one OMPL benchmark log per problem, which OMPL's
//! `ompl_benchmark_statistics` loads into the same database as OMPL's own runs.
//!
//! Everything is validated before the first run: maps load, queries lie in free cells,
//! planners and their parameter names exist; bad input exits 2.
//!
//! One path for every way of running: the runs (all of them, or one shard's) become
//! records ([`BenchRun`]); the outputs are written from records ([`output::write_outputs`]),
//! whether they come straight from the runs or from shards read back by `hyplan bench
//! merge` ([`shard`]).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use anyhow::{Context as _, bail};
use envmap::{GridMap, LoadOptions};
use harness::bench::shard::Shard;
use harness::bench::{self, BenchRun};
use harness::{Explored, PlannerConfig, PlannerSpec, Scoring};
use hyplan_core::{Goal, PlanError, Planner, Query, Zone};
use serde::{Deserialize, Serialize};

mod output;
mod shard;

use super::{input_scale, parse_xy};
use output::{Clock, Outputs, Timing};

/// Options of `hyplan bench`.
#[derive(clap::Args, Debug)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct Args {
    /// `merge`: the outputs of a sharded experiment from its shards' folders.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// An experiment file (RON): maps, queries, planners and options together (see
    /// docs/bench.md). Excludes --map, --query and --planner.
    #[arg(long, conflicts_with_all = ["map", "query", "planner"])]
    pub experiment: Option<PathBuf>,
    /// A map: picture, ROS `.yaml` or MovingAI `.map` (repeat for several maps; each
    /// query is run on each map).
    #[arg(long, required_unless_present = "experiment")]
    pub map: Vec<PathBuf>,
    /// A query `X,Y X,Y` (start, goal) in the map's input frame (pictures and `.map`:
    /// column, row from the top); repeat for several queries.
    #[arg(long, num_args = 2, value_names = ["START", "GOAL"], required_unless_present = "experiment", allow_hyphen_values = true)]
    pub query: Vec<String>,
    /// A planner `NAME[:key=value,...]` (repeat for several), NAME one of the registry's
    /// (listed below); keys are the planner's parameters (`step`, `goal_bias`,
    /// `max_iterations`, `stop_at_first_solution`, ...; `hyplan planners` lists them).
    #[arg(long, required_unless_present = "experiment", value_parser = crate::planners::SpecParser::default())]
    pub planner: Vec<String>,
    /// Runs per planner and problem [default: 20].
    #[arg(long)]
    pub runs: Option<u32>,
    /// Time limit per run, seconds (sampling planners and hybrids; the grid searches run
    /// to the end).
    #[arg(long)]
    pub time_limit: Option<f64>,
    /// Base seed; run k uses SplitMix64(seed) output k + 1, whatever the thread [default: 1].
    #[arg(long)]
    pub seed: Option<u64>,
    /// Post-processing of every path: none, prune, pchip, bspline, bspline-interp
    /// [default: none].
    #[arg(long)]
    pub smooth: Option<String>,
    /// Goal tolerance in the input's units; 0: the exact goal point [default: 0].
    #[arg(long)]
    pub goal_radius: Option<f64>,
    /// Robot limits `VMAX,WMAX,AMAX` (input units/s, rad/s, input units/s^2): each run's
    /// transfer time.
    #[arg(long)]
    pub limits: Option<String>,
    /// Output directory [default: bench-out]. With --shard: the shard's records and
    /// manifest only (`hyplan bench merge` writes the outputs).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Run shard K of N only (K from 0 to N - 1): the work items (problem x planner x
    /// run) j with j mod N = K. Overrides the experiment file's `shard`.
    #[arg(long, value_name = "K/N")]
    pub shard: Option<Shard>,
    /// Worker threads [default: all cores]; the results do not depend on it.
    #[arg(long)]
    pub threads: Option<usize>,
    /// Significance level of the pairwise rank tests.
    #[arg(long, default_value_t = 0.05)]
    pub alpha: f64,
    /// Memory limit: maps with more cells (width x height) are refused before loading.
    #[arg(long, value_name = "N", default_value_t = envmap::DEFAULT_MAX_CELLS)]
    pub max_cells: usize,
}

/// `hyplan bench`'s subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Check that shard folders cover one experiment exactly once and write its outputs
    /// (the same as an unsharded run's, the clocks aside).
    Merge(shard::MergeArgs),
}

/// An experiment as a RON file gives it (and as the flags build it).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Experiment {
    /// Name: the logs' experiment names start with it (one word).
    #[serde(default = "default_name")]
    pub name: String,
    /// Maps with their queries.
    pub problems: Vec<ProblemSpec>,
    /// Planners, `NAME[:key=value,...]`.
    pub planners: Vec<String>,
    /// Runs per planner and problem.
    #[serde(default = "default_runs")]
    pub runs: u32,
    /// Base seed.
    #[serde(default = "default_seed")]
    pub seed: u64,
    /// Time limit per run, s.
    #[serde(default)]
    pub time_limit: Option<f64>,
    /// Post-processing method.
    #[serde(default = "default_smooth")]
    pub smooth: String,
    /// Goal tolerance, input units.
    #[serde(default)]
    pub goal_radius: f64,
    /// Robot limits (v_max, omega_max, a_max) in input units.
    #[serde(default)]
    pub limits: Option<(f64, f64, f64)>,
    /// Run this shard only (`Some("K/N")`); `hyplan bench merge` joins the shards.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<Shard>,
}

/// One map and the queries run on it.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ProblemSpec {
    /// The map file (relative paths: to the experiment file's folder).
    pub map: PathBuf,
    /// Start and goal pairs, input frame.
    pub queries: Vec<((f64, f64), (f64, f64))>,
}

fn default_name() -> String {
    "hyplan".into()
}
const fn default_runs() -> u32 {
    20
}
const fn default_seed() -> u64 {
    1
}
fn default_smooth() -> String {
    "none".into()
}

/// A planner spec from `NAME[:key=value,...]` (the registry's form, see
/// [`registry::PlannerConfig::from_spec`]), with the command's defaults for what the user
/// left out: the defaults that follow the map's size
/// ([`registry::PlannerConfig::map_sized`]: a step of 5% of the map's diagonal for the
/// plain sampling planners, RRT-A*-BT's step and goal radius in seed 000's proportion),
/// the time limit (and no iteration cap) as every planner's budget. The pairs win over
/// both.
///
/// # Errors
///
/// A malformed spec, an unknown planner, key or value (the registry's message).
pub fn planner_spec(
    text: &str,
    map_diagonal: f64,
    time_limit: Option<f64>,
) -> Result<(PlannerSpec, Box<dyn Planner>), String> {
    let time_limit = time_limit
        .map(|t| {
            std::time::Duration::try_from_secs_f64(t)
                .map_err(|_| format!("time limit {t}: not a duration"))
        })
        .transpose()?;
    let config = PlannerConfig::from_spec(text, |c| {
        // No time limit: every planner keeps its own budget rule (`hyplan plan`'s too).
        c.map_sized(map_diagonal).with_limits(None, time_limit)
    })
    .map_err(|e| e.to_string())?;
    let planner = config.build();
    let spec = PlannerSpec {
        label: Some(text.to_string()),
        ..PlannerSpec::new(config)
    };
    Ok((spec, planner))
}

/// RRT* run to its whole budget (`stop_at_first_solution=false`), whose progress is
/// observed through its own `plan_with` (the trait has no observer); `None` for every
/// other planner.
pub fn anytime_rrt_star(spec: &PlannerSpec) -> Option<sampling::RrtStar> {
    match &spec.planner {
        PlannerConfig::RrtStar(p) if !p.stop_at_first_solution => Some(*p),
        _ => None,
    }
}

/// A problem ready to run: the map, its query in world coordinates, its planners.
struct Problem {
    /// `MAPSTEM-qK`, the log's experiment name.
    name: String,
    map_path: PathBuf,
    query_text: String,
    map: GridMap,
    obstacles: GridMap,
    query: Query,
    /// World units per input unit.
    scale: f64,
    planners: Vec<(PlannerSpec, Box<dyn Planner>)>,
    /// For each planner, the RRT* whose progress is recorded (see [`anytime_rrt_star`]).
    anytime: Vec<Option<sampling::RrtStar>>,
}

/// The experiment the flags describe, or the RON file's (its map paths made relative to
/// the file's folder).
fn experiment(args: &Args) -> anyhow::Result<Experiment> {
    let mut e = if let Some(path) = &args.experiment {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("reading experiment {}", path.display()))?;
        let mut e: Experiment = ron::from_str(&text).map_err(|err| {
            anyhow::anyhow!(
                "experiment {}:{}:{}: {}",
                path.display(),
                err.position.line,
                err.position.col,
                err.code
            )
        })?;
        let dir = path.parent().unwrap_or(Path::new("."));
        for p in &mut e.problems {
            if p.map.is_relative() {
                p.map = dir.join(&p.map);
            }
        }
        e
    } else {
        let mut queries = Vec::new();
        for pair in args.query.chunks(2) {
            let [s, g] = pair else {
                bail!("--query takes two points, START and GOAL");
            };
            let start = parse_xy(s).with_context(|| format!("--query {s} {g}: start"))?;
            let goal = parse_xy(g).with_context(|| format!("--query {s} {g}: goal"))?;
            queries.push((start, goal));
        }
        Experiment {
            name: default_name(),
            problems: args
                .map
                .iter()
                .map(|m| ProblemSpec {
                    map: m.clone(),
                    queries: queries.clone(),
                })
                .collect(),
            planners: args.planner.clone(),
            runs: default_runs(),
            seed: default_seed(),
            time_limit: None,
            smooth: default_smooth(),
            goal_radius: 0.0,
            limits: None,
            shard: None,
        }
    };
    // Flags override the file's options.
    if args.shard.is_some() {
        e.shard = args.shard;
    }
    if let Some(r) = args.runs {
        e.runs = r;
    }
    if let Some(s) = args.seed {
        e.seed = s;
    }
    if args.time_limit.is_some() {
        e.time_limit = args.time_limit;
    }
    if let Some(s) = &args.smooth {
        e.smooth.clone_from(s);
    }
    if let Some(r) = args.goal_radius {
        e.goal_radius = r;
    }
    if let Some(l) = &args.limits {
        let v: Vec<f64> = l
            .split(',')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .with_context(|| format!("--limits {l}: expected VMAX,WMAX,AMAX"))?;
        let [v, w, a] = v[..] else {
            bail!("--limits {l}: expected three numbers VMAX,WMAX,AMAX");
        };
        e.limits = Some((v, w, a));
    }
    Ok(e)
}

/// Loads the maps, places the queries and builds the planners: every error before a run.
fn prepare(e: &Experiment, max_cells: usize) -> anyhow::Result<Vec<Problem>> {
    if e.runs == 0 {
        bail!("runs = 0: must be at least 1");
    }
    if e.name.split_whitespace().count() != 1 || e.name.contains(['/', '\\']) {
        bail!("experiment name {:?}: must be one word", e.name);
    }
    if let Some(t) = e.time_limit
        && !(t.is_finite() && t > 0.0)
    {
        bail!("time limit {t}: must be a positive number of seconds");
    }
    if !(e.goal_radius.is_finite() && e.goal_radius >= 0.0) {
        bail!("goal radius {}: must be >= 0", e.goal_radius);
    }
    if e.problems.is_empty() || e.problems.iter().all(|p| p.queries.is_empty()) {
        bail!("no problem: give at least one map and one query");
    }
    if e.planners.is_empty() {
        bail!("no planner: give at least one");
    }
    let mut seen = std::collections::HashSet::new();
    if let Some(dup) = e.planners.iter().find(|p| !seen.insert(p.as_str())) {
        bail!("planner {dup} is given twice");
    }
    if let Some((v, w, a)) = e.limits {
        postproc::Limits::new(v, w, a)
            .map_err(|err| anyhow::anyhow!("limits {v},{w},{a}: {err}"))?;
    }
    e.smooth
        .parse::<postproc::Smoothing>()
        .map_err(|err| anyhow::anyhow!("smoothing {:?}: {err}", e.smooth))?;
    let mut problems = Vec::new();
    for spec in &e.problems {
        let opts = LoadOptions {
            max_cells,
            ..LoadOptions::default()
        };
        let loaded = super::load_map(&spec.map, &opts)
            .with_context(|| format!("loading {}", spec.map.display()))?;
        let frame = loaded.frame;
        let scale = input_scale(&frame);
        let map = loaded.map;
        let mut obstacles = map.clone();
        obstacles.blocked_from = Zone::Forbidden;
        let stem = spec
            .map
            .file_stem()
            .map_or_else(|| "map".into(), |s| s.to_string_lossy().into_owned())
            .replace(
                |c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '_'),
                "_",
            );
        for (k, &(s, g)) in spec.queries.iter().enumerate() {
            let query_text = format!("{},{} {},{}", s.0, s.1, g.0, g.1);
            let start = frame.to_world(s.0, s.1);
            let centre = frame.to_world(g.0, g.1);
            let goal = if e.goal_radius == 0.0 {
                Goal::Point(centre)
            } else {
                Goal::disc(centre, e.goal_radius * scale)
            };
            let query = Query::new(start, goal);
            query.validate(&map).map_err(|err| {
                let (which, reason) = match err {
                    PlanError::InvalidStart { reason, .. } => ("start", reason),
                    PlanError::InvalidGoal { reason, .. } => ("goal", reason),
                    _ => ("query", "invalid"),
                };
                anyhow::anyhow!(
                    "query {query_text} on {}: the {which} is {reason}",
                    spec.map.display()
                )
            })?;
            let planners = e
                .planners
                .iter()
                .map(|text| {
                    planner_spec(text, map.bounds().diagonal(), e.time_limit)
                        .map_err(|err| anyhow::anyhow!("planner {text}: {err}"))
                })
                .collect::<anyhow::Result<Vec<_>>>()?;
            let anytime = planners.iter().map(|(s, _)| anytime_rrt_star(s)).collect();
            problems.push(Problem {
                name: format!("{}-{stem}-q{k}", e.name),
                map_path: spec.map.clone(),
                query_text,
                map: map.clone(),
                obstacles: obstacles.clone(),
                query,
                scale,
                planners,
                anytime,
            });
        }
    }
    Ok(problems)
}

/// Everything a bench produced, as `runs.json` holds it.
#[derive(Debug, Serialize)]
pub struct Report {
    /// The experiment as run.
    pub experiment: Experiment,
    /// Problems: name, map, query.
    pub problems: Vec<ProblemRecord>,
    /// Every run.
    pub runs: Vec<BenchRun>,
    /// One row per planner and problem.
    pub summary: Vec<bench::SummaryRow>,
    /// Every pair of planners on each problem.
    pub comparisons: Vec<bench::Comparison>,
    /// Wall time of the runs, s (summed over the shards of a merged experiment).
    pub wall_s: f64,
    /// Sum of the runs' times (planning and post-processing), s.
    pub sum_run_time_s: f64,
    /// Sum of the planning times alone, s.
    pub sum_planning_time_s: f64,
    /// Sum of the planning calls' thread CPU times, s.
    pub sum_planning_cpu_s: f64,
    /// CPU time of the whole command (every thread) up to the report, s.
    pub command_cpu_s: f64,
    /// Worker threads (summed over the shards of a merged experiment).
    pub threads: usize,
}

/// A problem in the report.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ProblemRecord {
    /// The log's experiment name.
    pub name: String,
    /// The map file.
    pub map: PathBuf,
    /// The query as given (`SX,SY GX,GY`, input frame).
    pub query: String,
}

/// Each planner's settings on one problem, by label: the OMPL log's `common` properties.
pub type Settings = BTreeMap<String, BTreeMap<String, String>>;

/// Runs `hyplan bench` (or `hyplan bench merge`).
///
/// # Errors
///
/// Bad input (before any run), or an output that cannot be written.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    if let Some(Command::Merge(m)) = &args.command {
        return shard::merge(m);
    }
    let started = Instant::now();
    let cpu_started = cpu_time::ProcessTime::try_now().ok();
    let e = experiment(args)?;
    let problems = prepare(&e, args.max_cells)?;
    if !(args.alpha > 0.0 && args.alpha < 0.5) {
        bail!("--alpha {}: must be in (0, 0.5)", args.alpha);
    }
    let smoothing: postproc::Smoothing =
        e.smooth.parse().map_err(|err| anyhow::anyhow!("{err}"))?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("bench-out"));
    let sharded = e.shard.is_some();
    let shard = e.shard.unwrap_or(Shard::WHOLE);
    if sharded {
        harness::bench::shard::begin_shard(&out)?;
    } else {
        std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    }
    let threads = args.threads.unwrap_or(0);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .context("starting the worker threads")?;
    let threads = pool.current_num_threads();

    let scorings: Vec<Scoring<'_>> = problems
        .iter()
        .map(|p| Scoring {
            ws: &p.map,
            obstacles: &p.obstacles,
            explored_by_expansions: false,
            smoothing,
            // Checked in `prepare`; given in input units, the map's scale makes them world's.
            limits: e
                .limits
                .and_then(|(v, w, a)| postproc::Limits::new(v * p.scale, w, a * p.scale).ok()),
            spacing: 0.25 * p.map.resolution(),
        })
        .collect();
    let start = bench::utc_timestamp();
    let runs_started = Instant::now();
    let runs = run_all(&pool, &problems, &scorings, &e, shard);
    let wall_s = runs_started.elapsed().as_secs_f64();
    if let Some(bad) = runs.iter().find(|r| r.status == "invalid input") {
        bail!(
            "planner {}: {}",
            bad.planner,
            bad.error.as_deref().unwrap_or("invalid input")
        );
    }
    let outputs = Outputs {
        problems: problems
            .iter()
            .map(|p| ProblemRecord {
                name: p.name.clone(),
                map: p.map_path.clone(),
                query: p.query_text.clone(),
            })
            .collect(),
        settings: problems.iter().map(|p| settings(&e, p)).collect(),
        experiment: Experiment { shard: None, ..e },
        alpha: args.alpha,
        runs,
        timing: Timing {
            host: host_name(),
            start,
            wall_s,
            threads,
        },
    };
    if !sharded {
        let clock = Clock::Live {
            started,
            cpu: cpu_started,
        };
        output::write_outputs(&out, outputs, &clock)?;
    } else {
        let total_s = started.elapsed().as_secs_f64();
        let cpu_s = cpu_started.map_or(f64::NAN, |t| t.elapsed().as_secs_f64());
        shard::write_shard(&out, shard, &outputs, total_s, cpu_s)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// The machine's name for the OMPL log (`UNKNOWN` where it has none).
fn host_name() -> String {
    std::fs::read_to_string("/etc/hostname")
        .map(|h| h.trim().to_string())
        .ok()
        .filter(|h| !h.is_empty())
        .unwrap_or_else(|| "UNKNOWN".into())
}

/// Every planner's settings on a problem, as `hyplan planners` shows them.
fn settings(e: &Experiment, prob: &Problem) -> Settings {
    prob.planners
        .iter()
        .map(|(spec, _)| {
            let mut s: BTreeMap<String, String> = spec.planner.params().into_iter().collect();
            s.insert("planner".into(), spec.planner.name().to_string());
            s.insert("smoothing".into(), e.smooth.clone());
            (spec.label().to_string(), s)
        })
        .collect()
}

/// The work items of an experiment in its order (problem, then planner, then run
/// index): item j is `jobs[j]`, as (problem, planner, run).
fn work_items(
    problems: usize,
    planners: usize,
    runs: u32,
) -> impl Iterator<Item = (usize, usize, u32)> {
    (0..problems)
        .flat_map(move |p| (0..planners).flat_map(move |i| (0..runs).map(move |k| (p, i, k))))
}

/// The runs of `shard`'s work items (every run for [`Shard::WHOLE`]), in the
/// experiment's order, on the worker threads, with a progress bar.
fn run_all(
    pool: &rayon::ThreadPool,
    problems: &[Problem],
    scorings: &[Scoring<'_>],
    e: &Experiment,
    shard: Shard,
) -> Vec<BenchRun> {
    let jobs: Vec<(usize, usize, u32)> = work_items(problems.len(), e.planners.len(), e.runs)
        .enumerate()
        .filter(|&(j, _)| shard.takes(j as u64))
        .map(|(_, job)| job)
        .collect();
    let bar = indicatif::ProgressBar::new(jobs.len() as u64).with_style(
        indicatif::ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} runs ({eta} left)",
        )
        .expect("a valid template"),
    );
    // Each worker thread plans on its own copy of the map of the problem it is on: a map
    // lends a prepared search to one run at a time (`GridMap::take_kept`), so a second
    // thread would make its own inside a timed run. One copy a thread, replaced when the
    // thread moves to another problem, so that memory grows with the threads only.
    let copies: Vec<std::sync::Mutex<Option<(usize, GridMap)>>> = (0..pool.current_num_threads())
        .map(|_| std::sync::Mutex::new(None))
        .collect();
    let runs: Vec<BenchRun> = pool.install(|| {
        use rayon::prelude::*;
        jobs.par_iter()
            .map(|&(p, i, k)| {
                let prob = &problems[p];
                let (spec, planner) = &prob.planners[i];
                let thread = rayon::current_thread_index().unwrap_or(0) % copies.len();
                // Only this thread takes this lock; a poisoned one still holds a whole map.
                let mut copy = copies[thread]
                    .lock()
                    .unwrap_or_else(std::sync::PoisonError::into_inner);
                if copy.as_ref().is_some_and(|(q, _)| *q != p) {
                    *copy = None;
                }
                let (_, map) = copy.get_or_insert_with(|| (p, prob.map.clone()));
                let map: &GridMap = map;
                // The map's one-time preparation, not timed, as `hyplan plan` makes it (kept
                // with the copy; made again only if the copy let it go for another
                // planner's).
                harness::prepare_map(&spec.planner, planner.as_ref(), map);
                let scoring = Scoring {
                    ws: map,
                    // Graph searches count expansions, the others their nodes.
                    explored_by_expansions: spec.planner.explored() == Explored::Expansions,
                    ..scorings[p]
                };
                let call = match &prob.anytime[i] {
                    Some(rrt_star) => bench::PlanCall::RrtStar(rrt_star),
                    None => bench::PlanCall::Planner(planner.as_ref()),
                };
                let r = bench::run_once(
                    call,
                    &scoring,
                    &prob.query,
                    p,
                    spec.label(),
                    k,
                    harness::run_seed(e.seed, u64::from(k)),
                );
                bar.inc(1);
                r
            })
            .collect()
    });
    bar.finish_and_clear();
    runs
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Only RRT* to its whole budget is observed as anytime.
    #[test]
    fn anytime_rrt_star_only_for_the_whole_budget() {
        let (spec, _) = planner_spec("rrt-star:stop_at_first_solution=false", 50.0, None).unwrap();
        assert!(anytime_rrt_star(&spec).is_some());
        let (spec, _) = planner_spec("rrt-star", 50.0, None).unwrap();
        assert!(anytime_rrt_star(&spec).is_none());
        let (spec, _) = planner_spec("rrt", 50.0, None).unwrap();
        assert!(anytime_rrt_star(&spec).is_none());
    }

    #[test]
    fn planner_specs_parse() {
        let (spec, p) = planner_spec(
            "rrt-star:step=2,stop_at_first_solution=false",
            100.0,
            Some(0.5),
        )
        .unwrap();
        assert_eq!(p.info().name, "rrt-star");
        assert_eq!(spec.planner.step(), Some(2.0));
        let budget = spec.planner.budget().unwrap();
        assert_eq!(budget.max_time, Some(std::time::Duration::from_millis(500)));
        assert_eq!(budget.max_iterations, Some(u64::MAX));
        // The map-sized default step: 5 % of the diagonal for the plain sampling
        // planners, RRT-A*-BT's seed-000 pixels in proportion (40 on the paper's room).
        let (spec, _) = planner_spec("rrt", 100.0, None).unwrap();
        assert_eq!(spec.planner.step(), Some(5.0));
        let room = 960_f64.hypot(640.0);
        let (spec, _) = planner_spec("rrt-astar-bt", room, None).unwrap();
        assert_eq!(spec.planner.step(), Some(40.0));
        let (spec, _) = planner_spec("rrt-astar-bt", room / 8.0, None).unwrap();
        assert_eq!(spec.planner.step(), Some(5.0));
        assert!(
            planner_spec("rrt:stpe=2", 1.0, None)
                .err()
                .unwrap()
                .contains("stpe")
        );
        assert!(planner_spec("nope", 1.0, None).is_err());
        assert!(planner_spec("rrt:step", 1.0, None).is_err());
        assert!(planner_spec("rrt:step=x", 1.0, None).is_err());
    }
}
