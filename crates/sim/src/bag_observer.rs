//! A run as a ROS 2 bag (feature `mcap`): what a ROS navigation stack would have
//! published, stamped with simulated time, for Foxglove and RViz.
//!
//! Topics (frames as REP 105 names them: `map` -> `odom` -> `base_link` -> `laser`):
//!
//! | topic | type | when |
//! |---|---|---|
//! | `/map` | `nav_msgs/msg/OccupancyGrid` | the known map once at the start (a run with `known_map`), else the built map at map updates that changed it |
//! | `/scan` | `sensor_msgs/msg/LaserScan` | every scan (the laser's rate; one in `n` with [`BagRecorder::with_scan_every`]); REP 117 ranges |
//! | `/odom` | `nav_msgs/msg/Odometry` | every scan, the pose the trace records |
//! | `/tf` | `tf2_msgs/msg/TFMessage` | with `/odom`: map->odom, odom->base_link, base_link->laser |
//! | `/cmd_vel` | `geometry_msgs/msg/Twist` | every control step |
//! | `/plan` | `nav_msgs/msg/Path` | every plan and re-plan |
//! | `/people` | `visualization_msgs/msg/MarkerArray` | every control step, when there are people |
//! | `/frontiers`, `/rrt_tree` | `visualization_msgs/msg/MarkerArray` | every 10 s and at the end, when the goal source shows some ([`GoalSource::frontiers`](crate::GoalSource::frontiers), [`GoalSource::tree_edges`](crate::GoalSource::tree_edges)); `/rrt_tree` sends only what changed (see below) |
//!
//! `/rrt_tree` keeps the edges that stayed since the last array (the global tree only
//! grows) in markers `0, 1, ...` of namespace `rrt_tree` and sends the rest (the global
//! tree's new edges, the local tree) in marker `i32::MAX`, which each array replaces; a
//! tree that lost edges clears the topic (DELETEALL) and starts again. The union of the
//! topic's markers is the trees at that time.
//!
//! The simulated robot has no odometry drift: map->odom is the identity and `/odom` is
//! the true pose. Log time, publish time and every header stamp are the tick's time.

use std::path::Path;
use std::sync::mpsc::{Receiver, SyncSender, channel, sync_channel};
use std::thread::JoinHandle;

use bag::{
    BagError, BagWriter, ColorRGBA, Header, LaserScan, MapMetaData, Marker, MarkerArray, Odometry,
    Pose, Quaternion, TFMessage, Transform, TransformStamped, Vector3,
};

use hyplan_core::Point2;

use crate::engine::{Observer, Sim, TICKS_PER_SECOND, TickInfo};
use crate::laser::Scan;
use crate::mapping::{FREE, OCCUPIED};
use crate::navigator::NavEvent;

/// Nanoseconds per tick.
const TICK_NS: u64 = 1_000_000_000 / TICKS_PER_SECOND;

/// The frame names (REP 105).
const MAP: &str = "map";
const ODOM: &str = "odom";
const BASE: &str = "base_link";
const LASER: &str = "laser";

/// Writes a run into a ROS 2 bag (see the module doc for the topics).
///
/// ```no_run
/// use sim::{BagRecorder, GlobalPlanner, Scenario};
/// let (scenario, world) = Scenario::load("scenarios/sim/3-person.ron".as_ref())?;
/// let mut bag = BagRecorder::create("run.mcap".as_ref())?;
/// let out = sim::run_with(&scenario, &world, 1, GlobalPlanner::Dijkstra, &mut [&mut bag]);
/// bag.finish()?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct BagRecorder {
    /// The writer thread's queue: messages are built here and encoded, compressed and
    /// written there, so the run waits only for their building.
    queue: Option<SyncSender<Vec<Job>>>,
    writer: Option<JoinHandle<Result<(), BagError>>>,
    /// Messages not yet handed over: they go in batches, a wake-up of the thread each.
    batch: Vec<Job>,
    /// Batches written, sent back to be dropped here: what the run's thread allocated
    /// is freed by it, not by the writer (whose frees into this thread's heap would
    /// contend with it for the allocator's lock).
    written: Receiver<Vec<Job>>,
    /// The map's cells as last published, and the map's version they are of.
    map: Vec<i8>,
    map_version: u64,
    path_version: u64,
    /// The tick at which the goal source's frontiers and trees were last shown.
    shown_tick: Option<u64>,
    /// The trees' edges as `/rrt_tree` shows them.
    trees: TreeMarkers,
    /// One scan in this many is written (1: every scan).
    scan_every: u64,
    scans: u64,
}

/// One message for the writer thread (called once; `FnMut` so that what it holds comes
/// back with its batch).
type Job = Box<dyn FnMut(&mut BagWriter) -> Result<(), BagError> + Send>;

/// Messages handed to the writer thread at a time.
const BATCH: usize = 64;
/// Batches the writer thread may lag behind (a few seconds of a run: the memory a slow
/// disk can cost is bounded).
const QUEUE: usize = 8;

/// Ticks between two `/frontiers` and `/rrt_tree` arrays (10 s): a global tree grows to
/// thousands of edges, and each array repeats them all.
const SHOW_EVERY: u64 = 10 * TICKS_PER_SECOND;

impl BagRecorder {
    /// Creates the bag at `path` and its writer thread.
    ///
    /// # Errors
    ///
    /// [`BagError`] naming the file when it cannot be created.
    pub fn create(path: &Path) -> Result<Self, BagError> {
        let mut bag = BagWriter::create(path)?;
        let (queue, batches) = sync_channel::<Vec<Job>>(QUEUE);
        let (back, written) = channel::<Vec<Job>>();
        let write = move || {
            for mut batch in batches {
                for job in &mut batch {
                    job(&mut bag)?;
                }
                // The run may be over (its end drops the receiver): then they go here.
                let _ = back.send(batch);
            }
            bag.finish()
        };
        let writer = std::thread::Builder::new()
            .name("bag-writer".into())
            .spawn(write)
            .map_err(|source| BagError::Io {
                path: path.to_path_buf(),
                source,
            })?;
        Ok(Self {
            queue: Some(queue),
            writer: Some(writer),
            batch: Vec::with_capacity(BATCH),
            written,
            map: Vec::new(),
            map_version: 0,
            path_version: 0,
            shown_tick: None,
            trees: TreeMarkers::default(),
            scan_every: 1,
            scans: 0,
        })
    }

    /// Writes one scan in `n` on `/scan` (decimation for long runs; the robot still scans
    /// at the laser's rate, and `/odom` and `/tf` keep it).
    ///
    /// ```no_run
    /// let bag = sim::BagRecorder::create("long.mcap".as_ref())?.with_scan_every(4);
    /// # Ok::<(), bag::BagError>(())
    /// ```
    #[must_use]
    pub fn with_scan_every(mut self, n: u64) -> Self {
        self.scan_every = n.max(1);
        self
    }

    /// Waits for the writer thread and closes the bag.
    ///
    /// # Errors
    ///
    /// The first [`BagError`] of the run, or of closing the file.
    pub fn finish(mut self) -> Result<(), BagError> {
        self.close()
    }

    fn close(&mut self) -> Result<(), BagError> {
        self.hand_over();
        // Closing the queue ends the thread's loop.
        self.queue = None;
        match self.writer.take().map(JoinHandle::join) {
            None => Ok(()),
            Some(Ok(result)) => result,
            Some(Err(panic)) => std::panic::resume_unwind(panic),
        }
    }

    /// Queues `msg` on `topic` at `tick`. A failed write ends the thread, which keeps
    /// the error for [`BagRecorder::finish`]; later messages are dropped.
    fn write<M: bag::RosMessage + Send + 'static>(
        &mut self,
        topic: &'static str,
        tick: u64,
        msg: M,
    ) {
        let ns = tick * TICK_NS;
        self.queue(Box::new(move |bag: &mut BagWriter| {
            bag.write(topic, ns, &msg)
        }));
    }

    /// Queues `job` for the writer thread.
    fn queue(&mut self, job: Job) {
        self.batch.push(job);
        if self.batch.len() >= BATCH {
            self.hand_over();
        }
    }

    /// Sends the batch to the writer thread (the next one reuses a written batch).
    fn hand_over(&mut self) {
        let mut next = Vec::new();
        while let Ok(mut done) = self.written.try_recv() {
            done.clear();
            next = done;
        }
        next.reserve(BATCH);
        let batch = std::mem::replace(&mut self.batch, next);
        if let Some(queue) = &self.queue
            && queue.send(batch).is_err()
        {
            self.queue = None;
        }
    }

    /// The map the robot navigates on as a map server publishes it: with the map known
    /// (`known_map`), the known static world once, on the built map's grid (100 where it
    /// reaches into a cell, 0 elsewhere); else the built map whenever an update changed
    /// it, as gmapping does.
    fn publish_map(&mut self, sim: &Sim<'_>) {
        if sim.scenario.known_map {
            if !self.map.is_empty() {
                return;
            }
            let frame = sim.map.frame();
            let (_, _, cells) =
                crate::costmap::rasterize(sim.world.bounds, &sim.world.mapped, frame.resolution);
            self.map = cells
                .iter()
                .map(|&c| if c { OCCUPIED } else { FREE })
                .collect();
        } else {
            let since = std::mem::replace(&mut self.map_version, sim.map.version());
            if !sim.map.update_ros_values(&mut self.map, since) {
                return;
            }
        }
        let ns = sim.tick() * TICK_NS;
        let frame = sim.map.frame();
        let origin = frame.origin;
        let grid = bag::OccupancyGrid {
            header: Header::at(ns, MAP),
            info: MapMetaData {
                map_load_time: bag::Time::from_nanos(ns),
                resolution: frame.resolution as f32,
                width: frame.width as u32,
                height: frame.height as u32,
                origin: Pose::planar(origin.x, origin.y, 0.0),
            },
            data: self.map.clone(),
        };
        self.write("/map", sim.tick(), grid);
    }

    fn publish_scan(&mut self, sim: &Sim<'_>, scan: &Scan) {
        let laser = &sim.laser().laser;
        let half = laser.fov_deg.to_radians() / 2.0;
        let msg = LaserScan {
            header: Header::at(sim.tick() * TICK_NS, LASER),
            angle_min: -half as f32,
            angle_max: half as f32,
            angle_increment: scan.angle_increment as f32,
            time_increment: 0.0,
            scan_time: (1.0 / laser.rate_hz) as f32,
            range_min: laser.range_min as f32,
            range_max: laser.range_max as f32,
            ranges: scan.ranges.iter().map(|&r| r as f32).collect(),
            intensities: Vec::new(),
        };
        self.write("/scan", sim.tick(), msg);
    }

    /// `/odom` and `/tf`, built by the writer thread from the pose: their dozen frame
    /// names and vectors are then allocated and freed there, where the run's thread
    /// would otherwise contend with it for the allocator's lock at the laser's rate.
    fn publish_pose(&mut self, sim: &Sim<'_>) {
        let ns = sim.tick() * TICK_NS;
        let (pose, twist) = (sim.pose(), sim.twist());
        let mount = sim.laser().laser.mount_offset;
        self.queue(Box::new(move |bag: &mut BagWriter| {
            let mut odom = Odometry {
                header: Header::at(ns, ODOM),
                child_frame_id: BASE.into(),
                ..Odometry::default()
            };
            odom.pose.pose = Pose::planar(pose.x, pose.y, pose.phi);
            odom.twist.twist.linear.x = twist.v;
            odom.twist.twist.angular.z = twist.omega;
            bag.write("/odom", ns, &odom)?;
            let link = |parent: &str, child: &str, x: f64, y: f64, yaw: f64| TransformStamped {
                header: Header::at(ns, parent),
                child_frame_id: child.into(),
                transform: Transform {
                    translation: Vector3 { x, y, z: 0.0 },
                    rotation: Quaternion::from_yaw(yaw),
                },
            };
            let tf = TFMessage {
                transforms: vec![
                    link(MAP, ODOM, 0.0, 0.0, 0.0),
                    link(ODOM, BASE, pose.x, pose.y, pose.phi),
                    link(BASE, LASER, mount, 0.0, 0.0),
                ],
            };
            bag.write("/tf", ns, &tf)
        }));
    }

    fn publish_plan(&mut self, sim: &Sim<'_>) {
        let points = sim.nav.path().iter().map(|p| (p.x, p.y));
        let path = bag::Path::planar(sim.tick() * TICK_NS, MAP, points);
        self.write("/plan", sim.tick(), path);
    }

    /// `/frontiers` (spheres, each array replacing the last: a DELETEALL marker first)
    /// and `/rrt_tree`, when the goal source has any.
    fn publish_exploration(&mut self, sim: &Sim<'_>, info: &TickInfo<'_>) {
        let ns = sim.tick() * TICK_NS;
        let frontiers = info.goals.frontiers();
        if !frontiers.is_empty() {
            let colour = ColorRGBA {
                r: 0.9,
                g: 0.1,
                b: 0.6,
                a: 1.0,
            };
            let points = frontiers.iter().map(|p| (p.x, p.y));
            let dots = Marker::planar(
                Header::at(ns, MAP),
                "frontiers",
                0,
                Marker::SPHERE_LIST,
                0.2,
                colour,
                points,
            );
            let markers = vec![delete_all(ns), dots];
            self.write("/frontiers", sim.tick(), MarkerArray { markers });
        }
        let mut edges = self.trees.buffer();
        info.goals.tree_edges(&mut edges);
        if edges.is_empty() {
            self.trees.spare = edges;
        } else if let Some(array) = self.trees.show(ns, edges) {
            self.write("/rrt_tree", sim.tick(), array);
        }
    }

    fn publish_people(&mut self, sim: &Sim<'_>) {
        let ns = sim.tick() * TICK_NS;
        let markers = sim
            .people()
            .iter()
            .enumerate()
            .map(|(k, p)| Marker {
                header: Header::at(ns, MAP),
                ns: "people".into(),
                id: k as i32,
                kind: Marker::CYLINDER,
                action: Marker::ADD,
                pose: Pose::planar(p.center.x, p.center.y, 0.0),
                scale: Vector3 {
                    x: 2.0 * p.radius,
                    y: 2.0 * p.radius,
                    z: 1.7,
                },
                color: ColorRGBA {
                    r: 0.93,
                    g: 0.53,
                    b: 0.0,
                    a: 0.9,
                },
                ..Marker::default()
            })
            .collect();
        self.write("/people", sim.tick(), MarkerArray { markers });
    }
}

/// A marker that clears what the topic showed (ROS and Foxglove: every marker of the
/// topic).
fn delete_all(ns: u64) -> Marker {
    Marker {
        header: Header::at(ns, MAP),
        action: Marker::DELETEALL,
        ..Marker::default()
    }
}

/// `/rrt_tree` without repeating the trees: the global tree only grows, so the edges a
/// show shares with the last one (a common prefix: the global tree's edges come first)
/// are kept in a marker of their own, and only the rest (the global tree's new edges,
/// the local tree, which restarts) is sent again. A 22 m exploration's global tree
/// reaches tens of thousands of edges: whole trees every 10 s were 90 MB.
#[derive(Default)]
struct TreeMarkers {
    /// The edges of the last show.
    last: Vec<(Point2, Point2)>,
    /// A buffer for the next show's edges (the one before's, reused).
    spare: Vec<(Point2, Point2)>,
    /// How many of them kept markers `0..kept` hold.
    settled: usize,
    kept: i32,
}

/// The id of the marker holding the edges not yet settled (replaced at every show).
const TREE_TAIL: i32 = i32::MAX;

impl TreeMarkers {
    /// An empty vector for the next show's edges, with the capacity of an earlier one.
    fn buffer(&mut self) -> Vec<(Point2, Point2)> {
        let mut edges = std::mem::take(&mut self.spare);
        edges.clear();
        edges
    }

    /// The array showing `edges` at `ns`, or `None` when they did not change.
    fn show(&mut self, ns: u64, edges: Vec<(Point2, Point2)>) -> Option<MarkerArray> {
        if edges == self.last {
            self.spare = edges;
            return None;
        }
        let common = edges
            .iter()
            .zip(&self.last)
            .take_while(|(a, b)| a == b)
            .count();
        let mut markers = Vec::new();
        if common < self.settled {
            // A settled edge went (a tree restarted): start again.
            markers.push(delete_all(ns));
            (self.settled, self.kept) = (0, 0);
        }
        let lines = |id, part: &[(Point2, Point2)]| {
            let colour = ColorRGBA {
                r: 0.2,
                g: 0.4,
                b: 1.0,
                a: 0.5,
            };
            let points = part.iter().flat_map(|(a, b)| [(a.x, a.y), (b.x, b.y)]);
            let header = Header::at(ns, MAP);
            Marker::planar(
                header,
                "rrt_tree",
                id,
                Marker::LINE_LIST,
                0.02,
                colour,
                points,
            )
        };
        if common > self.settled {
            markers.push(lines(self.kept, &edges[self.settled..common]));
            (self.settled, self.kept) = (common, self.kept + 1);
        }
        // The tail, even empty: it replaces the last one.
        markers.push(lines(TREE_TAIL, &edges[self.settled..]));
        self.spare = std::mem::replace(&mut self.last, edges);
        Some(MarkerArray { markers })
    }
}

impl Observer for BagRecorder {
    fn map_updated(&mut self, sim: &Sim<'_>, _scan: &Scan) {
        self.publish_map(sim);
    }

    fn sensed(&mut self, sim: &Sim<'_>, scan: &Scan) {
        if self.scans.is_multiple_of(self.scan_every) {
            self.publish_scan(sim, scan);
        }
        self.scans += 1;
    }

    fn ticked(&mut self, sim: &Sim<'_>, info: &TickInfo<'_>) {
        if sim.scenario.known_map && self.map.is_empty() {
            self.publish_map(sim);
        }
        // What the goal source shows, every SHOW_EVERY ticks and at the end.
        if self.shown_tick.is_none_or(|t| info.tick >= t + SHOW_EVERY) || info.stopped {
            self.shown_tick = Some(info.tick);
            self.publish_exploration(sim, info);
        }
        // The pose as the trace records it: on laser ticks and at the end.
        if info.sensed || info.stopped {
            self.publish_pose(sim);
        }
        if info
            .events
            .iter()
            .any(|e| matches!(e, NavEvent::Plan | NavEvent::Replan))
            && sim.nav.path_version() != self.path_version
        {
            self.path_version = sim.nav.path_version();
            self.publish_plan(sim);
        }
        if info.controlled {
            let t = sim.twist();
            let twist = bag::Twist {
                linear: Vector3 {
                    x: t.v,
                    ..Vector3::default()
                },
                angular: Vector3 {
                    z: t.omega,
                    ..Vector3::default()
                },
            };
            self.write("/cmd_vel", info.tick, twist);
            if !sim.people().is_empty() {
                self.publish_people(sim);
            }
        }
    }
}

impl Drop for BagRecorder {
    /// A recorder dropped without [`BagRecorder::finish`] still closes its file.
    fn drop(&mut self) {
        if self.writer.is_some() {
            let _ = self.close();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The markers a viewer holds after `arrays`: DELETEALL clears, ADD replaces by id.
    fn replay(arrays: &[MarkerArray]) -> Vec<(f64, f64)> {
        let mut shown = std::collections::BTreeMap::new();
        for a in arrays {
            for m in &a.markers {
                if m.action == Marker::DELETEALL {
                    shown.clear();
                } else {
                    shown.insert(m.id, m.points.iter().map(|p| (p.x, p.y)).collect());
                }
            }
        }
        shown.into_values().flat_map(|v: Vec<_>| v).collect()
    }

    fn edges(n: usize, local: usize) -> Vec<(Point2, Point2)> {
        let e = |k: usize, y: f64| (Point2::new(k as f64, y), Point2::new(k as f64 + 1.0, y));
        (0..n)
            .map(|k| e(k, 0.0))
            .chain((0..local).map(|k| e(k, 1.0)))
            .collect()
    }

    fn flat(edges: &[(Point2, Point2)]) -> Vec<(f64, f64)> {
        edges
            .iter()
            .flat_map(|(a, b)| [(a.x, a.y), (b.x, b.y)])
            .collect()
    }

    #[test]
    fn tree_markers_send_only_what_changed_and_replay_to_the_trees() {
        let mut trees = TreeMarkers::default();
        let mut arrays = Vec::new();
        let mut sent = 0;
        for (n, local) in [(5, 2), (9, 3), (9, 1), (30, 0), (31, 4)] {
            let now = edges(n, local);
            let array = trees.show(0, now.clone()).expect("changed");
            sent += array.markers.iter().map(|m| m.points.len()).sum::<usize>();
            arrays.push(array);
            let mut held = replay(&arrays);
            let mut want = flat(&now);
            held.sort_by(|a, b| a.partial_cmp(b).unwrap());
            want.sort_by(|a, b| a.partial_cmp(b).unwrap());
            assert_eq!(held, want, "after ({n}, {local})");
        }
        // Whole trees each time would have sent 2 x (7 + 12 + 10 + 30 + 35) points.
        assert!(sent < 2 * 94, "{sent}");
        assert!(trees.show(0, edges(31, 4)).is_none(), "unchanged: nothing");
        // A tree that lost settled edges clears the topic first.
        let array = trees.show(0, edges(3, 0)).expect("changed");
        assert_eq!(array.markers[0].action, Marker::DELETEALL);
        arrays.push(array);
        assert_eq!(replay(&arrays), flat(&edges(3, 0)));
    }
}
