//! `cargo xtask bench-peers`: our sampling planners side by side with OMPL 1.5.
//!
//! Builds the OMPL peer (`../shared/peers/ompl`, copied to `target/peers/ompl-timed`, whose
//! `build.sh` apt-installs `libompl-dev` when missing), then for every case (map, start,
//! goal, step = OMPL's `--range`, goal bias, goal radius) runs the peer with `--runs N` and
//! ours in-process for the same number of seeded runs, timing only the `plan` call (the
//! peer's `time_s` is `SimpleSetup::solve`). Prints a Markdown table of medians, ratios,
//! success rates and lengths. With `--rounds R` it does that R times per row, the two sides
//! in turn, and the medians are over all rounds' runs.
//!
//! With `--db FILE`, both sides' runs are also written as OMPL benchmark logs (the peer
//! through `ompl::tools::Benchmark`, `--ompl-log`; ours through `harness::bench`) under
//! `target/bench-peers/logs/`, and OMPL's `ompl_benchmark_statistics` loads them all into
//! the one SQLite database FILE, which Planner Arena opens.
//!
//! OMPL's clock: `SimpleSetup::solve(seconds)`, which the peer calls, starts a thread that
//! watches the clock when the limit is 1 s or more (OMPL 1.5's `Planner::solve(double)`),
//! and on this host its start and join added 0.1-1 ms to every solve, bimodal from one
//! process to the next: on the small cases that was most of OMPL's median. So by default
//! the xtask builds its copy of the peer with one call changed, `ss.solve(seconds)` to
//! `ss.solve(timedPlannerTerminationCondition(seconds))`, the clock check without a thread
//! that `solve` itself uses below 1 s: the planner's own time. `--ompl-watch-thread` builds
//! and times the peer as it ships.
//!
//! Caveat printed with the table: OMPL's motion check is sampled (a state every 0.25 cells,
//! the peer's default); ours is exact (every cell a segment touches), which costs us time
//! and never cuts a corner. The `OMPL cut` column counts OMPL paths that cross a blocked
//! cell (the peer's own `--check-exact`).
//!
//! The grid searches' peer is the `pathfinding` crate's A*, in process: the criterion group
//! `grid_search` (benches/benches/grid_search.rs) and the example `grid_jps_rounds` put our
//! `jps` and `astar` beside it on the same MovingAI and generated queries and print the
//! ratios; `--planners jps` here says so.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use anyhow::{Context as _, bail};
use envmap::{GridMap, load_map};
use harness::Scoring;
use harness::bench::{self, BenchRun, ExperimentInfo, RunId};
use harness::stats::median;
use hyplan_benches::PeerCase as Case;
use hyplan_core::{Budget, Query, Workspace};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use registry::{PlannerConfig, PlannerKind};

/// Options of `cargo xtask bench-peers`.
#[derive(clap::Args)]
pub struct Args {
    /// Runs (seeds) per planner and case, for us and for OMPL.
    #[arg(long, default_value_t = 30)]
    pub runs: u32,
    /// Rounds of those runs per planner and case, ours and OMPL's in turn (who goes first
    /// alternates), each OMPL round a new process: the medians are then over every round's
    /// runs, and the table adds the range of the rounds' own ratios. On a noisy host one
    /// process's median moves by a third between runs; rounds spread both sides over the
    /// same stretch of time and over several of OMPL's processes.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    pub rounds: u32,
    /// Time limit per run, seconds (both sides).
    #[arg(long, default_value_t = 20.0)]
    pub time_limit: f64,
    /// Only the cases whose name contains this text.
    #[arg(long)]
    pub only: Option<String>,
    /// Only these planners (comma separated: rrt, rrt-connect, rrt-star, bi-rrt; the
    /// registry's names).
    #[arg(long, value_delimiter = ',', value_parser = compared_planner)]
    pub planners: Option<Vec<PlannerKind>>,
    /// Rebuild the OMPL peer even if it is already built.
    #[arg(long)]
    pub rebuild: bool,
    /// Time OMPL's `solve(seconds)` as the peer ships it, with the thread OMPL starts to
    /// watch the clock for limits of 1 s or more (by default the peer is built to check
    /// the clock without that thread; see the module's documentation).
    #[arg(long)]
    pub ompl_watch_thread: bool,
    /// Also write both sides' runs as OMPL benchmark logs and load them with OMPL's
    /// `ompl_benchmark_statistics` (package ompl-demos) into this SQLite database.
    #[arg(long)]
    pub db: Option<PathBuf>,
}

/// One case a row (the table is `hyplan_benches`'s, which the examples that time one case
/// share). The room is converted to binary P5 under target/peers/maps (the peer reads
/// P2/P3/P5/P6 only).
const CASES: &[Case] = hyplan_benches::PEER_CASES;

/// (our planner, OMPL's name or None when OMPL has no such planner).
const PLANNERS: &[(PlannerKind, Option<&str>)] = &[
    (PlannerKind::Rrt, Some("rrt")),
    (PlannerKind::RrtConnect, Some("rrtconnect")),
    (PlannerKind::RrtStar, Some("rrtstar")),
    (PlannerKind::BiRrt, None),
];

/// Where the grid searches meet their peer, the `pathfinding` crate's A* (not OMPL).
const GRID_PEER_RUN: &str =
    "cargo run --release -p hyplan-benches --example grid_jps_rounds -- 5 --generated";

/// `--planners`' value: a registry name of a planner this comparison runs.
fn compared_planner(name: &str) -> Result<PlannerKind, String> {
    let kind = PlannerConfig::by_name(name)
        .map_err(|e| e.to_string())?
        .kind();
    if PLANNERS.iter().any(|(k, _)| *k == kind) {
        Ok(kind)
    } else if kind.capabilities().family == registry::Family::GridSearch {
        Err(format!(
            "{name} is a grid search: its peer is the pathfinding crate's A*, timed beside \
             our jps and astar by `{GRID_PEER_RUN}`"
        ))
    } else {
        let compared: Vec<&str> = PLANNERS.iter().map(|(k, _)| k.name()).collect();
        Err(format!(
            "{name} is not compared with OMPL (compared: {})",
            compared.join(", ")
        ))
    }
}

/// Our side of a case: `kind` with its defaults, the case's step and goal bias (for the
/// planners that have one) and `budget`. RRT* stops at its first solution (its default),
/// as OMPL's peer does.
fn our_config(kind: PlannerKind, case: &Case, budget: Budget) -> PlannerConfig {
    PlannerConfig::from(kind)
        .with_step(case.step)
        .with_goal_bias(case.goal_bias)
        .with_budget(budget)
}

/// One side of one row: every run's time, the counts and the median length.
#[derive(Debug)]
struct Summary {
    runs: usize,
    solved: usize,
    /// Every run's time, seconds.
    times: Vec<f64>,
    median_length: Option<f64>,
    /// Solved paths that cross a blocked cell (OMPL's `--check-exact`; ours are checked
    /// here with `segment_free` and must be 0).
    cut: usize,
}

impl Summary {
    /// Adds a round of the same runs to the rounds so far (`None` before the first): its
    /// times and counts. The rounds repeat the same seeds, so the lengths stay the first
    /// round's.
    fn pool(so_far: &mut Option<Self>, round: Self) {
        match so_far {
            None => *so_far = Some(round),
            Some(s) => {
                s.runs += round.runs;
                s.solved += round.solved;
                s.cut += round.cut;
                s.times.extend(round.times);
            }
        }
    }
}

/// The median of a side's run times, seconds (NaN without runs).
fn time_median(s: &Summary) -> f64 {
    median(s.times.iter().copied()).unwrap_or(f64::NAN)
}

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives one level below the workspace root")
        .to_path_buf()
}

/// The peer's call that `solve`s with OMPL's watching thread, and the same call with
/// OMPL's thread-free clock check.
const SOLVE_CALL: &str = "ss.solve(o.timeLimit)";
const SOLVE_TIMED: &str = "ss.solve(ob::timedPlannerTerminationCondition(o.timeLimit))";

/// Copies the peer's sources to `target/peers/ompl` (or, with the thread-free clock check,
/// `target/peers/ompl-timed`, its [`SOLVE_CALL`] changed) and builds it there.
fn build_peer(root: &Path, args: &Args) -> anyhow::Result<PathBuf> {
    let dir = root.join(if args.ompl_watch_thread {
        "target/peers/ompl"
    } else {
        "target/peers/ompl-timed"
    });
    let bin = dir.join("build/ompl_peer");
    if bin.exists() && !args.rebuild {
        return Ok(bin);
    }
    let src = root.join("../shared/peers/ompl");
    std::fs::create_dir_all(&dir)?;
    for entry in std::fs::read_dir(&src).with_context(|| {
        format!(
            "reading {}: the OMPL peer's sources (the benchmark peers folder beside the repository)",
            src.display()
        )
    })? {
        let entry = entry?;
        if entry.file_type()?.is_file() {
            std::fs::copy(entry.path(), dir.join(entry.file_name()))?;
        }
    }
    if !args.ompl_watch_thread {
        let file = dir.join("ompl_peer.cpp");
        let source = std::fs::read_to_string(&file)
            .with_context(|| format!("reading {}", file.display()))?;
        if source.matches(SOLVE_CALL).count() != 1 {
            bail!(
                "{}: expected one `{SOLVE_CALL}` to time without OMPL's watching thread \
                 (the peer changed?); run with --ompl-watch-thread",
                file.display()
            );
        }
        std::fs::write(&file, source.replace(SOLVE_CALL, SOLVE_TIMED))
            .with_context(|| format!("writing {}", file.display()))?;
    }
    eprintln!("building the OMPL peer in {} ...", dir.display());
    let status = Command::new("bash")
        .arg("build.sh")
        .current_dir(&dir)
        .status()
        .context("running build.sh")?;
    if !status.success() || !bin.exists() {
        bail!("building the OMPL peer failed ({status})");
    }
    Ok(bin)
}

/// The map file both sides read: the case's file, or for pictures that are not plain
/// P5/P2/P6/P3 a binary P5 copy under `target/peers/maps`.
fn peer_map(root: &Path, case: &Case) -> anyhow::Result<PathBuf> {
    let path = root.join(case.map);
    if !path.exists() {
        bail!("{} is missing", path.display());
    }
    let header = std::fs::read(&path)?;
    let plain = header.starts_with(b"P5")
        || header.starts_with(b"P2")
        || header.starts_with(b"P6")
        || header.starts_with(b"P3");
    if path.extension().is_some_and(|e| e == "map") || plain {
        return Ok(path);
    }
    let gray = image::open(&path)
        .with_context(|| format!("decoding {}", path.display()))?
        .to_luma8();
    let out_dir = root.join("target/peers/maps");
    std::fs::create_dir_all(&out_dir)?;
    let out = out_dir.join(path.file_name().unwrap_or_default());
    let mut bytes = format!("P5\n{} {}\n255\n", gray.width(), gray.height()).into_bytes();
    bytes.extend_from_slice(gray.as_raw());
    std::fs::write(&out, bytes)?;
    Ok(out)
}

/// Runs the peer once with `--runs N` and summarises its CSV.
fn run_ompl(
    bin: &Path,
    map: &Path,
    case: &Case,
    planner: &str,
    args: &Args,
    log: Option<&Path>,
) -> anyhow::Result<Summary> {
    let mut cmd = Command::new(bin);
    cmd.arg("--map")
        .arg(map)
        .args([
            "--start",
            &case.start.0.to_string(),
            &case.start.1.to_string(),
        ])
        .args(["--goal", &case.goal.0.to_string(), &case.goal.1.to_string()])
        .args(["--planner", planner])
        .args(["--range", &case.step.to_string()])
        .args(["--time-limit", &args.time_limit.to_string()])
        .args(["--runs", &args.runs.to_string()])
        .args(["--seed", "1", "--check-exact"]);
    if planner != "rrtconnect" {
        cmd.args(["--goal-bias", &case.goal_bias.to_string()]);
    }
    if case.goal_radius > 0.0 {
        cmd.args(["--goal-radius", &case.goal_radius.to_string()]);
    }
    if let Some(log) = log {
        // OMPL's Benchmark runs the problem again (the same runs and time limit) and
        // writes its own log.
        cmd.arg("--ompl-log").arg(log);
    }
    let out = cmd.output().context("running ompl_peer")?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        bail!("ompl_peer failed: {stderr}");
    }
    let mut times = Vec::new();
    let mut lengths = Vec::new();
    let mut solved = 0;
    for line in stdout.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        if f.len() < 8 {
            continue;
        }
        times.push(f[4].parse::<f64>()?);
        if f[3] == "1" {
            solved += 1;
            lengths.push(f[5].parse::<f64>()?);
        }
    }
    // "exact grid check: K of N solved paths cross a blocked cell"
    let cut = stderr
        .lines()
        .find_map(|l| l.split("exact grid check: ").nth(1))
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|k| k.parse().ok())
        .unwrap_or(0);
    Ok(Summary {
        runs: times.len(),
        solved,
        times,
        median_length: median(lengths),
        cut,
    })
}

/// Runs our planner `runs` times in-process (seeds 0..runs), timing `plan` only, and checks
/// every solved path against the map.
fn run_ours(
    map: &GridMap,
    query: &Query,
    case: &Case,
    planner: PlannerKind,
    args: &Args,
    records: Option<&mut Vec<BenchRun>>,
) -> anyhow::Result<Summary> {
    let limit = Duration::try_from_secs_f64(args.time_limit).context("--time-limit")?;
    let budget = Budget::iterations(u64::MAX).with_time(limit);
    let ours = our_config(planner, case, budget).build();
    let plan = |rng: &mut ChaCha8Rng| ours.plan(map, query, rng);
    let mut times = Vec::new();
    let mut lengths = Vec::new();
    let mut cut = 0;
    let mut obstacles = map.clone();
    obstacles.blocked_from = hyplan_core::Zone::Forbidden;
    let scoring = Scoring {
        ws: map,
        obstacles: &obstacles,
        explored_by_expansions: false,
        smoothing: postproc::Smoothing::None,
        limits: None,
        spacing: 0.25 * map.resolution(),
    };
    let label = format!("hyplan_{planner}");
    let mut records = records;
    for seed in 0..u64::from(args.runs) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cpu = cpu_time::ThreadTime::try_now().ok();
        let started = Instant::now();
        let result = plan(&mut rng);
        let wall = started.elapsed().as_secs_f64();
        times.push(wall);
        if let Some(records) = records.as_deref_mut() {
            let cpu_s = cpu.map_or(f64::NAN, |t| t.elapsed().as_secs_f64());
            let id = RunId {
                problem: 0,
                label: &label,
                run: u32::try_from(seed).unwrap_or(u32::MAX),
                seed,
            };
            records.push(bench::score_run(&result, wall, cpu_s, &scoring, &id));
        }
        match result {
            Ok(p) => {
                let valid = p.path.first() == Some(&query.start)
                    && p.path.last().is_some_and(|&g| query.goal.contains(g))
                    && p.path.windows(2).all(|w| map.segment_free(w[0], w[1]));
                if !valid {
                    cut += 1;
                }
                lengths.push(p.length());
            }
            Err(e) if e.is_no_path() => {}
            Err(e) => bail!("{planner} on {}: {e}", case.name),
        }
    }
    Ok(Summary {
        runs: times.len(),
        solved: lengths.len(),
        times,
        median_length: median(lengths),
        cut,
    })
}

fn fmt_len(l: Option<f64>) -> String {
    l.map_or_else(|| "-".into(), |l| format!("{l:.1}"))
}

/// Runs the comparison and prints the table.
///
/// # Errors
///
/// A missing map, a failed peer build or run.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let root = root();
    let bin = build_peer(&root, args)?;
    let log_dir = root.join("target/bench-peers/logs");
    if args.db.is_some() {
        // Stale logs of other cases or planners would land in the database too.
        let _ = std::fs::remove_dir_all(&log_dir);
        std::fs::create_dir_all(&log_dir)
            .with_context(|| format!("creating {}", log_dir.display()))?;
    }
    let mut logs: Vec<PathBuf> = Vec::new();
    let (rounds_head, rounds_rule) = if args.rounds > 1 {
        (" rounds' ratios |", "---:|")
    } else {
        ("", "")
    };
    println!(
        "| case | planner | step | runs | ours median ms | OMPL median ms | ours/OMPL | ours solved | OMPL exact | ours median length | OMPL median length | OMPL cut |{rounds_head}"
    );
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|{rounds_rule}");
    let mut worst_ratio: f64 = 0.0;
    let mut success_ok = true;
    for case in CASES {
        if args.only.as_deref().is_some_and(|o| !case.name.contains(o)) {
            continue;
        }
        let map_path = match peer_map(&root, case) {
            Ok(p) => p,
            Err(e) => {
                eprintln!("skipping {}: {e:#}", case.name);
                continue;
            }
        };
        let loaded = load_map(&map_path, &hyplan_benches::peer_load_options())
            .with_context(|| format!("loading {}", map_path.display()))?;
        let query = case.query(&loaded.frame);
        query
            .validate(&loaded.map)
            .with_context(|| format!("case {}", case.name))?;
        // The map's one-time preparation for edge checks (its stride table), not in the
        // times, as the peer's map set-up is not in its times.
        let prepared = Instant::now();
        let _ = loaded.map.blocked_strides();
        eprintln!(
            "{}: map prepared for edge checks in {:.2} ms (not timed)",
            case.name,
            prepared.elapsed().as_secs_f64() * 1e3
        );
        for &(ours, ompl) in PLANNERS {
            if args.planners.as_ref().is_some_and(|ps| !ps.contains(&ours)) {
                continue;
            }
            let (mut o, mut p) = (None, None);
            let mut round_ratios = Vec::new();
            for round in 0..args.rounds {
                // The logs are of the first round (the rounds repeat the same runs).
                let first = round == 0;
                let ours_round = |logs: &mut Vec<PathBuf>| -> anyhow::Result<Summary> {
                    let mut records = args.db.as_ref().filter(|_| first).map(|_| Vec::new());
                    let started = Instant::now();
                    let o = run_ours(&loaded.map, &query, case, ours, args, records.as_mut())?;
                    if let Some(records) = &records {
                        let log = log_dir.join(format!("hyplan-{}-{ours}.log", case.name));
                        write_our_log(&log, case, &map_path, ours, args, records, started)?;
                        logs.push(log);
                    }
                    Ok(o)
                };
                let peer_round = |logs: &mut Vec<PathBuf>| -> anyhow::Result<Option<Summary>> {
                    let Some(name) = ompl else {
                        return Ok(None);
                    };
                    let log = args
                        .db
                        .as_ref()
                        .filter(|_| first)
                        .map(|_| log_dir.join(format!("ompl-{}-{name}.log", case.name)));
                    let summary = run_ompl(&bin, &map_path, case, name, args, log.as_deref())?;
                    logs.extend(log);
                    Ok(Some(summary))
                };
                // Who goes first alternates, so that a drift of the host's speed falls on
                // both sides alike.
                let (o_r, p_r) = if round % 2 == 0 {
                    let o_r = ours_round(&mut logs)?;
                    (o_r, peer_round(&mut logs)?)
                } else {
                    let p_r = peer_round(&mut logs)?;
                    (ours_round(&mut logs)?, p_r)
                };
                if o_r.cut > 0 {
                    bail!(
                        "{ours} on {}: {} paths failed the exact check",
                        case.name,
                        o_r.cut
                    );
                }
                if let Some(p_r) = &p_r {
                    round_ratios.push(time_median(&o_r) / time_median(p_r));
                }
                Summary::pool(&mut o, o_r);
                if let Some(p_r) = p_r {
                    Summary::pool(&mut p, p_r);
                }
            }
            let o = o.expect("at least one round (`--rounds` is 1 or more)");
            let o_ms = time_median(&o) * 1e3;
            let (ompl_ms, ratio, ompl_exact, ompl_len, ompl_cut) = match &p {
                Some(p) => {
                    let ratio = time_median(&o) / time_median(p);
                    worst_ratio = worst_ratio.max(ratio);
                    success_ok &= o.solved >= p.solved;
                    (
                        format!("{:.3}", time_median(p) * 1e3),
                        format!("{ratio:.3}"),
                        format!("{}/{}", p.solved, p.runs),
                        fmt_len(p.median_length),
                        p.cut.to_string(),
                    )
                }
                None => ("-".into(), "-".into(), "-".into(), "-".into(), "-".into()),
            };
            let lo = round_ratios.iter().copied().reduce(f64::min);
            let hi = round_ratios.iter().copied().reduce(f64::max);
            let range = match (lo, hi) {
                _ if args.rounds == 1 => String::new(),
                (Some(lo), Some(hi)) => format!(" {lo:.3}-{hi:.3} |"),
                _ => " - |".to_string(),
            };
            println!(
                "| {} | {} | {} | {} | {:.3} | {} | {} | {}/{} | {} | {} | {} | {} |{range}",
                case.name,
                ours,
                case.step,
                o.runs,
                o_ms,
                ompl_ms,
                ratio,
                o.solved,
                o.runs,
                ompl_exact,
                fmt_len(o.median_length),
                ompl_len,
                ompl_cut
            );
        }
    }
    if let Some(db) = &args.db {
        load_logs(db, &logs)?;
    }
    println!();
    println!(
        "worst ours/OMPL median-time ratio: {worst_ratio:.3}; success >= OMPL's everywhere: {success_ok}"
    );
    println!(
        "note: OMPL's time is {}.",
        if args.ompl_watch_thread {
            "`SimpleSetup::solve(seconds)` as the peer ships it, with the thread OMPL starts to \
             watch the clock for limits of 1 s or more"
        } else {
            "`solve` with OMPL's thread-free clock check (`timedPlannerTerminationCondition`); \
             `--ompl-watch-thread` times `solve(seconds)`, with its watching thread"
        }
    );
    println!(
        "note: OMPL checks motions at sampled states 0.25 cells apart (`OMPL cut` = its paths that \
         cross a blocked cell); ours checks every cell a segment touches."
    );
    Ok(())
}

/// Writes our runs of one planner on one case as an OMPL benchmark log.
fn write_our_log(
    path: &Path,
    case: &Case,
    map: &Path,
    planner: PlannerKind,
    args: &Args,
    records: &[BenchRun],
    started: Instant,
) -> anyhow::Result<()> {
    let info = ExperimentInfo {
        // OMPL's peer names its experiment after the map path: ours says the same.
        name: map.display().to_string().replace(char::is_whitespace, "_"),
        host: std::fs::read_to_string("/etc/hostname")
            .map(|h| h.trim().to_string())
            .ok()
            .filter(|h| !h.is_empty())
            .unwrap_or_else(|| "UNKNOWN".into()),
        start: bench::utc_timestamp(),
        setup: format!(
            "cargo xtask bench-peers\ncase {}\nstart {:?} goal {:?} goal radius {}\nstep {} goal bias {}",
            case.name, case.start, case.goal, case.goal_radius, case.step, case.goal_bias
        ),
        seed: 0,
        max_time: args.time_limit,
        run_count: u64::from(args.runs),
        total_duration: started.elapsed().as_secs_f64(),
    };
    let mut settings = std::collections::BTreeMap::new();
    settings.insert(
        format!("hyplan_{planner}"),
        [
            ("range".to_string(), case.step.to_string()),
            ("goal_bias".to_string(), case.goal_bias.to_string()),
        ]
        .into(),
    );
    let refs: Vec<&BenchRun> = records.iter().collect();
    let log = bench::experiment_log(&info, &refs, &settings).to_log()?;
    std::fs::write(path, log).with_context(|| format!("writing {}", path.display()))
}

/// Loads the logs into `db` with OMPL's own script (a fresh database).
fn load_logs(db: &Path, logs: &[PathBuf]) -> anyhow::Result<()> {
    let script = "ompl_benchmark_statistics";
    let _ = std::fs::remove_file(db);
    let out = Command::new(script)
        .arg("-d")
        .arg(db)
        .args(logs)
        .output()
        .with_context(|| format!("running {script} (apt-get install ompl-demos)"))?;
    if !out.status.success() {
        bail!("{script} failed: {}", String::from_utf8_lossy(&out.stderr));
    }
    eprintln!(
        "{} OMPL logs (ours and OMPL's) loaded into {}",
        logs.len(),
        db.display()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The registry's planners, set up as the comparison sets them, are the structs OMPL's
    /// settings describe: the case's range and goal bias, the budget, RRT* to its first
    /// solution.
    #[test]
    fn our_planners_carry_the_case_settings() {
        let case = &CASES[0];
        let budget = Budget::iterations(u64::MAX).with_time(Duration::from_secs(2));
        let (step, goal_bias) = (case.step, case.goal_bias);
        let set = |kind| our_config(kind, case, budget);
        let rrt = sampling::Rrt {
            step,
            goal_bias,
            budget,
        };
        assert_eq!(set(PlannerKind::Rrt), PlannerConfig::Rrt(rrt));
        let star = sampling::RrtStar {
            step,
            goal_bias,
            budget,
            stop_at_first_solution: true,
            ..sampling::RrtStar::default()
        };
        assert_eq!(set(PlannerKind::RrtStar), PlannerConfig::RrtStar(star));
        let connect = sampling::RrtConnect { step, budget };
        assert_eq!(
            set(PlannerKind::RrtConnect),
            PlannerConfig::RrtConnect(connect)
        );
        let bi = sampling::BiRrt { step, budget };
        assert_eq!(set(PlannerKind::BiRrt), PlannerConfig::BiRrt(bi));
        assert!(compared_planner("rrt-connect").is_ok());
        let grid = compared_planner("jps").unwrap_err();
        assert!(grid.contains("grid_jps_rounds"), "{grid}");
        assert!(compared_planner("astar").is_err());
        assert!(compared_planner("nope").is_err());
    }

    /// A second round's runs join the first's: the median is over both, the counts add up,
    /// and the lengths stay the first round's (the same seeds).
    #[test]
    fn rounds_pool_their_runs() {
        let round = |times: &[f64], length| Summary {
            runs: times.len(),
            solved: times.len() - 1,
            times: times.to_vec(),
            median_length: Some(length),
            cut: 0,
        };
        let mut side = None;
        Summary::pool(&mut side, round(&[1.0, 2.0, 3.0], 5.0));
        assert_eq!(time_median(side.as_ref().unwrap()), 2.0);
        Summary::pool(&mut side, round(&[10.0, 20.0, 30.0], 6.0));
        let side = side.unwrap();
        assert_eq!((side.runs, side.solved), (6, 4));
        assert_eq!(time_median(&side), 6.5);
        assert_eq!(side.median_length, Some(5.0));
    }
}
