//! What a run leaves behind: the trace (CSV and JSON), the figures of the paper (the
//! trajectory over the built map with the people's tracks, v(t) and omega(t)), and an
//! animated SVG of the run that any browser plays. The figures are `viz` scenes and
//! charts; this module says what they show.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use hyplan_core::Point2;
use viz::{FigureError, GridImage, Mark, Rgba, Scene, Stroke, TimePanel, rgb, with_alpha};

use crate::mapping::{FREE, OCCUPIED, OccupancyGrid};
use crate::navigator::NavEvent;
use crate::run::Outcome;
use crate::world::World;

/// One sample of the robot's state (recorded at the laser rate).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Row {
    /// Time, s.
    pub t: f64,
    /// x, m.
    pub x: f64,
    /// y, m.
    pub y: f64,
    /// Heading, rad.
    pub phi: f64,
    /// Forward speed, m/s.
    pub v: f64,
    /// Turn rate, rad/s.
    pub omega: f64,
    /// Right wheel, rad/s.
    pub wheel_right: f64,
    /// Left wheel, rad/s.
    pub wheel_left: f64,
    /// Gap between the body and the nearest static obstacle, m (negative: contact).
    pub d_obstacle: f64,
    /// Gap between the body and the nearest person, m (none without people).
    pub d_person: Option<f64>,
}

/// Who was moving when a contact began.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum ContactClass {
    /// The robot was driving toward the obstacle (its speed toward the contact point
    /// above 1 mm/s): the robot's fault.
    AtFault,
    /// The robot stood still (|v| <= 1 mm/s; it may have been turning in place, which a
    /// round body cannot hit anything with): someone walked into it.
    RobotStopped,
    /// The robot was moving, but not toward the obstacle (a person ran into its side).
    NotApproaching,
}

/// A contact, at its start.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Contact {
    /// Time, s.
    pub t: f64,
    /// "static" or "person K".
    pub with: String,
    /// Who was moving.
    pub class: ContactClass,
}

/// What happened.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum EventKind {
    /// A navigator event.
    Nav(NavEvent),
    /// A contact began.
    Contact(ContactClass),
}

/// An event at a time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Event {
    /// Time, s.
    pub t: f64,
    /// What.
    pub kind: EventKind,
}

/// A person's personal space, m from the edge of their body: the near phase of Hall's
/// personal distance, 0.45-0.75 m (E. T. Hall, *The Hidden Dimension*, 1966, ch. X),
/// the zone crowd-navigation work counts the robot's intrusions into.
///
/// ```
/// assert_eq!(sim::PERSONAL_SPACE, 0.45);
/// ```
pub const PERSONAL_SPACE: f64 = 0.45;

/// Totals of a run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    /// Scenario name.
    pub scenario: String,
    /// Seed.
    pub seed: u64,
    /// Global planner.
    pub planner: String,
    /// Goal reached.
    pub reached: bool,
    /// Time the goal was reached, s.
    pub travel_time: Option<f64>,
    /// Time the run ended, s.
    pub end_time: f64,
    /// Distance driven, m.
    pub distance: f64,
    /// Re-plans.
    pub replans: usize,
    /// Stops for a blocked path.
    pub stops: usize,
    /// Planning failures.
    pub failures: usize,
    /// Smallest gap to a static obstacle, m.
    pub min_obstacle_distance: f64,
    /// Smallest gap to a person, m.
    pub min_person_distance: Option<f64>,
    /// Time the robot's body spent within [`PERSONAL_SPACE`] of a person's edge, s (crowd
    /// navigation's intrusion time; 0 without people).
    #[serde(default)]
    pub personal_space_time: f64,
    /// Contacts the robot caused.
    pub contacts_at_fault: usize,
    /// Contacts while the robot stood still.
    pub contacts_robot_stopped: usize,
    /// Contacts while the robot moved, but not toward the obstacle.
    pub contacts_not_approaching: usize,
}

/// A run's trace.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Trace {
    /// Totals.
    pub summary: Summary,
    /// Samples.
    pub rows: Vec<Row>,
    /// Events.
    pub events: Vec<Event>,
    /// Contacts.
    pub contacts: Vec<Contact>,
}

impl Trace {
    /// The samples as CSV, one line per row, events of the row's time slot in the last
    /// column (`;`-separated).
    #[must_use]
    pub fn to_csv(&self) -> String {
        let mut s =
            String::from("t,x,y,phi,v,omega,wheel_right,wheel_left,d_obstacle,d_person,events\n");
        let mut e = 0;
        for (k, r) in self.rows.iter().enumerate() {
            let until = self.rows.get(k + 1).map_or(f64::INFINITY, |n| n.t);
            let mut evs = Vec::new();
            while e < self.events.len() && self.events[e].t < until {
                evs.push(match self.events[e].kind {
                    EventKind::Nav(n) => format!("{n:?}"),
                    EventKind::Contact(c) => format!("Contact{c:?}"),
                });
                e += 1;
            }
            let _ = writeln!(
                s,
                "{:.3},{},{},{},{},{},{},{},{},{},{}",
                r.t,
                r.x,
                r.y,
                r.phi,
                r.v,
                r.omega,
                r.wheel_right,
                r.wheel_left,
                r.d_obstacle,
                r.d_person.map_or(String::new(), |d| d.to_string()),
                evs.join(";")
            );
        }
        s
    }
}

/// An output file of a run that could not be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// Creating the directory or writing a file failed.
    #[error("writing {}: {source}", path.display())]
    Io {
        /// The directory or file.
        path: PathBuf,
        /// What the file system said.
        source: std::io::Error,
    },
    /// The trace could not be serialised.
    #[error("writing {}: {source}", path.display())]
    Json {
        /// The file.
        path: PathBuf,
        /// What serde_json said.
        source: serde_json::Error,
    },
    /// The built map could not be written as ROS YAML + PGM.
    #[error(transparent)]
    Map(#[from] envmap::MapError),
    /// A figure could not be drawn.
    #[error(transparent)]
    Figure(#[from] viz::FigureError),
}

/// Writes `trace.csv`, `trace.json`, `map.yaml` + `map.pgm`, `trajectory.svg`,
/// `velocity.svg` and `animation.svg` into `dir`; returns the files written.
///
/// # Errors
///
/// [`OutputError`] naming the directory or file that could not be written.
pub fn write_all(
    outcome: &Outcome,
    world: &World,
    dir: &Path,
) -> Result<Vec<PathBuf>, OutputError> {
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| OutputError::Io { path, source }
    };
    std::fs::create_dir_all(dir).map_err(io(dir))?;
    let mut files = Vec::new();
    let mut put = |name: &str, text: String| -> Result<(), OutputError> {
        let p = dir.join(name);
        std::fs::write(&p, text).map_err(io(&p))?;
        files.push(p);
        Ok(())
    };
    put("trace.csv", outcome.trace.to_csv())?;
    let json = serde_json::to_string(outcome).map_err(|source| OutputError::Json {
        path: dir.join("trace.json"),
        source,
    })?;
    put("trace.json", json)?;
    put("trajectory.svg", trajectory_scene(outcome, world).to_svg()?)?;
    put("velocity.svg", velocity_svg(&outcome.trace)?)?;
    put("animation.svg", animation_scene(outcome, world).to_svg()?)?;
    if let Some(map) = &outcome.map {
        let p = dir.join("map.yaml");
        map.write_ros(&p)?;
        files.push(p.clone());
        files.push(p.with_extension("pgm"));
    }
    Ok(files)
}

/// Pixels per metre in the map figures.
const SCALE: f64 = 30.0;
/// A width in metres as pixels of the map figures.
const fn px(metres: f64) -> f64 {
    metres * SCALE
}

/// Unknown space (and the figure's background): grey.
const UNKNOWN_COLOUR: Rgba = rgb(0xb, 0xb, 0xb);
/// The true static world's outlines: red.
const WORLD_COLOUR: Rgba = rgb(0xc, 0x3, 0x3);
/// The robot and its track: green.
const ROBOT_COLOUR: Rgba = rgb(0x0, 0xa, 0x0);
/// People: orange.
const PERSON_COLOUR: Rgba = rgb(0xe, 0x8, 0x0);

/// A built map as a map layer: free white, occupied near-black, unknown the background's
/// grey.
pub(crate) fn map_layer(map: &OccupancyGrid) -> GridImage {
    let (w, h) = (map.width(), map.height());
    let mut grid = GridImage::filled(
        map.frame(),
        vec![UNKNOWN_COLOUR, [255; 4], rgb(0x2, 0x2, 0x2)],
    );
    for j in 0..h {
        for i in 0..w {
            match map.value(i, j) {
                FREE => grid.set(i, j, 1),
                OCCUPIED => grid.set(i, j, 2),
                _ => {}
            }
        }
    }
    grid
}

/// The static world in a scene of its bounds: `map` below (when given), the true world's
/// outlines over it.
pub(crate) fn world_scene(map: Option<&OccupancyGrid>, world: &World) -> Scene {
    let b = world.bounds;
    let mut scene = Scene::new(b.min, b.max, SCALE).with_background(UNKNOWN_COLOUR);
    if let Some(map) = map {
        scene.push(Mark::Grid(map_layer(map)));
    }
    let outline = Stroke::new(WORLD_COLOUR, px(0.03));
    scene.push(Mark::Segments {
        pairs: world.statics.segments.iter().map(|s| (s.a, s.b)).collect(),
        stroke: outline,
    });
    for d in &world.statics.discs {
        scene.push(Mark::ring(d.center, d.radius, outline));
    }
    scene
}

fn points(list: &[(f64, f64)]) -> Vec<Point2> {
    list.iter().map(|&(x, y)| Point2::new(x, y)).collect()
}

/// The robot's driven path.
fn driven(rows: &[Row]) -> Vec<Point2> {
    rows.iter().map(|r| Point2::new(r.x, r.y)).collect()
}

/// The trajectory over the built map, with the planned paths and the people's tracks
/// (the paper's Figs. 6a, 7a, 8): drawn as SVG by [`Scene::to_svg`], as PNG by
/// [`Scene::png_bytes`].
#[must_use]
pub fn trajectory_scene(outcome: &Outcome, world: &World) -> Scene {
    let mut scene = world_scene(outcome.map.as_ref(), world);
    let rows = &outcome.trace.rows;
    let end = rows.last().map_or(0.0, |r| r.t);
    for (k, p) in world.people.iter().enumerate() {
        let n = (end * 10.0).ceil() as usize;
        scene.push(Mark::Polyline {
            points: (0..=n).map(|i| p.position(i as f64 / 10.0)).collect(),
            stroke: Stroke::new(PERSON_COLOUR, px(0.05)).dashed(px(0.15), px(0.1)),
            title: Some(format!("person {k}")),
        });
    }
    for (t, path) in &outcome.plans {
        scene.push(Mark::Polyline {
            points: points(path),
            stroke: Stroke::new(with_alpha(rgb(0x3, 0x9, 0xf), 153), px(0.03)),
            title: Some(format!("plan at {t:.1} s")),
        });
    }
    scene.push(Mark::polyline(
        driven(rows),
        Stroke::new(ROBOT_COLOUR, px(0.06)),
    ));
    scene
}

/// v(t) and omega(t), one panel each (the paper's Figs. 6b-c, 7b-c, 9), re-plans and
/// stops marked.
///
/// # Errors
///
/// [`FigureError`] with the chart library's message.
pub fn velocity_svg(trace: &Trace) -> Result<String, FigureError> {
    let rows = &trace.rows;
    let t_end = rows.last().map_or(1.0, |r| r.t).max(1.0);
    let events: Vec<f64> = trace
        .events
        .iter()
        .filter(|e| matches!(e.kind, EventKind::Nav(NavEvent::Replan | NavEvent::Stop)))
        .map(|e| e.t)
        .collect();
    type Quantity = (&'static str, fn(&Row) -> f64);
    let quantities: [Quantity; 2] = [("v (m/s)", |r| r.v), ("omega (rad/s)", |r| r.omega)];
    let panels: Vec<TimePanel> = quantities
        .iter()
        .map(|(label, f)| {
            let vals: Vec<f64> = rows.iter().map(f).collect();
            let lo = vals.iter().copied().fold(0.0_f64, f64::min).min(-0.1);
            let hi = vals.iter().copied().fold(0.0_f64, f64::max).max(0.1);
            TimePanel {
                label: (*label).to_string(),
                points: rows.iter().zip(&vals).map(|(r, &v)| (r.t, v)).collect(),
                colour: rgb(0x0, 0x6, 0xc),
                events: events.clone(),
                range: Some((lo, hi)),
            }
        })
        .collect();
    viz::time_series_svg(&panels, t_end, 800, 220)
}

/// The run in real time: the robot with its heading and the people, over the built map
/// and the trajectory. The robot and the people are [`Mark::Moving`], a frame every 0.1 s:
/// [`Scene::to_svg`] draws it as an animated SVG (SMIL, opens in any browser),
/// [`Scene::at_frame`] picks one frame, [`viz::apng_scenes`] plays them as PNG.
#[must_use]
pub fn animation_scene(outcome: &Outcome, world: &World) -> Scene {
    let mut scene = world_scene(outcome.map.as_ref(), world);
    let rows = &outcome.trace.rows;
    let end = rows.last().map_or(0.0, |r| r.t).max(0.1);
    let frames = (end * 10.0).ceil() as usize;
    let times: Vec<f64> = (0..=frames).map(|k| k as f64 / 10.0).collect();
    let at = |t: f64| {
        let i = rows
            .partition_point(|r| r.t < t)
            .min(rows.len().saturating_sub(1));
        rows.get(i).copied()
    };
    scene.push(Mark::polyline(
        driven(rows),
        Stroke::new(with_alpha(ROBOT_COLOUR, 128), px(0.03)),
    ));
    for p in &world.people {
        scene.push(Mark::Moving {
            times: times.clone(),
            frames: times
                .iter()
                .map(|&t| Mark::disc(p.position(t), p.radius, PERSON_COLOUR))
                .collect(),
        });
    }
    // The robot, and its heading: a line from the centre to the front.
    let r = 0.178;
    let pose = |t: f64| {
        at(t).map_or((Point2::new(0.0, 0.0), 0.0), |row| {
            (Point2::new(row.x, row.y), row.phi)
        })
    };
    scene.push(Mark::Moving {
        times: times.clone(),
        frames: times
            .iter()
            .map(|&t| Mark::disc(pose(t).0, r, with_alpha(ROBOT_COLOUR, 204)))
            .collect(),
    });
    scene.push(Mark::Moving {
        times: times.clone(),
        frames: times
            .iter()
            .map(|&t| {
                let (c, phi) = pose(t);
                Mark::Segments {
                    pairs: vec![(c, Point2::new(c.x + r * phi.cos(), c.y + r * phi.sin()))],
                    stroke: Stroke::new([0, 0, 0, 255], px(0.04)),
                }
            })
            .collect(),
    });
    scene
}
