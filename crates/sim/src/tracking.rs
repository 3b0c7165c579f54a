//! Moving obstacles from successive scans: the hits that the static prior map does not
//! explain are grouped into clusters, clusters are associated scan to scan into tracks,
//! and each track's velocity is the least-squares slope of its centroid over the last
//! fraction of a second.
//!
//! This is what a ROS people tracker (`leg_detector`, `costmap_converter`'s dynamic
//! obstacles) adds to a `move_base` stack so that a local planner can look ahead in time:
//! without it, the controller checks its arc against where people are now, and a person
//! walking at the robot's side toward it is seen but not anticipated.
//!
//! Choices (constants below): hits within about 5 cm of the prior map are static; beams
//! next to each other whose hits are closer than [`CLUSTER_GAP`] form a cluster; clusters
//! wider than [`MAX_EXTENT`], of fewer than [`MIN_POINTS`] hits, or cut by the tracked
//! range are not used (their centroids slide with the view); of a cluster cut by the edge
//! of the field of view only the motion along that edge is used and are left to the obstacle memory; a cluster
//! joins the track whose predicted centroid is nearest within [`GATE`]; velocities come
//! from the last [`WINDOW_S`] and need [`MIN_SPAN_S`] of history; a track not seen for
//! [`FORGET_S`] is dropped, one slower than [`MIN_SPEED`] is no mover, and until then it is extrapolated (a person who leaves the
//! field of view at the robot's side is still anticipated).

use std::collections::VecDeque;

use hyplan_core::{Bounds, Point2};
use nalgebra::Vector2;

use envmap::CellFrame;

use crate::costmap::rasterize;
use crate::laser::Scan;
use crate::world::StaticWorld;

/// Neighbouring hits closer than this belong to one cluster, m.
pub const CLUSTER_GAP: f64 = 0.15;
/// Clusters wider than this (first to last hit) are not tracked: a person's visible side
/// is at most their diameter (0.5 m for the default 0.25 m radius); the corner of a box
/// off the prior map, whose centroid slides as the robot drives past, is wider, m.
pub const MAX_EXTENT: f64 = 0.6;
/// Clusters of fewer hits are not tracked: a surface seen at a grazing angle breaks into
/// single hits that slide along it as the robot moves (a person 3.5 m away still
/// returns about 30 beams of the default laser).
pub const MIN_POINTS: usize = 4;
/// A cluster joins a track whose predicted centroid is within this distance, m.
pub const GATE: f64 = 0.35;
/// Velocity window, s.
pub const WINDOW_S: f64 = 0.25;
/// History needed before a track has a velocity, s.
pub const MIN_SPAN_S: f64 = 0.1;
/// A track unseen this long is dropped, s.
pub const FORGET_S: f64 = 1.0;
/// Estimated speeds are capped here (a wrong association must not teleport a track), m/s.
pub const MAX_SPEED: f64 = 2.0;
/// Tracks slower than this are left to the obstacle memory (a static thing off the prior
/// map, whose centroid wanders a little as the robot moves), m/s.
pub const MIN_SPEED: f64 = 0.05;
/// Side of the static-prior grid, m (the obstacle memory's cells).
pub const STATIC_RES: f64 = crate::costmap::MEMORY_RESOLUTION;

/// The cells of a `res`-sided grid over `bounds` within about a cell of the static
/// geometry `mapped` (its rasterisation dilated by one cell), and the grid's rim (nothing
/// walks there): (columns, rows, cells). A hit in such a cell is explained by the prior
/// map.
#[must_use]
pub fn static_prior(bounds: Bounds, mapped: &StaticWorld, res: f64) -> (usize, usize, Vec<bool>) {
    let (width, height, cells) = rasterize(bounds, mapped, res);
    let mut prior = vec![false; width * height];
    for j in 0..height {
        for i in 0..width {
            if i == 0 || j == 0 || i + 1 == width || j + 1 == height {
                prior[j * width + i] = true;
            }
            if cells[j * width + i] {
                for jj in j.saturating_sub(1)..(j + 2).min(height) {
                    prior[jj * width + i.saturating_sub(1)..jj * width + (i + 2).min(width)]
                        .fill(true);
                }
            }
        }
    }
    (width, height, prior)
}

/// A moving obstacle as the controller sees it: a disc that covers the track's last
/// hits, moving at the track's velocity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mover {
    /// Centre now (extrapolated to the query time), m.
    pub center: Point2,
    /// Radius covering the last hits around the centre, m.
    pub radius: f64,
    /// Velocity, m/s.
    pub velocity: Vector2<f64>,
}

impl Mover {
    /// The centre `tau` seconds from now.
    #[must_use]
    pub fn at(&self, tau: f64) -> Point2 {
        self.center + self.velocity * tau
    }
}

/// One cluster of a scan.
#[derive(Debug, Clone, Copy)]
struct Cluster {
    centre: Point2,
    radius: f64,
    /// Direction of the field-of-view edge that cuts the cluster, if one does.
    edge: Option<Vector2<f64>>,
}

#[derive(Debug, Clone)]
struct Track {
    /// (tick, centroid) of the last observations, oldest first.
    history: VecDeque<(u64, Point2)>,
    radius: f64,
    velocity: Option<Vector2<f64>>,
    /// The field-of-view edge cutting the last observation, if one did.
    edge: Option<Vector2<f64>>,
}

impl Track {
    fn last(&self) -> (u64, Point2) {
        *self
            .history
            .back()
            .expect("a track has at least one observation")
    }

    fn predict(&self, tick: u64, ticks_per_s: f64) -> Point2 {
        let (t0, p) = self.last();
        let v = self.velocity.unwrap_or_else(Vector2::zeros);
        p + v * ((tick.saturating_sub(t0)) as f64 / ticks_per_s)
    }

    /// Least-squares slope of the centroid over the window.
    fn estimate(&mut self, ticks_per_s: f64) {
        let (first, last) = (self.history[0].0, self.last().0);
        if ((last - first) as f64) < MIN_SPAN_S * ticks_per_s {
            self.velocity = None;
            return;
        }
        let n = self.history.len() as f64;
        let mean_t = self.history.iter().map(|h| h.0 as f64).sum::<f64>() / n;
        let mean_p = self
            .history
            .iter()
            .fold(Vector2::zeros(), |m, h| m + h.1.coords)
            / n;
        let (mut stt, mut stp) = (0.0, Vector2::zeros());
        for &(t, p) in &self.history {
            let dt = t as f64 - mean_t;
            stt += dt * dt;
            stp += (p.coords - mean_p) * dt;
        }
        let v = stp / stt * ticks_per_s;
        self.velocity = Some(if v.norm() > MAX_SPEED {
            v * (MAX_SPEED / v.norm())
        } else {
            v
        });
    }
}

/// The tracker: static prior, live tracks.
#[derive(Debug, Clone)]
pub struct Tracker {
    width: usize,
    height: usize,
    origin: Point2,
    prior: Vec<bool>,
    tracks: Vec<Track>,
    ticks_per_s: f64,
    range: f64,
    /// A cluster's points while it is read (kept between scans).
    run: Vec<Point2>,
}

impl Tracker {
    /// A tracker whose static prior is `mapped` over `bounds`; hits farther than `range`
    /// from the scanner are ignored; time is counted in ticks of `1 / ticks_per_s` s.
    #[must_use]
    pub fn new(bounds: Bounds, mapped: &StaticWorld, range: f64, ticks_per_s: f64) -> Self {
        let (width, height, prior) = static_prior(bounds, mapped, STATIC_RES);
        Self {
            width,
            height,
            origin: bounds.min,
            prior,
            tracks: Vec::new(),
            ticks_per_s,
            range,
            run: Vec::new(),
        }
    }

    /// Forgets every track, keeping the static prior: a new run in the same world.
    pub fn forget(&mut self) {
        self.tracks.clear();
    }

    /// Whether `p` is within about a cell of the static prior (or outside the world:
    /// nothing walks there).
    fn explained(&self, p: Point2) -> bool {
        let frame = CellFrame::new(self.origin, STATIC_RES, self.width, self.height);
        frame.index_of(p).is_none_or(|k| self.prior[k])
    }

    /// How far from the scanner the tracker reads a scan, m: its range, and a cluster's
    /// gap beyond it (to tell whether an object goes on past the range).
    #[must_use]
    pub fn reach(&self) -> f64 {
        self.range + CLUSTER_GAP
    }

    /// The clusters of a scan's unexplained hits: (centroid, covering radius). `c` holds
    /// each run of hits while it is read, so that a kept cluster's centroid is folded over
    /// the points found, not over points computed again.
    fn clusters(&self, scan: &Scan, c: &mut Vec<Point2>) -> Vec<Cluster> {
        let n = scan.ranges.len();
        let point = |k: usize| {
            (scan.ranges[k] <= self.range)
                .then(|| scan.hit(k))
                .flatten()
                .filter(|&p| !self.explained(p))
        };
        // Whether the object goes on past beam `k` (next to a cluster's end `end`): beyond
        // the tracked range, or too close to measure.
        let cut = |k: usize, end: Point2| {
            scan.too_close(k)
                || (scan.ranges[k] > self.range
                    && scan.hit(k).is_some_and(|q| (q - end).norm() <= CLUSTER_GAP))
        };
        let mut out = Vec::new();
        let mut k = 0;
        while k < n {
            let Some(p) = point(k) else {
                k += 1;
                continue;
            };
            let first = k;
            c.clear();
            c.push(p);
            let (a, mut b) = (p, p);
            k += 1;
            while k < n
                && let Some(q) = point(k)
                && (q - b).norm() <= CLUSTER_GAP
            {
                c.push(q);
                b = q;
                k += 1;
            }
            // A cluster cut by the range or a too-close beam: its centroid slides as more
            // or less of the object shows, and says nothing of the object's motion.
            if (b - a).norm() > MAX_EXTENT
                || k - first < MIN_POINTS
                || first.checked_sub(1).is_some_and(|j| cut(j, a))
                || (k < n && cut(k, b))
            {
                continue;
            }
            // Cut by the edge of the field of view: the centroid slides across the edge
            // ray as the scanner moves, but not along it (a person walking at the robot's
            // side toward it is half out of view and must still be anticipated).
            let edge = if first == 0 {
                Some(scan.directions[0])
            } else if k == n {
                Some(scan.directions[n - 1])
            } else {
                None
            };
            let mean = c.iter().fold(Vector2::zeros(), |m, p| m + p.coords) / c.len() as f64;
            let centre = Point2::from(mean);
            let radius = c.iter().map(|p| (p - centre).norm()).fold(0.05, f64::max);
            out.push(Cluster {
                centre,
                radius,
                edge,
            });
        }
        out
    }

    /// Takes in the scan seen at `tick`.
    pub fn update(&mut self, scan: &Scan, tick: u64) {
        let forget = (FORGET_S * self.ticks_per_s) as u64;
        self.tracks
            .retain(|t| tick.saturating_sub(t.last().0) <= forget);
        let mut run = std::mem::take(&mut self.run);
        let clusters = self.clusters(scan, &mut run);
        self.run = run;
        let predicted: Vec<Point2> = self
            .tracks
            .iter()
            .map(|t| t.predict(tick, self.ticks_per_s))
            .collect();
        // Greedy association, nearest pairs first.
        let mut pairs: Vec<(f64, usize, usize)> = Vec::new();
        for (c, cl) in clusters.iter().enumerate() {
            let p = cl.centre;
            for (t, q) in predicted.iter().enumerate() {
                let d = (p - q).norm();
                if d <= GATE {
                    pairs.push((d, c, t));
                }
            }
        }
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut cluster_used = vec![false; clusters.len()];
        let mut track_used = vec![false; self.tracks.len()];
        let window = (WINDOW_S * self.ticks_per_s) as u64;
        for (_, c, t) in pairs {
            if cluster_used[c] || track_used[t] {
                continue;
            }
            cluster_used[c] = true;
            track_used[t] = true;
            let track = &mut self.tracks[t];
            track.history.push_back((tick, clusters[c].centre));
            track.radius = clusters[c].radius;
            track.edge = clusters[c].edge;
            while track.history.front().is_some_and(|h| tick - h.0 > window) {
                track.history.pop_front();
            }
            track.estimate(self.ticks_per_s);
        }
        for (c, cl) in clusters.iter().enumerate() {
            if !cluster_used[c] {
                self.tracks.push(Track {
                    history: VecDeque::from([(tick, cl.centre)]),
                    radius: cl.radius,
                    velocity: None,
                    edge: cl.edge,
                });
            }
        }
    }

    /// The tracks with a velocity, as movers at `tick`.
    #[must_use]
    pub fn movers(&self, tick: u64) -> Vec<Mover> {
        self.tracks
            .iter()
            .filter_map(|t| {
                // Of a track cut by the field of view, only the motion along the edge.
                let v = t
                    .velocity
                    .map(|v| t.edge.map_or(v, |e| e * v.dot(&e)))
                    .filter(|v| v.norm() >= MIN_SPEED)?;
                Some(Mover {
                    center: t.predict(tick, self.ticks_per_s),
                    radius: t.radius,
                    velocity: v,
                })
            })
            .collect()
    }
}
