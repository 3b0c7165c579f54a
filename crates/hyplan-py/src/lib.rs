//! Python bindings of hyplan (`import hyplan`): maps from NumPy arrays or files, every
//! planner of `hyplan plan` with the same seeds and flags, smoothing, transfer time and
//! scenario runs.
//!
//! Coordinates are in the map's *input frame*, as on the command line: world units with y
//! up for maps made from arrays and for ROS YAML maps; cells with y counted down from the
//! top row for pictures and MovingAI `.map` files loaded with `GridMap.load`.
//!
//! The GIL is released while a planner runs (and while a path is smoothed or a scenario
//! runs), so Python threads plan in parallel.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use envmap::{GridMap, InputFrame, LoadOptions, Mask};
use hyplan_core::{Goal, Plan, PlanError, Point2, Query, Zone};
use numpy::ndarray::{ArrayView2, Axis};
use numpy::{PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use postproc::{Limits, PostprocError, Smoothing};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyType};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::SeedableRng;

fn value_err(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// World units per input unit of `frame`.
fn input_scale(frame: &InputFrame) -> f64 {
    match *frame {
        InputFrame::Cells { resolution, .. } => resolution,
        InputFrame::World | InputFrame::MapFrame { .. } => 1.0,
    }
}

/// An occupancy grid with its zones (0 free, 1 high-risk, 2 forbidden) and the frame its
/// coordinates are given in. Immutable: the methods return new maps.
#[pyclass(frozen, name = "GridMap", module = "hyplan")]
struct PyGridMap {
    map: Arc<GridMap>,
    frame: InputFrame,
}

impl PyGridMap {
    fn scale(&self) -> f64 {
        input_scale(&self.frame)
    }
    fn to_world(&self, x: f64, y: f64) -> Point2 {
        self.frame.to_world(x, y)
    }
    fn points_to_world(&self, pts: &ArrayView2<'_, f64>) -> Vec<Point2> {
        pts.rows()
            .into_iter()
            .map(|r| self.to_world(r[0], r[1]))
            .collect()
    }
    fn points_from_world<'py>(&self, py: Python<'py>, pts: &[Point2]) -> Bound<'py, PyArray2<f64>> {
        points_array(py, pts.iter().map(|&p| self.frame.from_world(p)), pts.len())
    }
}

/// An `(n, 2)` float64 array of the `n` points of `xy`, written in place into a new NumPy
/// array (no Rust-side buffer, no copy).
fn points_array<'py>(
    py: Python<'py>,
    xy: impl Iterator<Item = (f64, f64)>,
    n: usize,
) -> Bound<'py, PyArray2<f64>> {
    // SAFETY: a new C-contiguous array that nothing else references yet; every element is
    // written below before the array is handed out (`xy` yields exactly `n` points).
    let arr = unsafe { PyArray2::<f64>::new(py, [n, 2], false) };
    let out = unsafe { arr.as_slice_mut() }.expect("a new array is contiguous");
    let mut filled = 0;
    for (slot, (x, y)) in out.chunks_exact_mut(2).zip(xy) {
        slot[0] = x;
        slot[1] = y;
        filled += 1;
    }
    assert_eq!(filled, n, "points_array: fewer points than announced");
    arr
}

/// `occupied` as zones, bottom row first: the one copy of the array.
fn zones_of(occ: &ArrayView2<'_, bool>) -> Vec<Zone> {
    let (h, w) = occ.dim();
    let mut zones = Vec::with_capacity(h * w);
    for row in occ.axis_iter(Axis(0)).rev() {
        if let Some(s) = row.as_slice() {
            zones.extend(
                s.iter()
                    .map(|&b| if b { Zone::Forbidden } else { Zone::Free }),
            );
        } else {
            zones.extend(
                row.iter()
                    .map(|&b| if b { Zone::Forbidden } else { Zone::Free }),
            );
        }
    }
    zones
}

#[pymethods]
impl PyGridMap {
    /// A map from a 2-D boolean array, `occupied[row, col]` with row 0 the top row (as an
    /// image or `plt.imshow` shows it). Coordinates are world units, y up:
    /// cell `(row, col)` spans x in `origin[0] + col*resolution ...`, y from the bottom.
    #[staticmethod]
    #[pyo3(signature = (occupied, resolution = 1.0, origin = (0.0, 0.0)))]
    fn from_array(
        py: Python<'_>,
        occupied: &Bound<'_, PyAny>,
        resolution: f64,
        origin: (f64, f64),
    ) -> PyResult<Self> {
        // A bool array is read in place; anything else is converted by NumPy first.
        let arr: PyReadonlyArray2<'_, bool> = match occupied.extract() {
            Ok(a) => a,
            Err(_) => {
                let np = py.import("numpy")?;
                let conv = np.call_method1("asarray", (occupied,))?;
                let conv = conv.call_method1("astype", ("bool",))?;
                conv.extract().map_err(|_| {
                    PyValueError::new_err("occupied: expected a 2-D array of booleans")
                })?
            }
        };
        let view = arr.as_array();
        let (h, w) = view.dim();
        let zones = zones_of(&view);
        let map = GridMap::from_zones(w, h, resolution, Point2::new(origin.0, origin.1), zones)
            .map_err(value_err)?;
        Ok(Self {
            map: Arc::new(map),
            frame: InputFrame::World,
        })
    }

    /// Loads a map file as `hyplan plan --map` does: a picture (PNG, PGM, PPM), a ROS
    /// map_server `.yaml` or a MovingAI `.map`. `safety_radius` (input units) adds the
    /// high-risk band (default: 20 cells for pictures, none otherwise).
    #[staticmethod]
    #[pyo3(signature = (path, threshold = 100, safety_radius = None, invert = false,
                        unknown_free = false, max_cells = envmap::DEFAULT_MAX_CELLS))]
    fn load(
        py: Python<'_>,
        path: PathBuf,
        threshold: u8,
        safety_radius: Option<f64>,
        invert: bool,
        unknown_free: bool,
        max_cells: usize,
    ) -> PyResult<Self> {
        if !path.exists() {
            return Err(PyOSError::new_err(format!(
                "{}: no such file",
                path.display()
            )));
        }
        let opts = LoadOptions {
            threshold,
            invert,
            safety_radius,
            unknown_free,
            max_cells,
            ..LoadOptions::default()
        };
        let loaded = py
            .detach(|| envmap::load_map(&path, &opts))
            .map_err(|e| PyValueError::new_err(format!("loading {}: {e}", path.display())))?;
        Ok(Self {
            map: Arc::new(loaded.map),
            frame: loaded.frame,
        })
    }

    /// The same map with a high-risk band of `radius` (input units) around the
    /// forbidden cells (the band is recomputed from the forbidden cells alone).
    fn with_safety_band(&self, py: Python<'_>, radius: f64) -> PyResult<Self> {
        if !(radius.is_finite() && radius >= 0.0) {
            return Err(PyValueError::new_err(format!(
                "radius {radius}: must be finite and >= 0"
            )));
        }
        let cells = radius * self.scale() / self.map.resolution();
        let src = Arc::clone(&self.map);
        let map = py
            .detach(move || {
                let mask = Mask::from_zones_at_least(&src, Zone::Forbidden);
                let dist = envmap::distance_transform(&mask);
                let zones = envmap::zones(&mask, &dist, cells);
                GridMap::from_zones(
                    src.width(),
                    src.height(),
                    src.resolution(),
                    src.origin(),
                    zones,
                )
                .map(|mut m| {
                    m.blocked_from = src.blocked_from;
                    m
                })
            })
            .map_err(value_err)?;
        Ok(Self {
            map: Arc::new(map),
            frame: self.frame,
        })
    }

    /// The same map with the high-risk band blocked too (`hyplan plan --avoid-risk`).
    fn avoiding_risk(&self) -> Self {
        Self {
            map: Arc::new((*self.map).clone().avoiding_risk()),
            frame: self.frame,
        }
    }

    /// Zones as a read-only `uint8` array `[row, col]`, row 0 the top row: 0 free, 1
    /// high-risk, 2 forbidden. A view of the map's own cells, not a copy.
    #[getter]
    fn zones<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyArray2<u8>>> {
        let this = slf.get();
        let cells: &[Zone] = this.map.zones();
        // SAFETY: `Zone` is `#[repr(u8)]`, so its cells are bytes; the map is immutable
        // (frozen class, no `&mut` to the Arc) and the array keeps `slf` alive as its base.
        let bytes: &[u8] =
            unsafe { std::slice::from_raw_parts(cells.as_ptr().cast::<u8>(), cells.len()) };
        let mut view = ArrayView2::from_shape((this.map.height(), this.map.width()), bytes)
            .map_err(value_err)?;
        view.invert_axis(Axis(0));
        // SAFETY: as above, the container owns the memory for the array's lifetime.
        let arr = unsafe { PyArray2::borrow_from_array(&view, slf.clone().into_any()) };
        let kwargs = PyDict::new(slf.py());
        kwargs.set_item("write", false)?;
        arr.call_method("setflags", (), Some(&kwargs))?;
        Ok(arr)
    }

    /// Columns.
    #[getter]
    fn width(&self) -> usize {
        self.map.width()
    }
    /// Rows.
    #[getter]
    fn height(&self) -> usize {
        self.map.height()
    }
    /// World units per cell.
    #[getter]
    fn resolution(&self) -> f64 {
        self.map.resolution()
    }
    /// World position of the lower-left corner.
    #[getter]
    fn origin(&self) -> (f64, f64) {
        let o = self.map.origin();
        (o.x, o.y)
    }
    /// `"world"` (y up, world units) or `"cells"` (y down from the top row, cell units).
    #[getter]
    fn frame(&self) -> &'static str {
        match self.frame {
            InputFrame::Cells { .. } => "cells",
            InputFrame::World => "world",
            InputFrame::MapFrame { .. } => "map",
        }
    }
    /// Whether the high-risk band blocks motion (after `avoiding_risk`).
    #[getter]
    fn avoids_risk(&self) -> bool {
        self.map.blocked_from == Zone::Risk
    }
    fn __repr__(&self) -> String {
        format!(
            "GridMap({} x {}, resolution {}, frame {})",
            self.map.width(),
            self.map.height(),
            self.map.resolution(),
            self.frame()
        )
    }
}

/// One plan's outcome (also carried by `NoPathError.result`).
#[pyclass(frozen, name = "PlanResult", module = "hyplan", get_all)]
struct PlanResult {
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
    /// Wall time of the planner call, s.
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
fn plan(
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
    let time_limit = time_limit
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
        .transpose()?;
    if !(0.0..=1.0).contains(&goal_bias) {
        return Err(PyValueError::new_err(format!(
            "goal_bias {goal_bias}: invalid parameter goal_bias, must be a probability in [0, 1]"
        )));
    }
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
    let config = match CONFIGS.get(&key) {
        Some(c) => c,
        None => {
            let named: registry::PlannerConfig = planner.parse().map_err(value_err)?;
            let step = match step {
                Some(s) => Some(s * scale),
                None if named.wants_default_step() => Some(0.05 * map.map.bounds().diagonal()),
                None => None,
            };
            let mut config = registry::PlannerConfig::from_spec(planner, |mut c| {
                if let Some(step) = step {
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
    };
    let smoothing: Smoothing = smooth
        .parse()
        .map_err(|e| PyValueError::new_err(format!("smooth {smooth:?}: {e}")))?;
    let limits = match (vmax, wmax, amax) {
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
    };
    let start_w = map.to_world(start.0, start.1);
    let goal_c = map.to_world(goal.0, goal.1);
    let goal_region = if goal_radius == 0.0 {
        Goal::Point(goal_c)
    } else {
        Goal::disc(goal_c, goal_radius * scale)
    };
    let query = Query::new(start_w, goal_region);
    query.validate(&*map.map).map_err(|e| match e {
        PlanError::InvalidStart { reason, .. } => {
            PyValueError::new_err(format!("start {},{}: {reason}", start.0, start.1))
        }
        PlanError::InvalidGoal { reason, .. } => PyValueError::new_err(format!(
            "goal {},{} (radius {goal_radius}): {reason}",
            goal.0, goal.1
        )),
        other => value_err(other),
    })?;

    let run_seed = harness::run_seed(seed, run);
    let grid = Arc::clone(&map.map);
    let built = config.build();
    let budget_used = config.budget_on(&*map.map);
    // The planner runs without the GIL; post-processing too.
    let (outcome, time_s, post) = py.detach(move || {
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
    let name = config.name().to_string();
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

/// `path` (an `(N, 2)` array in the map's input frame) smoothed with `method` (`none`,
/// `prune`, `pchip`, `bspline`, `bspline-interp`), checked a quarter cell apart against
/// the map and repaired where it collides; the curve in the same frame.
#[pyfunction]
#[pyo3(signature = (path, map, method = "pchip"))]
fn smooth<'py>(
    py: Python<'py>,
    path: PyReadonlyArray2<'py, f64>,
    map: &PyGridMap,
    method: &str,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let view = path.as_array();
    if view.ncols() != 2 {
        return Err(PyValueError::new_err(format!(
            "path: expected shape (N, 2), got {:?}",
            path.shape()
        )));
    }
    let pts = map.points_to_world(&view);
    let method: postproc::Smoothing = method
        .parse()
        .map_err(|e| PyValueError::new_err(format!("method {method:?}: {e}")))?;
    let grid = Arc::clone(&map.map);
    let spacing = 0.25 * grid.resolution();
    let out = py
        .detach(move || {
            postproc::smooth_checked(&pts, method, spacing, |a, b| grid.segment_free_cells(a, b))
        })
        .map_err(value_err)?;
    Ok(map.points_from_world(py, &out.points))
}

/// Rest-to-rest time (s) to follow the polyline `path` (`(N, 2)`, any length unit) with
/// speed limit `vmax` (units/s), turn-rate limit `wmax` (rad/s, turning on the spot at
/// each corner) and acceleration `amax` (units/s^2).
#[pyfunction]
fn transfer_time(
    path: PyReadonlyArray2<'_, f64>,
    vmax: f64,
    wmax: f64,
    amax: f64,
) -> PyResult<f64> {
    let view = path.as_array();
    if view.ncols() != 2 {
        return Err(PyValueError::new_err(format!(
            "path: expected shape (N, 2), got {:?}",
            path.shape()
        )));
    }
    let pts: Vec<Point2> = view
        .rows()
        .into_iter()
        .map(|r| Point2::new(r[0], r[1]))
        .collect();
    let limits = postproc::Limits::new(vmax, wmax, amax).map_err(value_err)?;
    Ok(postproc::time_polyline(&pts, &limits)
        .map_err(value_err)?
        .transfer_time)
}

/// Runs every planner of the scenario file (RON) as `hyplan scen`/the harness does and
/// returns one record (a dict of the harness's `RunMetrics` plus `planner`) per run.
#[pyfunction]
#[pyo3(signature = (path, runs = None))]
fn run_scenario<'py>(
    py: Python<'py>,
    path: PathBuf,
    runs: Option<u32>,
) -> PyResult<Bound<'py, PyList>> {
    if !path.exists() {
        return Err(PyOSError::new_err(format!(
            "{}: no such file",
            path.display()
        )));
    }
    let records = py
        .detach(
            || -> Result<Vec<(String, Vec<harness::RunMetrics>)>, String> {
                let (scenario, world) =
                    harness::Scenario::load(&path).map_err(|e| e.to_string())?;
                let runs = runs.unwrap_or(scenario.runs);
                let mut out = Vec::new();
                for spec in &scenario.planners {
                    let metrics =
                        harness::run_planner(&scenario, &world, spec, runs, false, &|| {})
                            .map_err(|e| e.to_string())?;
                    out.push((spec.label().to_string(), metrics));
                }
                Ok(out)
            },
        )
        .map_err(PyValueError::new_err)?;
    let json = py.import("json")?;
    let list = PyList::empty(py);
    for (label, metrics) in records {
        for m in metrics {
            let text = serde_json::to_string(&m).map_err(value_err)?;
            let d = json.call_method1("loads", (text,))?;
            d.set_item("planner", &label)?;
            list.append(d)?;
        }
    }
    Ok(list)
}

/// The planner names `plan` accepts.
#[pyfunction]
fn planners() -> Vec<&'static str> {
    registry::PlannerConfig::names()
}

/// The parameters of planner `name` (a `NAME[:key=value,...]` spec) with their default
/// values, as RON text: what `**params` of `plan` may set.
#[pyfunction]
fn planner_params(name: &str) -> PyResult<Vec<(String, String)>> {
    let c: registry::PlannerConfig = name.parse().map_err(value_err)?;
    Ok(c.params())
}

/// What the registry says of planner `name` (a `NAME[:key=value,...]` spec): its help
/// line, its capabilities and its parameters (name, type, value, doc), as `hyplan
/// planners NAME` prints them.
#[pyfunction]
fn planner_info<'py>(py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyDict>> {
    let c: registry::PlannerConfig = name.parse().map_err(value_err)?;
    let caps = c.capabilities();
    let d = PyDict::new(py);
    d.set_item("name", c.name())?;
    d.set_item("help", c.help())?;
    d.set_item("family", caps.family.to_string())?;
    d.set_item("grid_only", caps.grid_only)?;
    d.set_item("uses_risk", caps.uses_risk)?;
    d.set_item("has_step", caps.has_step)?;
    d.set_item("wants_default_step", caps.wants_default_step)?;
    d.set_item("goal_bias", caps.goal_bias)?;
    d.set_item("own_goal_radius", caps.own_goal_radius)?;
    d.set_item("deterministic", caps.deterministic)?;
    let params = PyList::empty(py);
    for p in c.parameters() {
        let item = PyDict::new(py);
        item.set_item("name", p.name)?;
        item.set_item("type", p.ty)?;
        item.set_item("default", p.default)?;
        item.set_item("doc", p.doc)?;
        params.append(item)?;
    }
    d.set_item("params", params)?;
    Ok(d)
}

/// The native module; `hyplan/__init__.py` re-exports it.
#[pymodule]
fn _hyplan(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyGridMap>()?;
    m.add_class::<PlanResult>()?;
    m.add_function(wrap_pyfunction!(plan, m)?)?;
    m.add_function(wrap_pyfunction!(smooth, m)?)?;
    m.add_function(wrap_pyfunction!(transfer_time, m)?)?;
    m.add_function(wrap_pyfunction!(run_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(planners, m)?)?;
    m.add_function(wrap_pyfunction!(planner_params, m)?)?;
    m.add_function(wrap_pyfunction!(planner_info, m)?)?;
    // For the timing tests, which mean nothing on a debug build (`maturin develop`).
    m.add("_debug_build", cfg!(debug_assertions))?;
    Ok(())
}
