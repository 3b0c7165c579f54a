//! Benchmarks of planners on a user's own problems: one record per run, the summary
//! (success rate, median and inter-quartile range), the pairwise rank tests, and the
//! runs as an OMPL benchmark log ([`ompl_log`]) that OMPL's `ompl_benchmark_statistics`
//! loads into the same database as OMPL's own runs.
//!
//! A problem is a map and a query; an experiment is one problem and the planners run on
//! it, as in OMPL. [`run_once`] plans and scores one run; [`summarise`] and [`compare`]
//! reduce the runs; [`experiment_log`] writes them in OMPL's format. [`shard`] cuts an
//! experiment's runs into shards that run apart and checks that their records cover it
//! exactly once before they merge.

pub mod ompl_log;
pub mod shard;

use std::collections::BTreeMap;
use std::time::Instant;

use hyplan_core::{Plan, PlanError, Planner, Query};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Deserializer, Serialize};

use crate::stats::{Alternative, Verdict, decide_less, mann_whitney_u};
pub use crate::stats::{Spread, quantile};
use crate::{RunMetrics, Scoring, measure};
use ompl_log::{Experiment, PlannerBlock, Property, PropertyType, Status, Value};

/// One run of one planner on one problem, as the CSV, the JSON and the OMPL log hold it.
///
/// Serialised as RON it reads back bit for bit (NaN and infinities included; JSON
/// writes those as `null`): the records of a shard ([`shard`]).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct BenchRun {
    /// Index of the problem (map and query) in the experiment list.
    pub problem: usize,
    /// The planner's label (its spec as given, e.g. `rrt-star:step=20`).
    pub planner: String,
    /// Run index, seed, success, times, final length, nodes, turns, explored nodes,
    /// transfer time and minimum clearance, as the harness scores every run (the path
    /// itself is not kept).
    #[serde(flatten)]
    pub metrics: RunMetrics,
    /// Whether the planner returned a path reaching the goal region (before
    /// post-processing; `metrics.success` also needs the post-processed curve free).
    pub exact: bool,
    /// How the planning call ended: `exact solution`, `timeout` (budget spent), `no path`
    /// (proved) or `invalid input` (a parameter or the query refused by the planner).
    #[serde(deserialize_with = "status_from_str")]
    pub status: String,
    /// The planner's message when it refused its input.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// Wall time of the planning call alone, s (OMPL's `time`, the `solve` call).
    pub planning_time_s: f64,
    /// Length of the planner's own path before post-processing (OMPL's `solution length`);
    /// NaN without a path.
    pub raw_length: f64,
    /// Main-loop iterations of the planner.
    pub iterations: u64,
    /// Collision checks (`is_free` and `segment_free` calls) of the planner.
    pub collision_checks: u64,
    /// An anytime planner's progress (RRT* run through [`PlanCall::RrtStar`]): samples
    /// every 64 iterations and one at the end; empty for the others.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub progress: Vec<ProgressPoint>,
    /// Largest discrete curvature of the final path, 1 / world unit (turning angle over
    /// the mean of the two adjacent segment lengths): at the nodes of a polyline left
    /// unsmoothed, at the samples (a quarter cell apart) of a smoothed curve; NaN without
    /// a path.
    pub max_curvature: f64,
}

/// The run statuses [`score_run`] gives.
pub const STATUSES: [&str; 4] = ["exact solution", "timeout", "no path", "invalid input"];

fn status_from_str<'de, D: Deserializer<'de>>(d: D) -> Result<String, D::Error> {
    let s = String::deserialize(d)?;
    if STATUSES.contains(&s.as_str()) {
        Ok(s)
    } else {
        Err(serde::de::Error::custom(format!(
            "unknown run status {s:?}"
        )))
    }
}

impl BenchRun {
    /// The OMPL `status` enum value of the run.
    #[must_use]
    pub fn ompl_status(&self) -> Status {
        match self.status.as_str() {
            "exact solution" => Status::ExactSolution,
            "timeout" => Status::Timeout,
            _ => Status::Unknown,
        }
    }
}

/// One sample of an anytime planner's progress: OMPL's progress properties `time`,
/// `iterations` and `best cost`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ProgressPoint {
    /// Time since the planning call started, s.
    pub time_s: f64,
    /// Iterations done.
    pub iterations: u64,
    /// Cost of the best path so far (NaN before the first).
    pub best_cost: f64,
}

/// How a run calls its planner.
#[derive(Clone, Copy)]
pub enum PlanCall<'a> {
    /// Any planner, through the trait.
    Planner(&'a dyn Planner),
    /// RRT* through `plan_with`, its best cost recorded as it improves (every 64
    /// iterations: RRT*'s observer period) for OMPL's progress properties.
    RrtStar(&'a sampling::RrtStar),
}

/// Plans one run with the RNG `ChaCha8Rng::seed_from_u64(seed)` and scores it.
///
/// Bad queries and parameters are the caller's to catch before the runs: here such an
/// error is a failed run with status `invalid input` and the planner's message.
#[must_use]
pub fn run_once(
    call: PlanCall<'_>,
    scoring: &Scoring<'_>,
    query: &Query,
    problem: usize,
    label: &str,
    run: u32,
    seed: u64,
) -> BenchRun {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut progress = Vec::new();
    let cpu = cpu_time::ThreadTime::try_now().ok();
    let started = Instant::now();
    let outcome: Result<Plan, PlanError> = match call {
        PlanCall::Planner(planner) => planner.plan(scoring.ws, query, &mut rng),
        PlanCall::RrtStar(planner) => {
            let mut observe = |p: &hyplan_core::Progress| {
                progress.push(ProgressPoint {
                    time_s: started.elapsed().as_secs_f64(),
                    iterations: p.iterations,
                    best_cost: p.best_cost.unwrap_or(f64::NAN),
                });
                std::ops::ControlFlow::Continue(())
            };
            planner.plan_with(scoring.ws, query, &mut rng, &mut observe)
        }
    };
    let wall = started.elapsed().as_secs_f64();
    let cpu_s = cpu.map_or(f64::NAN, |t| t.elapsed().as_secs_f64());
    if matches!(call, PlanCall::RrtStar(_)) {
        let stats = match &outcome {
            Ok(plan) => Some(plan.stats),
            Err(e) => e.stats().copied(),
        };
        progress.push(ProgressPoint {
            time_s: wall,
            iterations: stats.map_or(0, |s| s.iterations),
            best_cost: outcome.as_ref().map_or(f64::NAN, |p| p.cost),
        });
    }
    let id = RunId {
        problem,
        label,
        run,
        seed,
    };
    let mut record = score_run(&outcome, wall, cpu_s, scoring, &id);
    record.progress = progress;
    record
}

/// Which run a record is: problem index, planner label, run index and seed.
#[derive(Debug, Clone, Copy)]
pub struct RunId<'a> {
    /// Problem index.
    pub problem: usize,
    /// Planner label.
    pub label: &'a str,
    /// Run index.
    pub run: u32,
    /// The run's seed.
    pub seed: u64,
}

/// Scores a planning outcome its caller timed itself (`wall_s` and `cpu_s` for the
/// planning call): what [`run_once`] does after planning, for callers that plan in their
/// own way (`cargo xtask bench-peers`).
#[must_use]
pub fn score_run(
    outcome: &Result<Plan, PlanError>,
    wall_s: f64,
    cpu_s: f64,
    scoring: &Scoring<'_>,
    id: &RunId<'_>,
) -> BenchRun {
    let RunId {
        problem,
        label,
        run,
        seed,
    } = *id;
    let wall = wall_s;
    let mut metrics = measure(scoring, outcome, run, seed);
    metrics.cpu_time_s = cpu_s;
    let stats = match outcome {
        Ok(plan) => Some(plan.stats),
        Err(e) => e.stats().copied(),
    };
    let status = match outcome {
        Ok(_) => "exact solution",
        Err(PlanError::BudgetExhausted { .. }) => "timeout",
        Err(e) if e.is_no_path() => "no path",
        Err(_) => "invalid input",
    };
    let error = match outcome {
        Err(e) if !e.is_no_path() => Some(e.to_string()),
        _ => None,
    };
    // A polyline left as it is: the curvature at its nodes (the dense samples would put
    // each corner's whole angle on a quarter cell); a smoothed curve: at its samples.
    let curve: &[hyplan_core::Point2] = match (outcome, scoring.smoothing) {
        (Ok(plan), postproc::Smoothing::None) if metrics.success => plan.nodes(),
        _ => &metrics.path,
    };
    let max_curvature = if curve.len() >= 2 {
        postproc::discrete_curvature(curve)
            .into_iter()
            .map(f64::abs)
            .fold(0.0, f64::max)
    } else {
        f64::NAN
    };
    // The final path served the measures above; 400 runs of dense samples would only
    // cost memory.
    metrics.path = Vec::new();
    // The planning time is the whole call (what a user waits for), not the planner's own
    // `stats.elapsed`, which leaves out building the returned plan; `measure` added the
    // post-processing to the latter.
    metrics.time_s = match stats {
        Some(s) if metrics.time_s.is_finite() => metrics.time_s - s.elapsed.as_secs_f64() + wall,
        _ => wall,
    };
    BenchRun {
        problem,
        planner: label.to_string(),
        exact: outcome.is_ok(),
        status: status.into(),
        error,
        planning_time_s: wall,
        raw_length: outcome.as_ref().map_or(f64::NAN, Plan::length),
        iterations: stats.map_or(0, |s| s.iterations),
        collision_checks: stats.map_or(0, |s| s.collision_checks),
        max_curvature,
        progress: Vec::new(),
        metrics,
    }
}

/// One line of the summary table: a planner on a problem.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SummaryRow {
    /// Problem index.
    pub problem: usize,
    /// Planner label.
    pub planner: String,
    /// Runs.
    pub runs: usize,
    /// Fraction of runs with a checked path.
    pub success_rate: f64,
    /// Time of the planning call (OMPL's `time`, wall clock) of every run, s.
    pub planning_time_s: Spread,
    /// Time with the post-processing and the scoring's check of the final path (OMPL
    /// log's `total time`) of every run, s.
    pub time_s: Spread,
    /// Final path length of the successful runs.
    pub length: Spread,
}

/// The summary rows, in the order the (problem, planner) pairs first appear in `runs`.
#[must_use]
pub fn summarise(runs: &[BenchRun]) -> Vec<SummaryRow> {
    groups(runs)
        .into_iter()
        .map(|((problem, planner), rs)| SummaryRow {
            problem,
            runs: rs.len(),
            success_rate: rs.iter().filter(|r| r.metrics.success).count() as f64
                / rs.len().max(1) as f64,
            planning_time_s: Spread::of(rs.iter().map(|r| r.planning_time_s)),
            time_s: Spread::of(rs.iter().map(|r| r.metrics.time_s)),
            length: Spread::of(
                rs.iter()
                    .filter(|r| r.metrics.success)
                    .map(|r| r.metrics.length),
            ),
            planner,
        })
        .collect()
}

/// The runs grouped by (problem, planner label), groups in order of first appearance.
#[must_use]
pub fn groups(runs: &[BenchRun]) -> Vec<((usize, String), Vec<&BenchRun>)> {
    let mut out: Vec<((usize, String), Vec<&BenchRun>)> = Vec::new();
    for r in runs {
        match out
            .iter_mut()
            .find(|((p, l), _)| *p == r.problem && *l == r.planner)
        {
            Some((_, v)) => v.push(r),
            None => out.push(((r.problem, r.planner.clone()), vec![r])),
        }
    }
    out
}

/// A two-sided Mann-Whitney U test of one metric between two planners, with the
/// direction decided by [`decide_less`] (the test `cargo xtask reproduce` decides the
/// papers' ordering claims with).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MetricTest {
    /// Two-sided p-value; NaN when a side has no value.
    pub p_value: f64,
    /// Cliff's delta of the first planner against the second (negative: the first tends
    /// to be smaller).
    pub cliffs_delta: f64,
    /// [`Verdict::Held`]: the first is significantly smaller; [`Verdict::NotHeld`]: the
    /// second is; otherwise not significant or no data. Two-sided at the comparison's
    /// level (each one-sided test at half of it), so a verdict goes with `p_value` below
    /// the level.
    pub verdict: Verdict,
}

/// The comparison of two planners on one problem.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Comparison {
    /// Problem index.
    pub problem: usize,
    /// First planner.
    pub a: String,
    /// Second planner.
    pub b: String,
    /// Time of the planning call of every run (`planning_time_s`, OMPL's `time`): what
    /// the planners differ in, without the post-processing and the scoring's check of
    /// the final path, which on fast planners would outweigh it.
    pub time: MetricTest,
    /// Final length of the successful runs.
    pub length: MetricTest,
}

fn metric_test(x: &[f64], y: &[f64], alpha: f64) -> MetricTest {
    // Neither order is claimed beforehand, so both one-sided tests share the level: each
    // at alpha / 2 is the two-sided test at alpha whose p the report prints.
    let d = decide_less(x, y, alpha / 2.0);
    let two = mann_whitney_u(x, y, Alternative::TwoSided);
    MetricTest {
        p_value: two.map_or(f64::NAN, |t| t.p_value),
        cliffs_delta: d.cliffs_delta,
        verdict: d.verdict,
    }
}

/// Every pair of planners on each problem, time and length compared at level `alpha`.
#[must_use]
pub fn compare(runs: &[BenchRun], alpha: f64) -> Vec<Comparison> {
    let g = groups(runs);
    let mut out = Vec::new();
    for (i, ((pa, la), ra)) in g.iter().enumerate() {
        for ((pb, lb), rb) in &g[i + 1..] {
            if pa != pb {
                continue;
            }
            let time = |rs: &[&BenchRun]| rs.iter().map(|r| r.planning_time_s).collect::<Vec<_>>();
            // Failed runs have NaN lengths, which the test leaves out.
            let length = |rs: &[&BenchRun]| rs.iter().map(|r| r.metrics.length).collect::<Vec<_>>();
            out.push(Comparison {
                problem: *pa,
                a: la.clone(),
                b: lb.clone(),
                time: metric_test(&time(ra), &time(rb), alpha),
                length: metric_test(&length(ra), &length(rb), alpha),
            });
        }
    }
    out
}

/// How a run property's value is read off a run.
pub type ReadValue = fn(&BenchRun) -> Value;

/// The run properties of the OMPL log, sorted by name as OMPL sorts them, and how each
/// is read off a run. OMPL's own names where OMPL has the measure (`time`, `solved`,
/// `solution length`, `graph states`, `status`, ...), so our runs and OMPL's share columns.
#[must_use]
pub fn ompl_properties() -> Vec<(Property, ReadValue)> {
    use PropertyType::{Boolean, Enum, Integer, Real};
    let mut props: Vec<(Property, ReadValue)> = vec![
        (Property::new("approximate solution", Boolean), |_| {
            Value::Bool(false)
        }),
        (Property::new("collision checks", Integer), |r| {
            Value::Int(i64::try_from(r.collision_checks).unwrap_or(i64::MAX))
        }),
        (Property::new("correct solution", Boolean), |r| {
            if r.exact {
                Value::Bool(r.metrics.success)
            } else {
                Value::None
            }
        }),
        (Property::new("cpu time", Real), |r| {
            Value::Real(r.metrics.cpu_time_s)
        }),
        (Property::new("graph states", Integer), |r| {
            int_or_none(r.metrics.explored)
        }),
        (Property::new("iterations", Integer), |r| {
            Value::Int(i64::try_from(r.iterations).unwrap_or(i64::MAX))
        }),
        (Property::new("max curvature", Real), |r| {
            Value::Real(r.max_curvature)
        }),
        (Property::new("minimum clearance", Real), |r| {
            Value::Real(r.metrics.min_clearance)
        }),
        (Property::new("path length", Real), |r| {
            Value::Real(r.metrics.length)
        }),
        (Property::new("path nodes", Integer), |r| {
            int_or_none(r.metrics.nodes)
        }),
        (Property::new("run index", Integer), |r| {
            Value::Int(i64::from(r.metrics.run))
        }),
        (Property::new("solution length", Real), |r| {
            Value::Real(r.raw_length)
        }),
        (Property::new("solved", Boolean), |r| {
            Value::Bool(r.metrics.success)
        }),
        (Property::new("status", Enum), |r| {
            Value::Int(r.ompl_status() as i64)
        }),
        (Property::new("time", Real), |r| {
            Value::Real(r.planning_time_s)
        }),
        (Property::new("total time", Real), |r| {
            Value::Real(r.metrics.time_s)
        }),
        (Property::new("transfer time", Real), |r| {
            Value::Real(r.metrics.transfer_time_s)
        }),
        (Property::new("turns", Integer), |r| {
            int_or_none(r.metrics.turns)
        }),
    ];
    props.sort_by(|a, b| a.0.name.cmp(&b.0.name));
    props
}

fn int_or_none(v: f64) -> Value {
    if v.is_finite() {
        Value::Int(v as i64)
    } else {
        Value::None
    }
}

/// What the OMPL log says about the experiment besides the runs.
#[derive(Debug, Clone, Default)]
pub struct ExperimentInfo {
    /// One-word name.
    pub name: String,
    /// Host name.
    pub host: String,
    /// Start, `YYYY-MM-DD HH:MM:SS`.
    pub start: String,
    /// Setup text: the map, the query, the options.
    pub setup: String,
    /// Base seed.
    pub seed: u64,
    /// Time limit per run, s (0: none).
    pub max_time: f64,
    /// Runs per planner.
    pub run_count: u64,
    /// Wall time of the whole experiment, s.
    pub total_duration: f64,
}

/// One problem's runs as an OMPL experiment: one planner block per label (in order of
/// first appearance), with its settings (`common`) from `settings`.
#[must_use]
pub fn experiment_log(
    info: &ExperimentInfo,
    runs: &[&BenchRun],
    settings: &BTreeMap<String, BTreeMap<String, String>>,
) -> Experiment {
    let props = ompl_properties();
    let mut planners: Vec<PlannerBlock> = Vec::new();
    for r in runs {
        let block = match planners.iter_mut().position(|p| p.name == r.planner) {
            Some(i) => &mut planners[i],
            None => {
                planners.push(PlannerBlock {
                    name: r.planner.clone(),
                    common: settings.get(&r.planner).cloned().unwrap_or_default(),
                    properties: props.iter().map(|(p, _)| p.clone()).collect(),
                    runs: Vec::new(),
                    progress: None,
                });
                planners.last_mut().expect("just pushed")
            }
        };
        block.runs.push(props.iter().map(|(_, f)| f(r)).collect());
    }
    // OMPL's progress properties for the planners that report progress, sorted by name.
    for block in &mut planners {
        let mine: Vec<&&BenchRun> = runs.iter().filter(|r| r.planner == block.name).collect();
        if mine.iter().all(|r| r.progress.is_empty()) {
            continue;
        }
        block.progress = Some(ompl_log::ProgressBlock {
            properties: vec![
                Property::new("best cost", PropertyType::Real),
                Property::new("iterations", PropertyType::Integer),
                Property::new("time", PropertyType::Real),
            ],
            runs: mine
                .iter()
                .map(|r| {
                    r.progress
                        .iter()
                        .map(|p| {
                            vec![
                                Value::Real(p.best_cost),
                                Value::Int(i64::try_from(p.iterations).unwrap_or(i64::MAX)),
                                Value::Real(p.time_s),
                            ]
                        })
                        .collect()
                })
                .collect(),
        });
    }
    Experiment {
        version: format!("hyplan {}", env!("CARGO_PKG_VERSION")),
        name: info.name.clone(),
        properties: Vec::new(),
        host: info.host.clone(),
        start: info.start.clone(),
        setup: info.setup.clone(),
        cpu_info: String::new(),
        seed: info.seed,
        max_time: info.max_time,
        max_mem: 0.0,
        run_count: info.run_count,
        total_duration: info.total_duration,
        planners,
    }
}

/// Now in UTC as OMPL writes its start time, `YYYY-MM-DD HH:MM:SS`.
#[must_use]
pub fn utc_timestamp() -> String {
    utc_date_time(
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_secs()),
    )
}

/// `YYYY-MM-DD HH:MM:SS` (UTC) of a Unix time in seconds.
#[must_use]
pub fn utc_date_time(secs: u64) -> String {
    let (days, rem) = (secs / 86_400, secs % 86_400);
    // Howard Hinnant's days-to-civil algorithm.
    let z = days as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02} {:02}:{:02}:{:02}",
        rem / 3600,
        rem % 3600 / 60,
        rem % 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_verdict_goes_with_a_two_sided_p_below_alpha() {
        // Pairs of small samples whose two-sided p falls on both sides of alpha (and
        // between alpha and 2 alpha, where one-sided tests at alpha would still decide).
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut between = 0;
        for case in 0..2_000 {
            let shift = 0.5 * next();
            let x: Vec<f64> = (0..6).map(|_| next()).collect();
            let y: Vec<f64> = (0..7).map(|_| next() + shift).collect();
            let t = metric_test(&x, &y, 0.05);
            between += usize::from((0.05..0.1).contains(&t.p_value));
            assert_eq!(
                t.verdict != Verdict::NotSignificant,
                t.p_value < 0.05,
                "case {case}: p {} verdict {:?}",
                t.p_value,
                t.verdict
            );
        }
        assert!(between > 20, "{between} cases between alpha and 2 alpha");
    }

    #[test]
    fn dates_are_civil() {
        assert_eq!(utc_date_time(0), "1970-01-01 00:00:00");
        // 2024-02-29 12:34:56 UTC, a leap day.
        assert_eq!(utc_date_time(1_709_210_096), "2024-02-29 12:34:56");
    }

    #[test]
    fn quantiles_as_numpy() {
        let v = [1.0, 2.0, 3.0, 4.0];
        assert_eq!(quantile(&v, 0.5), 2.5);
        assert_eq!(quantile(&v, 0.25), 1.75);
        assert_eq!(quantile(&v, 0.75), 3.25);
        assert!(quantile(&[], 0.5).is_nan());
        let s = Spread::of([3.0, f64::NAN, 1.0, 2.0]);
        assert_eq!((s.q1, s.median, s.q3), (1.5, 2.0, 2.5));
    }

    #[test]
    fn runs_read_back_from_ron_bit_for_bit() {
        let metrics = RunMetrics {
            run: 3,
            seed: u64::MAX,
            success: false,
            time_s: 0.1 + 0.2,
            cpu_time_s: f64::NAN,
            length: f64::INFINITY,
            nodes: 1e-310,
            inner_nodes: -0.0,
            segments: 2.0,
            turns: 0.0,
            explored: 7.0,
            transfer_time_s: f64::NEG_INFINITY,
            min_clearance: 1.5,
            path: Vec::new(),
            trees: Vec::new(),
        };
        let run = BenchRun {
            problem: 1,
            planner: "rrt:step=2,goal_bias=0.1".into(),
            metrics,
            exact: false,
            status: "timeout".into(),
            error: None,
            planning_time_s: 0.25,
            raw_length: f64::NAN,
            iterations: 9,
            collision_checks: 11,
            progress: vec![ProgressPoint {
                time_s: 0.5,
                iterations: 64,
                best_cost: f64::NAN,
            }],
            max_curvature: 2.0,
        };
        let text = ron::to_string(&run).unwrap();
        let back: BenchRun = ron::from_str(&text).unwrap();
        // Bit for bit: written again, the same text.
        assert_eq!(ron::to_string(&back).unwrap(), text);
        assert_eq!(back.metrics.nodes.to_bits(), 1e-310_f64.to_bits());
        assert_eq!(back.status, "timeout");
        let bad = text.replace("timeout", "timed out");
        assert!(ron::from_str::<BenchRun>(&bad).is_err());
    }

    /// A run of `planner` whose planning call took `planning` s and whose scoring took
    /// `total` s in all.
    fn timed_run(planner: &str, run: u32, planning: f64, total: f64) -> BenchRun {
        BenchRun {
            problem: 0,
            planner: planner.into(),
            metrics: RunMetrics {
                run,
                seed: 0,
                success: true,
                time_s: total,
                cpu_time_s: planning,
                length: 1.0,
                nodes: 2.0,
                inner_nodes: 0.0,
                segments: 1.0,
                turns: 0.0,
                explored: 1.0,
                transfer_time_s: f64::NAN,
                min_clearance: 1.0,
                path: Vec::new(),
                trees: Vec::new(),
            },
            exact: true,
            status: "exact solution".into(),
            error: None,
            planning_time_s: planning,
            raw_length: 1.0,
            iterations: 0,
            collision_checks: 0,
            progress: Vec::new(),
            max_curvature: 0.0,
        }
    }

    #[test]
    fn the_summary_and_the_tests_time_the_planning_call() {
        // A plans in 1 ms but its long path takes 9 ms more to check; B plans in 5 ms and
        // its path takes 1 ms. A is the faster planner, B the faster in total.
        let runs: Vec<BenchRun> = (0..10)
            .flat_map(|k| {
                let jitter = f64::from(k) * 1e-5;
                [
                    timed_run("a", k, 1e-3 + jitter, 10e-3 + jitter),
                    timed_run("b", k, 5e-3 + jitter, 6e-3 + jitter),
                ]
            })
            .collect();
        let rows = summarise(&runs);
        assert!((rows[0].planning_time_s.median - 1.045e-3).abs() < 1e-12);
        assert!((rows[0].time_s.median - 10.045e-3).abs() < 1e-12);
        let pair = &compare(&runs, 0.05)[0];
        assert_eq!((pair.a.as_str(), pair.b.as_str()), ("a", "b"));
        assert_eq!(pair.time.verdict, Verdict::Held, "{pair:?}");
        assert!(pair.time.cliffs_delta < -0.99);
    }

    #[test]
    fn properties_are_sorted_and_sql_safe() {
        let props = ompl_properties();
        let names: Vec<&str> = props.iter().map(|(p, _)| p.name.as_str()).collect();
        let mut sorted = names.clone();
        sorted.sort_unstable();
        assert_eq!(names, sorted);
        assert!(names.contains(&"time") && names.contains(&"solved"));
    }
}
