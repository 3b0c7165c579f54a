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

/// The name of seed 004's navigation replay (scenarios/sim/, three runs), as its report
/// section and `--only` name it.
const SIM004_NAVIGATION: &str = "004-navigation";
/// The name of seed 004's exploration replay (scenarios/sim/explore-22m.ron).
const SIM004_EXPLORATION: &str = "004-exploration";

/// Options of `cargo xtask reproduce`.
#[derive(clap::Args)]
pub struct Args {
    /// Few runs per experiment (each scenario's `quick_runs`), for CI: about a minute.
    #[arg(long)]
    pub quick: bool,
    /// Only the experiments whose name contains this text.
    #[arg(long)]
    pub only: Option<String>,
    /// Runs per planner, overriding the scenario files (1 to 1000000).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=i64::from(harness::MAX_RUNS)))]
    pub runs: Option<u32>,
    /// Output folder (default `target/reproduce`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Seed 004's eta sweep over all seven etas (2, 4, 6, 8, 10, 12, 15 m) instead of five
    /// (2, 6, 8, 10, 15): about 40 % longer.
    #[arg(long)]
    pub all_etas: bool,
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

/// The files of `dir` with the extension `ext`, sorted by path.
pub fn files_ending_in(dir: &Path, ext: &str) -> anyhow::Result<Vec<PathBuf>> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .with_context(|| format!("reading {}", dir.display()))?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == ext))
        .collect();
    files.sort();
    Ok(files)
}

/// Loads every scenario (all of them, so a bad file stops the run before any work).
fn load_all(dir: &Path) -> anyhow::Result<Vec<(PathBuf, Scenario, World)>> {
    let files = files_ending_in(dir, "ron")?;
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
    // Seed 004's two experiments run in `sim`, beside the scenario files: `--only` picks
    // among all of them by the names the report's sections give.
    let picked = |name: &str| args.only.as_deref().is_none_or(|o| name.contains(o));
    let (navigation, exploration) = (picked(SIM004_NAVIGATION), picked(SIM004_EXPLORATION));
    if let Some(only) = &args.only {
        let mut names: Vec<String> = scenarios.iter().map(|(_, s, _)| s.name.clone()).collect();
        names.extend([SIM004_NAVIGATION.into(), SIM004_EXPLORATION.into()]);
        scenarios.retain(|(_, s, _)| picked(&s.name));
        anyhow::ensure!(
            !scenarios.is_empty() || navigation || exploration,
            "--only {only:?}: no experiment name contains it (experiments: {})",
            names.join(", ")
        );
    }
    eprintln!(
        "reproducing {} experiment(s){} into {}",
        scenarios.len() + usize::from(navigation) + usize::from(exploration),
        if args.quick { " (quick)" } else { "" },
        out.display()
    );
    let started = Instant::now();
    let bars = MultiProgress::new();
    let mut results = Vec::new();
    for (file, scenario, world) in &scenarios {
        let result = run_experiment(args, &root, (file, scenario, world), &figures, &bars)?;
        results.push((scenario, result));
    }
    let series = series_claims(&results);
    let seconds = started.elapsed().as_secs_f64();
    let mut report = markdown::report(&results, &series, args.quick, seconds);
    // Seed 004 runs in the `sim` crate (scenarios/sim/), with claims of its own.
    // Seed 004's claims are judged inside its sections: (held, total) of each.
    let mut sim_claims = (0, 0);
    if navigation {
        let (text, held, total) = crate::sim004::section(&root, &figures)?;
        report.push_str(&text);
        sim_claims = (sim_claims.0 + held, sim_claims.1 + total);
    }
    if exploration {
        let (text, held, total) =
            crate::explore004::section(&root, &figures, args.quick, args.all_etas)?;
        report.push_str(&text);
        sim_claims = (sim_claims.0 + held, sim_claims.1 + total);
    }
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
        "done in {:.1} s: {} experiment(s); measured claims: {} held, {} not held, {} not significant, {} without data (alpha {ALPHA}); {} by construction and {} not comparable, shown apart; seed 004 (sim): {} of {} claims held\nreport:  {}\nresults: {}\nfigures: {}",
        started.elapsed().as_secs_f64(),
        results.len() + usize::from(navigation) + usize::from(exploration),
        tally.held,
        tally.not_held,
        tally.not_significant,
        tally.no_data,
        tally.by_construction,
        tally.not_comparable,
        sim_claims.0,
        sim_claims.1,
        report_path.display(),
        json_path.display(),
        figures.display()
    );
    Ok(())
}

/// One scenario file's experiment: every planner's runs (with a progress bar each), the
/// figures, the claims and the length yardstick.
fn run_experiment(
    args: &Args,
    root: &Path,
    (file, scenario, world): (&PathBuf, &Scenario, &World),
    figures: &Path,
    bars: &MultiProgress,
) -> anyhow::Result<ExperimentResult> {
    let style = ProgressStyle::with_template("{prefix:>40} {bar:30} {pos:>5}/{len:5} {elapsed:>4}")
        .unwrap_or_else(|_| ProgressStyle::default_bar());
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
        figure(scenario, world, spec, &metrics, figures)?;
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
    Ok(ExperimentResult {
        name: scenario.name.clone(),
        seed_file: scenario.source.seed_file.clone(),
        experiment: scenario.source.experiment.clone(),
        file: file
            .strip_prefix(root)
            .unwrap_or(file)
            .display()
            .to_string(),
        runs,
        planners,
        claims,
        shortest,
    })
}

/// The shortest path to the goal region on the planning map by Theta* (any-angle, on the
/// grid's cells), and the straight start-goal distance: the yardstick for lengths.
fn shortest_path(world: &World) -> Option<(f64, f64)> {
    // The original (eager) Theta*, as the yardstick was first computed.
    let planner = search::ThetaStar {
        lazy: false,
        ..search::ThetaStar::default()
    };
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
