//! The seed-004 exploration section of `cargo xtask reproduce`: Fig. 5d as a sweep of the
//! growth rate eta for the local, global and both detectors over several seeds (time to
//! 95 % and 99 % coverage, area missed), the claims "global best at eta = 10" and "local
//! best at eta = 6", Fig. 5a-c as a field-of-view comparison, and the nearest-frontier
//! baseline, all on `scenarios/sim/explore-22m.ron` (crate `sim`, module `explore`).
//!
//! Runs are independent and each is bit-identical per seed, so they run in parallel
//! (rayon) and are gathered in a fixed order.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Context;
use rayon::prelude::*;
use sim::{Scenario, Strategy};
use viz::{Claim, Table, claims_held, claims_markdown};

/// eta values of the sweep, m.
const ETAS: [f64; 7] = [2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 15.0];
/// eta values of `--quick`.
const QUICK_ETAS: [f64; 4] = [2.0, 6.0, 10.0, 15.0];
/// Fields of view of Fig. 5a-c, degrees.
const FOVS: [f64; 4] = [90.0, 180.0, 270.0, 360.0];

/// One run of the section.
#[derive(Debug, Clone, Copy)]
struct Spec {
    strategy: Strategy,
    eta: Option<f64>,
    fov: f64,
    seed: u64,
}

/// What a run measured.
#[derive(Debug, Clone)]
struct Result {
    spec: Spec,
    t95: Option<f64>,
    t99: Option<f64>,
    end: f64,
    finished: bool,
    coverage: f64,
    missed: f64,
    distance: f64,
}

fn run(base: &Scenario, world: &sim::World, spec: Spec) -> anyhow::Result<Result> {
    let mut scenario = base.clone();
    if let Some(eta) = spec.eta {
        scenario.exploration.eta_global = eta;
        scenario.exploration.eta_local = eta;
    }
    scenario.laser.fov_deg = spec.fov;
    let out = sim::explore(&scenario, world, spec.seed, spec.strategy)?;
    Ok(Result {
        spec,
        t95: out.time_to(0.95),
        t99: out.time_to(0.99),
        end: out.end_time,
        finished: out.finished,
        coverage: out.final_coverage(),
        missed: out.missed_area(),
        distance: out.distance,
    })
}

fn mean(v: impl Iterator<Item = f64>) -> f64 {
    let (s, n) = v.fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
    if n == 0 { f64::NAN } else { s / n as f64 }
}

/// Mean time to 99 % over a group's runs, a run that never reached it counted at its end
/// time (a lower bound on its true time), and how many did not reach it.
fn mean_t99(rs: &[&Result]) -> (f64, usize) {
    (
        mean(rs.iter().map(|r| r.t99.unwrap_or(r.end))),
        rs.iter().filter(|r| r.t99.is_none()).count(),
    )
}

fn fmt_t(t: Option<f64>) -> String {
    t.map_or("-".into(), |t| format!("{t:.0}"))
}

/// Runs the section, writes `sweep.csv` under `figures/004-exploration/`, and returns the
/// report section and (claims held, claims).
pub fn section(root: &Path, figures: &Path, quick: bool) -> anyhow::Result<(String, usize, usize)> {
    let file = root.join("scenarios/sim/explore-22m.ron");
    let (base, world) = Scenario::load(&file)?;
    let started = std::time::Instant::now();
    let seeds: Vec<u64> = if quick { vec![0] } else { vec![0, 1, 2] };
    let etas: &[f64] = if quick { &QUICK_ETAS } else { &ETAS };
    let sweep_strategies: &[Strategy] = if quick {
        &[Strategy::Local, Strategy::Global]
    } else {
        &[Strategy::Local, Strategy::Global, Strategy::Both]
    };
    let fovs: &[f64] = if quick { &[] } else { &FOVS };
    let results: Vec<Result> = specs(&seeds, etas, sweep_strategies, fovs)
        .par_iter()
        .map(|&s| run(&base, &world, s))
        .collect::<anyhow::Result<_>>()?;
    let elapsed = started.elapsed().as_secs_f64();
    let dir = figures.join("004-exploration");
    std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    std::fs::write(dir.join("sweep.csv"), sweep_csv(&results))
        .with_context(|| format!("writing {}", dir.join("sweep.csv").display()))?;

    let mut s = String::new();
    let _ = writeln!(s, "## `004_3e5a323113b41ded.txt` Fig. 5: 004-exploration\n");
    let _ = writeln!(
        s,
        "{} explorations of `scenarios/sim/explore-22m.ron` (22 m x 22 m, reconstructed) in {elapsed:.1} s of computing{}; \
         seeds {seeds:?}; eta in metres (the reference's unit; the paper states none); laser 180 degrees unless said. \
         Coverage = known free / reachable free area of the true world. Times are simulated seconds. \
         See `docs/papers/004-exploration.md`. Data: `figures/004-exploration/sweep.csv`.\n",
        results.len(),
        if quick {
            " (quick: fewer etas, one seed, local and global only, no field-of-view runs)"
        } else {
            ""
        },
    );
    let _ = writeln!(
        s,
        "Fig. 5d, mean over seeds (runs not reaching 99 % counted at their end time; `n<99` says how many):\n"
    );
    let (table, best) = fig5d(&results, etas, sweep_strategies);
    s.push_str(&table);
    let _ = writeln!(s, "\nRuns that did not reach 99 %: {}.\n", not_99(&results));
    let claims = claims(&best);
    s.push_str(&claims_markdown(&claims));
    let held = claims_held(&claims);
    let _ = writeln!(
        s,
        "\nClaims held: {held} of {}. A least mean over {} seed(s) is a ranking, not a significance test.\n",
        claims.len(),
        seeds.len()
    );
    let _ = writeln!(
        s,
        "Field of view (Fig. 5a-c: the paper shows maps, no numbers) and the nearest-frontier baseline, mean over seeds:\n"
    );
    s.push_str(&fov_table(&results, fovs));
    // The navigation scenarios on the map the robot built itself (full runs only).
    if !quick {
        s.push_str(&self_mapped(root)?);
    }
    eprintln!(
        "004-exploration: {} runs in {elapsed:.1} s, claims held {held}/{}",
        results.len(),
        claims.len()
    );
    Ok((s, held, claims.len()))
}

/// The runs: the eta sweep of each detector, the fields of view (both detectors, default
/// etas) and the nearest-frontier baseline, each on every seed.
fn specs(seeds: &[u64], etas: &[f64], strategies: &[Strategy], fovs: &[f64]) -> Vec<Spec> {
    let mut specs = Vec::new();
    for &strategy in strategies {
        for &eta in etas {
            for &seed in seeds {
                specs.push(Spec {
                    strategy,
                    eta: Some(eta),
                    fov: 180.0,
                    seed,
                });
            }
        }
    }
    for &fov in fovs {
        for &seed in seeds {
            specs.push(Spec {
                strategy: Strategy::Both,
                eta: None,
                fov,
                seed,
            });
        }
    }
    for &seed in seeds {
        specs.push(Spec {
            strategy: Strategy::Frontier,
            eta: None,
            fov: 180.0,
            seed,
        });
    }
    specs
}

/// `sweep.csv`: one line per run.
fn sweep_csv(results: &[Result]) -> String {
    let mut csv = Table::new([
        "detector",
        "eta_m",
        "fov_deg",
        "seed",
        "t95_s",
        "t99_s",
        "end_s",
        "finished",
        "coverage",
        "missed_m2",
        "distance_m",
    ]);
    for r in results {
        csv.row([
            r.spec.strategy.name().to_string(),
            r.spec.eta.map_or("default".into(), |e| e.to_string()),
            r.spec.fov.to_string(),
            r.spec.seed.to_string(),
            fmt_t(r.t95),
            fmt_t(r.t99),
            format!("{:.1}", r.end),
            r.finished.to_string(),
            format!("{:.5}", r.coverage),
            format!("{:.3}", r.missed),
            format!("{:.1}", r.distance),
        ]);
    }
    csv.to_csv()
}

/// The runs of one detector, eta (`None`: the defaults) and field of view.
fn group(results: &[Result], st: Strategy, eta: Option<f64>, fov: f64) -> Vec<&Result> {
    results
        .iter()
        .filter(|r| r.spec.strategy == st && r.spec.eta == eta && r.spec.fov == fov)
        .collect()
}

/// A detector's eta of least mean time to 99 %, with each eta's mean.
type Best = (Strategy, f64, Vec<(f64, f64)>);

/// Fig. 5d's table (a row per detector, a column per eta), and each detector's best eta.
fn fig5d(results: &[Result], etas: &[f64], strategies: &[Strategy]) -> (String, Vec<Best>) {
    let mut table = Table::new(
        std::iter::once("detector".to_string()).chain(etas.iter().map(|e| format!("eta {e}"))),
    );
    let mut best = Vec::new();
    for &st in strategies {
        let mut cells = vec![format!("{} t95 / t99 / missed m^2", st.name())];
        let mut rows = Vec::new();
        for &e in etas {
            let g = group(results, st, Some(e), 180.0);
            let (t99, miss99) = mean_t99(&g);
            let t95 = mean(g.iter().map(|r| r.t95.unwrap_or(r.end)));
            let missed = mean(g.iter().map(|r| r.missed));
            rows.push((e, t99));
            cells.push(format!(
                "{t95:.0} / {t99:.0}{} / {missed:.2}",
                if miss99 > 0 {
                    format!(" (n<99 {miss99})")
                } else {
                    String::new()
                }
            ));
        }
        table.row(cells);
        let b = rows
            .iter()
            .copied()
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map_or(f64::NAN, |(e, _)| e);
        best.push((st, b, rows));
    }
    (table.to_markdown(), best)
}

/// The runs that did not reach 99 %, `none` when every run did.
fn not_99(results: &[Result]) -> String {
    let not99: Vec<String> = results
        .iter()
        .filter(|r| r.t99.is_none())
        .map(|r| {
            format!(
                "{} eta {} fov {} seed {} ({:.2} % at {:.0} s, {})",
                r.spec.strategy.name(),
                r.spec.eta.map_or("default".into(), |e| e.to_string()),
                r.spec.fov,
                r.spec.seed,
                100.0 * r.coverage,
                r.end,
                if r.finished {
                    "ended with no frontier left"
                } else {
                    "time limit"
                }
            )
        })
        .collect();
    if not99.is_empty() {
        "none".to_string()
    } else {
        not99.join("; ")
    }
}

/// The paper's claims on the sweep: each detector's best eta.
fn claims(best: &[Best]) -> Vec<Claim> {
    let mut claims = Vec::new();
    for (st, paper_eta, text) in [
        (Strategy::Global, 10.0, "global detector best at eta = 10"),
        (Strategy::Local, 6.0, "local detector best at eta = 6"),
    ] {
        let Some((_, b, rows)) = best.iter().find(|(k, _, _)| *k == st) else {
            continue;
        };
        claims.push(Claim {
            text: text.into(),
            paper: format!("Fig. 5d: eta = {paper_eta}"),
            ours: format!(
                "least mean time to 99 % at eta = {b} ({})",
                rows.iter()
                    .map(|(e, t)| format!("{e}: {t:.0} s"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            held: *b == paper_eta,
        });
    }
    claims
}

/// Fig. 5a-c (both detectors per field of view) and the nearest-frontier baseline.
fn fov_table(results: &[Result], fovs: &[f64]) -> String {
    let mut table = Table::new([
        "run",
        "t95 (s)",
        "t99 (s)",
        "end (s)",
        "missed (m^2)",
        "distance (m)",
    ]);
    let mut rows: Vec<(String, Vec<&Result>)> = fovs
        .iter()
        .map(|&f| {
            (
                format!("both, default etas, fov {f}"),
                group(results, Strategy::Both, None, f),
            )
        })
        .collect();
    rows.push((
        "nearest frontier (baseline), fov 180".into(),
        group(results, Strategy::Frontier, None, 180.0),
    ));
    for (name, g) in rows {
        let (t99, n) = mean_t99(&g);
        table.row([
            name,
            format!("{:.0}", mean(g.iter().map(|r| r.t95.unwrap_or(r.end)))),
            format!(
                "{t99:.0}{}",
                if n > 0 {
                    format!(" (n<99 {n})")
                } else {
                    String::new()
                }
            ),
            format!("{:.0}", mean(g.iter().map(|r| r.end))),
            format!("{:.2}", mean(g.iter().map(|r| r.missed))),
            format!("{:.1}", mean(g.iter().map(|r| r.distance))),
        ]);
    }
    table.to_markdown()
}

/// The three navigation scenarios on the map the robot built itself: the paragraph and
/// its table.
fn self_mapped(root: &Path) -> anyhow::Result<String> {
    let t0 = std::time::Instant::now();
    let runs: Vec<(String, sim::SelfMapped)> = crate::sim004::FILES
        .par_iter()
        .map(|f| {
            let path = root.join("scenarios/sim").join(f);
            let (sc, _) = Scenario::load(&path)?;
            let r = sim::explore_then_navigate(&sc, &path, 0, Strategy::Both, 1500.0)?;
            Ok((sc.name, r))
        })
        .collect::<anyhow::Result<_>>()?;
    let mut s = format!(
        "\nThe three navigation scenarios on the map the robot built itself (each scenario's mapped world explored with both detectors, seed 0; then Dijkstra on the built map, unknown cells passable; {:.1} s of computing):\n\n",
        t0.elapsed().as_secs_f64()
    );
    let mut table = Table::new([
        "scenario",
        "exploration: coverage / end (s)",
        "true map: reached / travel (s) / distance (m)",
        "built map: reached / travel (s) / distance (m)",
        "contacts at fault (true / built)",
    ]);
    let drive = |m: &sim::Summary| {
        format!(
            "{} / {} / {:.2}",
            if m.reached { "yes" } else { "no" },
            m.travel_time.map_or("-".into(), |t| format!("{t:.1}")),
            m.distance
        )
    };
    for (name, r) in &runs {
        let (a, b) = (&r.on_true.trace.summary, &r.on_built.trace.summary);
        table.row([
            name.clone(),
            format!(
                "{:.2} % / {:.0}",
                100.0 * r.exploration.final_coverage(),
                r.exploration.end_time
            ),
            drive(a),
            drive(b),
            format!("{} / {}", a.contacts_at_fault, b.contacts_at_fault),
        ]);
    }
    s.push_str(&table.to_markdown());
    Ok(s)
}
