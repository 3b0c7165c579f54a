//! `hyplan.plan` and its result: one planner run as `hyplan plan` makes it.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use hyplan_core::{Goal, Plan, PlanError, Point2, Query};
use numpy::PyArray2;
use postproc::{Limits, PostprocError, Smoothing};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyString, PyType};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;

use crate::map::PyGridMap;
use crate::value_err;

/// One plan's outcome (also carried by `NoPathError.result`).
#[pyclass(frozen, name = "PlanResult", module = "hyplan", get_all)]
pub(crate) struct PlanResult {
    /// Planner name.
    planner: String,
    /// The RNG seed of the run (`harness::run_seed(seed, run)`).
    seed: u64,
    /// Whether a path was found.
    solved: bool,
    /// The path, `(N, 2)`, in the map's input frame (empty when unsolved).
    path: Py<PyArray2<f64>>,
    /// Path length, input units (`nan` when unsolved).
    length: f64,
    /// Wall time of the planner call, s (the map's one-time preparation made before it,
    /// as `hyplan plan` makes it).
    time_s: f64,
    /// Nodes in the tree(s).
    nodes: u64,
    /// Iterations done.
    iterations: u64,
    /// Edge checks done.
    collision_checks: u64,
    /// The smoothed curve when `smooth` was not `"none"`.
    smoothed: Option<Py<PyArray2<f64>>>,
    /// Heading changes over 10 degrees of the final path's nodes.
    turns: Option<usize>,
    /// Rest-to-rest transfer time under `vmax`/`wmax`/`amax`, s.
    transfer_time_s: Option<f64>,
    /// Why no path was found: `{"kind", "cause", "band_radius", "max_safety_radius",
    /// "message"}`, or `None` when solved.
    no_path: Option<Py<PyDict>>,
}

#[pymethods]
impl PlanResult {
    fn __repr__(&self) -> String {
        format!(
            "PlanResult(planner={:?}, solved={}, length={}, nodes={}, time_s={})",
            self.planner, self.solved, self.length, self.nodes, self.time_s
        )
    }
}

/// A Python value as RON text for `PlannerConfig::with_params`.
fn ron_value(v: &Bound<'_, PyAny>) -> PyResult<String> {
    if v.is_none() {
        Ok("None".into())
    } else if v.is_instance_of::<PyBool>() {
        Ok(if v.extract::<bool>()? {
            "true"
        } else {
            "false"
        }
        .into())
    } else if v.is_instance_of::<PyInt>() {
        Ok(v.str()?.to_string())
    } else if v.is_instance_of::<PyFloat>() {
        let f: f64 = v.extract()?;
        // RON reads `2.0`, not `2`, as a float; repr gives that form.
        Ok(v.repr()?.to_string()).map(|s| if f.is_finite() { s } else { format!("{f}") })
    } else if v.is_instance_of::<PyString>() {
        Ok(v.extract::<String>()?)
    } else {
        Err(PyValueError::new_err(format!(
            "parameter value {}: expected a bool, int, float, None or RON text",
            v.repr()?
        )))
    }
}

/// How a Python caller raises a spent budget, named in the "no path within the budget"
/// message.
const RAISE_BUDGET: &str = "max_iter=N, time_limit=S, or max_iterations=N";

/// `NoPathError.result.no_path`: the record `hyplan plan --json` prints, with the budget the
/// run had.
fn no_path_dict<'py>(py: Python<'py>, r: &harness::NoPathRecord) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("kind", r.kind)?;
    d.set_item("cause", r.cause)?;
    d.set_item("band_radius", r.band_radius)?;
    d.set_item("max_safety_radius", r.max_safety_radius)?;
    d.set_item("max_iterations", r.max_iterations)?;
    d.set_item("time_limit_s", r.time_limit_s)?;
    d.set_item("message", &r.message)?;
    Ok(d)
}

/// The inputs of one `plan` call's planner configuration (floats by their bits).
#[derive(PartialEq, Eq)]
struct ConfigKey {
    planner: String,
    step: Option<u64>,
    scale: u64,
    diagonal: u64,
    size: (usize, usize),
    goal_bias: u64,
    goal_radius: u64,
    max_iter: Option<u64>,
    time_limit: Option<Duration>,
    pairs: Vec<(String, String)>,
}

/// The last few configurations `plan` made, most recent first: a call repeated with the
/// same planner, flags and parameters skips the registry's parsing (and the RON round trip
/// of `key=value` parameters, tens of microseconds).
struct ConfigCache(Mutex<Vec<(ConfigKey, registry::PlannerConfig)>>);

impl ConfigCache {
    const CAPACITY: usize = 16;

    fn get(&self, key: &ConfigKey) -> Option<registry::PlannerConfig> {
        let mut entries = self
            .0
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let at = entries.iter().position(|(k, _)| k == key)?;
        entries[..=at].rotate_right(1);
        Some(entries[0].1.clone())
    }

    fn put(&self, key: ConfigKey, config: registry::PlannerConfig) {
        let mut entries = self
            .0
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        entries.truncate(Self::CAPACITY - 1);
        entries.insert(0, (key, config));
    }
}

static CONFIGS: ConfigCache = ConfigCache(Mutex::new(Vec::new()));

/// What `plan` keeps of post-processing.
struct Post {
    /// The checked curve, when a smoothing was asked for.
    smoothed: Option<Vec<Point2>>,
    /// Turns of the final path's nodes.
    turns: usize,
    /// Transfer time under the limits, s.
    transfer_time_s: Option<f64>,
}

/// `harness::post_process`, as `hyplan plan` runs it, with a short cut for `smooth="none"`.
///
/// Left as it is, a polyline plan (and, without limits, a curve plan) needs none of the
/// quarter-cell samples `harness::post_process` builds: it checks the path with
/// `postproc::check_polyline`, the input checks of `postproc::smooth_checked` (the same
/// errors),
/// counts the turns of the plan's nodes and times the polyline on them, which are the
/// figures `post_process` reports. What it skips is the re-check of the samples between
/// the nodes, segments that lie on segments just found free, and the samples' metrics,
/// which nothing here reads: a fixed cost per call of about a millisecond on a 1000-cell
/// path. `tests/test_plan.py` compares the turns and transfer times with the CLI.
fn post_process(
    plan: &Plan,
    method: Smoothing,
    spacing: f64,
    limits: Option<&Limits>,
    mut segment_free: impl FnMut(Point2, Point2) -> bool,
) -> Result<Post, PostprocError> {
    let curve_plan = !plan.waypoints.is_empty();
    if method != Smoothing::None || (curve_plan && limits.is_some()) {
        let p = harness::post_process(plan, method, spacing, limits, segment_free)?;
        return Ok(Post {
            smoothed: (method != Smoothing::None).then_some(p.smoothed.points),
            turns: p.metrics.turns,
            transfer_time_s: p.transfer_time_s,
        });
    }
    let path = &plan.path;
    postproc::check_polyline(path, spacing, &mut segment_free)?;
    let turns = postproc::count_turns(
        plan.nodes(),
        postproc::DEFAULT_TURN_THRESHOLD_DEG.to_radians(),
    );
    let transfer_time_s = match limits {
        None => None,
        Some(l) => Some(postproc::time_polyline(path, l)?.transfer_time),
    };
    Ok(Post {
        smoothed: None,
        turns,
        transfer_time_s,
    })
}

/// Plans from `start` to `goal` on `map`, as `hyplan plan` does for run `run` of `--seed
/// seed` (same flags, same planner names and `key=value` parameters, same result).
#[pyfunction]
#[pyo3(signature = (map, start, goal, planner = "rrt-connect", seed = 0, *, run = 0,
                    step = None, goal_bias = 0.05, goal_radius = 0.0, max_iter = None,
                    time_limit = None, smooth = "none", vmax = None, wmax = None, amax = None,
                    **params))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn plan(
    py: Python<'_>,
    map: &PyGridMap,
    start: (f64, f64),
    goal: (f64, f64),
    planner: &str,
    seed: u64,
    run: u64,
    step: Option<f64>,
    goal_bias: f64,
    goal_radius: f64,
    max_iter: Option<u64>,
    time_limit: Option<f64>,
    smooth: &str,
    vmax: Option<f64>,
    wmax: Option<f64>,
    amax: Option<f64>,
    params: Option<&Bound<'_, PyDict>>,
) -> PyResult<PlanResult> {
    let scale = map.scale();
    let time_limit = time_limit_of(time_limit)?;
    if !(0.0..=1.0).contains(&goal_bias) {
        return Err(PyValueError::new_err(format!(
            "goal_bias {goal_bias}: invalid parameter goal_bias, must be a probability in [0, 1]"
        )));
    }
    let config = config_for(
        map,
        planner,
        (step, goal_bias, goal_radius),
        (max_iter, time_limit),
        params,
    )?;
    let smoothing: Smoothing = smooth
        .parse()
        .map_err(|e| PyValueError::new_err(format!("smooth {smooth:?}: {e}")))?;
    let limits = limits_of(vmax, wmax, amax, scale)?;
    let query = query_of(map, start, goal, goal_radius)?;

    let run_seed = harness::run_seed(seed, run);
    let grid = Arc::clone(&map.map);
    let built = config.build();
    let budget_used = config.budget_on(&*map.map);
    let name = config.name().to_string();
    // The planner runs without the GIL; post-processing too.
    let (outcome, time_s, post) = py.detach(move || {
        // The map's one-time preparation, kept with the map and not timed, as `hyplan
        // plan` makes it: the first call on a map reports what later ones do.
        harness::prepare_map(&config, &*built, &grid);
        let mut rng = ChaCha8Rng::seed_from_u64(run_seed);
        let started = Instant::now();
        let outcome = built.plan(&*grid, &query, &mut rng);
        let time_s = started.elapsed().as_secs_f64();
        let post = outcome.as_ref().ok().map(|p| {
            post_process(
                p,
                smoothing,
                0.25 * grid.resolution(),
                limits.as_ref(),
                |a, b| grid.segment_free_cells(a, b),
            )
        });
        (outcome, time_s, post)
    });
    match outcome {
        Ok(p) => {
            let post = post
                .expect("post-processed when solved")
                .map_err(|e| PyValueError::new_err(format!("smooth {}: {e}", smoothing.name())))?;
            Ok(PlanResult {
                planner: name,
                seed: run_seed,
                solved: true,
                path: map.points_from_world(py, &p.path).unbind(),
                length: p.length() / scale,
                time_s,
                nodes: p.stats.nodes,
                iterations: p.stats.iterations,
                collision_checks: p.stats.collision_checks,
                smoothed: post
                    .smoothed
                    .map(|c| map.points_from_world(py, &c).unbind()),
                turns: Some(post.turns),
                transfer_time_s: post.transfer_time_s,
                no_path: None,
            })
        }
        Err(e) if e.is_no_path() => {
            let stats = e.stats().copied().unwrap_or_default();
            let record =
                harness::NoPathRecord::new(&e, scale).with_budget(budget_used, RAISE_BUDGET);
            let result = PlanResult {
                planner: name,
                seed: run_seed,
                solved: false,
                path: PyArray2::<f64>::zeros(py, [0, 2], false).unbind(),
                length: f64::NAN,
                time_s,
                nodes: stats.nodes,
                iterations: stats.iterations,
                collision_checks: stats.collision_checks,
                smoothed: None,
                turns: None,
                transfer_time_s: None,
                no_path: Some(no_path_dict(py, &record)?.unbind()),
            };
            static NO_PATH_ERROR: PyOnceLock<Py<PyType>> = PyOnceLock::new();
            let cls = NO_PATH_ERROR.import(py, "hyplan", "NoPathError")?;
            Err(PyErr::from_value(cls.call1((record.message, result))?))
        }
        Err(e) => Err(value_err(e)),
    }
}

/// `time_limit` as a duration: positive seconds.
fn time_limit_of(time_limit: Option<f64>) -> PyResult<Option<Duration>> {
    time_limit
        .map(|t| {
            Duration::try_from_secs_f64(t)
                .ok()
                .filter(|d| !d.is_zero())
                .ok_or_else(|| {
                    PyValueError::new_err(format!(
                        "time_limit {t}: must be a positive number of seconds"
                    ))
                })
        })
        .transpose()
}

/// The planner configuration of a `plan` call (from the cache when the same call was
/// made before): `knobs` are step, goal bias and goal radius, `limits` the budget.
fn config_for(
    map: &PyGridMap,
    planner: &str,
    (step, goal_bias, goal_radius): (Option<f64>, f64, f64),
    (max_iter, time_limit): (Option<u64>, Option<Duration>),
    params: Option<&Bound<'_, PyDict>>,
) -> PyResult<registry::PlannerConfig> {
    let scale = map.scale();
    let mut pairs = Vec::new();
    if let Some(params) = params {
        for (k, v) in params.iter() {
            pairs.push((k.extract::<String>()?, ron_value(&v)?));
        }
    }
    // Everything the configuration is made of: the map enters through its scale and its
    // diagonal (the default step); its size too, should a default ever follow it.
    let key = ConfigKey {
        planner: planner.to_string(),
        step: step.map(f64::to_bits),
        scale: scale.to_bits(),
        diagonal: map.map.bounds().diagonal().to_bits(),
        size: (map.map.width(), map.map.height()),
        goal_bias: goal_bias.to_bits(),
        goal_radius: goal_radius.to_bits(),
        max_iter,
        time_limit,
        pairs,
    };
    Ok(match CONFIGS.get(&key) {
        Some(c) => c,
        None => {
            let diagonal = map.map.bounds().diagonal();
            let mut config = registry::PlannerConfig::from_spec(planner, |mut c| {
                c = c.map_sized(diagonal);
                if let Some(step) = step.map(|s| s * scale) {
                    c = c.with_step(step);
                }
                // No max_iter / time_limit: the planner's own budget rule, as on the CLI.
                c = c
                    .with_goal_bias(goal_bias)
                    .with_limits(max_iter, time_limit);
                if goal_radius > 0.0 {
                    c = c.with_goal_radius(goal_radius * scale);
                }
                c
            })
            .map_err(value_err)?;
            if !key.pairs.is_empty() {
                config = config
                    .with_params(key.pairs.iter().map(|(k, v)| (k.as_str(), v.as_str())))
                    .map_err(value_err)?;
            }
            CONFIGS.put(key, config.clone());
            config
        }
    })
}

/// The robot's limits, scaled to world units: all three or none.
fn limits_of(
    vmax: Option<f64>,
    wmax: Option<f64>,
    amax: Option<f64>,
    scale: f64,
) -> PyResult<Option<Limits>> {
    Ok(match (vmax, wmax, amax) {
        (Some(v), Some(w), Some(a)) => Some(
            Limits::new(v * scale, w, a * scale)
                .map_err(|e| PyValueError::new_err(format!("vmax/wmax/amax: {e}")))?,
        ),
        (None, None, None) => None,
        _ => {
            return Err(PyValueError::new_err(
                "vmax, wmax and amax go together: give all three or none",
            ));
        }
    })
}

/// The query of `start` and `goal` (input frame), checked against the map.
fn query_of(
    map: &PyGridMap,
    start: (f64, f64),
    goal: (f64, f64),
    goal_radius: f64,
) -> PyResult<Query> {
    let scale = map.scale();
    let start_w = map.to_world(start.0, start.1);
    let goal_c = map.to_world(goal.0, goal.1);
    let goal_region = if goal_radius == 0.0 {
        Goal::Point(goal_c)
    } else {
        Goal::disc(goal_c, goal_radius * scale)
    };
    let query = Query::new(start_w, goal_region);
    query.validate(&*map.map).map_err(|e| match e {
        PlanError::InvalidStart { reason, .. } => PyValueError::new_err(format!(
            "start {},{}: {}",
            start.0,
            start.1,
            map.frame.refusal(map.map.bounds(), start_w, reason)
        )),
        PlanError::InvalidGoal { reason, .. } => PyValueError::new_err(format!(
            "goal {},{} (radius {goal_radius}): {}",
            goal.0,
            goal.1,
            map.frame.refusal(map.map.bounds(), goal_c, reason)
        )),
        other => value_err(other),
    })?;
    Ok(query)
}
