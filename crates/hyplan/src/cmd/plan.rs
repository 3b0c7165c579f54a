//! `hyplan plan`: load a map, plan from a start to a goal with a sampling planner, print
//! one record per run (human text, CSV in the OMPL peer's columns, or JSON lines) and draw
//! an SVG.
//!
//! Coordinates, step and goal radius are in the input's own frame and units
//! ([`envmap::InputFrame`]): cells with y counted down from the top row for pictures and
//! MovingAI `.map` files (the frame of image viewers, MovingAI and the OMPL peer), metres
//! with y up for ROS YAML maps.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use anyhow::Context as _;
use envmap::{GridMap, InputFrame, LoadOptions};
use harness::stats::median;
use hyplan_core::{Goal, Plan, PlanError, Point2, Query};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;
use serde::Serialize;

use super::{input_scale, parse_xy};
use crate::planners::{self, PlannerFlags};

/// Options of `hyplan plan`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The map: a picture (PNG, PGM, PPM), a ROS map_server `.yaml`, a MovingAI `.map` or
    /// a ROS 2 bag (`.mcap`: its last `nav_msgs/msg/OccupancyGrid` on `--topic`).
    #[arg(long)]
    pub map: PathBuf,
    /// ROS 2 bags: the topic of the map.
    #[arg(long, default_value = envmap::DEFAULT_MAP_TOPIC)]
    pub topic: String,
    /// Write the first run as a ROS 2 bag (MCAP) for Foxglove or RViz: the map on /map
    /// (free 0, high-risk 50, forbidden 100), the path on /plan, the smoothed curve on
    /// /plan_smoothed, the trees on /tree (LINE_LIST markers); world frame `map`, stamp 0.
    #[arg(long, value_name = "FILE")]
    pub mcap: Option<PathBuf>,
    /// Start `X,Y` in the input's frame (pictures and `.map`: column, row from the top).
    #[arg(long, value_parser = parse_xy, allow_hyphen_values = true)]
    pub start: (f64, f64),
    /// Goal `X,Y` in the input's frame.
    #[arg(long, value_parser = parse_xy, allow_hyphen_values = true)]
    pub goal: (f64, f64),
    /// Planner `NAME[:key=value,...]`, NAME one of the registry's (listed below). The pairs
    /// set any field of the planner (`hyplan planners` lists them with their defaults),
    /// over the flags below.
    #[arg(long, default_value = "rrt", value_parser = planners::SpecParser::default())]
    pub planner: String,
    /// Maximum edge length in the input's units [default: 5% of the map's diagonal;
    /// rrt-astar-bt: seed 000's 40 px in proportion to the map, 3.5% of its diagonal].
    #[arg(long, allow_hyphen_values = true)]
    pub step: Option<f64>,
    /// Probability of sampling the goal (rrt and rrt-star), in [0, 1].
    #[arg(long, default_value_t = 0.05, allow_hyphen_values = true)]
    pub goal_bias: f64,
    /// Goal tolerance in the input's units; 0 means the path must end exactly on the goal.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub goal_radius: f64,
    /// Iteration cap per run (samples drawn, cells expanded) [default: the planner's rule:
    /// grid searches run to the end; sampling planners take 100000 samples, or one per four
    /// map cells when that is more; unlimited with --time-limit alone].
    #[arg(long)]
    pub max_iter: Option<u64>,
    /// Wall-clock limit per run, seconds.
    #[arg(long, allow_hyphen_values = true)]
    pub time_limit: Option<f64>,
    /// Number of runs; run k uses the seed SplitMix64(seed) output k + 1.
    #[arg(long, default_value_t = 1)]
    pub runs: u64,
    /// Base seed of the runs.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Print CSV: planner,run,solved,exact,time_s,length,states_in_path,graph_vertices.
    #[arg(long, conflicts_with = "json")]
    pub csv: bool,
    /// Print one JSON object per run, one per line (path in the input's frame).
    #[arg(long)]
    pub json: bool,
    /// Draw the map zones, the tree(s) and the path of the first run to this SVG file.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Pictures: luminance threshold, darker pixels are obstacles.
    #[arg(long, default_value_t = 100)]
    pub threshold: u8,
    /// Radius of the high-risk band around obstacles, in the input's units
    /// [default: 20 cells for pictures, none for ROS and MovingAI maps].
    #[arg(long, allow_hyphen_values = true)]
    pub safety_radius: Option<f64>,
    /// Treat the high-risk band as blocked too (by default only forbidden cells block).
    #[arg(long)]
    pub avoid_risk: bool,
    /// Post-processing of each path: none, prune (greedy shortcut), pchip (pairwise node
    /// reduction then PCHIP), bspline (shortcut then a clamped cubic B-spline on the nodes),
    /// bspline-interp (through the nodes). Curves are checked a quarter cell apart against
    /// the zones the planner avoided, repaired where they collide, never returned colliding.
    #[arg(long, default_value = "none")]
    pub smooth: postproc::Smoothing,
    /// Robot speed limit, input units per second (with --wmax and --amax: transfer time).
    #[arg(long, allow_hyphen_values = true, requires_all = ["wmax", "amax"])]
    pub vmax: Option<f64>,
    /// Robot turn-rate limit, rad/s.
    #[arg(long, allow_hyphen_values = true, requires_all = ["vmax", "amax"])]
    pub wmax: Option<f64>,
    /// Robot acceleration limit, input units per second squared.
    #[arg(long, allow_hyphen_values = true, requires_all = ["vmax", "wmax"])]
    pub amax: Option<f64>,
    /// Memory limit: maps with more cells (width x height) are refused before loading.
    #[arg(long, value_name = "N", default_value_t = envmap::DEFAULT_MAX_CELLS)]
    pub max_cells: usize,
}

/// How a user raises a spent budget, named in the "no path within the budget" message.
const RAISE_BUDGET: &str = "--max-iter N, --time-limit S, or --planner NAME:max_iterations=N";

/// What one run produced; one CSV row, one JSON line, one human line.
#[derive(Debug, Clone, Serialize)]
pub struct RunRecord {
    /// Planner name (without the `key=value` pairs given to `--planner`).
    pub planner: String,
    /// Run index, from 0.
    pub run: u64,
    /// The run's seed (derived from `--seed` and the run index).
    pub seed: u64,
    /// Whether a path was found.
    pub solved: bool,
    /// Whether the path reaches the goal region (always equal to `solved`: no approximate
    /// paths are returned; kept for the OMPL peer's columns).
    pub exact: bool,
    /// Wall time of the planner call, seconds.
    pub time_s: f64,
    /// Path length in the input's units.
    pub length: Option<f64>,
    /// Number of path points.
    pub states_in_path: Option<usize>,
    /// Nodes in the tree(s).
    pub nodes: u64,
    /// Iterations done.
    pub iterations: u64,
    /// Edge checks done.
    pub collision_checks: u64,
    /// The path in the input's frame.
    pub path: Vec<[f64; 2]>,
    /// With `--smooth` other than `none`: the final curve, points at most a quarter cell
    /// apart, in the input's frame.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub smoothed: Option<Vec<[f64; 2]>>,
    /// Heading changes over 10 degrees between consecutive segments of the final path's
    /// nodes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub turns: Option<usize>,
    /// Time to follow the final path from rest to rest under --vmax/--wmax/--amax, s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub transfer_time_s: Option<f64>,
    /// When no path was found: why.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub no_path: Option<harness::NoPathRecord>,
}

/// What the flags resolve to before any run: the map, its frame, the query and the
/// planner, all checked.
struct Setup {
    map: GridMap,
    /// How long the map's preparation took (the edge checks' table for planners that
    /// check segments, the search's tables for grid searches).
    preparation: Option<Duration>,
    frame: InputFrame,
    /// World units per input unit.
    scale: f64,
    query: Query,
    config: registry::PlannerConfig,
    planner: Box<dyn hyplan_core::Planner>,
    limits: Option<postproc::Limits>,
}

/// One run's record, its plan and, when smoothed, its curve (world frame).
struct Outcome {
    record: RunRecord,
    plan: Option<Plan>,
    curve: Option<Vec<Point2>>,
    error: Option<PlanError>,
}

/// Runs `hyplan plan`: checks the flags, runs, prints each record, then the summary and
/// the SVG.
///
/// # Errors
///
/// Unreadable maps, bad flags, a start or goal outside the map or blocked, bad planner
/// parameters.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    let setup = check_args(args)?;
    if args.csv {
        outln!("planner,run,solved,exact,time_s,length,states_in_path,graph_vertices")?;
    }
    // Records grow with the runs done, not with the number asked for.
    let mut records = Vec::with_capacity(args.runs.min(1024) as usize);
    let mut first: Option<Outcome> = None;
    for run in 0..args.runs {
        let outcome = run_once(args, &setup, run)?;
        print_record(args, &outcome.record, outcome.error.as_ref())?;
        records.push(outcome.record.clone());
        if run == 0 {
            first = Some(outcome);
        }
    }
    let solved = records.iter().filter(|r| r.solved).count();
    if !args.csv && !args.json && args.runs > 1 {
        print_summary(&records)?;
        if let Some(t) = setup.preparation {
            outln!(
                "map prepared for the planner in {:.3} ms, once, not in the run times",
                t.as_secs_f64() * 1e3
            )?;
        }
    }
    if let Some(path) = &args.mcap {
        let plan = first.as_ref().and_then(|o| o.plan.as_ref());
        let curve = first.as_ref().and_then(|o| o.curve.as_deref());
        write_bag(path, &setup.map, setup.frame, plan, curve)?;
    }
    if let Some(svg_path) = &args.svg {
        let plan = first.as_ref().and_then(|o| o.plan.as_ref());
        let curve = first.as_ref().and_then(|o| o.curve.as_deref());
        harness::Scene::new(&setup.map, &setup.query)
            .trees(plan.map_or(&[], |p| &p.trees))
            .path(plan.map_or(&[], |p| &p.path))
            .curve(curve.unwrap_or(&[]))
            .write_svg(svg_path)?;
    }
    Ok(if solved == records.len() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(crate::EXIT_NO_PATH)
    })
}

/// Loads the map and turns the flags into a checked query and planner, before any run.
fn check_args(args: &Args) -> anyhow::Result<Setup> {
    let opts = LoadOptions {
        threshold: args.threshold,
        safety_radius: args.safety_radius,
        max_cells: args.max_cells,
        ..LoadOptions::default()
    };
    let loaded = super::load_map_topic(&args.map, &args.topic, &opts)
        .with_context(|| format!("loading {}", args.map.display()))?;
    let frame = loaded.frame;
    let map = if args.avoid_risk {
        loaded.map.avoiding_risk()
    } else {
        loaded.map
    };
    let scale = input_scale(&frame);

    if args.runs == 0 {
        anyhow::bail!("--runs 0: must be at least 1");
    }
    let time_limit = args
        .time_limit
        .map(|t| {
            Duration::try_from_secs_f64(t)
                .ok()
                .filter(|d| !d.is_zero())
                .with_context(|| format!("--time-limit {t}: must be a positive number of seconds"))
        })
        .transpose()?;
    let flags = PlannerFlags {
        map_diagonal: Some(map.bounds().diagonal()),
        step: args.step.map(|s| s * scale),
        goal_bias: args.goal_bias,
        goal_radius: args.goal_radius * scale,
        max_iterations: args.max_iter,
        time_limit,
    };
    let limits = match (args.vmax, args.wmax, args.amax) {
        (Some(v), Some(w), Some(a)) => Some(
            postproc::Limits::new(v * scale, w, a * scale)
                .map_err(|e| anyhow::anyhow!("--vmax/--wmax/--amax: {e}"))?,
        ),
        _ => None,
    };
    if !(0.0..=1.0).contains(&args.goal_bias) {
        anyhow::bail!(
            "--goal-bias {}: invalid parameter goal_bias, must be a probability in [0, 1]",
            args.goal_bias
        );
    }
    let config = planners::configure(&args.planner, &flags)?;
    let planner = config.build();
    if !config.uses_goal_bias() && args.goal_bias != 0.05 && !args.csv && !args.json {
        eprintln!(
            "note: {} has no goal bias; --goal-bias is ignored",
            config.name()
        );
    }

    let start = frame.to_world(args.start.0, args.start.1);
    let goal_center = frame.to_world(args.goal.0, args.goal.1);
    let goal = if args.goal_radius == 0.0 {
        Goal::Point(goal_center)
    } else {
        Goal::disc(goal_center, args.goal_radius * scale)
    };
    let query = Query::new(start, goal);
    query.validate(&map).map_err(|e| match e {
        PlanError::InvalidStart { reason, .. } => anyhow::anyhow!(
            "--start {},{}: {}",
            args.start.0,
            args.start.1,
            frame.refusal(map.bounds(), start, reason)
        ),
        PlanError::InvalidGoal { reason, .. } => anyhow::anyhow!(
            "--goal {},{} (radius {}): {}",
            args.goal.0,
            args.goal.1,
            args.goal_radius,
            frame.refusal(map.bounds(), goal_center, reason)
        ),
        other => anyhow::Error::new(other),
    })?;
    // The map's one-time preparation (the edge checks' table, a grid search's tables,
    // kept with the map), timed apart from the runs.
    let prepared = Instant::now();
    let preparation = harness::prepare_map(&config, &*planner, &map).then(|| prepared.elapsed());
    Ok(Setup {
        map,
        preparation,
        frame,
        scale,
        query,
        config,
        planner,
        limits,
    })
}

/// Run `run`: plan with its seed, score and smooth the plan, and make its record.
fn run_once(args: &Args, setup: &Setup, run: u64) -> anyhow::Result<Outcome> {
    let seed = harness::run_seed(args.seed, run);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let started = Instant::now();
    let outcome = setup.planner.plan(&setup.map, &setup.query, &mut rng);
    let time_s = started.elapsed().as_secs_f64();
    let mut curve = None;
    let record = match &outcome {
        Ok(plan) => {
            let to_input = |pts: &[hyplan_core::Point2]| -> Vec<[f64; 2]> {
                pts.iter()
                    .map(|&p| {
                        let (x, y) = setup.frame.from_world(p);
                        [x, y]
                    })
                    .collect()
            };
            let path = to_input(&plan.path);
            // Curves are checked at most a quarter cell apart against the zones the
            // planner avoided (the map's `blocked_from`).
            let post = harness::post_process(
                plan,
                args.smooth,
                0.25 * setup.map.resolution(),
                setup.limits.as_ref(),
                |a, b| setup.map.segment_free_cells(a, b),
            )
            .map_err(|e| anyhow::anyhow!("--smooth {}: {e}", args.smooth.name()))?;
            if args.smooth != postproc::Smoothing::None {
                curve = Some(post.smoothed.points.clone());
            }
            RunRecord {
                planner: setup.config.name().to_string(),
                run,
                seed,
                solved: true,
                exact: true,
                time_s,
                length: Some(plan.length() / setup.scale),
                states_in_path: Some(path.len()),
                nodes: plan.stats.nodes,
                iterations: plan.stats.iterations,
                collision_checks: plan.stats.collision_checks,
                path,
                smoothed: (args.smooth != postproc::Smoothing::None)
                    .then(|| to_input(&post.smoothed.points)),
                turns: Some(post.metrics.turns),
                transfer_time_s: post.transfer_time_s,
                no_path: None,
            }
        }
        Err(e) if e.is_no_path() => {
            let stats = e.stats().copied().unwrap_or_default();
            RunRecord {
                planner: setup.config.name().to_string(),
                run,
                seed,
                solved: false,
                exact: false,
                time_s,
                length: None,
                states_in_path: None,
                nodes: stats.nodes,
                iterations: stats.iterations,
                collision_checks: stats.collision_checks,
                path: Vec::new(),
                smoothed: None,
                turns: None,
                transfer_time_s: None,
                no_path: Some(
                    harness::NoPathRecord::new(e, setup.scale)
                        .with_budget(setup.config.budget_on(&setup.map), RAISE_BUDGET),
                ),
            }
        }
        Err(e) => return Err(anyhow::Error::new(e.clone()).context("planning")),
    };
    let error = outcome.as_ref().err().cloned();
    Ok(Outcome {
        record,
        plan: outcome.ok(),
        curve,
        error,
    })
}

fn print_record(args: &Args, r: &RunRecord, err: Option<&PlanError>) -> anyhow::Result<()> {
    if args.csv {
        let opt = |v: Option<f64>| v.map(|v| format!("{v:.6}")).unwrap_or_default();
        outln!(
            "{},{},{},{},{:.6},{},{},{}",
            r.planner,
            r.run,
            u8::from(r.solved),
            u8::from(r.exact),
            r.time_s,
            opt(r.length),
            r.states_in_path.map(|n| n.to_string()).unwrap_or_default(),
            r.nodes
        )?;
    } else if args.json {
        outln!("{}", serde_json::to_string(r)?)?;
    } else if r.solved {
        // What was computed beyond the path: turns always, the curve and the transfer
        // time when asked for.
        let mut extra = format!(", {} turns > 10 deg", r.turns.unwrap_or(0));
        if let Some(c) = &r.smoothed {
            extra += &format!(", {} curve ({} points)", args.smooth.name(), c.len());
        }
        if let Some(t) = r.transfer_time_s {
            extra += &format!(", transfer time {t:.3} s");
        }
        outln!(
            "run {} (seed {}): path of length {:.3} ({} points){extra}, {} nodes, {} iterations, {} edge checks, {:.3} ms",
            r.run,
            r.seed,
            r.length.unwrap_or(f64::NAN),
            r.states_in_path.unwrap_or(0),
            r.nodes,
            r.iterations,
            r.collision_checks,
            r.time_s * 1e3
        )?;
    } else {
        outln!(
            "run {} (seed {}): {}, {} nodes, {:.3} ms",
            r.run,
            r.seed,
            r.no_path.as_ref().map_or_else(
                || err.map_or_else(|| "no path".to_string(), ToString::to_string),
                |n| n.message.clone()
            ),
            r.nodes,
            r.time_s * 1e3
        )?;
    }
    Ok(())
}

fn print_summary(records: &[RunRecord]) -> std::io::Result<()> {
    let solved: Vec<&RunRecord> = records.iter().filter(|r| r.solved).collect();
    let time = median(records.iter().map(|r| r.time_s)).unwrap_or(f64::NAN);
    let length = median(solved.iter().filter_map(|r| r.length));
    outln!(
        "solved {} of {} runs; median time {:.3} ms; median length {}",
        solved.len(),
        records.len(),
        time * 1e3,
        length.map_or_else(|| "-".to_string(), |l| format!("{l:.3}"))
    )?;
    Ok(())
}

/// Writes the map, the plan, its smoothed curve and the trees as a ROS 2 bag (frame `map`,
/// every stamp 0). A ROS map whose origin has a yaw goes out turned by it, as it came in,
/// and the paths and trees in its map frame (the frame of the query and of the printed
/// paths); other maps in their world frame.
fn write_bag(
    path: &std::path::Path,
    map: &GridMap,
    frame: InputFrame,
    plan: Option<&Plan>,
    curve: Option<&[Point2]>,
) -> anyhow::Result<()> {
    use bag::{ColorRGBA, Header, Marker, MarkerArray};
    use hyplan_core::Zone;
    let mut out = bag::BagWriter::create(path)?;
    let origin = map.origin();
    let to_map = |p: &Point2| match frame {
        InputFrame::MapFrame { .. } => frame.from_world(*p),
        InputFrame::Cells { .. } | InputFrame::World => (p.x, p.y),
    };
    let grid = bag::OccupancyGrid {
        header: Header::at(0, "map"),
        info: bag::MapMetaData {
            resolution: map.resolution() as f32,
            width: u32::try_from(map.width())?,
            height: u32::try_from(map.height())?,
            origin: bag::Pose::planar(origin.x, origin.y, frame.yaw()),
            ..bag::MapMetaData::default()
        },
        data: map
            .zones()
            .iter()
            .map(|z| match z {
                Zone::Free => 0,
                Zone::Risk => 50,
                Zone::Forbidden => 100,
            })
            .collect(),
    };
    out.write("/map", 0, &grid)?;
    let xy = |pts: &[Point2]| pts.iter().map(to_map).collect::<Vec<_>>();
    if let Some(plan) = plan {
        out.write("/plan", 0, &bag::Path::planar(0, "map", xy(&plan.path)))?;
        let blue = ColorRGBA {
            r: 0.2,
            g: 0.4,
            b: 1.0,
            a: 0.6,
        };
        let width = 0.3 * map.resolution();
        let markers =
            plan.trees
                .iter()
                .enumerate()
                .map(|(k, tree)| {
                    let edges =
                        tree.parent.iter().enumerate().filter_map(|(i, p)| {
                            p.map(|p| [tree.points[p as usize], tree.points[i]])
                        });
                    let points = edges.flatten().map(|p| to_map(&p));
                    Marker::planar(
                        Header::at(0, "map"),
                        "tree",
                        k as i32,
                        Marker::LINE_LIST,
                        width,
                        blue,
                        points,
                    )
                })
                .collect();
        out.write("/tree", 0, &MarkerArray { markers })?;
    }
    if let Some(curve) = curve {
        out.write("/plan_smoothed", 0, &bag::Path::planar(0, "map", xy(curve)))?;
    }
    out.finish()?;
    Ok(())
}
