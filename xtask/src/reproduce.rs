//! `cargo xtask reproduce`: every scenario of `scenarios/`, run with the papers' run
//! counts, reported beside the papers' numbers.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Context as _;
use harness::stats::{Decision, Verdict, decide_less};
use harness::{ClaimKind, PlannerSpec, RunMetrics, Scenario, Summary, World, run_planner};
use indicatif::{MultiProgress, ProgressBar, ProgressStyle};
use serde::Serialize;

/// Options of `cargo xtask reproduce`.
#[derive(clap::Args)]
pub struct Args {
    /// Few runs per experiment (each scenario's `quick_runs`), for CI: about a minute.
    #[arg(long)]
    pub quick: bool,
    /// Only the experiments whose name contains this text.
    #[arg(long)]
    pub only: Option<String>,
    /// Runs per planner, overriding the scenario files.
    #[arg(long)]
    pub runs: Option<u32>,
    /// Output folder (default `target/reproduce`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Also write each `docs/papers/` page's generated results section (between its
    /// `<!-- reproduce:begin -->` and `<!-- reproduce:end -->` markers) from this run.
    #[arg(long)]
    pub update_docs: bool,
}

/// The level at which every ordering claim is decided (two one-sided Mann-Whitney U
/// tests, see [`harness::stats::decide_less`]).
pub const ALPHA: f64 = 0.01;

/// The metrics shown in the tables, with their headings.
pub(crate) const COLUMNS: &[(&str, &str)] = &[
    ("cpu_time_s", "CPU (ms)"),
    ("time_s", "wall (ms)"),
    ("length", "length"),
    ("nodes", "nodes"),
    ("segments", "segments"),
    ("turns", "turns > 10°"),
    ("explored", "explored"),
    ("transfer_time_s", "transfer (s)"),
    ("min_clearance", "min clearance"),
];

#[derive(Serialize)]
pub(crate) struct PlannerResult {
    pub label: String,
    pub name: String,
    pub summary: Summary,
    pub runs: Vec<RunMetrics>,
}

/// One step of a claimed order: `smaller` < `larger`, decided on the runs.
#[derive(Serialize)]
pub(crate) struct Step {
    pub smaller: String,
    pub larger: String,
    pub means: (f64, f64),
    pub decision: Decision,
}

#[derive(Serialize)]
pub(crate) struct ClaimResult {
    pub text: String,
    pub metric: String,
    pub kind: ClaimKind,
    pub means: Vec<(String, f64)>,
    pub steps: Vec<Step>,
    pub verdict: Verdict,
}

#[derive(Serialize)]
pub(crate) struct ExperimentResult {
    pub name: String,
    pub seed_file: String,
    pub experiment: String,
    pub file: String,
    pub runs: u32,
    pub planners: Vec<PlannerResult>,
    pub claims: Vec<ClaimResult>,
    /// The shortest path to the goal region on the planning map (Theta*), and the
    /// straight start-goal distance, scenario units.
    pub shortest: Option<(f64, f64)>,
}

/// The values of `metric` over runs: every run for times and explored nodes, the
/// successful ones for path measures (as [`Summary`] counts them).
fn values(runs: &[RunMetrics], metric: &str) -> Vec<f64> {
    let all = matches!(metric, "time_s" | "cpu_time_s" | "explored");
    runs.iter()
        .filter(|r| all || r.success)
        .filter_map(|r| r.get(metric))
        .filter(|v| v.is_finite())
        .collect()
}

fn mean(v: &[f64]) -> f64 {
    if v.is_empty() {
        f64::NAN
    } else {
        v.iter().sum::<f64>() / v.len() as f64
    }
}

/// Decides a claimed increasing order over labelled samples, step by step.
fn decide_order(
    text: String,
    metric: &str,
    kind: ClaimKind,
    samples: Vec<(String, Vec<f64>)>,
) -> ClaimResult {
    let means = samples.iter().map(|(l, v)| (l.clone(), mean(v))).collect();
    let steps: Vec<Step> = samples
        .windows(2)
        .map(|w| Step {
            smaller: w[0].0.clone(),
            larger: w[1].0.clone(),
            means: (mean(&w[0].1), mean(&w[1].1)),
            decision: decide_less(&w[0].1, &w[1].1, ALPHA),
        })
        .collect();
    let verdicts: Vec<Verdict> = steps.iter().map(|s| s.decision.verdict).collect();
    let verdict = if verdicts.contains(&Verdict::NoData) {
        Verdict::NoData
    } else if verdicts.contains(&Verdict::NotHeld) {
        Verdict::NotHeld
    } else if verdicts.iter().all(|v| *v == Verdict::Held) {
        Verdict::Held
    } else {
        Verdict::NotSignificant
    };
    ClaimResult {
        text,
        metric: metric.to_string(),
        kind,
        means,
        steps,
        verdict,
    }
}

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

/// Loads every scenario (all of them, so a bad file stops the run before any work).
fn load_all(dir: &Path) -> anyhow::Result<Vec<(PathBuf, Scenario, World)>> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .with_context(|| format!("reading {}", dir.display()))?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .collect();
    files.sort();
    // Building a room's map (drawing, binarizing, the band) takes a fraction of a second
    // for the largest pictures: build them on every core.
    use rayon::prelude::*;
    let out = files
        .into_par_iter()
        .map(|f| Scenario::load(&f).map(|(s, w)| (f, s, w)))
        .collect::<Result<Vec<_>, _>>()?;
    anyhow::ensure!(
        !out.is_empty(),
        "no scenario files (*.ron) in {}",
        dir.display()
    );
    Ok(out)
}

/// Runs the reproduction.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let root = workspace_root();
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| root.join("target/reproduce"));
    let figures = out.join("figures");
    std::fs::create_dir_all(&figures).with_context(|| format!("creating {}", figures.display()))?;
    let mut scenarios = load_all(&root.join("scenarios"))?;
    if let Some(only) = &args.only {
        scenarios.retain(|(_, s, _)| s.name.contains(only.as_str()));
        anyhow::ensure!(!scenarios.is_empty(), "no scenario name contains {only:?}");
    }
    eprintln!(
        "reproducing {} experiment(s){} into {}",
        scenarios.len(),
        if args.quick { " (quick)" } else { "" },
        out.display()
    );
    let started = Instant::now();
    let bars = MultiProgress::new();
    let style = ProgressStyle::with_template("{prefix:>40} {bar:30} {pos:>5}/{len:5} {elapsed:>4}")
        .unwrap_or_else(|_| ProgressStyle::default_bar());
    let mut results = Vec::new();
    for (file, scenario, world) in &scenarios {
        let runs = args.runs.unwrap_or(if args.quick {
            scenario.quick_runs
        } else {
            scenario.runs
        });
        let mut planners = Vec::new();
        for spec in &scenario.planners {
            let bar = bars.add(ProgressBar::new(u64::from(runs)));
            bar.set_style(style.clone());
            bar.set_prefix(format!("{} / {}", scenario.name, spec.label()));
            let metrics = run_planner(scenario, world, spec, runs, true, &|| bar.inc(1))
                .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
            bar.finish();
            let ok = metrics.iter().filter(|m| m.success).count();
            bars.suspend(|| {
                eprintln!(
                    "{} / {}: {ok}/{runs} solved in {:.1} s",
                    scenario.name,
                    spec.label(),
                    bar.elapsed().as_secs_f64()
                );
            });
            figure(scenario, world, spec, &metrics, &figures)?;
            planners.push(PlannerResult {
                label: spec.label().to_string(),
                name: spec.planner.name().to_string(),
                summary: Summary::of(&metrics),
                runs: metrics,
            });
        }
        let chart_runs: Vec<(String, Vec<RunMetrics>)> = planners
            .iter()
            .map(|p| (p.label.clone(), p.runs.clone()))
            .collect();
        harness::chart_metrics(
            &format!("{} ({} runs)", scenario.name, runs),
            &chart_runs,
            &["length", "time_s", "turns", "explored"],
            &figures.join(format!("{}_metrics.svg", scenario.name)),
        )
        .map_err(|e| anyhow::anyhow!(e))?;
        let claims = scenario
            .claims
            .iter()
            .filter(|c| c.across.is_empty())
            .map(|c| {
                let samples = c
                    .order
                    .iter()
                    .map(|label| {
                        let v = planners
                            .iter()
                            .find(|p| &p.label == label)
                            .map_or_else(Vec::new, |p| values(&p.runs, &c.metric));
                        (label.clone(), v)
                    })
                    .collect();
                decide_order(c.text.clone(), &c.metric, c.kind.clone(), samples)
            })
            .collect();
        // The yardstick for the papers' lengths, where they publish one (Theta* on a large
        // room takes seconds, so not for the time-only tables).
        let shortest = scenario
            .published
            .iter()
            .any(|p| p.metric == "length")
            .then(|| shortest_path(world))
            .flatten();
        results.push((
            scenario,
            ExperimentResult {
                name: scenario.name.clone(),
                seed_file: scenario.source.seed_file.clone(),
                experiment: scenario.source.experiment.clone(),
                file: file
                    .strip_prefix(&root)
                    .unwrap_or(file)
                    .display()
                    .to_string(),
                runs,
                planners,
                claims,
                shortest,
            },
        ));
    }
    let series = series_claims(&results);
    let seconds = started.elapsed().as_secs_f64();
    let mut report = crate::report::report(&results, &series, args.quick, seconds);
    // Seed 004 runs in the `sim` crate (scenarios/sim/), with claims of its own.
    report.push_str(&crate::sim004::section(&root, &figures)?.0);
    let report_path = out.join("report.md");
    std::fs::write(&report_path, &report)
        .with_context(|| format!("writing {}", report_path.display()))?;
    let json = serde_json::json!({
        "alpha": ALPHA,
        "experiments": results.iter().map(|(_, r)| r).collect::<Vec<_>>(),
        "series_claims": series,
    });
    let json_path = out.join("results.json");
    std::fs::write(&json_path, serde_json::to_string_pretty(&json)?)
        .with_context(|| format!("writing {}", json_path.display()))?;
    if args.update_docs {
        for page in
            crate::report::update_docs(&root.join("docs/papers"), &results, &series, args.quick)?
        {
            println!("updated {}", page.display());
        }
    }
    let tally = crate::report::Tally::of(&results, &series);
    println!(
        "done in {seconds:.1} s: {} experiment(s); measured claims: {} held, {} not held, {} not significant, {} without data (alpha {ALPHA}); {} by construction and {} not comparable, shown apart\nreport:  {}\nresults: {}\nfigures: {}",
        results.len(),
        tally.held,
        tally.not_held,
        tally.not_significant,
        tally.no_data,
        tally.by_construction,
        tally.not_comparable,
        report_path.display(),
        json_path.display(),
        figures.display()
    );
    Ok(())
}

/// The shortest path to the goal region on the planning map by Theta* (any-angle, on the
/// grid's cells), and the straight start-goal distance: the yardstick for lengths.
fn shortest_path(world: &World) -> Option<(f64, f64)> {
    let planner = search::ThetaStar::default();
    let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(0);
    let plan = planner.plan(&world.map, &world.query, &mut rng).ok()?;
    let straight = (world.query.goal.center() - world.query.start).norm();
    Some((plan.length(), straight))
}

/// A claim over a series of experiments, with the experiment it is written in.
#[derive(Serialize)]
pub(crate) struct SeriesClaim {
    pub seed_file: String,
    pub experiment: String,
    pub claim: ClaimResult,
}

/// Whether the scenario `name` belongs to the entry `entry` of a claim's `across`: the
/// same name, or the name followed by `-` and a layout suffix.
fn in_group(name: &str, entry: &str) -> bool {
    name == entry
        || name
            .strip_prefix(entry)
            .is_some_and(|rest| rest.starts_with('-'))
}

/// Evaluates the claims that span several experiments (`across`), pooling the runs of
/// every layout of a group; those whose experiments did not all run (`--only`) are left
/// out.
fn series_claims(results: &[(&Scenario, ExperimentResult)]) -> Vec<SeriesClaim> {
    let mut out = Vec::new();
    for (scenario, r) in results {
        for c in scenario.claims.iter().filter(|c| !c.across.is_empty()) {
            if c.order.len() > 1 {
                // Planners compared on one group of scenarios, runs pooled.
                let group = &c.across[0];
                if !results.iter().any(|(_, o)| in_group(&o.name, group)) {
                    continue;
                }
                let samples = c
                    .order
                    .iter()
                    .map(|label| {
                        let pooled: Vec<f64> = results
                            .iter()
                            .filter(|(_, o)| in_group(&o.name, group))
                            .filter_map(|(_, o)| o.planners.iter().find(|p| &p.label == label))
                            .flat_map(|p| values(&p.runs, &c.metric))
                            .collect();
                        (label.clone(), pooled)
                    })
                    .collect();
                out.push(SeriesClaim {
                    seed_file: r.seed_file.clone(),
                    experiment: r.experiment.clone(),
                    claim: decide_order(c.text.clone(), &c.metric, c.kind.clone(), samples),
                });
                continue;
            }
            let label = &c.order[0];
            let samples: Option<Vec<(String, Vec<f64>)>> = c
                .across
                .iter()
                .map(|entry| {
                    let pooled: Vec<f64> = results
                        .iter()
                        .filter(|(_, o)| in_group(&o.name, entry))
                        .filter_map(|(_, o)| o.planners.iter().find(|p| &p.label == label))
                        .flat_map(|p| values(&p.runs, &c.metric))
                        .collect();
                    let any = results.iter().any(|(_, o)| in_group(&o.name, entry));
                    any.then(|| (entry.clone(), pooled))
                })
                .collect();
            let Some(samples) = samples else { continue };
            out.push(SeriesClaim {
                seed_file: r.seed_file.clone(),
                experiment: r.experiment.clone(),
                claim: decide_order(
                    format!("{} ({label})", c.text),
                    &c.metric,
                    c.kind.clone(),
                    samples,
                ),
            });
        }
    }
    out
}

/// Draws run 0 of a planner: its trees and the path the harness scored for it.
fn figure(
    scenario: &Scenario,
    world: &World,
    spec: &PlannerSpec,
    runs: &[RunMetrics],
    dir: &Path,
) -> anyhow::Result<()> {
    let (trees, path) = runs
        .first()
        .map_or((&[][..], &[][..]), |r| (&r.trees[..], &r.path[..]));
    let file = dir.join(format!("{}_{}.png", scenario.name, slug(spec.label())));
    harness::draw_world(world, trees, path, &file).map_err(|e| anyhow::anyhow!(e))
}

pub(crate) fn slug(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect()
}
