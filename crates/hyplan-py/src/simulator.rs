//! `hyplan.Sim`: seed 004's simulated robot, driven from Python one control period at a
//! time (`sim::Driven`), or by its own navigation stack (`run`).

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use sim::{Driven, GlobalPlanner, Observation, Scenario, Twist, World};

/// The scenario and its world, which the driven robot borrows.
struct Owned {
    scenario: Scenario,
    world: World,
}

self_cell::self_cell!(
    struct SimCell {
        owner: Owned,
        #[covariant]
        dependent: Driven,
    }
);

fn value_err(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// Seed 004's robot in a scenario of `hyplan sim` (a RON file, or a dict with the same
/// keys), driven one control period at a time.
///
/// `step(v, omega)` commands a forward speed (m/s) and turn rate (rad/s) for one control
/// period (`period` s; the robot reaches the command at its own accelerations) and
/// returns the observation at its end: a dict with
///
/// - `t` (s), `pose` (`[x, y, phi]`), `velocity` (`[v, omega]` in force);
/// - `ranges`: the latest scan (float32, one per beam, REP 117: `inf` nothing within
///   range, `-inf` closer than the shortest range), taken at most one laser period ago;
///   the laser fires at its own rate through the period;
/// - `tracked`: the people the robot's tracker follows in the scans, `(K, 5)` rows of
///   `x, y, vx, vy, radius`; `people`: everyone's true body, `(M, 3)` rows of `x, y,
///   radius`;
/// - `contacts`: `{"static": bool, "people": [index, ...]}`, what the body overlapped on
///   a laser tick of the period; `clearance`: the smallest distance (m) between body and
///   static world over the period;
/// - `goal_distance` (m), `goal_bearing` (rad, from the heading), `reached` (within the
///   navigation's goal tolerance), `timed_out` (past the scenario's time limit).
///
/// No map is built and no planner runs while the caller drives. The GIL is released
/// during a step. `run()` instead drives the scenario with the built-in stack (Dijkstra
/// and the scenario's local planner) from the start, as `hyplan sim` does.
#[pyclass(name = "Sim", module = "hyplan")]
pub struct PySim {
    cell: Mutex<SimCell>,
    seed: u64,
}

fn load(source: &Bound<'_, PyAny>) -> PyResult<Owned> {
    let (scenario, world) = if let Ok(d) = source.cast::<PyDict>() {
        let json = source.py().import("json")?;
        let text: String = json.call_method1("dumps", (d,))?.extract()?;
        let scenario: Scenario = serde_json::from_str(&text)
            .map_err(|e| PyValueError::new_err(format!("scenario dict: {e}")))?;
        // Map paths in a dict are relative to the working directory.
        let world = scenario
            .build_world(Path::new("scenario"))
            .map_err(value_err)?;
        (scenario, world)
    } else {
        let path: PathBuf = source.extract().map_err(|_| {
            PyValueError::new_err("scenario: expected a path (str or os.PathLike) or a dict")
        })?;
        if !path.exists() {
            return Err(PyOSError::new_err(format!(
                "{}: no such file",
                path.display()
            )));
        }
        Scenario::load(&path).map_err(value_err)?
    };
    Ok(Owned { scenario, world })
}

/// `owned` with `crowd` people per 100 m^2 added to its map, as `hyplan sim --crowd` adds
/// them (`sim::add_crowd`), drawn from `seed`.
fn with_crowd(mut owned: Owned, crowd: Option<f64>, seed: u64) -> PyResult<Owned> {
    if let Some(density) = crowd {
        sim::add_crowd(&mut owned.scenario, &mut owned.world, density, seed)
            .map_err(|e| PyValueError::new_err(format!("crowd = {density}: {e}")))?;
    }
    Ok(owned)
}

/// The scenarios that ship inside the module, by name: what `hyplan.gym.NavEnv` drives
/// by default, with no file beside the installed package.
const BUILTIN: &[(&str, &str)] = &[(
    "004-nav-3-person",
    include_str!("../../../scenarios/sim/3-person.ron"),
)];

/// The RON text of a scenario that ships inside the module (`004-nav-3-person`: seed
/// 004's scenario 3, `scenarios/sim/3-person.ron`), for `Sim.from_ron`.
#[pyfunction]
pub fn _builtin_scenario(name: &str) -> PyResult<&'static str> {
    BUILTIN
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
        .ok_or_else(|| {
            let names: Vec<&str> = BUILTIN.iter().map(|(n, _)| *n).collect();
            PyValueError::new_err(format!(
                "scenario {name:?}: not built in (built in: {names:?})"
            ))
        })
}

fn driven(owned: Owned, seed: u64, track_people: bool) -> SimCell {
    SimCell::new(owned, |o| {
        let d = Driven::new(&o.scenario, &o.world, seed);
        if track_people { d } else { d.without_tracker() }
    })
}

/// `[v, omega]` from a float32 or float64 array or a sequence of two numbers.
fn action_of(action: &Bound<'_, PyAny>) -> PyResult<[f64; 2]> {
    let pair = if let Ok(a) = action.cast::<PyArray1<f32>>() {
        a.readonly()
            .as_slice()
            .ok()
            .map(|s| s.iter().map(|&x| f64::from(x)).collect())
    } else if let Ok(a) = action.cast::<PyArray1<f64>>() {
        a.readonly().as_slice().ok().map(<[f64]>::to_vec)
    } else {
        action.extract::<Vec<f64>>().ok()
    };
    match pair.as_deref() {
        Some(&[v, omega]) => Ok([v, omega]),
        _ => Err(PyValueError::new_err(format!(
            "action: expected [v, omega] (two numbers), got {}",
            action.repr()?
        ))),
    }
}

/// `hyplan.gym.NavEnv`'s observation and outcome: the scan as float32 in `[0, range_max]`,
/// the goal's distance and bearing, the command in force, then the goal distance (f64),
/// contact, reached, timed out.
type GymStep<'py> = (
    Bound<'py, PyArray1<f32>>,
    Bound<'py, PyArray1<f32>>,
    Bound<'py, PyArray1<f32>>,
    f64,
    bool,
    bool,
    bool,
);

fn gym_step<'py>(py: Python<'py>, o: &Observation, range_max: f64) -> GymStep<'py> {
    let hi = range_max as f32;
    // REP 117 to a bounded box: nothing within range reads range_max, too close 0.
    let scan = PyArray1::from_iter(py, o.ranges.iter().map(|&r| (r as f32).clamp(0.0, hi)));
    let goal = PyArray1::from_slice(py, &[o.goal_distance as f32, o.goal_bearing as f32]);
    let velocity = PyArray1::from_slice(py, &[o.twist.v as f32, o.twist.omega as f32]);
    let contact = o.static_contact || !o.people_contact.is_empty();
    (
        scan,
        goal,
        velocity,
        o.goal_distance,
        contact,
        o.reached,
        o.timed_out,
    )
}

impl PySim {
    /// One control period with the GIL released; the robot, locked, after it.
    fn drive(&self, py: Python<'_>, v: f64, omega: f64) -> PyResult<MutexGuard<'_, SimCell>> {
        if !v.is_finite() || !omega.is_finite() {
            return Err(PyValueError::new_err(format!(
                "step: v = {v}, omega = {omega}: both must be finite"
            )));
        }
        let mut guard = self
            .cell
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let cell = &mut *guard;
        py.detach(|| {
            cell.with_dependent_mut(|_, d| {
                d.step(Twist { v, omega });
            });
        });
        Ok(guard)
    }

    fn with<R>(&self, f: impl FnOnce(&SimCell) -> R) -> R {
        let guard = self
            .cell
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        f(&guard)
    }
}

fn observation<'py>(py: Python<'py>, o: &Observation) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("t", o.t)?;
    d.set_item(
        "pose",
        PyArray1::from_slice(py, &[o.pose.x, o.pose.y, o.pose.phi]),
    )?;
    d.set_item(
        "velocity",
        PyArray1::from_slice(py, &[o.twist.v, o.twist.omega]),
    )?;
    d.set_item(
        "ranges",
        PyArray1::from_iter(py, o.ranges.iter().map(|&r| r as f32)),
    )?;
    let tracked: Vec<Vec<f64>> = o
        .tracked
        .iter()
        .map(|m| vec![m.center.x, m.center.y, m.velocity.x, m.velocity.y, m.radius])
        .collect();
    d.set_item("tracked", rows(py, &tracked, 5)?)?;
    let people: Vec<Vec<f64>> = o
        .people
        .iter()
        .map(|p| vec![p.center.x, p.center.y, p.radius])
        .collect();
    d.set_item("people", rows(py, &people, 3)?)?;
    let contacts = PyDict::new(py);
    contacts.set_item("static", o.static_contact)?;
    contacts.set_item("people", PyList::new(py, &o.people_contact)?)?;
    d.set_item("contacts", contacts)?;
    d.set_item("clearance", o.clearance)?;
    d.set_item("goal_distance", o.goal_distance)?;
    d.set_item("goal_bearing", o.goal_bearing)?;
    d.set_item("reached", o.reached)?;
    d.set_item("timed_out", o.timed_out)?;
    Ok(d)
}

/// An `(N, width)` float64 array (`(0, width)` when empty).
fn rows<'py>(py: Python<'py>, r: &[Vec<f64>], width: usize) -> PyResult<Bound<'py, PyArray2<f64>>> {
    if r.is_empty() {
        return Ok(PyArray2::zeros(py, [0, width], false));
    }
    PyArray2::from_vec2(py, r).map_err(value_err)
}

#[pymethods]
impl PySim {
    /// `scenario`: a scenario file of `hyplan sim` (RON) or a dict with its keys (shapes
    /// as `{"Wall": {"from": [x, y], ...}}`); `seed`: the laser noise's seed;
    /// `track_people`: run the people tracker on the scans (`tracked` stays empty
    /// without it, and a step costs less); `crowd`: people per 100 m^2 to add to the
    /// scenario's map, placed from `seed` as `hyplan sim --crowd` places them (the robot
    /// set up as the crowd rooms').
    #[new]
    #[pyo3(signature = (scenario, seed = 0, track_people = true, crowd = None))]
    fn new(
        scenario: &Bound<'_, PyAny>,
        seed: u64,
        track_people: bool,
        crowd: Option<f64>,
    ) -> PyResult<Self> {
        let owned = with_crowd(load(scenario)?, crowd, seed)?;
        Ok(Self {
            cell: Mutex::new(driven(owned, seed, track_people)),
            seed,
        })
    }

    /// A scenario from its RON text (map paths relative to the working directory).
    #[staticmethod]
    #[pyo3(signature = (text, seed = 0, track_people = true, crowd = None))]
    fn from_ron(text: &str, seed: u64, track_people: bool, crowd: Option<f64>) -> PyResult<Self> {
        let path = Path::new("scenario.ron");
        let scenario = Scenario::parse(text, path).map_err(value_err)?;
        let world = scenario.build_world(path).map_err(value_err)?;
        let owned = with_crowd(Owned { scenario, world }, crowd, seed)?;
        Ok(Self {
            cell: Mutex::new(driven(owned, seed, track_people)),
            seed,
        })
    }

    /// Back to the start (with a new `seed` if given); the first observation.
    #[pyo3(signature = (seed = None))]
    fn reset<'py>(&mut self, py: Python<'py>, seed: Option<u64>) -> PyResult<Bound<'py, PyDict>> {
        if let Some(s) = seed {
            self.seed = s;
        }
        let seed = self.seed;
        let mut guard = self
            .cell
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let cell = &mut *guard;
        cell.with_dependent_mut(|_, d| d.reset(seed));
        observation(py, cell.borrow_dependent().observation())
    }

    /// One control period commanding forward speed `v` (m/s) and turn rate `omega`
    /// (rad/s); the observation at its end. The GIL is released meanwhile.
    fn step<'py>(&self, py: Python<'py>, v: f64, omega: f64) -> PyResult<Bound<'py, PyDict>> {
        let guard = self.drive(py, v, omega)?;
        let cell = &*guard;
        observation(py, cell.borrow_dependent().observation())
    }

    /// `step` for `hyplan.gym.NavEnv`, with `action` `[v, omega]` (a float32 or float64
    /// array or a sequence) clipped to `[0, v_max] x [-omega_max, omega_max]`: `(scan,
    /// goal, velocity, goal_distance, contact, reached, timed_out)`, the first three the
    /// float32 arrays of its observation.
    fn _step_gym<'py>(
        &self,
        py: Python<'py>,
        action: &Bound<'py, PyAny>,
    ) -> PyResult<GymStep<'py>> {
        let [v, omega] = action_of(action)?;
        let robot = self.with(|c| c.borrow_owner().scenario.robot);
        let v = v.clamp(0.0, robot.v_max);
        let omega = omega.clamp(-robot.omega_max, robot.omega_max);
        let guard = self.drive(py, v, omega)?;
        let cell = &*guard;
        let range_max = cell.borrow_owner().scenario.laser.range_max;
        Ok(gym_step(
            py,
            cell.borrow_dependent().observation(),
            range_max,
        ))
    }

    /// `_step_gym`'s tuple for the observation now (after `reset`).
    fn _observe_gym<'py>(&self, py: Python<'py>) -> GymStep<'py> {
        self.with(|c| {
            let range_max = c.borrow_owner().scenario.laser.range_max;
            gym_step(py, c.borrow_dependent().observation(), range_max)
        })
    }

    /// The observation after the last step (or at the start).
    fn observation<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.with(|c| observation(py, c.borrow_dependent().observation()))
    }

    /// Runs the scenario from its start with the built-in navigation stack (Dijkstra on
    /// the costmap and the scenario's local planner), as `hyplan sim` does, and returns
    /// its `summary.json` as a dict with the track added (`track`: `(N, 6)` rows of `t,
    /// x, y, phi, v, omega`, one per laser tick). The driven robot is left as it was.
    fn run<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let seed = self.seed;
        let (summary, track) = self.with(|c| {
            let o = c.borrow_owner();
            py.detach(|| {
                let out = sim::run(&o.scenario, &o.world, seed, GlobalPlanner::Dijkstra);
                let track: Vec<Vec<f64>> = out
                    .trace
                    .rows
                    .iter()
                    .map(|r| vec![r.t, r.x, r.y, r.phi, r.v, r.omega])
                    .collect();
                (serde_json::to_string(&out.trace.summary), track)
            })
        });
        let text = summary.map_err(value_err)?;
        let d = py.import("json")?.call_method1("loads", (text,))?;
        let d = d.cast_into::<PyDict>()?;
        d.set_item("track", rows(py, &track, 6)?)?;
        Ok(d)
    }

    /// The control period, s: one `step`.
    #[getter]
    fn period(&self) -> f64 {
        self.with(|c| c.borrow_dependent().period())
    }

    /// The scenario's name.
    #[getter]
    fn name(&self) -> String {
        self.with(|c| c.borrow_owner().scenario.name.clone())
    }

    /// The seed of the laser noise.
    #[getter]
    fn seed(&self) -> u64 {
        self.seed
    }

    /// The goal, `(x, y)` m.
    #[getter]
    fn goal(&self) -> (f64, f64) {
        self.with(|c| c.borrow_owner().scenario.goal)
    }

    /// The scenario's time limit, s.
    #[getter]
    fn time_limit(&self) -> f64 {
        self.with(|c| c.borrow_owner().scenario.time_limit)
    }

    /// The laser: a dict of `beams`, `angle_min` and `angle_increment` (rad, in the
    /// robot's frame), `range_min` and `range_max` (m), `rate_hz`.
    #[getter]
    fn laser<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let l = self.with(|c| c.borrow_owner().scenario.laser);
        let d = PyDict::new(py);
        let fov = l.fov_deg.to_radians();
        d.set_item("beams", l.beams)?;
        d.set_item("angle_min", -0.5 * fov)?;
        d.set_item("angle_increment", fov / (l.beams.max(2) - 1) as f64)?;
        d.set_item("range_min", l.range_min)?;
        d.set_item("range_max", l.range_max)?;
        d.set_item("rate_hz", l.rate_hz)?;
        Ok(d)
    }

    /// The robot: a dict of `body_radius` (m), `v_max` (m/s), `omega_max` (rad/s),
    /// `acc_v` (m/s^2) and `acc_omega` (rad/s^2).
    #[getter]
    fn robot<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let r = self.with(|c| c.borrow_owner().scenario.robot);
        let d = PyDict::new(py);
        d.set_item("body_radius", r.body_radius)?;
        d.set_item("v_max", r.v_max)?;
        d.set_item("omega_max", r.omega_max)?;
        d.set_item("acc_v", r.acc_v)?;
        d.set_item("acc_omega", r.acc_omega)?;
        Ok(d)
    }

    fn __repr__(&self) -> String {
        format!("hyplan.Sim({:?}, seed={})", self.name(), self.seed)
    }
}
