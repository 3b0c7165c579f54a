//! `cargo xtask reproduce`: every scenario of `scenarios/`, run with the papers' run
//! counts, reported beside the papers' numbers.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Context as _;
use harness::report::{
    ALPHA, ExperimentResult, PlannerResult, experiment_claims, markdown, series_claims, slug,
};
use harness::{PlannerSpec, RunMetrics, Scenario, Summary, World, run_planner};
use indicatif::{MultiProgress, ProgressBar, ProgressStyle};

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
        let claims = experiment_claims(scenario, &planners);
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
    let mut report = markdown::report(&results, &series, args.quick, seconds);
    // Seed 004 runs in the `sim` crate (scenarios/sim/), with claims of its own.
    report.push_str(&crate::sim004::section(&root, &figures)?.0);
    report.push_str(&crate::explore004::section(&root, &figures, args.quick)?.0);
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
    let tally = harness::report::Tally::of(&results, &series);
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
