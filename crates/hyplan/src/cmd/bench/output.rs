//! `hyplan bench`'s tables: every run as CSV, the summary as Markdown.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Context as _;
use viz::{Align, Table};

use harness::bench::{self, Comparison};

use super::Report;

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
    for (p, prob) in r.problems.iter().enumerate() {
        let _ = writeln!(
            s,
            "## {}: {} query {}\n",
            prob.name,
            prob.map.display(),
            prob.query
        );
        let mut table = Table::new([
            "planner",
            "runs",
            "solved",
            "time median (ms)",
            "time IQR (ms)",
            "length median",
            "length IQR",
        ])
        .align(std::iter::once(Align::Left).chain(std::iter::repeat(Align::Right)));
        for row in r.summary.iter().filter(|x| x.problem == p) {
            table.row([
                row.planner.clone(),
                row.runs.to_string(),
                format!("{:.0}%", 100.0 * row.success_rate),
                g(1e3 * row.time_s.median, 3),
                g(1e3 * row.time_s.iqr(), 3),
                g(row.length.median, 2),
                g(row.length.iqr(), 2),
            ]);
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
