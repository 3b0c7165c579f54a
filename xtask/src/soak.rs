//! `cargo xtask soak`: every planner and every smoothing method on seeded generated maps,
//! each path and curve checked by an exact test of its own; and `cargo xtask
//! proptest-soak`: the property tests over and over with fresh seeds.
//!
//! `--maps M` runs a fixed number of maps instead of a time limit, and `--shard K/N` runs
//! the maps `k` of `0..M` with `k mod N = K` only (`harness::bench::shard`'s rule),
//! writing the maps' records and a shard manifest into `--out`; `cargo xtask soak-merge
//! DIR... [--out DIR]` checks that the shards cover one soak exactly once and prints (and
//! writes) the table of the whole soak.
//!
//! The collision check here is written independently of `GridMap::segment_free`: for
//! every segment of a path and every blocked cell near it, an exact separating-axis test
//! between the closed segment and the closed square (the axes x and y, and the
//! segment's normal). A path is "colliding" when any of its segments meets a blocked
//! cell, even at a single corner point, or leaves the map.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use anyhow::{Context as _, bail};
use envmap::GridMap;
use envmap::HardMap;
use harness::PlannerConfig;
use harness::bench::shard::{self, Shard, ShardManifest};
use hyplan_core::{Budget, Goal, Point2, Query, Workspace};
use postproc::Smoothing;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// Options of `cargo xtask soak`.
#[derive(clap::Args)]
pub struct Args {
    /// How long to run, minutes (fractions allowed).
    #[arg(long, default_value_t = 10.0)]
    pub minutes: f64,
    /// Seed of the first map; map k uses seed + k, so a report line replays.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Queries per generated map (every planner and smoothing method runs on each).
    #[arg(long, default_value_t = 8)]
    pub queries: usize,
    /// Replay one map only (its seed as printed in a collision report) and stop.
    #[arg(long, conflicts_with_all = ["maps", "shard"])]
    pub only_map: Option<u64>,
    /// Run this many maps (seeds seed..seed + M) instead of --minutes.
    #[arg(long, value_name = "M")]
    pub maps: Option<u64>,
    /// Run shard K of N of the --maps only (maps k with k mod N = K, K from 0) and write
    /// its records and manifest into --out; `cargo xtask soak-merge` joins the shards.
    #[arg(long, value_name = "K/N", requires = "maps")]
    pub shard: Option<Shard>,
    /// With --shard: the shard's folder.
    #[arg(long, default_value = "soak-out")]
    pub out: PathBuf,
}

/// Options of `cargo xtask soak-merge`.
#[derive(clap::Args)]
pub struct MergeArgs {
    /// The shards' folders (each a `--out` of `cargo xtask soak --shard K/N`).
    #[arg(required = true, value_name = "DIR")]
    pub dirs: Vec<PathBuf>,
    /// Also write the table to DIR/soak.txt.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// The tool name in the shard manifests.
const TOOL: &str = "xtask soak";
/// A shard's records file: a first line with the soak's options, then one map per line.
const RECORDS: &str = "maps.jsonl";

/// What decides a sharded soak's work: its maps and queries.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
struct SoakOptions {
    /// Seed of map 0.
    seed: u64,
    /// Queries per map.
    queries: usize,
    /// Maps.
    maps: u64,
}

/// One map's counts and failures.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
struct MapRecord {
    /// Index of the map (its seed is the soak's seed + k).
    k: u64,
    /// Counts per planner and smoothing method.
    tallies: BTreeMap<String, Tally>,
    /// Collisions and panics, described.
    failures: Vec<String>,
}

/// Map kinds of the soak: the generators' kinds (the 2000 x 2000 floor plan left out:
/// one map would take the time of hundreds of small ones), each also with a risk band,
/// planned around (the band blocks) or through (only Forbidden blocks).
const KINDS: &[HardMap] = &[
    HardMap::Maze,
    HardMap::Spiral,
    HardMap::BugTrap,
    HardMap::NarrowPassage,
    HardMap::Clutter,
    HardMap::Rooms,
];

/// Counts for one planner or one smoothing method.
#[derive(Default, Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
struct Tally {
    /// Plans (or curves) returned and checked.
    checked: u64,
    /// Of which colliding or leaving the map.
    colliding: u64,
    /// Calls that ended in no path (budget, proved disconnection).
    no_path: u64,
    /// Calls that panicked.
    panics: u64,
}

/// Runs the collision soak (or one shard of it).
///
/// # Errors
///
/// When a collision or a panic was found (after the report); a shard's records that
/// cannot be written.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let deadline = Instant::now() + Duration::from_secs_f64(args.minutes.max(0.0) * 60.0);
    let started = Instant::now();
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    if args.shard.is_some() {
        shard::begin_shard(&args.out)?;
    }
    let mut records: Vec<MapRecord> = Vec::new();
    // A panic inside a planner is counted, not printed through the default hook.
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    for k in 0.. {
        if args.maps.is_some_and(|m| k >= m) {
            break;
        }
        if !shard.takes(k) {
            continue;
        }
        let map_seed = args.only_map.unwrap_or(args.seed.wrapping_add(k));
        let mut record = MapRecord {
            k,
            ..MapRecord::default()
        };
        soak_map(
            map_seed,
            args.queries,
            &mut record.tallies,
            &mut record.failures,
        );
        records.push(record);
        if args.only_map.is_some() || (args.maps.is_none() && Instant::now() >= deadline) {
            break;
        }
        if records.len().is_multiple_of(50) {
            let plans: u64 = records
                .iter()
                .flat_map(|r| r.tallies.values())
                .map(|t| t.checked + t.no_path)
                .sum();
            eprintln!(
                "soak: {} maps, {plans} calls, {:.0} s",
                records.len(),
                started.elapsed().as_secs_f64()
            );
        }
    }
    std::panic::set_hook(default_hook);
    let minutes = started.elapsed().as_secs_f64() / 60.0;
    if let (Some(which), Some(maps)) = (args.shard, args.maps) {
        let options = SoakOptions {
            seed: args.seed,
            queries: args.queries,
            maps,
        };
        return write_shard(&args.out, which, options, minutes, &records);
    }
    let first = args.only_map.unwrap_or(args.seed);
    let header = format!(
        "collision soak: {} maps (seeds {first}..{}), {minutes:.1} min, {} queries per map",
        records.len(),
        first + records.len() as u64,
        args.queries
    );
    let (table, failed) = report(&header, &records);
    print!("{table}");
    failed
}

/// The table of a soak's maps (and up to 20 failures), and an error when any path
/// collided or any call panicked.
fn report(header: &str, records: &[MapRecord]) -> (String, anyhow::Result<()>) {
    let mut tallies: BTreeMap<&str, Tally> = BTreeMap::new();
    for (name, t) in records.iter().flat_map(|r| &r.tallies) {
        let sum = tallies.entry(name).or_default();
        sum.checked += t.checked;
        sum.colliding += t.colliding;
        sum.no_path += t.no_path;
        sum.panics += t.panics;
    }
    let mut s = format!("{header}\n");
    let _ = writeln!(
        s,
        "{:<28} {:>10} {:>10} {:>10} {:>8}",
        "planner / smoothing", "checked", "colliding", "no path", "panics"
    );
    let mut total = Tally::default();
    for (name, t) in &tallies {
        let _ = writeln!(
            s,
            "{name:<28} {:>10} {:>10} {:>10} {:>8}",
            t.checked, t.colliding, t.no_path, t.panics
        );
        total.checked += t.checked;
        total.colliding += t.colliding;
        total.no_path += t.no_path;
        total.panics += t.panics;
    }
    let _ = writeln!(
        s,
        "{:<28} {:>10} {:>10} {:>10} {:>8}",
        "total", total.checked, total.colliding, total.no_path, total.panics
    );
    for f in records.iter().flat_map(|r| &r.failures).take(20) {
        let _ = writeln!(s, "FAILURE {f}");
    }
    let verdict = if total.colliding + total.panics > 0 {
        Err(anyhow::anyhow!(
            "{} colliding paths or curves and {} panics",
            total.colliding,
            total.panics
        ))
    } else {
        Ok(())
    };
    (s, verdict)
}

/// Writes a soak shard's records (the options, then one map per line) and manifest.
fn write_shard(
    out: &Path,
    which: Shard,
    options: SoakOptions,
    minutes: f64,
    records: &[MapRecord],
) -> anyhow::Result<()> {
    let mut text = serde_json::to_string(&(options, minutes))?;
    text.push('\n');
    for r in records {
        text.push_str(&serde_json::to_string(r)?);
        text.push('\n');
    }
    let manifest = ShardManifest::new(
        TOOL,
        env!("CARGO_PKG_VERSION"),
        &shard::experiment_hash(&options)?,
        which,
        options.maps,
    );
    shard::finish_shard(out, manifest, RECORDS, text.as_bytes())?;
    println!(
        "soak shard {which}: {} of {} maps in {minutes:.1} min; records in {} \
         (join the shards with `cargo xtask soak-merge DIR...`)",
        records.len(),
        options.maps,
        out.display()
    );
    Ok(())
}

/// Runs `cargo xtask soak-merge`: checks that the shards cover one soak exactly once,
/// then prints (and writes) the whole soak's table.
///
/// # Errors
///
/// Missing, duplicate, foreign or unfinished shards, each named; records that do not
/// match their manifest; a collision or a panic in any shard (after the report).
pub fn merge(args: &MergeArgs) -> anyhow::Result<()> {
    let shards = shard::read_shards(&args.dirs, TOOL)?;
    let mut options: Option<SoakOptions> = None;
    let mut minutes = 0.0;
    let mut records: Vec<MapRecord> = Vec::new();
    for s in &shards {
        let where_ = || format!("{} (shard {})", s.dir.display(), s.manifest.shard);
        let mut lines = s.records.lines();
        let (o, m): (SoakOptions, f64) = serde_json::from_str(lines.next().unwrap_or(""))
            .with_context(|| format!("{}: the options line", where_()))?;
        if options.is_some_and(|x| x != o) {
            bail!("{}: the options differ from the other shards'", where_());
        }
        options = Some(o);
        minutes += m;
        for line in lines {
            let r: MapRecord =
                serde_json::from_str(line).with_context(|| format!("{}: a map", where_()))?;
            if !s.manifest.shard.takes(r.k) || r.k >= o.maps {
                bail!("{}: map {} is not this shard's", where_(), r.k);
            }
            records.push(r);
        }
    }
    let o = options.context("no shard")?;
    records.sort_by_key(|r| r.k);
    let every = records.iter().map(|r| r.k).eq(0..o.maps);
    if !every {
        bail!(
            "the shards' records do not hold every map of 0..{} exactly once",
            o.maps
        );
    }
    let header = format!(
        "collision soak: {} maps (seeds {}..{}), {minutes:.1} min in {} shards, {} queries per map",
        o.maps,
        o.seed,
        o.seed + o.maps,
        shards.len(),
        o.queries
    );
    let (table, failed) = report(&header, &records);
    print!("{table}");
    if let Some(out) = &args.out {
        std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
        let path = out.join("soak.txt");
        std::fs::write(&path, &table).with_context(|| format!("writing {}", path.display()))?;
    }
    failed
}

/// One generated map (kind, step and band from its seed) and `queries` random queries,
/// every planner on each, every smoothing method on each sampling or grid path.
fn soak_map(
    seed: u64,
    queries: usize,
    tallies: &mut BTreeMap<String, Tally>,
    failures: &mut Vec<String>,
) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let kind = KINDS[(seed % KINDS.len() as u64) as usize];
    let step = [1.0, 2.0, 3.0][rng.random_range(0..3)];
    let generated = kind.generate(step, &mut rng);
    // One map in three has a risk band; of those, half plan around it.
    let (map, label) = match rng.random_range(0..6) {
        0 => (
            envmap::with_risk_band(&generated.map, 2.0).avoiding_risk(),
            "band-avoided",
        ),
        1 => (envmap::with_risk_band(&generated.map, 2.0), "band-crossed"),
        _ => (generated.map.clone(), "plain"),
    };
    let where_ = |q: &Query| {
        format!(
            "map seed {seed} ({} step {step} {label}), start ({}, {}), goal ({}, {})",
            kind.name(),
            q.start.x,
            q.start.y,
            q.goal.center().x,
            q.goal.center().y
        )
    };
    for qi in 0..queries {
        let Some(query) = draw_query(&map, step, &mut rng) else {
            continue;
        };
        // Every planner of the registry.
        for config in PlannerConfig::all() {
            let name = config.name();
            let planner = soak_config(config, step).build();
            let plan_seed = seed.wrapping_mul(1000).wrapping_add(qi as u64);
            let mut prng = ChaCha8Rng::seed_from_u64(plan_seed);
            let outcome = catch_unwind(AssertUnwindSafe(|| planner.plan(&map, &query, &mut prng)));
            let tally = tallies.entry(name.to_string()).or_default();
            let plan = match outcome {
                Err(_) => {
                    tally.panics += 1;
                    failures.push(format!("{name} panicked: {}", where_(&query)));
                    continue;
                }
                Ok(Err(_)) => {
                    tally.no_path += 1;
                    continue;
                }
                Ok(Ok(plan)) => plan,
            };
            tally.checked += 1;
            if let Some(why) = path_collision(&map, &plan.path) {
                tally.colliding += 1;
                failures.push(format!("{name}: {why}; {}", where_(&query)));
            }
            // The smoothing methods, on the paths of planners that return polylines.
            if !plan.waypoints.is_empty() || plan.path.len() < 2 {
                continue;
            }
            for method in Smoothing::ALL {
                let key = format!("smooth {}", method.name());
                let smoothed = catch_unwind(AssertUnwindSafe(|| {
                    postproc::smooth_checked(&plan.path, method, 0.25 * map.resolution(), |a, b| {
                        map.segment_free(a, b)
                    })
                }));
                let tally = tallies.entry(key.clone()).or_default();
                match smoothed {
                    Err(_) => {
                        tally.panics += 1;
                        failures.push(format!(
                            "{key} panicked on {name}'s path: {}",
                            where_(&query)
                        ));
                    }
                    Ok(Err(_)) => tally.no_path += 1,
                    Ok(Ok(s)) => {
                        tally.checked += 1;
                        if let Some(why) = path_collision(&map, &s.points) {
                            tally.colliding += 1;
                            failures
                                .push(format!("{key} on {name}'s path: {why}; {}", where_(&query)));
                        }
                    }
                }
            }
        }
    }
}

/// A planner with small budgets so the soak sees many plans: the map's step (for the
/// planners that have one), 3000 iterations and 200 ms (for those that take a budget).
fn soak_config(config: PlannerConfig, step: f64) -> PlannerConfig {
    config
        .with_step(step)
        .with_budget(Budget::iterations(3000).with_time(Duration::from_millis(200)))
}

/// A random query on free points joined through free cells: cell centres, cell corners
/// and edge midpoints (where the boundary rule matters), or anywhere in the cell. The
/// goal is a point or a disc.
fn draw_query(map: &GridMap, step: f64, rng: &mut ChaCha8Rng) -> Option<Query> {
    let (a, b) = envmap::random_query(map, 4.0 * step, rng)?;
    let place = |c: Point2, rng: &mut ChaCha8Rng| {
        let p = match rng.random_range(0..3) {
            0 => c,
            1 => Point2::new(
                c.x + 0.5 * f64::from(rng.random_range(-1i32..=1)),
                c.y + 0.5 * f64::from(rng.random_range(-1i32..=1)),
            ),
            _ => Point2::new(
                c.x + rng.random_range(-0.5..0.5),
                c.y + rng.random_range(-0.5..0.5),
            ),
        };
        if map.is_free(p) { p } else { c }
    };
    let start = place(a, rng);
    let goal = place(b, rng);
    let goal = if rng.random_bool(0.5) {
        Goal::Point(goal)
    } else {
        Goal::disc(goal, step)
    };
    Some(Query::new(start, goal))
}

/// Why `path` collides (a segment meets a blocked closed cell, or a point leaves the
/// map), or `None`.
fn path_collision(map: &GridMap, path: &[Point2]) -> Option<String> {
    let b = map.bounds();
    if let Some(p) = path.iter().find(|p| !b.contains(**p)) {
        return Some(format!("point ({}, {}) outside the map", p.x, p.y));
    }
    if path.len() == 1 {
        return segment_collision(map, path[0], path[0]);
    }
    path.windows(2)
        .find_map(|w| segment_collision(map, w[0], w[1]))
}

/// The first blocked cell (under the map's `blocked_from`) whose closed square the closed
/// segment `a`-`b` meets.
fn segment_collision(map: &GridMap, a: Point2, b: Point2) -> Option<String> {
    let (r, o) = (map.resolution(), map.origin());
    // Cell units; the candidate cells are those of the segment's box, one cell wider
    // each way (a touch on a shared edge belongs to both cells).
    let (ax, ay) = ((a.x - o.x) / r, (a.y - o.y) / r);
    let (bx, by) = ((b.x - o.x) / r, (b.y - o.y) / r);
    let lo = |v: f64| (v.floor() - 1.0).max(0.0) as usize;
    let (i0, i1) = (lo(ax.min(bx)), (ax.max(bx).floor() + 1.0) as usize);
    let (j0, j1) = (lo(ay.min(by)), (ay.max(by).floor() + 1.0) as usize);
    for j in j0..=j1.min(map.height() - 1) {
        for i in i0..=i1.min(map.width() - 1) {
            if map.cell_zone(i, j) >= map.blocked_from
                && segment_meets_square((ax, ay), (bx, by), i, j)
            {
                return Some(format!(
                    "segment ({}, {})-({}, {}) meets blocked cell ({i}, {j})",
                    a.x, a.y, b.x, b.y
                ));
            }
        }
    }
    None
}

/// Whether the closed segment p-q meets the closed square `[i, i+1] x [j, j+1]`:
/// separating axes x, y and the segment's normal; touching counts.
fn segment_meets_square(p: (f64, f64), q: (f64, f64), i: usize, j: usize) -> bool {
    let (x0, x1, y0, y1) = (i as f64, i as f64 + 1.0, j as f64, j as f64 + 1.0);
    if p.0.max(q.0) < x0 || p.0.min(q.0) > x1 || p.1.max(q.1) < y0 || p.1.min(q.1) > y1 {
        return false;
    }
    let side = |x: f64, y: f64| (q.0 - p.0) * (y - p.1) - (q.1 - p.1) * (x - p.0);
    let s = [side(x0, y0), side(x1, y0), side(x0, y1), side(x1, y1)];
    !(s.iter().all(|&v| v > 0.0) || s.iter().all(|&v| v < 0.0))
}

/// Options of `cargo xtask proptest-soak`.
#[derive(clap::Args)]
pub struct PropArgs {
    /// How long to run, minutes (fractions allowed).
    #[arg(long, default_value_t = 10.0)]
    pub minutes: f64,
}

/// The property tests: crate and the test-name filters of its `main` test binary.
const PROPERTY_TESTS: &[(&str, &[&str])] = &[
    ("envmap", &["properties::", "ros_round_trip::"]),
    ("search", &["props::"]),
    ("sampling", &["planners::", "nearest::"]),
    (
        "postproc",
        &[
            "prune_props::",
            "smooth_props::",
            "pchip_props::",
            "spline_props::",
            "timing_props::",
            "errors::",
        ],
    ),
    ("hybrid", &["conformance::"]),
];

/// Runs every property test with a fresh seed per round until the time is up; a failing
/// round prints the seed and the command that replays it (and proptest adds the case to
/// the crate's `proptest-regressions/`, to be committed).
///
/// # Errors
///
/// When any round failed, or cargo could not be run.
pub fn run_proptests(args: &PropArgs) -> anyhow::Result<()> {
    let deadline = Instant::now() + Duration::from_secs_f64(args.minutes.max(0.0) * 60.0);
    let mut rounds = 0u64;
    let mut failed = Vec::new();
    let now = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .unwrap_or_default();
    let mut entropy =
        ChaCha8Rng::seed_from_u64(now.as_nanos() as u64 ^ u64::from(std::process::id()));
    while Instant::now() < deadline {
        let seed: u64 = entropy.random();
        for (krate, filters) in PROPERTY_TESTS {
            let status = Command::new(env!("CARGO"))
                .args(["test", "--quiet", "-p", krate, "--test", "main", "--"])
                .args(filters.iter())
                .env("PROPTEST_RNG_SEED", seed.to_string())
                .status()?;
            if !status.success() {
                let replay = format!(
                    "PROPTEST_RNG_SEED={seed} cargo test -p {krate} --test main -- {}",
                    filters.join(" ")
                );
                println!("FAILED: {replay}");
                failed.push(replay);
            }
        }
        rounds += 1;
        println!("proptest-soak: round {rounds} (seed {seed}) done");
    }
    println!("proptest-soak: {rounds} rounds, {} failed", failed.len());
    if !failed.is_empty() {
        bail!("failing rounds:\n{}", failed.join("\n"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_check_counts_corner_and_edge_contacts() {
        let map = GridMap::from_ascii(
            "
            .#.
            ...
            ",
        )
        .unwrap();
        // Through the lower-left corner (1, 1) of the blocked cell (1, 1).
        let p = [Point2::new(0.5, 0.5), Point2::new(1.0, 1.0)];
        assert!(path_collision(&map, &p).is_some());
        // Along its bottom edge.
        let p = [Point2::new(0.2, 1.0), Point2::new(2.8, 1.0)];
        assert!(path_collision(&map, &p).is_some());
        // Just below it.
        let p = [Point2::new(0.2, 0.99), Point2::new(2.8, 0.99)];
        assert!(path_collision(&map, &p).is_none());
        // Out of the map.
        let p = [Point2::new(0.5, 0.5), Point2::new(3.5, 0.5)];
        assert!(path_collision(&map, &p).is_some());
    }

    /// Shards of a soak merge to its table: every planner called as often (the counts of
    /// checked and no-path calls may move with the clock: 200 ms budgets).
    #[test]
    fn soak_shards_merge_to_the_whole_soak() {
        let root = std::env::temp_dir().join(format!("xtask-soak-{}", std::process::id()));
        let args = |shard: Option<Shard>, out: PathBuf| Args {
            minutes: 0.0,
            seed: 3,
            queries: 1,
            only_map: None,
            maps: Some(5),
            shard,
            out,
        };
        let dirs: Vec<PathBuf> = Shard::all(2)
            .map(|s| root.join(s.index().to_string()))
            .collect();
        for (s, d) in Shard::all(2).zip(&dirs) {
            run(&args(Some(s), d.clone())).unwrap();
        }
        let calls = |records: &[MapRecord]| {
            let mut c: BTreeMap<String, u64> = BTreeMap::new();
            for (n, t) in records.iter().flat_map(|r| &r.tallies) {
                *c.entry(n.clone()).or_default() += t.checked + t.no_path + t.panics;
            }
            c
        };
        let mut merged = Vec::new();
        for d in &dirs {
            let text = std::fs::read_to_string(d.join(RECORDS)).unwrap();
            merged.extend(
                text.lines()
                    .skip(1)
                    .map(|l| serde_json::from_str::<MapRecord>(l).unwrap()),
            );
        }
        let whole: Vec<MapRecord> = (0..5)
            .map(|k| {
                let mut r = MapRecord {
                    k,
                    ..MapRecord::default()
                };
                soak_map(3 + k, 1, &mut r.tallies, &mut r.failures);
                r
            })
            .collect();
        assert_eq!(calls(&merged), calls(&whole));
        let out = root.join("merged");
        merge(&MergeArgs {
            dirs: dirs.clone(),
            out: Some(out.clone()),
        })
        .unwrap();
        let table = std::fs::read_to_string(out.join("soak.txt")).unwrap();
        assert!(
            table.starts_with("collision soak: 5 maps (seeds 3..8)"),
            "{table}"
        );
        // A missing shard is named.
        let err = merge(&MergeArgs {
            dirs: dirs[..1].to_vec(),
            out: None,
        })
        .unwrap_err();
        assert!(err.to_string().contains("missing shard 1/2"), "{err}");
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn a_short_soak_finds_nothing() {
        let mut tallies = BTreeMap::new();
        let mut failures = Vec::new();
        for seed in 0..KINDS.len() as u64 {
            soak_map(seed, 1, &mut tallies, &mut failures);
        }
        assert!(failures.is_empty(), "{failures:?}");
        assert!(tallies.values().map(|t| t.checked).sum::<u64>() > 0);
    }
}
