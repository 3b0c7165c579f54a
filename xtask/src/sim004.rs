//! The replay of seed 004's navigation scenarios (Figs. 6-9): the `sim` crate's runs
//! against the paper's claims, its figures and its report section.
//!
//! Runs `1-free.ron`, `2-static.ron` and `3-person.ron` from a folder with Dijkstra and one
//! seed, and checks the paper's claims on the traces:
//!
//! | claim | paper | held when (ours) |
//! |---|---|---|
//! | scenario 1 path nearly straight | Fig. 6a | driven distance <= 1.03 x the straight start-goal distance |
//! | scenario 1 v and omega stable | Fig. 6b-c | between 2 s and 2 s before arrival, v varies by < 0.02 m/s and abs(omega) < 0.1 rad/s |
//! | scenario 2: two right turns | Fig. 7, text | two separate episodes of omega < -0.1 rad/s |
//! | scenario 2: peaks 0.3 and 0.75 rad/s | text | the first two right-turn peaks within 0.15 rad/s of 0.3 and 0.75 |
//! | scenario 3 slower than scenario 1 | 38.8 vs 36.4 s | T3 / T1 > 1 |
//! | scenario 3 ratio 1.066 | 38.8 / 36.4 | abs(T3 / T1 - 1.066) <= 0.05 |
//! | scenario 3: v changes abruptly twice | Fig. 9, 15 s and 20.2 s | exactly two runs of samples where v changes by >= 0.1 m/s within 0.5 s, away from the start and the arrival |
//! | scenario 3: omega fluctuates while avoiding | Fig. 9, 10-25 s | omega changes sign at least twice (abs(omega) > 0.05 rad/s) |
//! | no at-fault contact | (safety) | no contact the robot caused in the three runs |
//!
//! Absolute times are not claims: our robot, controller and world are reconstructions.

use std::fmt::Write as _;
use std::path::Path;

use sim::{GlobalPlanner, Outcome, Profile, Row, Scenario, ScenarioError, World, run};
use viz::Table;

/// The scenario files of the replay, in order.
pub const FILES: [&str; 3] = ["1-free.ron", "2-static.ron", "3-person.ron"];

/// One claim, checked: `viz`'s, the one type of every seed's replay.
pub use viz::Claim;

/// The replay's runs and claims.
#[derive(Debug)]
pub struct Seed004 {
    /// Seed used.
    pub seed: u64,
    /// The navigation stack's values.
    pub profile: Profile,
    /// Each scenario with its world and outcome.
    pub runs: Vec<(Scenario, World, Outcome)>,
    /// Claims.
    pub claims: Vec<Claim>,
    /// Wall-clock seconds the three runs took (not part of any claim).
    pub elapsed_s: f64,
}

/// Episodes where `f(row)` holds, as (start index, end index) ranges.
fn episodes(rows: &[Row], f: impl Fn(&Row) -> bool) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (k, r) in rows.iter().enumerate() {
        match (f(r), start) {
            (true, None) => start = Some(k),
            (false, Some(s)) => {
                out.push((s, k));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, rows.len()));
    }
    out
}

/// Start times of abrupt changes of v: maximal runs of samples from which v changes by
/// at least 0.1 m/s within the next 0.5 s, each run counted once, between 2 s after the
/// start and 2 s before the end.
#[must_use]
pub fn abrupt_v_changes(rows: &[Row]) -> Vec<f64> {
    let end = rows.last().map_or(0.0, |r| r.t);
    let mut times: Vec<f64> = Vec::new();
    let mut inside = false;
    for (k, r) in rows.iter().enumerate() {
        if r.t < 2.0 || r.t > end - 2.0 {
            inside = false;
            continue;
        }
        let abrupt = rows[k..]
            .iter()
            .take_while(|q| q.t <= r.t + 0.5)
            .any(|q| (q.v - r.v).abs() >= 0.1);
        if abrupt && !inside {
            times.push(r.t);
        }
        inside = abrupt;
    }
    times
}

/// Sign changes of omega among samples with abs(omega) > 0.05.
#[must_use]
pub fn omega_reversals(rows: &[Row]) -> usize {
    let signs: Vec<bool> = rows
        .iter()
        .filter(|r| r.omega.abs() > 0.05)
        .map(|r| r.omega > 0.0)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// Scenario 2's claims: two right turns, peaking near 0.3 and 0.75 rad/s.
fn static_claims(o2: &Outcome) -> [Claim; 2] {
    let rows2 = &o2.trace.rows;
    let right = episodes(rows2, |r| r.omega < -0.1);
    let peaks: Vec<(f64, f64)> = right
        .iter()
        .map(|&(a, b)| {
            let k = (a..b)
                .min_by(|&i, &j| rows2[i].omega.total_cmp(&rows2[j].omega))
                .unwrap_or(a);
            (rows2[k].t, -rows2[k].omega)
        })
        .collect();
    let peak_text = peaks
        .iter()
        .map(|(t, w)| format!("{w:.2} rad/s at {t:.1} s"))
        .collect::<Vec<_>>()
        .join(", ");
    let turns = Claim {
        text: "scenario 2: the robot turns right twice to avoid the obstacles".into(),
        paper: "two right turns".into(),
        ours: format!("{} right-turn episode(s): {peak_text}", peaks.len()),
        held: peaks.len() == 2,
    };
    let peaks_claim = Claim {
        text: "scenario 2: right-turn peaks of 0.3 and 0.75 rad/s".into(),
        paper: "0.3, 0.75 rad/s".into(),
        ours: peaks
            .iter()
            .take(2)
            .map(|(_, w)| format!("{w:.2}"))
            .collect::<Vec<_>>()
            .join(", "),
        held: peaks.len() >= 2
            && (peaks[0].1 - 0.3).abs() <= 0.15
            && (peaks[1].1 - 0.75).abs() <= 0.15,
    };
    [turns, peaks_claim]
}

/// Runs the three scenarios in `dir` with `seed` on `profile` and checks the claims.
///
/// # Errors
///
/// A scenario file that does not load.
pub fn seed004(dir: &Path, seed: u64, profile: Profile) -> Result<Seed004, ScenarioError> {
    let mut loaded = Vec::new();
    for f in FILES {
        let (mut sc, world) = Scenario::load(&dir.join(f))?;
        profile.apply(&mut sc);
        loaded.push((sc, world));
    }
    let started = std::time::Instant::now();
    let runs: Vec<(Scenario, World, Outcome)> = loaded
        .into_iter()
        .map(|(s, w)| {
            let out = run(&s, &w, seed, GlobalPlanner::Dijkstra);
            (s, w, out)
        })
        .collect();
    let elapsed_s = started.elapsed().as_secs_f64();
    let mut claims = Vec::new();
    let fmt_t = |t: Option<f64>| t.map_or("not reached".to_string(), |t| format!("{t:.1} s"));

    // Scenario 1.
    let (s1, _, o1) = &runs[0];
    let straight = ((s1.goal.0 - s1.start.0).powi(2) + (s1.goal.1 - s1.start.1).powi(2)).sqrt()
        - s1.navigation.goal_tolerance;
    let ratio1 = o1.trace.summary.distance / straight;
    claims.push(Claim {
        text: "scenario 1: a nearly straight path".into(),
        paper: "Fig. 6a".into(),
        ours: format!(
            "driven {:.2} m for {:.2} m straight ({ratio1:.3}x)",
            o1.trace.summary.distance, straight
        ),
        held: o1.trace.summary.reached && ratio1 <= 1.03,
    });
    let t1 = o1.trace.summary.travel_time;
    let mid: Vec<&Row> = o1
        .trace
        .rows
        .iter()
        .filter(|r| r.t >= 2.0 && t1.is_some_and(|t| r.t <= t - 2.0))
        .collect();
    let (vmin, vmax) = mid
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
            (a.min(r.v), b.max(r.v))
        });
    let wmax = mid.iter().map(|r| r.omega.abs()).fold(0.0, f64::max);
    claims.push(Claim {
        text: "scenario 1: stable linear and angular velocity".into(),
        paper: "Fig. 6b-c".into(),
        ours: format!("v in [{vmin:.3}, {vmax:.3}] m/s, max abs(omega) {wmax:.3} rad/s"),
        held: !mid.is_empty() && vmax - vmin < 0.02 && wmax < 0.1,
    });

    claims.extend(static_claims(&runs[1].2));

    // Scenario 3.
    let (_, _, o3) = &runs[2];
    let t3 = o3.trace.summary.travel_time;
    let ratio = match (t1, t3) {
        (Some(a), Some(b)) => Some(b / a),
        _ => None,
    };
    let ratio_text = ratio.map_or("n/a".to_string(), |r| format!("{r:.3}"));
    claims.push(Claim {
        text: "scenario 3: the person makes the trip longer".into(),
        paper: "38.8 s vs 36.4 s".into(),
        ours: format!("{} vs {} (ratio {ratio_text})", fmt_t(t3), fmt_t(t1)),
        held: ratio.is_some_and(|r| r > 1.0),
    });
    claims.push(Claim {
        text: "scenario 3: travel-time ratio 1.066".into(),
        paper: "1.066".into(),
        ours: ratio_text,
        held: ratio.is_some_and(|r| (r - 1.066).abs() <= 0.05),
    });
    let changes = abrupt_v_changes(&o3.trace.rows);
    claims.push(Claim {
        text: "scenario 3: v changes abruptly twice".into(),
        paper: "at 15 s and 20.2 s".into(),
        ours: format!(
            "{} change(s){}",
            changes.len(),
            if changes.is_empty() {
                String::new()
            } else {
                format!(
                    " at {}",
                    changes
                        .iter()
                        .map(|t| format!("{t:.1} s"))
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            }
        ),
        held: changes.len() == 2,
    });
    let rev = omega_reversals(&o3.trace.rows);
    claims.push(Claim {
        text: "scenario 3: omega fluctuates while the robot avoids the person".into(),
        paper: "between 10 s and 25 s".into(),
        ours: format!("{rev} sign change(s) of omega"),
        held: rev >= 2,
    });
    let at_fault: usize = runs
        .iter()
        .map(|(_, _, o)| o.trace.summary.contacts_at_fault)
        .sum();
    claims.push(Claim {
        text: "no contact caused by the robot".into(),
        paper: "(implied)".into(),
        ours: format!("{at_fault} at-fault contact(s)"),
        held: at_fault == 0,
    });
    Ok(Seed004 {
        seed,
        profile,
        runs,
        claims,
        elapsed_s,
    })
}

impl Seed004 {
    /// The report section (Markdown), with figure links relative to the report when
    /// `figures` names the folder they were written to (relative to the report).
    #[must_use]
    pub fn markdown(&self, figures: Option<&str>) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "### Profile `{}` ({})\n",
            self.profile.name(),
            self.runs
                .first()
                .map_or("", |(sc, _, _)| sc.local_planner.name())
        );
        let _ = writeln!(
            s,
            "Three runs of `sim` (Dijkstra, seed {}), scenario files in `scenarios/sim/` with the profile's values; \
             {:.2} s of computing for {:.1} s simulated.\n",
            self.seed,
            self.elapsed_s,
            self.runs
                .iter()
                .map(|(_, _, o)| o.trace.summary.end_time)
                .sum::<f64>()
        );
        let mut table = Table::new([
            "scenario",
            "reached",
            "travel time (s)",
            "distance (m)",
            "stops",
            "re-plans",
            "min gap obstacle (m)",
            "min gap person (m)",
            "contacts at fault / robot stopped / other",
        ]);
        for (sc, _, o) in &self.runs {
            let m = &o.trace.summary;
            table.row([
                sc.name.clone(),
                (if m.reached { "yes" } else { "no" }).to_string(),
                m.travel_time.map_or("-".into(), |t| format!("{t:.2}")),
                format!("{:.2}", m.distance),
                m.stops.to_string(),
                m.replans.to_string(),
                format!("{:.3}", m.min_obstacle_distance),
                m.min_person_distance
                    .map_or("-".into(), |d| format!("{d:.3}")),
                format!(
                    "{} / {} / {}",
                    m.contacts_at_fault, m.contacts_robot_stopped, m.contacts_not_approaching
                ),
            ]);
        }
        s.push_str(&table.to_markdown());
        s.push('\n');
        if let Some(dir) = figures {
            let _ = writeln!(s, "Figures:");
            for (sc, _, _) in &self.runs {
                let _ = writeln!(
                    s,
                    "- {0}: [trajectory]({1}/{0}/trajectory.svg), [v and omega]({1}/{0}/velocity.svg), [animation]({1}/{0}/animation.svg)",
                    sc.name, dir
                );
            }
            s.push('\n');
        }
        s
    }

    /// Writes each run's outputs ([`sim::write_all`]) into `dir/NAME/`.
    ///
    /// # Errors
    ///
    /// [`sim::OutputError`] naming the file.
    pub fn write_figures(&self, dir: &Path) -> Result<(), sim::OutputError> {
        for (sc, w, o) in &self.runs {
            sim::write_all(o, w, &dir.join(&sc.name))?;
        }
        Ok(())
    }
}

/// The figures' folder of `profile` under `figures/` (the `hyplan` profile's keeps the
/// folder of earlier reports).
fn figure_dir(profile: Profile) -> String {
    match profile {
        Profile::Hyplan => "004-navigation".into(),
        p => format!("004-navigation/{}", p.name()),
    }
}

/// The claims of every profile side by side: a row per claim, a verdict per profile.
#[must_use]
pub fn claims_side_by_side(replays: &[(Profile, &[Claim])]) -> String {
    let mut table = Table::new(
        ["claim", "paper"].into_iter().map(String::from).chain(
            replays
                .iter()
                .map(|(p, _)| format!("`{}` profile", p.name())),
        ),
    );
    let rows = replays.first().map_or(0, |(_, c)| c.len());
    for k in 0..rows {
        let first = &replays[0].1[k];
        table.row(
            [first.text.clone(), first.paper.clone()]
                .into_iter()
                .chain(replays.iter().map(|(_, claims)| {
                    claims.get(k).map_or("-".into(), |c| {
                        format!("{}: {}", if c.held { "held" } else { "not held" }, c.ours)
                    })
                })),
        );
    }
    let mut s = table.to_markdown();
    for (p, claims) in replays {
        let _ = write!(
            s,
            "\n`{}` profile: {} of {} held.",
            p.name(),
            viz::claims_held(claims),
            claims.len()
        );
    }
    s.push('\n');
    s
}

/// Runs the replay on every profile, writes its figures under `figures/004-navigation/`,
/// and returns the report section and (claims held, claims) over the profiles.
pub fn section(root: &Path, figures: &Path) -> anyhow::Result<(String, usize, usize)> {
    let mut replays = Vec::new();
    for profile in Profile::ALL {
        let replay = seed004(&root.join("scenarios/sim"), 0, profile)?;
        replay.write_figures(&figures.join(figure_dir(profile)))?;
        eprintln!(
            "004-navigation ({} profile): 3 runs in {:.2} s, claims held {}/{}",
            profile.name(),
            replay.elapsed_s,
            viz::claims_held(&replay.claims),
            replay.claims.len()
        );
        replays.push(replay);
    }
    let mut s = String::new();
    let _ = writeln!(
        s,
        "## `004_3e5a323113b41ded.txt` Figs. 6-9: 004-navigation\n\n\
         The three scenarios on two navigation stacks: `hyplan` (regulated pure pursuit with \
         stop and re-plan, our defaults) and `tutorial` (the values of \
         `rrt_exploration_tutorials`, `base_local_planner`'s trajectory roll-out; each value's \
         source in `sim::Profile`). See `docs/papers/004-dynamic-obstacles.md`.\n"
    );
    let pairs: Vec<(Profile, &[Claim])> = replays
        .iter()
        .map(|r| (r.profile, r.claims.as_slice()))
        .collect();
    s.push_str(&claims_side_by_side(&pairs));
    s.push('\n');
    for r in &replays {
        s.push_str(&r.markdown(Some(&format!("figures/{}", figure_dir(r.profile)))));
    }
    let held = replays.iter().map(|r| viz::claims_held(&r.claims)).sum();
    let total = replays.iter().map(|r| r.claims.len()).sum();
    Ok((s, held, total))
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    #[test]
    fn the_replay_reports_the_seed_and_its_verdicts() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenarios/sim");
        let replay = super::seed004(&dir, 0, sim::Profile::Tutorial).unwrap();
        assert_eq!(replay.runs.len(), 3);
        assert!(
            replay
                .runs
                .iter()
                .all(|(sc, _, _)| sc.controller.rate_hz == 5.0)
        );
        let md = replay.markdown(None);
        assert!(md.contains("### Profile `tutorial` (trajectory)"));
        let table = super::claims_side_by_side(&[(replay.profile, &replay.claims)]);
        assert!(table.contains("`tutorial` profile:"));
    }
}
