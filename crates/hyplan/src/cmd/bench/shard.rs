//! `hyplan bench --shard K/N` writes a shard's records; `hyplan bench merge` reads every
//! shard's back and writes the outputs of the whole experiment.
//!
//! A shard's folder holds `records.ron` (a first line with the experiment, its problems,
//! planner settings and the shard's clocks, then one run per line, in RON, which reads
//! back bit for bit) and `shard.json`, the manifest of `harness::bench::shard` (the
//! experiment's hash, `K/N`, the version, the work items), written last.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context as _, bail};
use harness::bench::BenchRun;
use harness::bench::shard::{self, Shard, ShardManifest};
use serde::{Deserialize, Serialize};

use super::output::{self, Clock, Outputs, Timing};
use super::{Experiment, ProblemRecord, Settings, work_items};

/// The tool name in the manifests.
const TOOL: &str = "hyplan bench";
/// The records' file name in a shard's folder.
const RECORDS: &str = "records.ron";

/// Options of `hyplan bench merge`.
#[derive(clap::Args, Debug)]
pub struct MergeArgs {
    /// The shards' folders (each a `--out` of `hyplan bench --shard K/N`), every shard
    /// of the experiment exactly once, in any order.
    #[arg(required = true, value_name = "DIR")]
    pub dirs: Vec<PathBuf>,
    /// Output directory [default: bench-out].
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// The first line of a shard's records: what every output needs besides the runs.
#[derive(Debug, Serialize, Deserialize)]
struct Context {
    /// The experiment, its shard left out (the hashed part, with `alpha`).
    experiment: Experiment,
    /// Level of the rank tests.
    alpha: f64,
    /// Name, map and query of each problem.
    problems: Vec<ProblemRecord>,
    /// Each problem's planner settings.
    settings: Vec<Settings>,
    /// The shard's host, start, wall time of its runs and threads.
    timing: Timing,
    /// Whole command's wall time, s.
    total_s: f64,
    /// Whole command's CPU time, s.
    command_cpu_s: f64,
}

/// The experiment's identity: the hash of what decides every value of the outputs.
fn experiment_hash(e: &Experiment, alpha: f64) -> anyhow::Result<String> {
    Ok(shard::experiment_hash(&(e, alpha))?)
}

/// The number of work items of `e`.
fn total_items(e: &Experiment, problems: usize) -> u64 {
    problems as u64 * e.planners.len() as u64 * u64::from(e.runs)
}

/// Writes shard `which`'s records and manifest into `out` (made ready by
/// `begin_shard` before the runs).
pub(super) fn write_shard(
    out: &Path,
    which: Shard,
    o: &Outputs,
    total_s: f64,
    command_cpu_s: f64,
) -> anyhow::Result<()> {
    let context = Context {
        experiment: o.experiment.clone(),
        alpha: o.alpha,
        problems: o.problems.clone(),
        settings: o.settings.clone(),
        timing: o.timing.clone(),
        total_s,
        command_cpu_s,
    };
    let mut text = ron::to_string(&context)?;
    text.push('\n');
    for r in &o.runs {
        text.push_str(&ron::to_string(r)?);
        text.push('\n');
    }
    let total = total_items(&o.experiment, o.problems.len());
    let manifest = ShardManifest::new(
        TOOL,
        env!("CARGO_PKG_VERSION"),
        &experiment_hash(&o.experiment, o.alpha)?,
        which,
        total,
    );
    if manifest.items != o.runs.len() as u64 {
        bail!(
            "shard {which}: {} runs where the shard has {} items",
            o.runs.len(),
            manifest.items
        );
    }
    shard::finish_shard(out, manifest, RECORDS, text.as_bytes())?;
    outln!(
        "shard {which}: {} of {total} runs in {:.3} s; records and manifest in {} \
         (merge every shard with `hyplan bench merge DIR... --out DIR`)",
        o.runs.len(),
        o.timing.wall_s,
        out.display()
    )?;
    Ok(())
}

/// One shard's records read back.
struct ShardRecords {
    context: Context,
    runs: Vec<BenchRun>,
}

fn parse_records(dir: &Path, text: &str) -> anyhow::Result<ShardRecords> {
    let path = dir.join(RECORDS);
    let mut lines = text.lines().enumerate();
    let (_, first) = lines
        .next()
        .with_context(|| format!("{}: empty", path.display()))?;
    let context: Context =
        ron::from_str(first).with_context(|| format!("{}:1: the experiment", path.display()))?;
    let runs = lines
        .map(|(n, line)| {
            ron::from_str(line).with_context(|| format!("{}:{}: a run", path.display(), n + 1))
        })
        .collect::<anyhow::Result<Vec<BenchRun>>>()?;
    Ok(ShardRecords { context, runs })
}

/// Runs `hyplan bench merge`: checks the shards, then writes the outputs as an
/// unsharded run does.
///
/// # Errors
///
/// Missing, duplicate, foreign or unfinished shards (each named with its folder and
/// `K/N`); records that do not match their manifest; outputs that cannot be written.
pub(super) fn merge(args: &MergeArgs) -> anyhow::Result<ExitCode> {
    let shards = shard::read_shards(&args.dirs, TOOL)?;
    let mut parsed = Vec::with_capacity(shards.len());
    for s in &shards {
        let r = parse_records(&s.dir, &s.records)?;
        let hash = experiment_hash(&r.context.experiment, r.context.alpha)?;
        if hash != s.manifest.experiment_hash {
            bail!(
                "{} (shard {}): its records are of another experiment than its manifest",
                s.dir.display(),
                s.manifest.shard
            );
        }
        parsed.push((s, r));
    }
    let (_, first) = parsed.first().context("no shard")?;
    let e = first.context.experiment.clone();
    let (problems, settings) = (
        first.context.problems.clone(),
        first.context.settings.clone(),
    );
    let total = total_items(&e, problems.len());
    // Every run in its place in the experiment's order, each exactly once.
    let index: std::collections::HashMap<(usize, &str, u32), u64> =
        work_items(problems.len(), e.planners.len(), e.runs)
            .enumerate()
            .map(|(j, (p, i, k))| ((p, e.planners[i].as_str(), k), j as u64))
            .collect();
    let mut slots: Vec<Option<BenchRun>> = vec![None; usize::try_from(total)?];
    for (s, r) in &parsed {
        let which = s.manifest.shard;
        if r.runs.len() as u64 != s.manifest.items {
            bail!(
                "{} (shard {which}): {} runs where the manifest has {}",
                s.dir.display(),
                r.runs.len(),
                s.manifest.items
            );
        }
        for run in &r.runs {
            let key = (run.problem, run.planner.as_str(), run.metrics.run);
            let Some(&j) = index.get(&key) else {
                bail!(
                    "{} (shard {which}): a run of no work item ({key:?})",
                    s.dir.display()
                );
            };
            let slot = &mut slots[j as usize];
            if !which.takes(j) || slot.is_some() {
                bail!(
                    "{} (shard {which}): work item {j} is not this shard's or is there twice",
                    s.dir.display()
                );
            }
            *slot = Some(run.clone());
        }
    }
    // Each shard held its item count, each item in its shard: every slot is full.
    let runs: Vec<BenchRun> = slots.into_iter().flatten().collect();
    let mut hosts: Vec<&str> = Vec::new();
    for (_, r) in &parsed {
        if !hosts.contains(&r.context.timing.host.as_str()) {
            hosts.push(&r.context.timing.host);
        }
    }
    let sum = |f: fn(&ShardRecords) -> f64| parsed.iter().map(|(_, r)| f(r)).sum::<f64>();
    let timing = Timing {
        host: hosts.join(","),
        start: parsed
            .iter()
            .map(|(_, r)| r.context.timing.start.clone())
            .min()
            .unwrap_or_default(),
        wall_s: sum(|r| r.context.timing.wall_s),
        threads: parsed.iter().map(|(_, r)| r.context.timing.threads).sum(),
    };
    let clock = Clock::Recorded {
        total_s: sum(|r| r.context.total_s),
        command_cpu_s: sum(|r| r.context.command_cpu_s),
    };
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("bench-out"));
    let outputs = Outputs {
        alpha: first.context.alpha,
        experiment: e,
        problems,
        settings,
        runs,
        timing,
    };
    output::write_outputs(&out, outputs, &clock)?;
    Ok(ExitCode::SUCCESS)
}
