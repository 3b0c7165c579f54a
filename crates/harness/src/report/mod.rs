//! The replay's verdicts and its report: each paper's ordering claims decided on our runs
//! by a rank test ([`decide_order`]), claims across experiments pooled
//! ([`series_claims`]), and the Markdown report and `docs/papers/` sections rendered from
//! them ([`markdown`]). `cargo xtask reproduce` keeps only the files and the progress
//! bars.

use serde::Serialize;

use crate::stats::{Decision, Verdict, decide_less};
use crate::{ClaimKind, RunMetrics, Scenario, Summary};

pub mod markdown;

/// The level at which every ordering claim is decided (two one-sided Mann-Whitney U
/// tests, see [`crate::stats::decide_less`]).
pub const ALPHA: f64 = 0.01;

/// The metrics shown in the tables, with their headings.
pub const COLUMNS: &[(&str, &str)] = &[
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

/// One planner's runs in one experiment.
#[derive(Debug, Serialize)]
pub struct PlannerResult {
    /// The planner's label in the scenario.
    pub label: String,
    /// The planner's registry name.
    pub name: String,
    /// Statistics of the runs.
    pub summary: Summary,
    /// Every run.
    pub runs: Vec<RunMetrics>,
}

/// One step of a claimed order: `smaller` < `larger`, decided on the runs.
#[derive(Debug, Serialize)]
pub struct Step {
    /// The label claimed smaller.
    pub smaller: String,
    /// The label claimed larger.
    pub larger: String,
    /// Their means.
    pub means: (f64, f64),
    /// The rank test's decision.
    pub decision: Decision,
}

/// A claimed order decided on the runs.
#[derive(Debug, Serialize)]
pub struct ClaimResult {
    /// The claim as the paper words it.
    pub text: String,
    /// The metric compared.
    pub metric: String,
    /// Measured, by construction or not comparable.
    pub kind: ClaimKind,
    /// Each label's mean.
    pub means: Vec<(String, f64)>,
    /// Each step of the order with its test.
    pub steps: Vec<Step>,
    /// The claim's verdict (held only when every step is).
    pub verdict: Verdict,
}

/// One scenario's runs and claims.
#[derive(Debug, Serialize)]
pub struct ExperimentResult {
    /// The scenario's name.
    pub name: String,
    /// The seed paper's file.
    pub seed_file: String,
    /// The paper's experiment (table, figure).
    pub experiment: String,
    /// The scenario file, relative to the workspace.
    pub file: String,
    /// Runs per planner.
    pub runs: u32,
    /// Each planner's runs.
    pub planners: Vec<PlannerResult>,
    /// The claims within this experiment.
    pub claims: Vec<ClaimResult>,
    /// The shortest path to the goal region on the planning map (Theta*), and the
    /// straight start-goal distance, scenario units.
    pub shortest: Option<(f64, f64)>,
}

/// The values of `metric` over runs: every run for times and explored nodes, the
/// successful ones for path measures (as [`Summary`] counts them).
pub fn values(runs: &[RunMetrics], metric: &str) -> Vec<f64> {
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
#[must_use]
pub fn decide_order(
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

/// Decides the claims of one experiment (those without `across`) on its planners' runs.
#[must_use]
pub fn experiment_claims(scenario: &Scenario, planners: &[PlannerResult]) -> Vec<ClaimResult> {
    scenario
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
        .collect()
}

/// A claim over a series of experiments, with the experiment it is written in.
#[derive(Debug, Serialize)]
pub struct SeriesClaim {
    /// The seed paper's file.
    pub seed_file: String,
    /// The experiment the claim is written in.
    pub experiment: String,
    /// The decided claim.
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
#[must_use]
pub fn series_claims(results: &[(&Scenario, ExperimentResult)]) -> Vec<SeriesClaim> {
    let mut out = Vec::new();
    // The runs of planner `label` over every layout of the group `entry`, pooled.
    let pooled = |entry: &str, label: &str, metric: &str| -> Vec<f64> {
        results
            .iter()
            .filter(|(_, o)| in_group(&o.name, entry))
            .filter_map(|(_, o)| o.planners.iter().find(|p| p.label == label))
            .flat_map(|p| values(&p.runs, metric))
            .collect()
    };
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
                    .map(|label| (label.clone(), pooled(group, label, &c.metric)))
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
                    let any = results.iter().any(|(_, o)| in_group(&o.name, entry));
                    any.then(|| (entry.clone(), pooled(entry, label, &c.metric)))
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

/// Counts of claims by outcome; only measured claims have a verdict that counts.
#[derive(Debug, Default)]
pub struct Tally {
    /// Measured and held.
    pub held: usize,
    /// Measured and not held.
    pub not_held: usize,
    /// Measured, not significant at [`ALPHA`].
    pub not_significant: usize,
    /// Measured without data (a planner that never solved).
    pub no_data: usize,
    /// By construction (shown, not counted).
    pub by_construction: usize,
    /// Not comparable (shown, not counted).
    pub not_comparable: usize,
}

impl Tally {
    fn add(&mut self, c: &ClaimResult) {
        match (&c.kind, c.verdict) {
            (ClaimKind::ByConstruction(_), _) => self.by_construction += 1,
            (ClaimKind::NotComparable(_), _) => self.not_comparable += 1,
            (ClaimKind::Measured, Verdict::Held) => self.held += 1,
            (ClaimKind::Measured, Verdict::NotHeld) => self.not_held += 1,
            (ClaimKind::Measured, Verdict::NotSignificant) => self.not_significant += 1,
            (ClaimKind::Measured, Verdict::NoData) => self.no_data += 1,
        }
    }

    /// The tally over every claim of a run.
    #[must_use]
    pub fn of(results: &[(&Scenario, ExperimentResult)], series: &[SeriesClaim]) -> Self {
        let mut t = Self::default();
        for c in claims(results, series, None) {
            t.add(c.2);
        }
        t
    }

    /// The measured claims.
    #[must_use]
    pub fn measured(&self) -> usize {
        self.held + self.not_held + self.not_significant + self.no_data
    }
}

/// Every claim with its seed file and experiment, optionally of one seed file only.
#[must_use]
pub fn claims<'a>(
    results: &'a [(&Scenario, ExperimentResult)],
    series: &'a [SeriesClaim],
    seed: Option<&str>,
) -> Vec<(&'a str, &'a str, &'a ClaimResult)> {
    let mut out: Vec<(&str, &str, &ClaimResult)> = Vec::new();
    for (_, r) in results {
        for c in &r.claims {
            out.push((&r.seed_file, &r.experiment, c));
        }
    }
    for s in series {
        out.push((&s.seed_file, &s.experiment, &s.claim));
    }
    out.retain(|(f, _, _)| seed.is_none_or(|s| f.starts_with(s)));
    out
}

/// A label as a file-name part: ASCII letters and digits lowered, the rest `-`.
#[must_use]
pub fn slug(s: &str) -> String {
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
