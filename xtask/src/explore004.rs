//! The seed-004 exploration section of `cargo xtask reproduce`: Fig. 5d as a sweep of the
//! growth rate eta for the local and global detectors over ten seeds (time to 95 % and
//! 99 % coverage, with 95 % confidence intervals), the claims "global best at eta = 10"
//! and "local best at eta = 6" decided by the rank tests of seeds 000-003, Fig. 5a-c as a
//! field-of-view comparison, and the nearest-frontier baseline, all on
//! `scenarios/sim/explore-22m.ron` (crate `sim`, module `explore`), on each navigation
//! profile (`sim::Profile`).
//!
//! Runs are independent and each is bit-identical per seed, so they run in parallel
//! (rayon) and are gathered in a fixed order.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Context;
use harness::report::ALPHA;
use harness::stats::{Verdict, decide_less};
use rayon::prelude::*;
use sim::{Profile, Scenario, Strategy};
use statrs::distribution::{ContinuousCDF, StudentsT};
use viz::{Claim, Table, claims_held};

/// eta values of the sweep, m: the paper's two (6 and 10), their neighbours and the ends
/// (five keep the seed-004 part of `cargo xtask reproduce` under five minutes on two
/// cores; `--all-etas` runs [`ALL_ETAS`]).
const ETAS: [f64; 5] = [2.0, 6.0, 8.0, 10.0, 15.0];
/// eta values of `--all-etas`, m.
const ALL_ETAS: [f64; 7] = [2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 15.0];
/// eta values of `--quick`.
const QUICK_ETAS: [f64; 4] = [2.0, 6.0, 10.0, 15.0];
/// Fields of view of Fig. 5a-c, degrees.
const FOVS: [f64; 4] = [90.0, 180.0, 270.0, 360.0];

/// One run of the section.
#[derive(Debug, Clone, Copy)]
struct Spec {
    profile: Profile,
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

/// The sweep's runs end at this coverage: they are compared on their times to 95 and
/// 99 % (so a run's time to 99 % is its end).
const SWEEP_STOP: f64 = 0.99;

fn run(base: &Scenario, world: &sim::World, spec: Spec) -> anyhow::Result<Result> {
    let mut scenario = base.clone();
    // Seed 004's set-up: `assigner.py`'s revenue takes the straight line.
    scenario.exploration.revenue_distance = sim::RevenueDistance::Straight;
    spec.profile.apply(&mut scenario);
    if let Some(eta) = spec.eta {
        scenario.exploration.eta_global = eta;
        scenario.exploration.eta_local = eta;
        scenario.exploration.stop_at_coverage = Some(SWEEP_STOP);
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
/// report section and (claims held, claims) over the profiles.
pub fn section(
    root: &Path,
    figures: &Path,
    quick: bool,
    all_etas: bool,
) -> anyhow::Result<(String, usize, usize)> {
    let file = root.join("scenarios/sim/explore-22m.ron");
    let (base, world) = Scenario::load(&file)?;
    let started = std::time::Instant::now();
    let seeds: Vec<u64> = if quick { vec![0] } else { (0..10).collect() };
    let fov_seeds: Vec<u64> = if quick { vec![] } else { vec![0, 1] };
    let etas: &[f64] = match (quick, all_etas) {
        (true, _) => &QUICK_ETAS,
        (false, true) => &ALL_ETAS,
        (false, false) => &ETAS,
    };
    let sweep_strategies = [Strategy::Local, Strategy::Global];
    let fovs: &[f64] = if quick { &[] } else { &FOVS };
    let mut specs = specs(&seeds, &fov_seeds, etas, &sweep_strategies, fovs);
    // The longest runs first (whole runs, then the tutorial profile's roll-out), so that
    // the two cores finish together; results are put back in order by `group`.
    specs.sort_by_key(|s| (s.eta.is_some(), s.profile != Profile::Tutorial));
    let results: Vec<Result> = specs
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
        "{} explorations of `scenarios/sim/explore-22m.ron` (22 m x 22 m, reconstructed) in {elapsed:.1} s of computing{}, \
         on two navigation profiles (`sim::Profile`: `hyplan`, our defaults; `tutorial`, the values of \
         `rrt_exploration_tutorials` with the reference's detector compute time, filter pool and assigner); \
         eta in metres (the reference's unit; the paper states none); laser 180 degrees unless said. \
         Coverage = known free / reachable free area of the true world. Times are simulated seconds. \
         See `docs/papers/004-exploration.md`. Data: `figures/004-exploration/sweep.csv`.\n",
        results.len(),
        if quick {
            " (quick: fewer etas, one seed, no field-of-view runs)"
        } else {
            ""
        },
    );
    let _ = writeln!(
        s,
        "Fig. 5d: mean time to 99 % with its 95 % confidence interval (Student's t) over seeds {seeds:?}; \
         a run not reaching 99 % counts at its end time (`n<99` says how many); sweep runs end at {:.1} % coverage.\n",
        100.0 * SWEEP_STOP
    );
    let mut per_profile = Vec::new();
    for profile in Profile::ALL {
        let _ = writeln!(s, "Profile `{}`:\n", profile.name());
        s.push_str(&fig5d(&results, profile, etas, &sweep_strategies));
        s.push('\n');
        per_profile.push((profile, claims(&results, profile, etas)));
    }
    let _ = writeln!(s, "Runs that did not reach 99 %: {}.\n", not_99(&results));
    let _ = writeln!(
        s,
        "Each claim \"best at eta = e\" is decided by one-sided Mann-Whitney U tests at alpha = {ALPHA} \
         (as seeds 000-003) of the times to 99 % at e against those at every other eta: held when e is \
         significantly faster than each, NOT held when some eta is significantly faster than e, \
         otherwise not significant.\n"
    );
    let pairs: Vec<(Profile, &[Claim])> = per_profile
        .iter()
        .map(|(p, c)| (*p, c.as_slice()))
        .collect();
    s.push_str(&crate::sim004::claims_side_by_side(&pairs));
    s.push('\n');
    if !quick {
        let _ = writeln!(
            s,
            "Field of view (Fig. 5a-c: the paper shows maps, no numbers; tutorial profile) and the nearest-frontier \
             baseline, both detectors at the default etas, whole runs, mean over seeds {fov_seeds:?}:\n"
        );
        s.push_str(&fov_table(&results, fovs));
        // The navigation scenarios on the map the robot built itself.
        s.push_str(&self_mapped(root)?);
    }
    let held = per_profile.iter().map(|(_, c)| claims_held(c)).sum();
    let total = per_profile.iter().map(|(_, c)| c.len()).sum();
    eprintln!(
        "004-exploration: {} runs in {elapsed:.1} s, claims held {held}/{total}",
        results.len(),
    );
    Ok((s, held, total))
}

/// The runs: on every profile, the eta sweep of each detector on `seeds` and the
/// nearest-frontier baseline on `fov_seeds`; on the tutorial profile, the fields of view
/// (both detectors, default etas) on `fov_seeds`.
fn specs(
    seeds: &[u64],
    fov_seeds: &[u64],
    etas: &[f64],
    strategies: &[Strategy],
    fovs: &[f64],
) -> Vec<Spec> {
    let mut specs = Vec::new();
    for profile in Profile::ALL {
        let spec = |strategy, eta, fov, seed| Spec {
            profile,
            strategy,
            eta,
            fov,
            seed,
        };
        for &strategy in strategies {
            for &eta in etas {
                specs.extend(
                    seeds
                        .iter()
                        .map(|&seed| spec(strategy, Some(eta), 180.0, seed)),
                );
            }
        }
        // Fig. 5a-c has no claim: the fields of view run on the paper's stack only.
        for &fov in fovs.iter().filter(|_| profile == Profile::Tutorial) {
            specs.extend(
                fov_seeds
                    .iter()
                    .map(|&seed| spec(Strategy::Both, None, fov, seed)),
            );
        }
        specs.extend(
            fov_seeds
                .iter()
                .map(|&seed| spec(Strategy::Frontier, None, 180.0, seed)),
        );
    }
    specs
}

/// `sweep.csv`: one line per run.
fn sweep_csv(results: &[Result]) -> String {
    let mut csv = Table::new([
        "profile",
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
            r.spec.profile.name().to_string(),
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

/// The runs of one profile, detector, eta (`None`: the defaults) and field of view.
fn group(
    results: &[Result],
    profile: Profile,
    st: Strategy,
    eta: Option<f64>,
    fov: f64,
) -> Vec<&Result> {
    results
        .iter()
        .filter(|r| {
            r.spec.profile == profile
                && r.spec.strategy == st
                && r.spec.eta == eta
                && r.spec.fov == fov
        })
        .collect()
}

/// Times to 99 % of a group, a run that never reached it counted at its end time (a
/// lower bound on its true time).
fn t99s(g: &[&Result]) -> Vec<f64> {
    g.iter().map(|r| r.t99.unwrap_or(r.end)).collect()
}

/// Mean and half-width of the 95 % confidence interval (Student's t; 0 with one value).
fn mean_ci(v: &[f64]) -> (f64, f64) {
    let n = v.len();
    let m = mean(v.iter().copied());
    if n < 2 {
        return (m, 0.0);
    }
    let sd = (v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
    let t = StudentsT::new(0.0, 1.0, (n - 1) as f64).map_or(f64::NAN, |d| d.inverse_cdf(0.975));
    (m, t * sd / (n as f64).sqrt())
}

/// Fig. 5d's table for one profile: a row per detector, a column per eta.
fn fig5d(results: &[Result], profile: Profile, etas: &[f64], strategies: &[Strategy]) -> String {
    let mut table = Table::new(
        std::iter::once("detector".to_string()).chain(etas.iter().map(|e| format!("eta {e}"))),
    );
    for &st in strategies {
        let mut cells = vec![format!("{}: t95 / t99 +- 95 % CI", st.name())];
        for &e in etas {
            let g = group(results, profile, st, Some(e), 180.0);
            let (t99, ci) = mean_ci(&t99s(&g));
            let t95 = mean(g.iter().map(|r| r.t95.unwrap_or(r.end)));
            let miss99 = g.iter().filter(|r| r.t99.is_none()).count();
            cells.push(format!(
                "{t95:.0} / {t99:.0} +- {ci:.0}{}",
                if miss99 > 0 {
                    format!(" (n<99 {miss99})")
                } else {
                    String::new()
                }
            ));
        }
        table.row(cells);
    }
    table.to_markdown()
}

/// The runs that did not reach 99 %, `none` when every run did.
fn not_99(results: &[Result]) -> String {
    let not99: Vec<String> = results
        .iter()
        .filter(|r| r.t99.is_none())
        .map(|r| {
            format!(
                "{} {} eta {} fov {} seed {} ({:.2} % at {:.0} s, {})",
                r.spec.profile.name(),
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

/// The paper's claims on one profile's sweep, each decided by rank tests of the claimed
/// eta's times to 99 % against every other eta's.
fn claims(results: &[Result], profile: Profile, etas: &[f64]) -> Vec<Claim> {
    let mut claims = Vec::new();
    for (st, paper_eta, text) in [
        (Strategy::Global, 10.0, "global detector best at eta = 10"),
        (Strategy::Local, 6.0, "local detector best at eta = 6"),
    ] {
        let times = |e: f64| t99s(&group(results, profile, st, Some(e), 180.0));
        let claimed = times(paper_eta);
        let verdicts: Vec<(f64, Verdict)> = etas
            .iter()
            .filter(|&&e| e != paper_eta)
            .map(|&e| (e, decide_less(&claimed, &times(e), ALPHA).verdict))
            .collect();
        let verdict = if verdicts.iter().any(|(_, v)| *v == Verdict::NoData) || claimed.is_empty() {
            Verdict::NoData
        } else if verdicts.iter().any(|(_, v)| *v == Verdict::NotHeld) {
            Verdict::NotHeld
        } else if verdicts.iter().all(|(_, v)| *v == Verdict::Held) {
            Verdict::Held
        } else {
            Verdict::NotSignificant
        };
        let best = etas
            .iter()
            .map(|&e| (e, mean(times(e).into_iter())))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map_or(f64::NAN, |(e, _)| e);
        let beaten: Vec<String> = verdicts
            .iter()
            .filter(|(_, v)| *v == Verdict::NotHeld)
            .map(|(e, _)| e.to_string())
            .collect();
        claims.push(Claim {
            text: text.into(),
            paper: format!("Fig. 5d: eta = {paper_eta}"),
            ours: format!(
                "rank tests {}; least mean at eta = {best}{}",
                verdict.label(),
                if beaten.is_empty() {
                    String::new()
                } else {
                    format!("; significantly faster: eta {}", beaten.join(", "))
                }
            ),
            held: verdict == Verdict::Held,
        });
    }
    claims
}

/// Fig. 5a-c (both detectors per field of view) and the nearest-frontier baseline.
fn fov_table(results: &[Result], fovs: &[f64]) -> String {
    let mut table = Table::new([
        "profile",
        "run",
        "t95 (s)",
        "t99 (s)",
        "end (s)",
        "missed (m^2)",
        "distance (m)",
    ]);
    let mut rows: Vec<(Profile, String, Vec<&Result>)> = Vec::new();
    for profile in Profile::ALL {
        let fovs = fovs.iter().filter(|_| profile == Profile::Tutorial);
        rows.extend(fovs.map(|&f| {
            (
                profile,
                format!("both, default etas, fov {f}"),
                group(results, profile, Strategy::Both, None, f),
            )
        }));
        rows.push((
            profile,
            "nearest frontier (baseline), fov 180".into(),
            group(results, profile, Strategy::Frontier, None, 180.0),
        ));
    }
    for (profile, name, g) in rows {
        let (t99, n) = mean_t99(&g);
        table.row([
            profile.name().to_string(),
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
