//! Scenario files (RON): the world, the people, the robot's task and every parameter.
//!
//! Unknown keys are refused (`deny_unknown_fields`); every value is checked by
//! [`Scenario::build_world`], and errors name the file, the field and the value.
//!
//! ```ron
//! SimScenario(
//!     name: "corridor",
//!     world: (size: (10.0, 4.0), shapes: [Wall(from: (0.0, 0.0), to: (10.0, 0.0), thickness: 0.1)]),
//!     people: [(path: [(8.0, 3.5), (8.0, 0.5)], speed: 0.5, start: 2.0)],
//!     start: (1.0, 2.0), start_heading_deg: 0.0, goal: (9.0, 2.0),
//! )
//! ```

use std::path::{Path, PathBuf};

use hyplan_core::{Bounds, Point2};
use serde::{Deserialize, Serialize};

use crate::control::Controller;
use crate::costmap::{CostmapParams, MEMORY_RESOLUTION};
use crate::explore::Exploration;
use crate::kinematics::{Pose, Robot, wrap_angle};
use crate::laser::Laser;
use crate::mapping::Mapping;
use crate::navigator::Navigation;
use crate::rollout::LocalPlanner;
use crate::social_force::PeopleModelKind;
use crate::world::{Person, Shape, StaticWorld, World, pt};

/// A map file as the static world (instead of, or beside, shapes).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum MapSpec {
    /// A ROS `map_server` YAML file (its image beside it), metres; path relative to the
    /// scenario file.
    Ros(String),
    /// A picture (PNG / PGM / PPM), dark pixels are obstacles, with its scale.
    Picture {
        /// Image file, relative to the scenario file.
        path: String,
        /// Metres per pixel.
        resolution: f64,
        /// World position of the picture's lower-left corner, m (default (0, 0)).
        #[serde(default)]
        origin: (f64, f64),
    },
    /// A generated multi-room building, its lower-left corner at (0, 0): envmap's
    /// [`floor_plan`](envmap::floor_plan) at [`BUILDING_RESOLUTION`] (0.05 m) per cell.
    /// Outer walls, then regions split recursively until a split would leave a room
    /// under `max(4 door, 5 m)` a side (so rooms of 5 to about 10 m with 0.8 m doors); each
    /// split wall is pierced by one door, at least a wall's thickness from either end, and
    /// a region four smallest rooms wide is split by a corridor one to two doors wide
    /// between two walls. Every room is reachable. Lengths are whole cells;
    /// `door + 2 wall` must be under 5 m. The same seed gives the same building.
    ///
    /// ```ron
    /// world: (map: Some(Building(size: (60.0, 60.0), door: 0.8, wall: 0.15, seed: 0)))
    /// ```
    ///
    /// [`BUILDING_RESOLUTION`]: crate::BUILDING_RESOLUTION
    Building {
        /// Width and height, m.
        size: (f64, f64),
        /// Width of every door, m (default 0.8).
        #[serde(default = "default_door")]
        door: f64,
        /// Thickness of every wall, m (default 0.15).
        #[serde(default = "default_wall")]
        wall: f64,
        /// Seed of the layout (default 0).
        #[serde(default)]
        seed: u64,
    },
}

fn default_door() -> f64 {
    0.8
}

fn default_wall() -> f64 {
    0.15
}

/// The static world.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WorldSpec {
    /// Width and height of the world, m (from the map when absent and a map is given).
    #[serde(default)]
    pub size: Option<(f64, f64)>,
    /// Lower-left corner of the world, m (default (0, 0)).
    #[serde(default)]
    pub origin: (f64, f64),
    /// Obstacles on the robot's prior map.
    #[serde(default)]
    pub shapes: Vec<Shape>,
    /// Obstacles placed after the map was made: the robot meets them with its laser.
    #[serde(default)]
    pub unmapped: Vec<Shape>,
    /// A map file, on the prior map.
    #[serde(default)]
    pub map: Option<MapSpec>,
}

fn default_time_limit() -> f64 {
    120.0
}

fn default_true() -> bool {
    true
}

/// A simulation scenario.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "SimScenario", deny_unknown_fields)]
pub struct Scenario {
    /// Short name (used in reports and file names).
    pub name: String,
    /// What the scenario is.
    #[serde(default)]
    pub description: String,
    /// Which values come from the paper and which are reconstructions.
    #[serde(default)]
    pub notes: Vec<String>,
    /// The static world.
    pub world: WorldSpec,
    /// People.
    #[serde(default)]
    pub people: Vec<Person>,
    /// How the people move (default `Scripted`: their routes, blind to everything;
    /// a file without this key means it): `SocialForce(( .. ))` for Helbing and Molnár's
    /// social forces ([`crate::SocialForce`]), e.g. `SocialForce((sees_robot: false))`.
    #[serde(default)]
    pub people_model: PeopleModelKind,
    /// Start position, m.
    pub start: (f64, f64),
    /// Start heading, degrees counter-clockwise from +x.
    #[serde(default)]
    pub start_heading_deg: f64,
    /// Goal position, m.
    pub goal: (f64, f64),
    /// Whether the robot knows `world.shapes` and `world.map` in advance (default true);
    /// when false it starts from an empty map and relies on its laser.
    #[serde(default = "default_true")]
    pub known_map: bool,
    /// Simulated seconds before the run is stopped (default 120).
    #[serde(default = "default_time_limit")]
    pub time_limit: f64,
    /// Robot geometry and limits.
    #[serde(default)]
    pub robot: Robot,
    /// Laser.
    #[serde(default)]
    pub laser: Laser,
    /// Map building.
    #[serde(default)]
    pub mapping: Mapping,
    /// Costmap.
    #[serde(default)]
    pub costmap: CostmapParams,
    /// Regulated pure pursuit's parameters, and the control rate of every local planner.
    #[serde(default)]
    pub controller: Controller,
    /// Which local planner drives (default `Rpp`, [`Scenario::controller`]'s pure
    /// pursuit; a file without this key means it): `Trajectory(( .. ))` or `Dwa(( .. ))`
    /// for `base_local_planner`'s roll-out.
    #[serde(default)]
    pub local_planner: LocalPlanner,
    /// Navigator.
    #[serde(default)]
    pub navigation: Navigation,
    /// Exploration (used by [`crate::explore::explore`]).
    #[serde(default)]
    pub exploration: Exploration,
}

/// Why a scenario was refused.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ScenarioError {
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The io error.
        #[source]
        source: std::io::Error,
    },
    /// Malformed RON, an unknown key, a missing key or a wrong type.
    #[error("{path}: {message}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// RON's message with line and column (it names an unknown key and the keys
        /// expected).
        message: String,
    },
    /// A value out of range.
    #[error("{path}: field `{field}` = {value}: {reason}")]
    Field {
        /// The file.
        path: PathBuf,
        /// The field, as a path (`people[1].speed`).
        field: String,
        /// The value given.
        value: String,
        /// What it must be.
        reason: String,
    },
    /// A grid the run would allocate over the world, or the laser's scan, has more cells
    /// (beams) than the memory limit (the `max_cells` of [`Scenario::load_limited`]):
    /// refused before any is allocated.
    #[error("{path}: field `{field}` = {value}: {what}, above the memory limit of {limit} cells")]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// The field that makes it this large: a grid's resolution when the scenario
        /// changed it from its default, else where the world's size comes from
        /// (`world.size`, `world.map`, `world.map.resolution`); `laser.beams`.
        field: String,
        /// Its value as given.
        value: String,
        /// What would be allocated, with its size (the grid, the world, the resolution,
        /// columns x rows = cells).
        what: String,
        /// How many cells (a float: the count may exceed every integer type).
        cells: f64,
        /// The limit, cells.
        limit: usize,
    },
    /// The map file could not be loaded.
    #[error("{path}: world.map: {source}")]
    Map {
        /// The scenario file.
        path: PathBuf,
        /// The loader's error (it names the map file).
        #[source]
        source: envmap::MapError,
    },
}

impl Scenario {
    /// Reads, parses and validates a scenario file, and builds its world.
    ///
    /// # Errors
    ///
    /// Any [`ScenarioError`].
    pub fn load(path: &Path) -> Result<(Self, World), ScenarioError> {
        Self::load_limited(path, envmap::DEFAULT_MAX_CELLS)
    }

    /// [`Scenario::load`] with a memory limit: no map file, and no grid the run allocates
    /// over the world (built map, costmap, obstacle memory), may have more than
    /// `max_cells` cells (see [`Scenario::build_world_limited`]).
    ///
    /// # Errors
    ///
    /// Any [`ScenarioError`]; [`ScenarioError::TooLarge`] above the limit.
    pub fn load_limited(path: &Path, max_cells: usize) -> Result<(Self, World), ScenarioError> {
        let text = std::fs::read_to_string(path).map_err(|source| ScenarioError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        let scenario = Self::parse(&text, path)?;
        let world = scenario.build_world_limited(path, max_cells)?;
        Ok((scenario, world))
    }

    /// Parses RON text; `path` names the file in errors.
    ///
    /// # Errors
    ///
    /// [`ScenarioError::Parse`].
    pub fn parse(text: &str, path: &Path) -> Result<Self, ScenarioError> {
        ron::Options::default()
            .with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
            .from_str(text)
            .map_err(|e| ScenarioError::Parse {
                path: path.to_path_buf(),
                message: e.to_string(),
            })
    }

    /// A generated scenario (the soak's rooms, the crowds): a world of `shapes` over
    /// `size` from the origin, known to the robot, `people` walking their scripted routes,
    /// from `start` (heading `start_heading_deg`) to `goal` within `time_limit`; every
    /// other value its default.
    pub(crate) fn generated(
        (name, description): (String, String),
        (size, shapes): ((f64, f64), Vec<crate::world::Shape>),
        people: Vec<Person>,
        (start, start_heading_deg, goal): ((f64, f64), f64, (f64, f64)),
        time_limit: f64,
    ) -> Self {
        Self {
            name,
            description,
            notes: Vec::new(),
            world: WorldSpec {
                size: Some(size),
                origin: (0.0, 0.0),
                shapes,
                unmapped: Vec::new(),
                map: None,
            },
            people,
            people_model: PeopleModelKind::default(),
            start,
            start_heading_deg,
            goal,
            known_map: true,
            exploration: crate::explore::Exploration::default(),
            time_limit,
            robot: Robot::default(),
            laser: Default::default(),
            mapping: Default::default(),
            costmap: Default::default(),
            controller: Default::default(),
            local_planner: Default::default(),
            navigation: Default::default(),
        }
    }

    /// The robot's pose at the start: `start`, heading `start_heading_deg` (wrapped).
    #[must_use]
    pub fn start_pose(&self) -> Pose {
        Pose {
            x: self.start.0,
            y: self.start.1,
            phi: wrap_angle(self.start_heading_deg.to_radians()),
        }
    }

    /// Checks every value and builds the world; `path` names the file in errors and
    /// anchors relative map paths.
    ///
    /// # Errors
    ///
    /// [`ScenarioError::Field`], [`ScenarioError::Map`] or [`ScenarioError::TooLarge`]
    /// (with the limit [`envmap::DEFAULT_MAX_CELLS`]).
    pub fn build_world(&self, path: &Path) -> Result<World, ScenarioError> {
        self.build_world_limited(path, envmap::DEFAULT_MAX_CELLS)
    }

    /// [`Scenario::build_world`] with a memory limit of `max_cells` cells for the map file
    /// (as [`envmap::LoadOptions::max_cells`]) and for every grid a run allocates over the
    /// world's bounds: the built map (`mapping.resolution`), the costmap
    /// (`costmap.resolution`) and the obstacle memory and people tracker
    /// ([`MEMORY_RESOLUTION`]); the laser's beams count
    /// against the same limit. A huge world, a tiny resolution or a huge laser is refused
    /// here, before anything is allocated.
    ///
    /// # Errors
    ///
    /// As [`Scenario::build_world`].
    pub fn build_world_limited(
        &self,
        path: &Path,
        max_cells: usize,
    ) -> Result<World, ScenarioError> {
        crate::validate::validate_values(self, path)?;
        let field = |f: &str, v: String, r: &str| ScenarioError::Field {
            path: path.to_path_buf(),
            field: f.to_string(),
            value: v,
            reason: r.to_string(),
        };
        let mut statics = StaticWorld::default();
        let mut mapped = StaticWorld::default();
        let mut bounds = None;
        let opts = envmap::LoadOptions {
            max_cells,
            ..envmap::LoadOptions::default()
        };
        if let Some(map) = &self.world.map {
            let base = path.parent().unwrap_or(Path::new(""));
            let grid = match map {
                MapSpec::Ros(file) => {
                    envmap::load_map(&base.join(file), &opts)
                        .map_err(|source| ScenarioError::Map {
                            path: path.to_path_buf(),
                            source,
                        })?
                        .map
                }
                MapSpec::Picture {
                    path: file,
                    resolution,
                    origin,
                } => envmap::load_map(&base.join(file), &opts)
                    .map_err(|source| ScenarioError::Map {
                        path: path.to_path_buf(),
                        source,
                    })?
                    .map
                    .with_frame(*resolution, pt(*origin))
                    .map_err(|e| {
                        field(
                            "world.map.resolution",
                            resolution.to_string(),
                            &e.to_string(),
                        )
                    })?,
                MapSpec::Building {
                    size,
                    door,
                    wall,
                    seed,
                } => crate::building::building(*size, *door, *wall, *seed, path, max_cells)?,
            };
            bounds = Some(grid.bounds());
            statics.add_grid(grid.clone());
            mapped.add_grid(grid);
        }
        if let Some((w, h)) = self.world.size {
            let o = pt(self.world.origin);
            bounds = Some(Bounds::new(o, Point2::new(o.x + w, o.y + h)));
        }
        let bounds =
            bounds.ok_or_else(|| field("world.size", "missing".into(), "give a size or a map"))?;
        self.check_sizes(path, bounds, max_cells)?;
        for s in &self.world.shapes {
            statics.add_shape(s);
            mapped.add_shape(s);
        }
        for s in &self.world.unmapped {
            statics.add_shape(s);
        }
        if !self.known_map {
            mapped = StaticWorld::default();
        }
        let r = self.robot.body_radius;
        for (name, p) in [("start", self.start), ("goal", self.goal)] {
            let q = pt(p);
            let show = format!("({}, {})", p.0, p.1);
            if !(q.x - r >= bounds.min.x
                && q.x + r <= bounds.max.x
                && q.y - r >= bounds.min.y
                && q.y + r <= bounds.max.y)
            {
                return Err(field(
                    name,
                    show,
                    &format!(
                        "outside the world [{}, {}] x [{}, {}] (with the robot's radius {r})",
                        bounds.min.x, bounds.max.x, bounds.min.y, bounds.max.y
                    ),
                ));
            }
            if statics.inside(q) || statics.nearest(q).0 < r {
                return Err(field(
                    name,
                    show,
                    &format!("inside an obstacle (the robot's radius is {r} m)"),
                ));
            }
        }
        Ok(World {
            bounds,
            statics,
            mapped,
            people: self.people.clone(),
        })
    }

    /// Refuses a world whose grids would exceed `max_cells` cells: the obstacle memory's
    /// (fixed 5 cm cells, so only the world's size can be at fault), then the built map's
    /// and the costmap's; and a laser of more than `max_cells` beams (each scan holds a
    /// range and a direction per beam). Counts are computed as the grids compute them, in
    /// floating point so that no product overflows.
    fn check_sizes(
        &self,
        path: &Path,
        bounds: Bounds,
        max_cells: usize,
    ) -> Result<(), ScenarioError> {
        let too_large =
            |field: String, value: String, what: String, cells: f64| ScenarioError::TooLarge {
                path: path.to_path_buf(),
                field,
                value,
                what,
                cells,
                limit: max_cells,
            };
        let beams = self.laser.beams as f64;
        if beams > max_cells as f64 {
            return Err(too_large(
                "laser.beams".into(),
                self.laser.beams.to_string(),
                format!(
                    "a scan of {} beams, each counted as a cell",
                    show_count(beams)
                ),
                beams,
            ));
        }
        let size_source = || match (&self.world.size, &self.world.map) {
            (Some((w, h)), _) => ("world.size".to_string(), format!("({w}, {h})")),
            (None, Some(MapSpec::Picture { resolution, .. })) => {
                ("world.map.resolution".to_string(), resolution.to_string())
            }
            (None, Some(MapSpec::Ros(file))) => ("world.map".to_string(), file.clone()),
            (None, Some(MapSpec::Building { size: (w, h), .. })) => {
                ("world.map.size".to_string(), format!("({w}, {h})"))
            }
            (None, None) => ("world.size".to_string(), "missing".to_string()),
        };
        // (which grid, the field of its resolution, the resolution, its default)
        let grids = [
            ("the obstacle memory", None, MEMORY_RESOLUTION, None),
            (
                "the built map (mapping.resolution)",
                Some("mapping.resolution"),
                self.mapping.resolution,
                Some(Mapping::default().resolution),
            ),
            (
                "the costmap (costmap.resolution)",
                Some("costmap.resolution"),
                self.costmap.resolution,
                Some(CostmapParams::default().resolution),
            ),
        ];
        for (grid, res_field, res, default) in grids {
            // As `OccupancyGrid::new` and `costmap::rasterize` size their grids.
            let columns = (bounds.width() / res).ceil().max(1.0);
            let rows = (bounds.height() / res).ceil().max(1.0);
            let cells = columns * rows;
            if cells <= max_cells as f64 {
                continue;
            }
            // A resolution the scenario changed is the likely culprit; else the size.
            let (field, value) = match (res_field, default) {
                (Some(f), Some(d)) if res != d => (f.to_string(), res.to_string()),
                _ => size_source(),
            };
            let what = format!(
                "{grid} over the {} m x {} m world at {res} m per cell would be {} x {} = {} cells",
                bounds.width(),
                bounds.height(),
                show_count(columns),
                show_count(rows),
                show_count(cells)
            );
            return Err(too_large(field, value, what, cells));
        }
        Ok(())
    }
}

/// A cell count for messages: exact below 10^15, else in scientific notation (a count
/// computed in floating point is not exact beyond that).
fn show_count(n: f64) -> String {
    if n < 1e15 {
        format!("{n:.0}")
    } else {
        format!("{n:.3e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scenario(world: &str, extra: &str) -> Scenario {
        let text = format!(
            "SimScenario(name: \"t\", world: ({world}), start: (1.0, 1.0), goal: (2.0, 2.0),{extra})"
        );
        Scenario::parse(&text, Path::new("t.ron")).unwrap()
    }

    fn too_large(sc: &Scenario, max_cells: usize) -> (String, String, String) {
        match sc.build_world_limited(Path::new("big.ron"), max_cells) {
            Err(e @ ScenarioError::TooLarge { .. }) => {
                let text = e.to_string();
                let ScenarioError::TooLarge { field, value, .. } = e else {
                    unreachable!()
                };
                (field, value, text)
            }
            other => panic!("expected TooLarge, got {other:?}"),
        }
    }

    /// Every grid a run allocates over the world is counted before it is allocated: the
    /// message names the file, the field at fault, its value and the cell counts.
    #[test]
    fn grids_above_the_limit_are_refused() {
        let limit = envmap::DEFAULT_MAX_CELLS;
        // A huge world: the obstacle memory's fixed 5 cm cells.
        let (field, value, text) = too_large(&scenario("size: (1e6, 1e6)", ""), limit);
        assert_eq!(
            (field.as_str(), value.as_str()),
            ("world.size", "(1000000, 1000000)")
        );
        assert!(text.starts_with("big.ron: field `world.size`"), "{text}");
        assert!(
            text.contains("20000000 x 20000000 = 400000000000000 cells"),
            "{text}"
        );
        assert!(text.contains(&format!("limit of {limit} cells")), "{text}");
        // A size beyond every integer: no overflow, a count in scientific notation.
        let (field, _, text) = too_large(&scenario("size: (1e300, 1.0)", ""), limit);
        assert_eq!(field, "world.size");
        assert!(text.contains("e301"), "{text}");
        // A tiny resolution on a small world names the resolution.
        let sc = scenario("size: (22.0, 22.0)", " mapping: (resolution: 0.0001)");
        let (field, value, text) = too_large(&sc, limit);
        assert_eq!(
            (field.as_str(), value.as_str()),
            ("mapping.resolution", "0.0001")
        );
        assert!(text.contains("220000 x 220000"), "{text}");
        let sc = scenario("size: (22.0, 22.0)", " costmap: (resolution: 0.0001)");
        let (field, value, _) = too_large(&sc, limit);
        assert_eq!(
            (field.as_str(), value.as_str()),
            ("costmap.resolution", "0.0001")
        );
        // A laser of more beams than the limit.
        let sc = scenario("size: (6.0, 3.0)", " laser: (beams: 1000000000000)");
        let (field, value, text) = too_large(&sc, limit);
        assert_eq!(
            (field.as_str(), value.as_str()),
            ("laser.beams", "1000000000000")
        );
        assert!(text.contains("a scan of 1000000000000 beams"), "{text}");
        // A lower limit: the hall's 5 cm grids (120 x 60) fit exactly.
        let sc = scenario("size: (6.0, 3.0)", "");
        assert!(sc.build_world_limited(Path::new("t.ron"), 7200).is_ok());
        let (field, _, text) = too_large(&sc, 7199);
        assert_eq!(field, "world.size");
        assert!(text.contains("120 x 60 = 7200 cells"), "{text}");
        assert!(sc.build_world(Path::new("t.ron")).is_ok());
    }

    /// A map file above the limit is refused by the loader (naming the map file); a small
    /// picture stretched by a huge resolution is refused by its grids, naming the field.
    #[test]
    fn map_files_count_too() {
        let dir = std::env::temp_dir().join(format!("sim-scenario-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("room.pgm"),
            b"P5\n4 3\n255\n\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff",
        )
        .unwrap();
        let path = dir.join("t.ron");
        let sc = scenario(
            "map: Some(Picture(path: \"room.pgm\", resolution: 1.0))",
            "",
        );
        match sc.build_world_limited(&path, 11) {
            Err(ScenarioError::Map {
                source:
                    envmap::MapError::TooLarge {
                        width: 4,
                        height: 3,
                        ..
                    },
                ..
            }) => {}
            other => panic!("expected the loader's TooLarge, got {other:?}"),
        }
        // The 4 m x 3 m world's obstacle memory: 80 x 60 cells.
        assert!(sc.build_world_limited(&path, 4800).is_ok());
        let sc = scenario(
            "map: Some(Picture(path: \"room.pgm\", resolution: 1e4))",
            "",
        );
        match sc.build_world_limited(&path, envmap::DEFAULT_MAX_CELLS) {
            Err(ScenarioError::TooLarge { field, value, .. }) => {
                assert_eq!(
                    (field.as_str(), value.as_str()),
                    ("world.map.resolution", "10000")
                );
            }
            other => panic!("expected TooLarge, got {other:?}"),
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
