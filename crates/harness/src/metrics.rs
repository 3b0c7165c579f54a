//! What one run is scored on.

use hyplan_core::{Plan, PlanError, Point2, Workspace};
use postproc::{Limits, PathMetrics, Smoothing};
use serde::{Deserialize, Serialize};

/// The measures of one run, in the scenario's units.
///
/// Failed runs keep `success = false`, their time and explored nodes; path measures are
/// NaN for them so that statistics skip them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunMetrics {
    /// Run index.
    pub run: u32,
    /// Seed of the run's RNG.
    pub seed: u64,
    /// Whether a path was found.
    pub success: bool,
    /// Computation time, seconds (planning plus post-processing).
    pub time_s: f64,
    /// CPU time of the planning call on its thread, seconds (the planner's own smoothing
    /// included, the harness's post-processing not): what time claims are decided on, as
    /// it does not count the time other processes hold the core. NaN where the platform
    /// gives no thread CPU clock.
    pub cpu_time_s: f64,
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
    /// The planner's trees, kept for run 0 only (for figures); empty otherwise.
    #[serde(skip)]
    pub trees: Vec<hyplan_core::Tree>,
}

impl RunMetrics {
    /// The value of a metric by its name (`time_s`, `cpu_time_s`, `length`, `nodes`, `inner_nodes`, `segments`, `turns`,
    /// `explored`, `transfer_time_s`, `min_clearance`, `success`).
    #[must_use]
    pub fn get(&self, metric: &str) -> Option<f64> {
        Some(match metric {
            "time_s" => self.time_s,
            "cpu_time_s" => self.cpu_time_s,
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
        "cpu_time_s",
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
        cpu_time_s: nan,
        length: nan,
        nodes: nan,
        inner_nodes: nan,
        segments: nan,
        turns: nan,
        explored: nan,
        transfer_time_s: nan,
        min_clearance: nan,
        path: Vec::new(),
        trees: Vec::new(),
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
    let processed = post_process(plan, smoothing, spacing, limits, |a, b| {
        ws.segment_free(a, b)
    });
    m.time_s = plan.stats.elapsed.as_secs_f64() + started.elapsed().as_secs_f64();
    let Ok(processed) = processed else {
        // A curve that cannot be repaired is a failed run: we never report a colliding path.
        return m;
    };
    m.success = true;
    let metrics = processed.metrics;
    m.length = processed.smoothed.length();
    m.nodes = metrics.nodes as f64;
    m.inner_nodes = metrics.nodes.saturating_sub(2) as f64;
    m.segments = metrics.segments as f64;
    m.turns = metrics.turns as f64;
    m.transfer_time_s = processed.transfer_time_s.unwrap_or(nan);
    m.min_clearance = min_clearance(obstacles, &processed.smoothed.points);
    m.path = processed.smoothed.points;
    m
}

/// What post-processing made of one plan.
#[derive(Debug, Clone)]
pub struct Processed {
    /// The checked final curve (samples at most `spacing` apart).
    pub smoothed: postproc::Smoothed,
    /// Length, nodes, segments and turns of the final path's nodes.
    pub metrics: PathMetrics,
    /// Transfer time under the limits, s (`None` without limits).
    pub transfer_time_s: Option<f64>,
}

/// Post-processes a plan as the harness and `hyplan plan` both do: smooths it with
/// `method` (checked with `segment_free` at most `spacing` apart), measures its nodes and
/// times it under `limits`.
///
/// A planner that returns a dense curve names the nodes it is built on
/// ([`Plan::waypoints`]); left as it is (`Smoothing::None`), such a path is counted on those
/// nodes, as the papers count, and timed as a curve rather than as a polyline that stops
/// at every sample. Asked for another smoothing, such a planner's nodes are fitted with
/// `method` in place of its own curve: a plan is smoothed once, never a curve smoothed
/// again.
///
/// # Errors
///
/// The smoothing's or the timing's [`postproc::PostprocError`].
pub fn post_process(
    plan: &Plan,
    method: Smoothing,
    spacing: f64,
    limits: Option<&Limits>,
    segment_free: impl FnMut(Point2, Point2) -> bool,
) -> Result<Processed, postproc::PostprocError> {
    let curve_plan = !plan.waypoints.is_empty();
    let input = if curve_plan && method != Smoothing::None {
        &plan.waypoints
    } else {
        &plan.path
    };
    let smoothed = postproc::smooth_checked(input, method, spacing, segment_free)?;
    let as_curve = curve_plan && method == Smoothing::None;
    let metrics = if as_curve {
        PathMetrics::of(&plan.waypoints)
    } else {
        smoothed.metrics()
    };
    let transfer_time_s = match limits {
        None => None,
        Some(l) if as_curve => Some(postproc::time_curve(&smoothed.points, l)?.transfer_time),
        Some(l) => Some(smoothed.time(l)?.transfer_time),
    };
    Ok(Processed {
        smoothed,
        metrics,
        transfer_time_s,
    })
}

fn explored(stats: &hyplan_core::PlanStats, by_expansions: bool) -> f64 {
    if by_expansions {
        stats.expansions as f64
    } else {
        stats.nodes as f64
    }
}

/// Smallest clearance over the samples of a checked curve (they are at most a quarter
/// cell apart, so the samples themselves are the scan); NaN when the workspace does not
/// know clearances.
fn min_clearance(ws: &dyn Workspace, samples: &[Point2]) -> f64 {
    let mut best = f64::INFINITY;
    for &p in samples {
        match ws.clearance(p) {
            Some(c) => best = best.min(c),
            None => return f64::NAN,
        }
    }
    if best.is_finite() { best } else { f64::NAN }
}

#[cfg(test)]
mod tests {
    use nalgebra::point;

    use super::*;

    /// A plan that is already a curve is smoothed from its nodes, not smoothed again.
    #[test]
    fn a_curve_plan_is_smoothed_from_its_nodes_once() {
        let waypoints = vec![point![0.0, 0.0], point![4.0, 0.0], point![4.0, 4.0]];
        // The planner's own "curve", here with a bump off the L that the oracle below
        // refuses: smoothing it again would fail, smoothing the nodes does not.
        let mut path = postproc::densify(&waypoints, 0.1);
        path.insert(20, point![2.0, 0.5]);
        let plan = Plan {
            cost: hyplan_core::path_length(&path),
            path,
            trees: Vec::new(),
            waypoints: waypoints.clone(),
            stats: hyplan_core::PlanStats::default(),
        };
        // Nothing but the L's own segments is free, so pruning keeps the corner.
        let leg = |p: Point2, horizontal: bool| {
            let span = -1e-6..=4.0 + 1e-6;
            if horizontal {
                p.y.abs() < 1e-6 && span.contains(&p.x)
            } else {
                (p.x - 4.0).abs() < 1e-6 && span.contains(&p.y)
            }
        };
        let free = |a: Point2, b: Point2| {
            (leg(a, true) && leg(b, true)) || (leg(a, false) && leg(b, false))
        };
        let p = post_process(&plan, Smoothing::Pchip, 0.25, None, free).unwrap();
        assert_eq!(p.smoothed.nodes, waypoints);
        // Left as it is, it is counted on its nodes.
        let p = post_process(&plan, Smoothing::None, 0.25, None, |_, _| true).unwrap();
        assert_eq!(p.metrics.nodes, 3);
    }
}
