//! `hyplan scen`: run a MovingAI scenario file and compare with its optimal lengths.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use anyhow::{Context, bail};
use search::{GridOptions, GridSearch, GridSearchError, JumpPointSearch, ScenEntry};

/// Which grid search runs the scenarios: the registry's grid planners that answer
/// MovingAI queries (8-connected, no corner cutting), by their registry names.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum Algo {
    /// A* with the octile heuristic.
    Astar,
    /// Dijkstra (no heuristic).
    Dijkstra,
    /// Jump point search (A*'s costs, only jump points expanded; the fastest, or as fast
    /// as A* on maps with about a fifth of the cells blocked at random).
    Jps,
}

/// Options of `hyplan scen`.
#[derive(clap::Args)]
pub struct Args {
    /// The MovingAI `.scen` file (version 1; x = column, y = row from the top).
    #[arg(value_name = "SCEN", required_unless_present = "scen")]
    pub scen_file: Option<PathBuf>,
    /// The `.scen` file, as a flag (the same as the argument).
    #[arg(long, conflicts_with = "scen_file")]
    pub scen: Option<PathBuf>,
    /// The MovingAI `.map` file (its file name must match the `.scen`'s map column).
    /// Default: the map the `.scen` names, found next to the `.scen` file (by its file
    /// name, then by the path it gives).
    #[arg(long)]
    pub map: Option<PathBuf>,
    /// The grid planner to run (`--algo` is the old name of this flag); all three find the
    /// optimal lengths. Use jps: on game maps, city streets and rooms it is 5 to 60 times
    /// faster than astar, on mazes 1.3 (1-cell corridors) to 120 times, on random
    /// obstacles up to 1.4 times, but with about a fifth of the cells blocked at random the
    /// two take the same time. Total search time over the queries of generated 512 x 512
    /// maps, JPS against A*: city streets 0.25 against 6.3 ms, 32-cell rooms 0.27 against
    /// 9.4 ms, a maze of 4-cell corridors 2.3 against 42 ms, 35 % blocked at random 11.5
    /// against 15.6 ms, 20 % blocked 7.5 against 8.0 ms; the arena game map's 160 queries
    /// 0.033 against 0.163 ms (`cargo run --release -p hyplan-benches --example
    /// grid_jps_rounds -- 20 --generated`). Over queries of every length on random maps 10
    /// to 40 % blocked, 1,300-1,550 a map (`-- 3 --random-family`): JPS 0.70-0.98 of A*'s
    /// time, 0.98 at 20 %.
    #[arg(long = "planner", alias = "algo", value_enum, default_value_t = Algo::Astar)]
    pub planner: Algo,
    /// Only the first N scenarios.
    #[arg(long)]
    pub limit: Option<usize>,
}

/// The map a `.scen` file names, next to it: its file name in the `.scen`'s directory (the
/// layout of the MovingAI downloads, `arena.map` beside `arena.map.scen`), else the path
/// it gives, from that directory.
fn map_beside(scen_path: &Path, scen: &[ScenEntry]) -> anyhow::Result<PathBuf> {
    let Some(first) = scen.first() else {
        bail!(
            "{} has no scenario, so it names no map: give --map",
            scen_path.display()
        );
    };
    let dir = scen_path.parent().unwrap_or(Path::new(""));
    let tried = [dir.join(first.map_file_name()), dir.join(&first.map)];
    tried
        .iter()
        .find(|p| p.is_file())
        .cloned()
        .with_context(|| {
            format!(
                "{}: the map it names, {:?}, is neither {} nor {}: give --map",
                scen_path.display(),
                first.map,
                tried[0].display(),
                tried[1].display()
            )
        })
}

/// Tolerance on the `.scen` length: the files print about 6 significant digits (old ones)
/// or 8 decimals, so `max(1e-3, 1e-5 * length)`.
fn tolerance(expected: f64) -> f64 {
    f64::max(1e-3, 1e-5 * expected)
}

/// Runs `hyplan scen`: CSV `id,expected,cost,time_us,expanded` on stdout, a summary on
/// stderr. Every scenario is checked before any search runs, so bad input prints no CSV.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    let scen_path = args
        .scen_file
        .as_ref()
        .or(args.scen.as_ref())
        .context("give the .scen file")?;
    let mut scen = search::read_scen(scen_path)?;
    let map_path = match &args.map {
        Some(m) => m.clone(),
        None => map_beside(scen_path, &scen)?,
    };
    let map = envmap::read_movingai(&map_path)
        .with_context(|| format!("cannot load the map {}", map_path.display()))?;
    if let Some(n) = args.limit {
        scen.truncate(n);
    }
    let map_name = map_path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let (w, h) = (map.width(), map.height());
    let at = |s: &ScenEntry| format!("{}:{}", scen_path.display(), s.line);
    let mut queries = Vec::with_capacity(scen.len());
    for s in &scen {
        if s.map_file_name() != map_name {
            bail!(
                "{}: scenario map {:?} does not match --map {}",
                at(s),
                s.map,
                map_path.display()
            );
        }
        if (s.width, s.height) != (w, h) {
            bail!(
                "{}: scenario declares a {} x {} map, {} is {w} x {h}",
                at(s),
                s.width,
                s.height,
                map_path.display()
            );
        }
        let cell = |(x, y): (usize, usize), what: &str| -> anyhow::Result<(usize, usize)> {
            let Some((i, j)) = ScenEntry::to_cell((x, y), h).filter(|&(i, _)| i < w) else {
                bail!("{}: {what} ({x}, {y}) is outside the {w} x {h} map", at(s));
            };
            if !map.cell_free(i, j) {
                bail!("{}: {what} ({x}, {y}) is on a blocked cell", at(s));
            }
            Ok((i, j))
        };
        queries.push((cell(s.start, "start")?, cell(s.goal, "goal")?));
    }

    let mut search = GridSearch::new(&map, GridOptions::default())?;
    // Prepared once (bit rows and columns), like the A* scratch above; not timed either.
    let mut jps = match args.planner {
        Algo::Jps => Some(JumpPointSearch::new(&map, GridOptions::default())?),
        Algo::Astar | Algo::Dijkstra => None,
    };
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    writeln!(out, "id,expected,cost,time_us,expanded")?;
    let (mut total_us, mut expanded, mut pushes, mut mismatches, mut no_path) =
        (0.0, 0u64, 0u64, 0usize, 0usize);
    for (id, (s, &(start, goal))) in scen.iter().zip(&queries).enumerate() {
        let t = Instant::now();
        let found = match &mut jps {
            Some(jps) => jps.search(start, goal),
            None if matches!(args.planner, Algo::Dijkstra) => search.dijkstra(start, goal),
            None => search.astar(start, goal),
        };
        let us = t.elapsed().as_secs_f64() * 1e6;
        total_us += us;
        let (cost, n) = match found {
            Ok(p) => {
                pushes += p.stats.pushes;
                (Some(p.cost), p.stats.expansions)
            }
            Err(GridSearchError::NoPath { stats }) => {
                pushes += stats.pushes;
                (None, stats.expansions)
            }
            Err(e) => return Err(e).with_context(|| at(s)),
        };
        expanded += n;
        match cost {
            Some(c) if (c - s.optimal).abs() <= tolerance(s.optimal) => {}
            Some(c) => {
                mismatches += 1;
                eprintln!(
                    "mismatch: scenario {id} ({}): expected {} found {c:.8}",
                    at(s),
                    s.optimal
                );
            }
            None => {
                mismatches += 1;
                no_path += 1;
                eprintln!(
                    "mismatch: scenario {id} ({}): expected {} found no path",
                    at(s),
                    s.optimal
                );
            }
        }
        let cost = cost.map(|c| format!("{c:.8}")).unwrap_or_default();
        writeln!(out, "{id},{},{cost},{us:.3},{n}", s.optimal)?;
    }
    out.flush()?;
    let n = scen.len();
    eprintln!(
        "scenarios {n}, mismatches {mismatches} (no path {no_path}; tolerance max(1e-3, 1e-5*len)), \
         total search time {:.3} ms (mean {:.2} us), expanded {expanded}, pushed {pushes}{}",
        total_us / 1e3,
        if n > 0 { total_us / n as f64 } else { 0.0 },
        if expanded > 0 {
            format!(", {:.1} ns per expansion", total_us * 1e3 / expanded as f64)
        } else {
            String::new()
        }
    );
    Ok(ExitCode::SUCCESS)
}
