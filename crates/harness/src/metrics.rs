//! What one run is scored on.

use hyplan_core::{Plan, PlanError, Point2, Workspace};
use postproc::{Limits, PathMetrics, Smoothing};
use serde::Serialize;

/// The measures of one run, in the scenario's units.
///
/// Failed runs keep `success = false`, their time and explored nodes; path measures are
/// NaN for them so that statistics skip them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunMetrics {
    /// Run index.
    pub run: u32,
    /// Seed of the run's RNG.
    pub seed: u64,
    /// Whether a path was found.
    pub success: bool,
    /// Computation time, seconds (planning plus post-processing).
    pub time_s: f64,
    /// Path length, scenario units.
    pub length: f64,
    /// Path nodes (waypoints, start and goal included) before any dense resampling.
    pub nodes: f64,
    /// Path nodes without the start and the goal (seed 000 counts these: 20 nodes, 21
    /// segments).
    pub inner_nodes: f64,
    /// Path segments (nodes - 1).
    pub segments: f64,
    /// Heading changes over 10 degrees between consecutive segments.
    pub turns: f64,
    /// Nodes explored: tree size for sampling planners, expansions for graph searches
    /// (the papers' "cost (node)").
    pub explored: f64,
    /// Transfer time under the scenario's limits, seconds (NaN without limits).
    pub transfer_time_s: f64,
    /// Smallest distance from the path to an obstacle cell centre, scenario units
    /// (NaN when the workspace does not know clearances).
    pub min_clearance: f64,
    /// The final path (world coordinates), kept for figures.
    #[serde(skip)]
    pub path: Vec<Point2>,
}

impl RunMetrics {
    /// The value of a metric by its name (`time_s`, `length`, `nodes`, `inner_nodes`, `segments`, `turns`,
    /// `explored`, `transfer_time_s`, `min_clearance`, `success`).
    #[must_use]
    pub fn get(&self, metric: &str) -> Option<f64> {
        Some(match metric {
            "time_s" => self.time_s,
            "length" => self.length,
            "nodes" => self.nodes,
            "inner_nodes" => self.inner_nodes,
            "segments" => self.segments,
            "turns" => self.turns,
            "explored" => self.explored,
            "transfer_time_s" => self.transfer_time_s,
            "min_clearance" => self.min_clearance,
            "success" => f64::from(u8::from(self.success)),
            _ => return None,
        })
    }

    /// Names accepted by [`get`](RunMetrics::get).
    pub const METRICS: &'static [&'static str] = &[
        "time_s",
        "length",
        "nodes",
        "inner_nodes",
        "segments",
        "turns",
        "explored",
        "transfer_time_s",
        "min_clearance",
        "success",
    ];
}

/// How runs are scored: the workspace the path must be valid in, the one clearances are
/// measured in, and the post-processing.
pub struct Scoring<'a> {
    /// The planning workspace: smoothing is checked against it.
    pub ws: &'a (dyn Workspace + Sync),
    /// The workspace whose blocked cells are the obstacles for `min_clearance` (the map
    /// with only `Forbidden` blocking, even when the planner avoided the risk band).
    pub obstacles: &'a (dyn Workspace + Sync),
    /// Whether explored nodes are the planner's expansions (graph searches) rather than
    /// its `stats.nodes` (trees, and the hybrids' own counts).
    pub explored_by_expansions: bool,
    /// Post-processing applied to the planner's path.
    pub smoothing: Smoothing,
    /// Robot limits for the transfer time.
    pub limits: Option<Limits>,
    /// Curve sampling spacing, world units (a quarter cell).
    pub spacing: f64,
}

/// Scores one planning outcome: the plan (or the failure), post-processed and checked
/// as `scoring` says, timed under its limits.
///
/// The planning time comes from the plan's stats; smoothing time is added to it.
#[must_use]
pub fn measure(
    scoring: &Scoring<'_>,
    outcome: &Result<Plan, PlanError>,
    run: u32,
    seed: u64,
) -> RunMetrics {
    let Scoring {
        ws,
        obstacles,
        explored_by_expansions,
        smoothing,
        limits,
        spacing,
    } = *scoring;
    let limits = limits.as_ref();
    let nan = f64::NAN;
    let mut m = RunMetrics {
        run,
        seed,
        success: false,
        time_s: nan,
        length: nan,
        nodes: nan,
        inner_nodes: nan,
        segments: nan,
        turns: nan,
        explored: nan,
        transfer_time_s: nan,
        min_clearance: nan,
        path: Vec::new(),
    };
    let plan = match outcome {
        Ok(plan) => plan,
        Err(e) => {
            if let Some(stats) = e.stats() {
                m.time_s = stats.elapsed.as_secs_f64();
                m.explored = explored(stats, explored_by_expansions);
            }
            return m;
        }
    };
    m.explored = explored(&plan.stats, explored_by_expansions);
    let started = std::time::Instant::now();
    let smoothed =
        postproc::smooth_checked(&plan.path, smoothing, spacing, |a, b| ws.segment_free(a, b));
    let smooth_s = started.elapsed().as_secs_f64();
    m.time_s = plan.stats.elapsed.as_secs_f64() + smooth_s;
    let Ok(smoothed) = smoothed else {
        // A curve that cannot be repaired is a failed run: we never report a colliding path.
        return m;
    };
    m.success = true;
    // A planner that returns a dense curve names the nodes it is built on: count nodes,
    // segments and turns on those, as the papers do, and time the curve as a curve.
    let dense = !plan.waypoints.is_empty();
    let metrics = if dense {
        PathMetrics::of(&plan.waypoints)
    } else {
        smoothed.metrics()
    };
    m.length = smoothed.length();
    m.nodes = metrics.nodes as f64;
    m.inner_nodes = metrics.nodes.saturating_sub(2) as f64;
    m.segments = metrics.segments as f64;
    m.turns = metrics.turns as f64;
    if let Some(limits) = limits {
        let timing = if dense {
            postproc::time_curve(&smoothed.points, limits)
        } else {
            smoothed.time(limits)
        };
        m.transfer_time_s = timing.map_or(nan, |t| t.transfer_time);
    }
    m.min_clearance = min_clearance(obstacles, &smoothed.points, spacing);
    m.path = smoothed.points;
    m
}

fn explored(stats: &hyplan_core::PlanStats, by_expansions: bool) -> f64 {
    if by_expansions {
        stats.expansions as f64
    } else {
        stats.nodes as f64
    }
}

/// Smallest clearance along a polyline sampled at most `spacing` apart.
fn min_clearance(ws: &dyn Workspace, path: &[Point2], spacing: f64) -> f64 {
    let mut best = f64::INFINITY;
    for w in path.windows(2) {
        let d = nalgebra::distance(&w[0], &w[1]);
        let steps = (d / spacing).ceil().max(1.0) as usize;
        for k in 0..=steps {
            let p = w[0] + (w[1] - w[0]) * (k as f64 / steps as f64);
            match ws.clearance(p) {
                Some(c) => best = best.min(c),
                None => return f64::NAN,
            }
        }
    }
    if best.is_finite() { best } else { f64::NAN }
}
