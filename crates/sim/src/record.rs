//! What a run leaves behind: the trace (CSV and JSON), the figures of the paper (the
//! trajectory over the built map with the people's tracks, v(t) and omega(t)), and an
//! animated SVG of the run that any browser plays.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::mapping::{OCCUPIED, UNKNOWN};
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
    put("trajectory.svg", trajectory_svg(outcome, world))?;
    put("velocity.svg", velocity_svg(&outcome.trace))?;
    put("animation.svg", animation_svg(outcome, world))?;
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

/// SVG header and the static world (built map below when given) in a y-up frame.
fn world_svg(outcome: &Outcome, world: &World, s: &mut String) -> (f64, f64) {
    world_svg_with(outcome.map.as_ref(), world, s)
}

/// SVG header and the static world with `map` below, in a y-up frame (the group is left
/// open: close it with `</g></svg>`).
pub(crate) fn world_svg_with(
    map: Option<&crate::mapping::OccupancyGrid>,
    world: &World,
    s: &mut String,
) -> (f64, f64) {
    let b = world.bounds;
    let (w, h) = (b.width() * SCALE, b.height() * SCALE);
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="{} {} {} {}">"#,
        b.min.x,
        -b.max.y,
        b.width(),
        b.height()
    );
    let _ = writeln!(
        s,
        r##"<rect x="{}" y="{}" width="{}" height="{}" fill="#bbb"/>"##,
        b.min.x,
        -b.max.y,
        b.width(),
        b.height()
    );
    let _ = writeln!(s, r#"<g transform="scale(1,-1)">"#);
    if let Some(map) = map {
        let r = map.params.resolution;
        let o = map.origin();
        for j in 0..map.height() {
            let mut i = 0;
            while i < map.width() {
                let v = map.value(i, j);
                let mut k = i + 1;
                while k < map.width() && map.value(k, j) == v {
                    k += 1;
                }
                if v != UNKNOWN {
                    let fill = if v == OCCUPIED { "#222" } else { "#fff" };
                    let _ = writeln!(
                        s,
                        r#"<rect x="{:.3}" y="{:.3}" width="{:.3}" height="{:.3}" fill="{fill}"/>"#,
                        o.x + i as f64 * r,
                        o.y + j as f64 * r,
                        (k - i) as f64 * r,
                        r
                    );
                }
                i = k;
            }
        }
    }
    // The true static world as thin outlines.
    for seg in &world.statics.segments {
        let _ = writeln!(
            s,
            r##"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="#c33" stroke-width="0.03"/>"##,
            seg.a.x, seg.a.y, seg.b.x, seg.b.y
        );
    }
    for d in &world.statics.discs {
        let _ = writeln!(
            s,
            r##"<circle cx="{}" cy="{}" r="{}" fill="none" stroke="#c33" stroke-width="0.03"/>"##,
            d.center.x, d.center.y, d.radius
        );
    }
    (w, h)
}

pub(crate) fn polyline(points: impl Iterator<Item = (f64, f64)>) -> String {
    points
        .map(|(x, y)| format!("{x:.3},{y:.3}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The trajectory over the built map, with the planned paths and the people's tracks
/// (the paper's Figs. 6a, 7a, 8).
#[must_use]
pub fn trajectory_svg(outcome: &Outcome, world: &World) -> String {
    let mut s = String::new();
    world_svg(outcome, world, &mut s);
    let rows = &outcome.trace.rows;
    let end = rows.last().map_or(0.0, |r| r.t);
    for (k, p) in world.people.iter().enumerate() {
        let n = (end * 10.0).ceil() as usize;
        let pts = (0..=n).map(|i| {
            let q = p.position(i as f64 / 10.0);
            (q.x, q.y)
        });
        let _ = writeln!(
            s,
            r##"<polyline points="{}" fill="none" stroke="#e80" stroke-width="0.05" stroke-dasharray="0.15 0.1"><title>person {k}</title></polyline>"##,
            polyline(pts)
        );
    }
    for (t, path) in &outcome.plans {
        let _ = writeln!(
            s,
            r##"<polyline points="{}" fill="none" stroke="#39f" stroke-width="0.03" opacity="0.6"><title>plan at {t:.1} s</title></polyline>"##,
            polyline(path.iter().copied())
        );
    }
    let _ = writeln!(
        s,
        r##"<polyline points="{}" fill="none" stroke="#0a0" stroke-width="0.06"/>"##,
        polyline(rows.iter().map(|r| (r.x, r.y)))
    );
    s.push_str("</g></svg>\n");
    s
}

/// v(t) and omega(t), one panel each (the paper's Figs. 6b-c, 7b-c, 9).
#[must_use]
pub fn velocity_svg(trace: &Trace) -> String {
    let rows = &trace.rows;
    let t_end = rows.last().map_or(1.0, |r| r.t).max(1.0);
    let (w, ph) = (800.0, 220.0);
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{}" font-family="sans-serif" font-size="12">"#,
        2.0 * ph + 20.0
    );
    s.push('\n');
    type Panel = (&'static str, fn(&Row) -> f64);
    let panels: [Panel; 2] = [("v (m/s)", |r| r.v), ("omega (rad/s)", |r| r.omega)];
    for (k, (label, f)) in panels.iter().enumerate() {
        let y0 = k as f64 * (ph + 10.0) + 10.0;
        let vals: Vec<f64> = rows.iter().map(f).collect();
        let lo = vals.iter().copied().fold(0.0_f64, f64::min).min(-0.1);
        let hi = vals.iter().copied().fold(0.0_f64, f64::max).max(0.1);
        let (left, right, top, bottom) = (60.0, w - 20.0, y0 + 10.0, y0 + ph - 30.0);
        let x = |t: f64| left + (right - left) * t / t_end;
        let y = |v: f64| bottom - (bottom - top) * (v - lo) / (hi - lo);
        let _ = writeln!(
            s,
            r##"<rect x="{left}" y="{top}" width="{}" height="{}" fill="none" stroke="#888"/>"##,
            right - left,
            bottom - top
        );
        let _ = writeln!(
            s,
            r##"<line x1="{left}" y1="{:.1}" x2="{right}" y2="{:.1}" stroke="#ccc"/>"##,
            y(0.0),
            y(0.0)
        );
        let _ = writeln!(
            s,
            r#"<text x="5" y="{:.1}">{label}</text>"#,
            top - 2.0 + 12.0
        );
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{:.1}">{hi:.2}</text>"#,
            left - 40.0,
            top + 10.0
        );
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{:.1}">{lo:.2}</text>"#,
            left - 40.0,
            bottom
        );
        for tick in 0..=(t_end / 5.0).floor() as usize {
            let t = tick as f64 * 5.0;
            let _ = writeln!(
                s,
                r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{t:.0} s</text>"#,
                x(t),
                bottom + 15.0
            );
        }
        let _ = writeln!(
            s,
            r##"<polyline points="{}" fill="none" stroke="#06c" stroke-width="1.5"/>"##,
            polyline(rows.iter().zip(&vals).map(|(r, &v)| (x(r.t), y(v))))
        );
        for e in &trace.events {
            if matches!(e.kind, EventKind::Nav(NavEvent::Replan | NavEvent::Stop)) {
                let _ = writeln!(
                    s,
                    r##"<line x1="{0:.1}" y1="{top}" x2="{0:.1}" y2="{bottom}" stroke="#e80" stroke-width="0.5"/>"##,
                    x(e.t)
                );
            }
        }
    }
    s.push_str("</svg>\n");
    s
}

/// An animated SVG (SMIL) of the run in real time: the robot with its heading, the
/// people, over the built map and the trajectory. Opens in any browser.
#[must_use]
pub fn animation_svg(outcome: &Outcome, world: &World) -> String {
    let mut s = String::new();
    world_svg(outcome, world, &mut s);
    let rows = &outcome.trace.rows;
    let end = rows.last().map_or(0.0, |r| r.t).max(0.1);
    let frames = (end * 10.0).ceil() as usize;
    let at = |k: usize| {
        let t = k as f64 / 10.0;
        let i = rows
            .partition_point(|r| r.t < t)
            .min(rows.len().saturating_sub(1));
        rows.get(i).copied()
    };
    let key_times = (0..=frames)
        .map(|k| format!("{:.4}", (k as f64 / 10.0 / end).min(1.0)))
        .collect::<Vec<_>>()
        .join(";");
    let anim = |attr: &str, vals: String| {
        format!(
            r#"<animate attributeName="{attr}" dur="{end:.2}s" repeatCount="indefinite" calcMode="linear" keyTimes="{key_times}" values="{vals}"/>"#
        )
    };
    let _ = writeln!(
        s,
        r##"<polyline points="{}" fill="none" stroke="#0a0" stroke-width="0.03" opacity="0.5"/>"##,
        polyline(rows.iter().map(|r| (r.x, r.y)))
    );
    for p in &world.people {
        let xs = (0..=frames)
            .map(|k| format!("{:.3}", p.position(k as f64 / 10.0).x))
            .collect::<Vec<_>>()
            .join(";");
        let ys = (0..=frames)
            .map(|k| format!("{:.3}", p.position(k as f64 / 10.0).y))
            .collect::<Vec<_>>()
            .join(";");
        let _ = writeln!(
            s,
            r##"<circle r="{}" fill="#e80">{}{}</circle>"##,
            p.radius,
            anim("cx", xs),
            anim("cy", ys)
        );
    }
    let r = outcome.trace.rows.first().map_or(0.178, |_| 0.178);
    let pick = |f: fn(&crate::record::Row) -> f64| {
        (0..=frames)
            .map(|k| at(k).map_or(0.0, |row| f(&row)))
            .map(|v| format!("{v:.3}"))
            .collect::<Vec<_>>()
            .join(";")
    };
    let _ = writeln!(
        s,
        r##"<circle r="{r}" fill="#0a0" opacity="0.8">{}{}</circle>"##,
        anim("cx", pick(|row| row.x)),
        anim("cy", pick(|row| row.y))
    );
    // The heading: a line from the centre to the front.
    let _ = writeln!(
        s,
        r##"<line stroke="#000" stroke-width="0.04">{}{}{}{}</line>"##,
        anim("x1", pick(|row| row.x)),
        anim("y1", pick(|row| row.y)),
        anim("x2", pick(|row| row.x + 0.178 * row.phi.cos())),
        anim("y2", pick(|row| row.y + 0.178 * row.phi.sin()))
    );
    s.push_str("</g></svg>\n");
    s
}
