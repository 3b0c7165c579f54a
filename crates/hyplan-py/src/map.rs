//! `hyplan.GridMap`: maps from NumPy arrays and files, in their input frame.

use std::path::PathBuf;
use std::sync::Arc;

use envmap::{GridMap, InputFrame, LoadOptions, Mask};
use hyplan_core::{Point2, Zone};
use numpy::ndarray::{ArrayView2, Axis};
use numpy::{PyArray2, PyArrayMethods, PyReadonlyArray2};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::value_err;

/// World units per input unit of `frame`.
pub(crate) fn input_scale(frame: &InputFrame) -> f64 {
    match *frame {
        InputFrame::Cells { resolution, .. } => resolution,
        InputFrame::World | InputFrame::MapFrame { .. } => 1.0,
    }
}

/// An occupancy grid with its zones (0 free, 1 high-risk, 2 forbidden) and the frame its
/// coordinates are given in. Immutable: the methods return new maps.
#[pyclass(frozen, name = "GridMap", module = "hyplan")]
pub(crate) struct PyGridMap {
    pub(crate) map: Arc<GridMap>,
    pub(crate) frame: InputFrame,
}

impl PyGridMap {
    pub(crate) fn scale(&self) -> f64 {
        input_scale(&self.frame)
    }
    pub(crate) fn to_world(&self, x: f64, y: f64) -> Point2 {
        self.frame.to_world(x, y)
    }
    pub(crate) fn points_to_world(&self, pts: &ArrayView2<'_, f64>) -> Vec<Point2> {
        pts.rows()
            .into_iter()
            .map(|r| self.to_world(r[0], r[1]))
            .collect()
    }
    pub(crate) fn points_from_world<'py>(
        &self,
        py: Python<'py>,
        pts: &[Point2],
    ) -> Bound<'py, PyArray2<f64>> {
        points_array(py, pts.iter().map(|&p| self.frame.from_world(p)), pts.len())
    }
}

/// An `(n, 2)` float64 array of the `n` points of `xy`, written in place into a new NumPy
/// array (no Rust-side buffer, no copy).
pub(crate) fn points_array<'py>(
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
pub(crate) fn zones_of(occ: &ArrayView2<'_, bool>) -> Vec<Zone> {
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
