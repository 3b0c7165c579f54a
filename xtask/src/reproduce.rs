//! `cargo xtask reproduce`: every scenario of `scenarios/`, run with the papers' run
//! counts, reported beside the papers' numbers.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Context as _;
use harness::{PlannerSpec, RunMetrics, Scenario, Summary, World, run_planner};
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
}

/// The metrics shown in the tables, with their headings.
const COLUMNS: &[(&str, &str)] = &[
    ("time_s", "time (ms)"),
    ("length", "length"),
    ("nodes", "nodes"),
    ("segments", "segments"),
    ("turns", "turns > 10°"),
    ("explored", "explored"),
    ("transfer_time_s", "transfer (s)"),
    ("min_clearance", "min clearance"),
];

#[derive(Serialize)]
struct PlannerResult {
    label: String,
    name: String,
    summary: Summary,
    runs: Vec<RunMetrics>,
}

#[derive(Serialize)]
struct ClaimResult {
    text: String,
    metric: String,
    means: Vec<(String, f64)>,
    held: bool,
}

#[derive(Serialize)]
struct ExperimentResult {
    name: String,
    seed_file: String,
    experiment: String,
    file: String,
    runs: u32,
    planners: Vec<PlannerResult>,
    claims: Vec<ClaimResult>,
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
    let mut out = Vec::new();
    for f in files {
        let (s, w) = Scenario::load(&f)?;
        out.push((f, s, w));
    }
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
                name: spec.name.clone(),
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
                let means: Vec<(String, f64)> = c
                    .order
                    .iter()
                    .map(|label| {
                        let mean = planners
                            .iter()
                            .find(|p| &p.label == label)
                            .and_then(|p| p.summary.get(&c.metric))
                            .map_or(f64::NAN, |s| s.mean);
                        (label.clone(), mean)
                    })
                    .collect();
                let held = means.windows(2).all(|w| w[0].1 < w[1].1);
                ClaimResult {
                    text: c.text.clone(),
                    metric: c.metric.clone(),
                    means,
                    held,
                }
            })
            .collect();
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
            },
        ));
    }
    let series = series_claims(&results);
    let mut report = report(
        &results,
        &series,
        args.quick,
        started.elapsed().as_secs_f64(),
    );
    // Seed 004 runs in the `sim` crate (scenarios/sim/), with claims of its own.
    report.push_str(&crate::sim004::section(&root, &figures)?.0);
    let report_path = out.join("report.md");
    std::fs::write(&report_path, report)
        .with_context(|| format!("writing {}", report_path.display()))?;
    let json = serde_json::json!({
        "experiments": results.iter().map(|(_, r)| r).collect::<Vec<_>>(),
        "series_claims": series,
    });
    let json_path = out.join("results.json");
    std::fs::write(&json_path, serde_json::to_string_pretty(&json)?)
        .with_context(|| format!("writing {}", json_path.display()))?;
    let (held, total) = results
        .iter()
        .flat_map(|(_, r)| &r.claims)
        .chain(series.iter().map(|s| &s.claim))
        .fold((0, 0), |(h, t), c| (h + usize::from(c.held), t + 1));
    println!(
        "done in {:.1} s: {} experiment(s), claims held {held}/{total}\nreport:  {}\nresults: {}\nfigures: {}",
        started.elapsed().as_secs_f64(),
        results.len(),
        report_path.display(),
        json_path.display(),
        figures.display()
    );
    Ok(())
}

/// A claim over a series of experiments, with the experiment it is written in.
#[derive(Serialize)]
struct SeriesClaim {
    seed_file: String,
    experiment: String,
    claim: ClaimResult,
}

/// Evaluates the claims that span several experiments (`across`); those whose experiments
/// did not all run (`--only`) are left out.
fn series_claims(results: &[(&Scenario, ExperimentResult)]) -> Vec<SeriesClaim> {
    let mut out = Vec::new();
    for (scenario, r) in results {
        for c in scenario.claims.iter().filter(|c| !c.across.is_empty()) {
            let label = &c.order[0];
            let means: Option<Vec<(String, f64)>> = c
                .across
                .iter()
                .map(|name| {
                    let (_, other) = results.iter().find(|(_, o)| &o.name == name)?;
                    let p = other.planners.iter().find(|p| &p.label == label)?;
                    Some((
                        name.clone(),
                        p.summary.get(&c.metric).map_or(f64::NAN, |s| s.mean),
                    ))
                })
                .collect();
            let Some(means) = means else { continue };
            let held = means.windows(2).all(|w| w[0].1 < w[1].1);
            out.push(SeriesClaim {
                seed_file: r.seed_file.clone(),
                experiment: r.experiment.clone(),
                claim: ClaimResult {
                    text: format!("{} ({label})", c.text),
                    metric: c.metric.clone(),
                    means,
                    held,
                },
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

fn slug(s: &str) -> String {
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

/// Writes one claim as a report bullet and files it under held or not held for the summary.
fn claim_line(
    s: &mut String,
    c: &ClaimResult,
    place: &str,
    held: &mut Vec<String>,
    not_held: &mut Vec<String>,
    seed_file: &str,
    experiment: &str,
) {
    let figures: Vec<String> = c
        .means
        .iter()
        .map(|(l, m)| format!("{l} {}", fmt_num(*m)))
        .collect();
    let mark = if c.held { "held" } else { "NOT held" };
    let _ = writeln!(
        s,
        "- **{mark}**{place}: {} (mean {}, claimed increasing: {})",
        c.text,
        c.metric,
        figures.join(", ")
    );
    let line = format!("{seed_file} {experiment}: {}", c.text);
    if c.held {
        held.push(line)
    } else {
        not_held.push(line)
    }
}

fn fmt_num(x: f64) -> String {
    if !x.is_finite() {
        "-".into()
    } else if x.abs() >= 100.0 {
        format!("{x:.1}")
    } else if x.abs() >= 1.0 {
        format!("{x:.2}")
    } else {
        format!("{x:.4}")
    }
}

fn report(
    results: &[(&Scenario, ExperimentResult)],
    series: &[SeriesClaim],
    quick: bool,
    seconds: f64,
) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# hyplan: the seed papers' experiments, replayed\n");
    let _ = writeln!(
        s,
        "Produced by `cargo xtask reproduce{}` in {seconds:.1} s. Every number under \"ours\" was \
         computed by this run; the only numbers typed in are the papers' own (from the scenario \
         files' `published` entries). Means are over successful runs; time and explored nodes \
         over all runs. Maps the papers show only in lost figures are reconstructions: see each \
         scenario file and `docs/papers/`.\n",
        if quick { " --quick" } else { "" }
    );
    let (mut held, mut not_held) = (Vec::new(), Vec::new());
    for (scenario, r) in results {
        let _ = writeln!(s, "## `{}` {}: {}\n", r.seed_file, r.experiment, r.name);
        if !scenario.description.is_empty() {
            let _ = writeln!(s, "{}\n", scenario.description);
        }
        let _ = writeln!(
            s,
            "Scenario `{}`, units: {}, {} runs per planner, base seed {}.",
            r.file, scenario.units, r.runs, scenario.base_seed
        );
        if !scenario.from_paper.is_empty() {
            let _ = writeln!(s, "From the paper: {}.", scenario.from_paper.join(", "));
        }
        if !scenario.reconstructed.is_empty() {
            let _ = writeln!(
                s,
                "Our reconstruction: {}.",
                scenario.reconstructed.join(", ")
            );
        }
        let _ = writeln!(
            s,
            "\n| planner | success | {} |",
            COLUMNS.iter().map(|c| c.1).collect::<Vec<_>>().join(" | ")
        );
        let _ = writeln!(s, "|---|---:|{}", "---:|".repeat(COLUMNS.len()));
        for p in &r.planners {
            let cells: Vec<String> = COLUMNS
                .iter()
                .map(|(m, _)| {
                    p.summary.get(m).map_or("-".into(), |st| {
                        // Times are shown in ms: ours are far below a second.
                        let k = if *m == "time_s" { 1e3 } else { 1.0 };
                        if st.count == 0 {
                            "-".into()
                        } else {
                            format!("{} ± {}", fmt_num(k * st.mean), fmt_num(k * st.std))
                        }
                    })
                })
                .collect();
            let _ = writeln!(
                s,
                "| {} | {:.0}% | {} |",
                p.label,
                100.0 * p.summary.success_rate,
                cells.join(" | ")
            );
        }
        if !scenario.published.is_empty() {
            let _ = writeln!(s, "\nThe paper's numbers beside ours (mean):\n");
            let _ = writeln!(s, "| planner | metric | paper | ours | ours / paper |");
            let _ = writeln!(s, "|---|---|---:|---:|---:|");
            for p in &scenario.published {
                let ours = r
                    .planners
                    .iter()
                    .find(|q| q.label == p.planner)
                    .and_then(|q| q.summary.get(&p.metric))
                    .map(|st| st.mean);
                let (ours_s, ratio) = match ours {
                    Some(o) if o.is_finite() => {
                        (fmt_num(o), format!("{:.3}", o / (p.value * p.unit_scale)))
                    }
                    Some(_) => ("-".into(), "-".into()),
                    None => ("paper only (not run)".into(), "-".into()),
                };
                let mut note = if p.note.is_empty() {
                    String::new()
                } else {
                    format!(" ({})", p.note)
                };
                if p.unit_scale != 1.0 {
                    let _ = write!(note, " [x{} to our units]", p.unit_scale);
                }
                let _ = writeln!(
                    s,
                    "| {} | {}{} | {} | {} | {} |",
                    p.planner,
                    p.metric,
                    note,
                    fmt_num(p.value),
                    ours_s,
                    ratio
                );
            }
        }
        if !r.claims.is_empty() {
            let _ = writeln!(s, "\nClaims:\n");
            for c in &r.claims {
                claim_line(
                    &mut s,
                    c,
                    "",
                    &mut held,
                    &mut not_held,
                    &r.seed_file,
                    &r.experiment,
                );
            }
        }
        let _ = writeln!(s);
        for p in &r.planners {
            let _ = writeln!(
                s,
                "![{} {}](figures/{}_{}.png)",
                r.name,
                p.label,
                r.name,
                slug(&p.label)
            );
        }
        let _ = writeln!(s, "\n![metrics](figures/{}_metrics.svg)\n", r.name);
    }
    if !series.is_empty() {
        let _ = writeln!(s, "## Claims across experiments\n");
        for sc in series {
            let place = format!(" (`{}` {})", sc.seed_file, sc.experiment);
            claim_line(
                &mut s,
                &sc.claim,
                &place,
                &mut held,
                &mut not_held,
                &sc.seed_file,
                &sc.experiment,
            );
        }
        let _ = writeln!(s);
    }
    let _ = writeln!(s, "## Summary\n");
    let _ = writeln!(
        s,
        "Claims held: {} of {}.\n",
        held.len(),
        held.len() + not_held.len()
    );
    for l in &held {
        let _ = writeln!(s, "- held: {l}");
    }
    for l in &not_held {
        let _ = writeln!(s, "- not held: {l}");
    }
    s
}
