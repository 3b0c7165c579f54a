//! `hyplan bench`'s outputs from its records: every run as CSV and JSON, the summary as
//! Markdown, per problem the OMPL log and Planner Arena's default views. The one writer
//! of an unsharded run and of `hyplan bench merge`.

use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

use anyhow::Context as _;
use viz::{Align, Table};

use harness::bench::{self, BenchRun, Comparison, ExperimentInfo};

use super::{Experiment, ProblemRecord, Report, Settings};

/// What the outputs are written from: the experiment, its problems and every run, in
/// the experiment's order.
pub(super) struct Outputs {
    /// The experiment (its shard left out).
    pub experiment: Experiment,
    /// Level of the pairwise rank tests.
    pub alpha: f64,
    /// Name, map and query of each problem.
    pub problems: Vec<ProblemRecord>,
    /// Each problem's planner settings, by label.
    pub settings: Vec<Settings>,
    /// Every run.
    pub runs: Vec<BenchRun>,
    /// Where and when the runs ran.
    pub timing: Timing,
}

/// Where and when the runs ran: the OMPL log's header and the timing line.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub(super) struct Timing {
    /// Host name(s).
    pub host: String,
    /// When the runs started (UTC, OMPL's format).
    pub start: String,
    /// Wall time of the runs, s.
    pub wall_s: f64,
    /// Worker threads.
    pub threads: usize,
}

/// The command's own clocks for the timing line: read now, or as recorded by shards.
pub(super) enum Clock {
    /// This command ran the experiment: its clocks since it started.
    Live {
        started: Instant,
        cpu: Option<cpu_time::ProcessTime>,
    },
    /// The shards' commands, summed: whole-command wall and CPU time, s.
    Recorded { total_s: f64, command_cpu_s: f64 },
}

/// Writes every output into `out` and prints the summary.
pub(super) fn write_outputs(out: &Path, o: Outputs, clock: &Clock) -> anyhow::Result<()> {
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let summary = bench::summarise(&o.runs);
    let comparisons = bench::compare(&o.runs, o.alpha);
    let sum_run_time_s: f64 = o.runs.iter().map(|r| r.metrics.time_s).sum();
    let sum_planning_time_s: f64 = o.runs.iter().map(|r| r.planning_time_s).sum();
    let sum_planning_cpu_s: f64 = o.runs.iter().map(|r| r.metrics.cpu_time_s).sum();
    write_problem_outputs(out, &o, &summary)?;
    let mut report = Report {
        experiment: o.experiment,
        problems: o.problems,
        runs: o.runs,
        summary,
        comparisons,
        wall_s: o.timing.wall_s,
        sum_run_time_s,
        sum_planning_time_s,
        sum_planning_cpu_s,
        command_cpu_s: f64::NAN,
        threads: o.timing.threads,
    };
    write_csv(&out.join("runs.csv"), &report)?;
    let json = serde_json::to_string_pretty(&report)?;
    std::fs::write(out.join("runs.json"), json).context("writing runs.json")?;
    // Everything but writing the report itself is in these totals.
    let total_s = match clock {
        Clock::Live { started, cpu } => {
            report.command_cpu_s = cpu.map_or(f64::NAN, |t| t.elapsed().as_secs_f64());
            started.elapsed().as_secs_f64()
        }
        Clock::Recorded {
            total_s,
            command_cpu_s,
        } => {
            report.command_cpu_s = *command_cpu_s;
            *total_s
        }
    };
    let md = markdown(&report, o.alpha, total_s);
    std::fs::write(out.join("summary.md"), &md).context("writing summary.md")?;
    outln!("{md}")?;
    outln!("outputs in {}", out.display())?;
    Ok(())
}

/// Per problem: its OMPL benchmark log and Planner Arena's default views (time and
/// length box plots, success bars).
fn write_problem_outputs(
    out: &Path,
    o: &Outputs,
    summary: &[bench::SummaryRow],
) -> anyhow::Result<()> {
    let (e, runs) = (&o.experiment, &o.runs);
    for (p, prob) in o.problems.iter().enumerate() {
        let mine: Vec<&BenchRun> = runs.iter().filter(|r| r.problem == p).collect();
        let info = ExperimentInfo {
            name: prob.name.clone(),
            host: o.timing.host.clone(),
            start: o.timing.start.clone(),
            setup: format!(
                "hyplan bench\nmap {}\nquery {} (goal radius {})\nsmoothing {}\nseed {}",
                prob.map.display(),
                prob.query,
                e.goal_radius,
                e.smooth,
                e.seed
            ),
            seed: e.seed,
            max_time: e.time_limit.unwrap_or(0.0),
            run_count: u64::from(e.runs),
            total_duration: o.timing.wall_s,
        };
        let settings = o.settings.get(p).cloned().unwrap_or_default();
        let log = bench::experiment_log(&info, &mine, &settings).to_log()?;
        let path = out.join(format!("{}.log", prob.name));
        std::fs::write(&path, log).with_context(|| format!("writing {}", path.display()))?;
        // Planner Arena's default views.
        let groups = bench::groups(runs);
        let mine: Vec<&(_, Vec<&BenchRun>)> = groups.iter().filter(|((q, _), _)| *q == p).collect();
        for (file, measure, get) in [
            (
                "time",
                "time (s)",
                (|r: &BenchRun| r.planning_time_s) as fn(&BenchRun) -> f64,
            ),
            ("length", "path length", |r: &BenchRun| r.metrics.length),
        ] {
            let series: Vec<(String, Vec<f64>)> = mine
                .iter()
                .map(|((_, l), rs)| (l.clone(), rs.iter().map(|r| get(r)).collect()))
                .collect();
            let path = out.join(format!("{}-{file}.svg", prob.name));
            harness::chart_box(&prob.name, measure, &series, &path)?;
        }
        let rates: Vec<(String, f64)> = summary
            .iter()
            .filter(|s| s.problem == p)
            .map(|s| (s.planner.clone(), s.success_rate))
            .collect();
        let path = out.join(format!("{}-success.svg", prob.name));
        harness::chart_success(&prob.name, &rates, &path)?;
    }
    Ok(())
}

pub(super) fn write_csv(path: &Path, r: &Report) -> anyhow::Result<()> {
    let mut s = String::from(
        "problem,map,query,planner,run,seed,solved,exact,status,time_s,planning_time_s,\
         cpu_time_s,length,raw_length,nodes,explored,iterations,collision_checks,turns,\
         max_curvature,min_clearance,transfer_time_s\n",
    );
    let f = |v: f64| {
        if v.is_finite() {
            v.to_string()
        } else {
            String::new()
        }
    };
    // Labels may hold commas (`rrt:step=2,goal_bias=0.1`): quoted as RFC 4180 says.
    let quote = |t: &str| format!("\"{}\"", t.replace('"', "\"\""));
    for run in &r.runs {
        let p = &r.problems[run.problem];
        let m = &run.metrics;
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            quote(&p.name),
            quote(&p.map.display().to_string()),
            quote(&p.query),
            quote(&run.planner),
            m.run,
            m.seed,
            u8::from(m.success),
            u8::from(run.exact),
            run.status,
            f(m.time_s),
            f(run.planning_time_s),
            f(m.cpu_time_s),
            f(m.length),
            f(run.raw_length),
            f(m.nodes),
            f(m.explored),
            run.iterations,
            run.collision_checks,
            f(m.turns),
            f(run.max_curvature),
            f(m.min_clearance),
            f(m.transfer_time_s),
        );
    }
    std::fs::write(path, s).with_context(|| format!("writing {}", path.display()))
}

pub(super) fn markdown(r: &Report, alpha: f64, total_s: f64) -> String {
    let mut s = String::new();
    let g = |v: f64, digits: usize| {
        if v.is_finite() {
            format!("{v:.digits$}")
        } else {
            "-".into()
        }
    };
    let smoothed = r
        .experiment
        .smooth
        .parse::<postproc::Smoothing>()
        .is_ok_and(|m| m != postproc::Smoothing::None);
    for (p, prob) in r.problems.iter().enumerate() {
        let _ = writeln!(
            s,
            "## {}: {} query {}\n",
            prob.name,
            prob.map.display(),
            prob.query
        );
        // The planning call's times; with `--smooth`, the smoothing's cost beside them (the
        // check of the final path that every run gets is in it, as in `time_s`).
        let mut headers = vec![
            "planner",
            "runs",
            "solved",
            "time median (ms)",
            "time IQR (ms)",
        ];
        if smoothed {
            headers.push("with smoothing median (ms)");
        }
        headers.extend(["length median", "length IQR"]);
        let mut table = Table::new(headers)
            .align(std::iter::once(Align::Left).chain(std::iter::repeat(Align::Right)));
        for row in r.summary.iter().filter(|x| x.problem == p) {
            let mut cells = vec![
                row.planner.clone(),
                row.runs.to_string(),
                format!("{:.0}%", 100.0 * row.success_rate),
                g(1e3 * row.planning_time_s.median, 3),
                g(1e3 * row.planning_time_s.iqr(), 3),
            ];
            if smoothed {
                cells.push(g(1e3 * row.time_s.median, 3));
            }
            cells.extend([g(row.length.median, 2), g(row.length.iqr(), 2)]);
            table.row(cells);
        }
        s.push_str(&table.to_markdown());
        let pairs: Vec<&Comparison> = r.comparisons.iter().filter(|c| c.problem == p).collect();
        if !pairs.is_empty() {
            let _ = writeln!(
                s,
                "\nPairwise Mann-Whitney U tests (two-sided p; Cliff's delta of A against B; \
                 verdict at alpha = {alpha}):\n"
            );
            let mut table = Table::new([
                "A",
                "B",
                "time p",
                "time delta",
                "time",
                "length p",
                "length delta",
                "length",
            ])
            .align([
                Align::Left,
                Align::Left,
                Align::Right,
                Align::Right,
                Align::Left,
                Align::Right,
                Align::Right,
                Align::Left,
            ]);
            for c in pairs {
                let word = |t: &bench::MetricTest, less: &str, more: &str| match t.verdict {
                    harness::stats::Verdict::Held => format!("A {less}"),
                    harness::stats::Verdict::NotHeld => format!("B {less}"),
                    harness::stats::Verdict::NotSignificant => format!("no {more} difference"),
                    harness::stats::Verdict::NoData => "no data".into(),
                };
                table.row([
                    c.a.clone(),
                    c.b.clone(),
                    p_fmt(c.time.p_value),
                    g(c.time.cliffs_delta, 2),
                    word(&c.time, "faster", "significant"),
                    p_fmt(c.length.p_value),
                    g(c.length.cliffs_delta, 2),
                    word(&c.length, "shorter", "significant"),
                ]);
            }
            s.push_str(&table.to_markdown());
        }
        s.push('\n');
    }
    let _ = writeln!(
        s,
        "{} runs on {} threads. Wall clock: the runs {:.3} s, the whole command {:.3} s; sum \
         of the run times (planning and post-processing) {:.3} s, of the planning times {:.3} s; \
         command / planning = {:.3}. CPU: the command {:.3} s, the planning calls {:.3} s; \
         command / planning = {:.3}.",
        r.runs.len(),
        r.threads,
        r.wall_s,
        total_s,
        r.sum_run_time_s,
        r.sum_planning_time_s,
        total_s / r.sum_planning_time_s,
        r.command_cpu_s,
        r.sum_planning_cpu_s,
        r.command_cpu_s / r.sum_planning_cpu_s,
    );
    s
}

fn p_fmt(p: f64) -> String {
    if !p.is_finite() {
        "-".into()
    } else if p < 1e-4 {
        format!("{p:.1e}")
    } else {
        format!("{p:.4}")
    }
}
