//! Python bindings of hyplan (`import hyplan`): maps from NumPy arrays or files, every
//! planner of `hyplan plan` with the same seeds and flags, smoothing, transfer time and
//! scenario runs; seed 004's simulated robot (`Sim`), driven step by step.
//!
//! Coordinates are in the map's *input frame*, as on the command line: world units with y
//! up for maps made from arrays and for ROS YAML maps; cells with y counted down from the
//! top row for pictures and MovingAI `.map` files loaded with `GridMap.load`.
//!
//! The GIL is released while a planner runs (and while a path is smoothed or a scenario
//! runs), so Python threads plan in parallel.

use std::path::PathBuf;
use std::sync::Arc;

use hyplan_core::Point2;
use numpy::{PyArray2, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

mod map;
mod plan;
mod simulator;

use map::PyGridMap;
use plan::PlanResult;
use simulator::PySim;

fn value_err(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
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
    d.set_item("checks_segments", caps.checks_segments)?;
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
    m.add_class::<PySim>()?;
    m.add_function(wrap_pyfunction!(simulator::_builtin_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(plan::plan, m)?)?;
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
