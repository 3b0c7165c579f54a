//! The scenario format: one RON file per experiment.

use std::path::{Path, PathBuf};

use envmap::GridMap;
use envmap::Shape;
use hyplan_core::{Goal, Point2, Query};
use serde::{Deserialize, Serialize};

/// One experiment: a map, a query, robot limits, planners, runs, and the paper's numbers.
///
/// Coordinates (`start`, `goal`) are in the scenario's `units`. For [`MapSpec::Picture`]
/// and [`MapSpec::File`] they are measured from the picture's top-left corner with y
/// down (the frame of the picture, as papers and image viewers give them); for
/// [`MapSpec::Grid`] they are y-up from the lower-left corner unless the grid says
/// `y_down: true`.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Short unique name (`seed000-table2`), used by `--only` and for output files.
    pub name: String,
    /// Source of the experiment: the seed file and the table or figure.
    pub source: Source,
    /// One or two sentences on what the experiment shows.
    #[serde(default)]
    pub description: String,
    /// The map.
    pub map: MapSpec,
    /// Unit of coordinates, lengths and limits (`"mm"`, `"cells"`, `"m"`).
    pub units: String,
    /// Start, scenario units.
    pub start: (f64, f64),
    /// Goal centre, scenario units.
    pub goal: (f64, f64),
    /// Goal region radius, scenario units (0: the exact goal point).
    #[serde(default)]
    pub goal_radius: f64,
    /// Whether the high-risk band blocks motion (a safe map in seed 000's sense).
    #[serde(default)]
    pub avoid_risk: bool,
    /// Robot limits for the transfer time, scenario units per second.
    #[serde(default)]
    pub limits: Option<postproc::Limits>,
    /// Runs per planner (the paper's count).
    pub runs: u32,
    /// Runs per planner with `--quick`.
    #[serde(default = "default_quick_runs")]
    pub quick_runs: u32,
    /// Base seed; run k of every planner uses [`run_seed`](crate::run_seed)`(base_seed, k)`.
    pub base_seed: u64,
    /// Planners to run, in report order.
    pub planners: Vec<PlannerSpec>,
    /// The paper's published figures.
    #[serde(default)]
    pub published: Vec<Published>,
    /// The paper's claims, checked on our runs.
    #[serde(default)]
    pub claims: Vec<Claim>,
    /// Which values come from the paper (field names), for the report.
    #[serde(default)]
    pub from_paper: Vec<String>,
    /// Which values are our reconstruction (field names), explained in `docs/papers/`.
    #[serde(default)]
    pub reconstructed: Vec<String>,
    /// Parameters fitted to one of the paper's numbers, each saying to which (the report
    /// marks them: a figure computed with them is not an independent measurement).
    #[serde(default)]
    pub fitted: Vec<String>,
    /// The label of the paper's baseline in this experiment: the report divides each
    /// method's published and measured means by the baseline's (ratios within the paper,
    /// ours beside the paper's).
    #[serde(default)]
    pub baseline: Option<String>,
}

/// The most runs a scenario may ask for (`runs`, `quick_runs`): every run's record is kept
/// in memory, so an input's run count is capped like its map's cells.
pub const MAX_RUNS: u32 = 1_000_000;

fn default_quick_runs() -> u32 {
    10
}

/// Where an experiment comes from.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Source {
    /// Seed file name, e.g. `000_9b224721fe327833.txt`.
    pub seed_file: String,
    /// Table or figure, e.g. `Table 2`.
    pub experiment: String,
}

/// How to build a scenario's map.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum MapSpec {
    /// A picture run through the seed-000 pipeline (binarize, optional rectangles,
    /// safety band). Path relative to the scenario file.
    Picture {
        /// Picture file (PNG, PGM, PPM).
        path: String,
        /// Luminance threshold (darker is an obstacle).
        #[serde(default = "default_threshold")]
        threshold: u8,
        /// Obstacles approximated by rectangles.
        #[serde(default)]
        rectangles: bool,
        /// Safety band radius, pixels.
        #[serde(default)]
        safety_radius_px: f64,
        /// Scenario units per pixel (6.34 mm/px in seed 000).
        #[serde(default = "one")]
        resolution: f64,
    },
    /// A room picture drawn in code from its furniture ([`draw_room`](crate::draw_room)),
    /// then run through the seed-000 pipeline like [`MapSpec::Picture`].
    Room {
        /// Picture width, px.
        width: usize,
        /// Picture height, px.
        height: usize,
        /// The furniture, px, y down.
        furniture: Vec<crate::Furniture>,
        /// Luminance threshold (darker is an obstacle).
        #[serde(default = "default_threshold")]
        threshold: u8,
        /// Obstacles approximated by rectangles.
        #[serde(default)]
        rectangles: bool,
        /// Safety band radius, pixels.
        #[serde(default)]
        safety_radius_px: f64,
        /// Scenario units per pixel.
        #[serde(default = "one")]
        resolution: f64,
    },
    /// A grid drawn from shapes in scenario units.
    Grid {
        /// Columns.
        width: usize,
        /// Rows.
        height: usize,
        /// Scenario units per cell.
        #[serde(default = "one")]
        resolution: f64,
        /// Obstacles; a cell is forbidden when the shape overlaps its interior.
        obstacles: Vec<Shape>,
        /// Safety band radius, cells (0: none).
        #[serde(default)]
        safety_radius_cells: f64,
        /// Obstacle padding, cells: every obstacle cell dilated by a square of this radius
        /// (seed 002's "padding 1"), before the safety band.
        #[serde(default)]
        padding_cells: usize,
        /// Shape and query coordinates have y down from the top row.
        #[serde(default)]
        y_down: bool,
    },
    /// A map file read as `hyplan map` reads it (MovingAI `.map`, ROS `.yaml`, picture).
    File {
        /// The file, relative to the scenario file.
        path: String,
        /// Safety band radius in the file's units (cells; metres for ROS).
        #[serde(default)]
        safety_radius: Option<f64>,
    },
}

fn default_threshold() -> u8 {
    100
}

fn one() -> f64 {
    1.0
}

/// A planner to run: its configuration, a display label and the smoothing applied after.
///
/// In a scenario file: `(label: Some("RRT"), planner: (name: "rrt", step: 2.0), smoothing:
/// Some("pchip"))`.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlannerSpec {
    /// The planner and its parameters (fields of the planner's struct, missing ones at
    /// their defaults).
    pub planner: crate::PlannerConfig,
    /// Label in the report (defaults to the planner's name).
    #[serde(default)]
    pub label: Option<String>,
    /// Post-processing by `postproc`'s method names: `none` (default), `prune`, `pchip`,
    /// `bspline`, `bspline-interp`.
    #[serde(default)]
    pub smoothing: Option<String>,
}

impl PlannerSpec {
    /// A spec running `planner` under its own name, without smoothing.
    #[must_use]
    pub fn new(planner: crate::PlannerConfig) -> Self {
        Self {
            planner,
            label: None,
            smoothing: None,
        }
    }

    /// The label used in reports.
    #[must_use]
    pub fn label(&self) -> &str {
        self.label.as_deref().unwrap_or(self.planner.name())
    }
}

/// A number the paper publishes, kept verbatim for the report.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Published {
    /// Label of the planner it belongs to (a planner label of this scenario, or a method
    /// we do not run, such as `GA-PCHIP`, shown with the paper's numbers only).
    pub planner: String,
    /// Metric name, as in [`RunMetrics`](crate::RunMetrics) (`time_s`, `length`, ...).
    pub metric: String,
    /// The paper's value, in the paper's unit.
    pub value: f64,
    /// Unit or note as printed in the paper.
    #[serde(default)]
    pub note: String,
    /// Our reading of the paper's unit: the paper's value times this is in the scenario's
    /// units (e.g. 100 when a length in mm is printed in units of 100 mm). Default 1.
    #[serde(default = "one")]
    pub unit_scale: f64,
    /// The value exactly as the paper prints it (`"6009.30"`, `"3815.034"`), shown in the
    /// report; empty: `value` as Rust prints it.
    #[serde(default)]
    pub printed: String,
}

impl Published {
    /// The value as the paper prints it.
    #[must_use]
    pub fn shown(&self) -> String {
        if self.printed.is_empty() {
            self.value.to_string()
        } else {
            self.printed.clone()
        }
    }
}

/// Whether a claim is a measurement that can go either way on our runs.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum ClaimKind {
    /// Decided by a rank test on our runs; counted in the summary.
    #[default]
    Measured,
    /// Follows from how the comparison is built (the reason says why): shown, not counted.
    ByConstruction(String),
    /// Cannot be compared on our runs (the reason says why): shown, not counted.
    NotComparable(String),
}

/// A claim of the paper: `metric` increases along `order` (the first label has the
/// smallest values); or, when `across` names scenarios, `metric` of the single planner in
/// `order` increases along those scenarios (a trend over a series of experiments, such as
/// time against obstacle count); or, when `across` names one group, the planners in
/// `order` compared on the runs of every scenario of the group pooled (a cell of a table
/// with several layouts). An entry of `across` stands for the scenario of that name
/// and for every scenario whose name is it followed by `-` (several layouts of one cell,
/// pooled). Each step of the order is decided by a rank test over the runs
/// ([`decide_less`](crate::stats::decide_less)).
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Claim {
    /// The claim in words.
    pub text: String,
    /// Metric name.
    pub metric: String,
    /// Planner labels from the smallest to the largest mean (one label with `across`).
    pub order: Vec<String>,
    /// Scenario names (or groups) from the smallest to the largest values of the one
    /// planner in `order`; one group to compare several planners pooled over it; empty for
    /// a claim within this scenario.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub across: Vec<String>,
    /// Measured, by construction or not comparable (default measured).
    #[serde(default, skip_serializing_if = "is_measured")]
    pub kind: ClaimKind,
}

fn is_measured(k: &ClaimKind) -> bool {
    *k == ClaimKind::Measured
}

/// A scenario's world: the map and the query in world coordinates.
#[derive(Debug, Clone)]
pub struct World {
    /// The three-zone map (its `blocked_from` set by `avoid_risk`).
    pub map: GridMap,
    /// Start and goal in world coordinates (y up).
    pub query: Query,
    /// Whether scenario coordinates have y down (for converting back in figures).
    pub y_down: bool,
    /// Obstacle rectangles found by the pipeline (cells), for figures.
    pub rectangles: Vec<envmap::CellRect>,
}

impl World {
    /// World point of scenario coordinates.
    #[must_use]
    pub fn to_world(&self, x: f64, y: f64) -> Point2 {
        to_world(&self.map, self.y_down, x, y)
    }
}

fn to_world(map: &GridMap, y_down: bool, x: f64, y: f64) -> Point2 {
    let o = map.origin();
    if y_down {
        Point2::new(o.x + x, o.y + map.height() as f64 * map.resolution() - y)
    } else {
        Point2::new(o.x + x, o.y + y)
    }
}

/// A problem with a scenario file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ScenarioError {
    /// The file could not be read.
    #[error("{path}: cannot read: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        #[source]
        source: std::io::Error,
    },
    /// The file is not valid RON for a scenario.
    #[error("{path}:{line}:{col}: {message}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        col: usize,
        /// What the parser says.
        message: String,
    },
    /// The map would have more cells than the memory limit (the `max_cells` of
    /// [`Scenario::load_limited`]): refused before it is drawn or decoded.
    #[error(
        "{path}: field `{field}` = {value}: the map is {width} x {height} = {} cells, above the memory limit of {limit} cells",
        (*width as u128) * (*height as u128)
    )]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// The field that sets the size (`map.width x map.height`, or `map.path` for a
        /// map file).
        field: String,
        /// Its value as given.
        value: String,
        /// Columns.
        width: usize,
        /// Rows.
        height: usize,
        /// The limit, cells.
        limit: usize,
    },
    /// A field has a value the scenario cannot use.
    #[error("{path}: field `{field}` = {value}: {reason}")]
    Invalid {
        /// The file.
        path: PathBuf,
        /// Field name (dotted for nested fields).
        field: String,
        /// The value, formatted.
        value: String,
        /// What is wrong.
        reason: String,
    },
}

impl Scenario {
    /// Reads and validates a scenario file: RON syntax, known planners and parameters,
    /// positive runs; the map is built and the start and goal checked by
    /// [`build_world`](Scenario::build_world).
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] naming the file, and the line or field.
    pub fn load(path: &Path) -> Result<(Self, World), ScenarioError> {
        Self::load_limited(path, envmap::DEFAULT_MAX_CELLS)
    }

    /// [`Scenario::load`] with a memory limit: a map of more than `max_cells` cells (a
    /// grid's or room's `width x height`, or a map file's size) is refused with
    /// [`ScenarioError::TooLarge`] before it is drawn or decoded.
    ///
    /// # Errors
    ///
    /// As [`Scenario::load`].
    pub fn load_limited(path: &Path, max_cells: usize) -> Result<(Self, World), ScenarioError> {
        let text = std::fs::read_to_string(path).map_err(|source| ScenarioError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let scenario = Self::parse(&text, path)?;
        scenario.validate(path)?;
        let world = scenario.build_world_limited(
            path.parent().unwrap_or(Path::new(".")),
            path,
            max_cells,
        )?;
        Ok((scenario, world))
    }

    /// Reads a scenario from RON text (with [`ron_options`](crate::ron_options)), without
    /// validating it; `path` names the file in errors.
    ///
    /// # Errors
    ///
    /// [`ScenarioError::Parse`] with the line and column.
    pub fn parse(text: &str, path: &Path) -> Result<Self, ScenarioError> {
        crate::ron_options()
            .from_str(text)
            .map_err(|e| ScenarioError::Parse {
                path: path.to_path_buf(),
                line: e.position.line,
                col: e.position.col,
                message: e.code.to_string(),
            })
    }

    pub(crate) fn invalid(
        path: &Path,
        field: &str,
        value: impl ToString,
        reason: &str,
    ) -> ScenarioError {
        ScenarioError::Invalid {
            path: path.to_path_buf(),
            field: field.to_string(),
            value: value.to_string(),
            reason: reason.to_string(),
        }
    }

    /// Checks the fields that need no map.
    ///
    /// # Errors
    ///
    /// [`ScenarioError::Invalid`] for the first bad field.
    pub fn validate(&self, path: &Path) -> Result<(), ScenarioError> {
        let bad = |field: &str, value: &dyn ToString, reason: &str| {
            Err(Self::invalid(path, field, value.to_string(), reason))
        };
        for (field, n) in [("runs", self.runs), ("quick_runs", self.quick_runs)] {
            if n == 0 {
                return bad(field, &0, "must be at least 1");
            }
            // The runs' records are kept in memory: a cap, as for the map's cells.
            if n > MAX_RUNS {
                return bad(field, &n, "must be at most 1000000 (harness::MAX_RUNS)");
            }
        }
        if self.planners.is_empty() {
            return bad("planners", &"[]", "at least one planner is needed");
        }
        for (k, v) in [("start", self.start), ("goal", self.goal)] {
            if !(v.0.is_finite() && v.1.is_finite()) {
                return bad(k, &format!("{v:?}"), "coordinates must be finite");
            }
        }
        if !(self.goal_radius.is_finite() && self.goal_radius >= 0.0) {
            return bad("goal_radius", &self.goal_radius, "must be finite and >= 0");
        }
        if let Some(l) = self.limits {
            for (k, v) in [
                ("limits.v_max", l.v_max),
                ("limits.omega_max", l.omega_max),
                ("limits.a_max", l.a_max),
            ] {
                if !(v.is_finite() && v > 0.0) {
                    return bad(k, &v, "must be finite and > 0");
                }
            }
            // postproc's own rule is the one that counts; the loop above names the field.
            if let Err(e) = l.validate() {
                return bad("limits", &format!("{l:?}"), &e.to_string());
            }
        }
        for (i, p) in self.planners.iter().enumerate() {
            // The planner's name and fields were checked by deserialisation; their values
            // are checked by the planner itself when it runs (typed errors).
            if let Some(s) = &p.smoothing
                && s.parse::<postproc::Smoothing>().is_err()
            {
                return bad(
                    &format!("planners[{i}].smoothing"),
                    s,
                    "expected none, prune, pchip, bspline or bspline-interp",
                );
            }
        }
        for c in &self.claims {
            if c.across.len() > 1 && c.order.len() != 1 {
                return bad(
                    "claims.order",
                    &c.order.join(", "),
                    "a trend across scenarios names exactly one planner",
                );
            }
            if c.across.len() == 1 && c.order.len() < 2 {
                return bad(
                    "claims.order",
                    &c.order.join(", "),
                    "a claim over one group of scenarios names two planners or more",
                );
            }
            for label in &c.order {
                if !self.planners.iter().any(|p| p.label() == label) {
                    return bad(
                        "claims.order",
                        label,
                        "not the label of a planner of this scenario",
                    );
                }
            }
        }
        Ok(())
    }

    /// Builds the map and places the query; `dir` is the folder paths are relative to and
    /// `path` the scenario file (for messages).
    ///
    /// # Errors
    ///
    /// [`ScenarioError::Invalid`] for a map that cannot be read or built, or a start or goal
    /// outside the map or blocked; [`ScenarioError::TooLarge`] for a map of more than
    /// [`envmap::DEFAULT_MAX_CELLS`] cells.
    pub fn build_world(&self, dir: &Path, path: &Path) -> Result<World, ScenarioError> {
        self.build_world_limited(dir, path, envmap::DEFAULT_MAX_CELLS)
    }

    /// [`Scenario::build_world`] with a memory limit of `max_cells` cells (see
    /// [`Scenario::load_limited`]).
    ///
    /// # Errors
    ///
    /// As [`Scenario::build_world`].
    pub fn build_world_limited(
        &self,
        dir: &Path,
        path: &Path,
        max_cells: usize,
    ) -> Result<World, ScenarioError> {
        let (mut map, y_down, rectangles) =
            crate::map_build::build_map(&self.map, dir, path, max_cells)?;
        if self.avoid_risk {
            map = map.avoiding_risk();
        }
        let start = to_world(&map, y_down, self.start.0, self.start.1);
        let goal_center = to_world(&map, y_down, self.goal.0, self.goal.1);
        let goal = if self.goal_radius > 0.0 {
            Goal::disc(goal_center, self.goal_radius)
        } else {
            Goal::Point(goal_center)
        };
        let query = Query::new(start, goal);
        query.validate(&map).map_err(|e| {
            Self::invalid(
                path,
                "start/goal",
                format!("{:?} / {:?}", self.start, self.goal),
                &e.to_string(),
            )
        })?;
        Ok(World {
            map,
            query,
            y_down,
            rectangles,
        })
    }
}
