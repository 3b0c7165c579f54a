//! A planar laser scanner with exact ray casts and seeded Gaussian range noise.
//!
//! Each beam's true range is the distance to the first static segment, static disc or
//! person it meets, computed exactly (no stepping). Rather than cast every beam against
//! every obstacle, each obstacle is swept once: its angular extent seen from the scanner
//! gives the few beams that can hit it, and only those are intersected. The result is the
//! same as the beam-by-beam minimum (a property test checks it against parry2d's ray casts).
//! A loaded map is not swept as the thousands of segments its walls can make: past 1.5
//! segments a beam, each beam marches over the map's own cells instead (`grid_cast`), so
//! the cost follows the beams' lengths in open space, not the map's wall count (both
//! property-tested against the brute-force reference). Measured (issue 27): the sweep
//! costs about 0.1 us a segment and the march about 0.15 us a beam per scan, hence the
//! switch.
//!
//! A run reads its scans only a few metres out (the map update to 4 m, the costmap and
//! the tracker to 3.5 m), so it casts each scan only that far
//! ([`LaserModel::scan_within`]): the walls within the horizon come from buckets
//! ([`NearSegments`]), and a loaded map's few boundary segments there are swept rather
//! than its cells marched. Every beam the run reads is the one a whole cast gives, with
//! the same noise (a property test checks it); a beam beyond reads `INFINITY`, unless an
//! observer asks for whole scans.

use hyplan_core::{Bounds, Point2};
use nalgebra::Vector2;
use rand::Rng;
use rand_distr::{Distribution, Normal};
use serde::{Deserialize, Serialize};

use crate::boxgrid::{BoxGrid, Marks};
use crate::kinematics::Pose;
use crate::world::{Disc, StaticWorld};

/// Scanner parameters.
///
/// Defaults: the 180-degree laser of the paper with the Kobuki tutorial's scanner
/// (rrt_exploration_tutorials' Kobuki set-up): 720 beams, 40 Hz, 0.10-60 m, noise sigma 0.01 m,
/// mounted 0.115 m ahead of the base centre.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Laser {
    /// Field of view, degrees, centred on the heading.
    pub fov_deg: f64,
    /// Number of beams (at least 2), the first at `-fov/2`, the last at `+fov/2`.
    pub beams: usize,
    /// Shortest valid range, m.
    pub range_min: f64,
    /// Longest valid range, m.
    pub range_max: f64,
    /// Scans per second.
    pub rate_hz: f64,
    /// Scanner position ahead of the base centre, m.
    pub mount_offset: f64,
    /// Standard deviation of the Gaussian range noise, m (0: exact ranges).
    pub noise_sd: f64,
}

impl Default for Laser {
    fn default() -> Self {
        Self {
            fov_deg: 180.0,
            beams: 720,
            range_min: 0.10,
            range_max: 60.0,
            rate_hz: 40.0,
            mount_offset: 0.115,
            noise_sd: 0.01,
        }
    }
}

impl Laser {
    /// The same scanner with a field of `fov_deg` degrees at the same angle between
    /// beams (seed 004's 720 beams over 180 degrees become 1,080 over 270).
    ///
    /// ```
    /// let wide = sim::Laser::default().with_fov(270.0);
    /// assert_eq!((wide.fov_deg, wide.beams), (270.0, 1080));
    /// assert_eq!(wide.with_fov(180.0), sim::Laser::default());
    /// ```
    #[must_use]
    pub fn with_fov(self, fov_deg: f64) -> Self {
        let beams = (self.beams as f64 * fov_deg / self.fov_deg).round();
        Self {
            fov_deg,
            // At least the two a scan needs; a bad field is the caller's check.
            beams: if beams.is_finite() {
                (beams as usize).max(2)
            } else {
                self.beams
            },
            ..self
        }
    }
}

/// One scan: where it was taken and a range per beam.
#[derive(Debug, Clone, PartialEq)]
pub struct Scan {
    /// Scanner position, m.
    pub origin: Point2,
    /// Direction of beam 0, rad (heading - fov / 2).
    pub angle_min: f64,
    /// Angle between neighbouring beams, rad.
    pub angle_increment: f64,
    /// Range per beam, m, as ROS's REP 117 has it: `f64::INFINITY` when nothing was hit
    /// within `range_max`, `f64::NEG_INFINITY` when the hit was closer than `range_min`
    /// (something is at the scanner: a reader must not take the beam for a clear view).
    pub ranges: Vec<f64>,
    /// The scanner's shortest valid range, m.
    pub range_min: f64,
    /// Unit direction of each beam in the world frame (beam `k` points at
    /// `angle_min + k angle_increment`), kept so that readers need no trigonometry.
    pub directions: Vec<Vector2<f64>>,
}

impl Scan {
    /// Whether beam `k` met something closer than the scanner's shortest range.
    #[must_use]
    pub fn too_close(&self, k: usize) -> bool {
        self.ranges[k] == f64::NEG_INFINITY
    }

    /// The world point a beam hit, if it hit something within the valid range.
    #[must_use]
    pub fn hit(&self, k: usize) -> Option<Point2> {
        let r = self.ranges[k];
        r.is_finite().then(|| self.origin + self.directions[k] * r)
    }

    /// The box holding every segment a map update with range `max` traces from this scan
    /// ([`crate::OccupancyGrid::integrate`]'s rule: to the hit, or `max` along a beam
    /// without one within it; nothing for a beam too close to measure), and the origin.
    #[must_use]
    pub fn traced_bounds(&self, max: f64) -> Bounds {
        let (mut lo, mut hi) = (self.origin, self.origin);
        for (r, d) in self.ranges.iter().zip(&self.directions) {
            if *r == f64::NEG_INFINITY {
                continue;
            }
            let len = if r.is_finite() && *r <= max { *r } else { max };
            let end = self.origin + d * len;
            lo = Point2::new(lo.x.min(end.x), lo.y.min(end.y));
            hi = Point2::new(hi.x.max(end.x), hi.y.max(end.y));
        }
        Bounds::new(lo, hi)
    }

    /// The beam pointing nearest to world direction `angle`, if inside the field of view.
    #[must_use]
    pub fn beam_toward(&self, angle: f64) -> Option<usize> {
        let u = (angle - self.angle_min).rem_euclid(std::f64::consts::TAU);
        let k = (u / self.angle_increment).round();
        (k < self.ranges.len() as f64).then_some(k as usize)
    }
}

/// Beam directions in the scanner frame, computed once per laser.
#[derive(Debug, Clone)]
pub struct LaserModel {
    /// Parameters.
    pub laser: Laser,
    /// Unit direction of each beam in the scanner frame.
    local: Vec<Vector2<f64>>,
    fov: f64,
    inc: f64,
    noise: Option<Normal<f64>>,
}

impl LaserModel {
    /// Prepares a scanner. Parameters are assumed validated (see the scenario checks).
    #[must_use]
    pub fn new(laser: Laser) -> Self {
        let fov = laser.fov_deg.to_radians();
        let n = laser.beams.max(2);
        let inc = fov / (n - 1) as f64;
        let local = (0..n)
            .map(|k| {
                let a = -fov / 2.0 + k as f64 * inc;
                Vector2::new(a.cos(), a.sin())
            })
            .collect();
        let noise = (laser.noise_sd > 0.0)
            .then(|| Normal::new(0.0, laser.noise_sd).ok())
            .flatten();
        Self {
            laser,
            local,
            fov,
            inc,
            noise,
        }
    }

    /// Where the scanner is when the base is at `pose`, and its heading.
    #[must_use]
    pub fn origin(&self, pose: &Pose) -> (Point2, f64) {
        let (s, c) = pose.phi.sin_cos();
        (
            Point2::new(
                pose.x + c * self.laser.mount_offset,
                pose.y + s * self.laser.mount_offset,
            ),
            pose.phi,
        )
    }

    /// Exact ranges from `origin` looking along `heading`: the distance to the first
    /// obstacle on each beam; `INFINITY` beyond `range_max`, `NEG_INFINITY` below
    /// `range_min` (REP 117).
    #[must_use]
    pub fn cast(&self, world: &StaticWorld, people: &[Disc], origin: Point2, heading: f64) -> Scan {
        self.cast_to(world, people, origin, heading, f64::INFINITY, None)
    }

    /// [`cast`](Self::cast) of the obstacles within `limit` only (all of them when it is
    /// infinite; those `near` finds, when given): a beam that meets none reads `limit`
    /// (or `INFINITY` beyond `range_max`).
    fn cast_to(
        &self,
        world: &StaticWorld,
        people: &[Disc],
        origin: Point2,
        heading: f64,
        limit: f64,
        near: Option<&mut NearSegments>,
    ) -> Scan {
        let n = self.local.len();
        let mut ranges = vec![limit; n];
        let (s, c) = heading.sin_cos();
        let dirs: Vec<Vector2<f64>> = self
            .local
            .iter()
            .map(|d| Vector2::new(c * d.x - s * d.y, s * d.x + c * d.y))
            .collect();
        let theta0 = heading - self.fov / 2.0;
        let tau = std::f64::consts::TAU;
        // Angle from beam 0 in [0, 2 pi), measured in the scanner's frame (no reduction of
        // a large heading) with the fast arctangent: only the beam spans below use it.
        let half_fov = self.fov / 2.0;
        let u_of = |v: Vector2<f64>| {
            let u = fast_atan2(c * v.y - s * v.x, c * v.x + s * v.y) + half_fov;
            if u < 0.0 {
                u + tau
            } else if u >= tau {
                u - tau
            } else {
                u
            }
        };
        let inc = self.inc;
        // The beams k with u_k = k inc in [lo, lo + span] (mod 2 pi), with a margin on
        // each side: the exact intersection test decides, so a span may be wider than the
        // obstacle but never narrower. One beam covers an error in the span's ends below
        // one increment (each end is off by at most the arctangent's error, plus
        // rounding); a laser finer than that gets more.
        let margin = if 4.0 * FAST_ATAN2_ERROR < inc {
            1.0
        } else {
            1.0 + (2.0 * FAST_ATAN2_ERROR / inc).ceil()
        };
        // In beam units, `x` to `y` widened by the margin: each end converted once to an
        // index (truncation floors what is not negative) rather than rounded, divided and
        // converted; a span one beam wider at an end costs a ray test, not an error. A
        // product, not a quotient, per end: its rounding is far inside the margin.
        let per_inc = 1.0 / inc;
        let last = n - 1;
        let spans = |lo: f64, span: f64| {
            [0.0, -tau].map(|shift| {
                let x = (lo + shift) * per_inc;
                let y = (lo + span + shift) * per_inc + margin;
                // `as` saturates: below 0 (or NaN) is beam 0.
                let a = (x - margin) as usize;
                let b = if y >= 0.0 {
                    (y as usize).min(last)
                } else if y.is_nan() {
                    last
                } else {
                    return 0..0;
                };
                if a <= b { a..b + 1 } else { 0..0 }
            })
        };
        // Nearest obstacles first, so that one hidden behind nearer hits over its whole
        // span is skipped without a ray test (its exact hits could not lower any range).
        let mut order: Vec<(f64, Obstacle)> = Vec::new();
        // A loaded map with more boundary segments than the sweep handles cheaply is cast
        // on its cells below (a world built by hand without the grid is always swept).
        // Within a horizon, the walls near enough to matter (their indices, the loaded
        // map's after the shapes'), and how many of them are the map's.
        let picked = near.map(|near| near.within(origin, limit));
        let map_segments = picked.map_or(world.grid_segments.len(), |p| {
            p.iter()
                .filter(|&&i| i as usize >= world.segments.len())
                .count()
        });
        // Past 1.5 map segments a beam a whole cast marches over the cells; within a
        // horizon, past 3 (measured on the real maps: sweeping up to 3 a beam, or always,
        // took 0.85 of the time of sweeping up to 1.5 on the Osnabrück floor, 0.97-0.99
        // on the others).
        let swept_per_two_beams = if picked.is_some() { 6 } else { 3 };
        let march = (2 * map_segments > swept_per_two_beams * n)
            .then(|| world.grid_rays())
            .flatten();
        let grid_segments: &[crate::world::Segment] = if march.is_some() {
            &[]
        } else {
            &world.grid_segments
        };
        // With a field of view of at most a half turn every beam points into the
        // half-plane ahead of the scanner (its component along the heading is >= 0), so
        // an obstacle wholly behind the scanner's line cannot be hit: it is left out
        // before any distance, angle or span is computed. (1 um of margin: an edge beam
        // at exactly 90 degrees is off the line by rounding, far below it.)
        let ahead = Vector2::new(c, s);
        let half_turn = self.fov <= std::f64::consts::PI;
        let wholly_behind = |along: f64| half_turn && along < -1e-6;
        // A loaded map's edge seen from its occupied side is met only after a nearer edge
        // of the same cells, unless the scanner is inside them (pressed into a wall).
        let shapes = world.segments.len();
        let in_occupied = world.in_occupied_cell(origin);
        let mut consider = |i: usize, seg: &crate::world::Segment| {
            let pa = seg.a - origin;
            // Seen from behind (the scanner inside the half-plane behind an outward
            // edge of a closed outline, or of occupied cells): another edge of the same
            // outline, or of the same cells, is nearer.
            if let Some(nrm) = seg.outward
                && nrm.dot(&pa) >= 0.0
                && (i < shapes || !in_occupied)
            {
                return;
            }
            let pb = seg.b - origin;
            if wholly_behind(ahead.dot(&pa).max(ahead.dot(&pb))) {
                return;
            }
            order.push((segment_distance(pa, seg.b - seg.a), Obstacle::Segment(i)));
        };
        match picked {
            Some(picked) => {
                for &i in picked {
                    let i = i as usize;
                    if i < shapes {
                        consider(i, &world.segments[i]);
                    } else if march.is_none() {
                        consider(i, &world.grid_segments[i - shapes]);
                    }
                }
            }
            None => {
                for (i, seg) in world.segments.iter().chain(grid_segments).enumerate() {
                    consider(i, seg);
                }
            }
        }
        for (i, disc) in world.discs.iter().chain(people).enumerate() {
            let dist = (disc.center - origin).norm();
            if dist <= disc.radius {
                // Inside the disc: every beam is blocked at once.
                ranges.iter_mut().for_each(|r| *r = 0.0);
                continue;
            }
            if wholly_behind(ahead.dot(&(disc.center - origin)) + disc.radius) {
                continue;
            }
            order.push((dist - disc.radius, Obstacle::Disc(i)));
        }
        let order = nearest_first(order);
        let segments = world.segments.len();
        let discs = world.discs.len();
        let mut reach = Reach::new(&ranges);
        for &(near, obstacle) in &order {
            // A beam whose range is already shorter than the obstacle's distance cannot
            // be lowered by it. Computed hits can fall a few ulps short of the computed
            // distance: a margin far above rounding keeps the skip exact.
            let behind = near - 1e-9 * (1.0 + near);
            // Nearest bin first: once every beam ends before this obstacle's bin, it and
            // all the later ones are hidden.
            let start = bin_start(near);
            let hidden = start - 1e-9 * (1.0 + start);
            if reach.all < hidden && reach.longest() < hidden {
                break;
            }
            match obstacle {
                Obstacle::Segment(i) => {
                    let seg = if i < segments {
                        &world.segments[i]
                    } else {
                        &grid_segments[i - segments]
                    };
                    let (pa, pb) = (seg.a - origin, seg.b - origin);
                    let e = seg.b - seg.a;
                    let (ua, ub) = (u_of(pa), u_of(pb));
                    let mut d = ub - ua;
                    if d > std::f64::consts::PI {
                        d -= tau;
                    } else if d < -std::f64::consts::PI {
                        d += tau;
                    }
                    let (lo, span) = if d >= 0.0 { (ua, d) } else { (ub, -d) };
                    lower(&mut ranges, &mut reach, spans(lo, span), behind, |k| {
                        ray_segment(dirs[k], pa, e)
                    });
                }
                Obstacle::Disc(i) => {
                    let disc = if i < discs {
                        &world.discs[i]
                    } else {
                        &people[i - discs]
                    };
                    let rel = disc.center - origin;
                    let half = (disc.radius / rel.norm()).asin();
                    let mid = u_of(rel);
                    let span = spans((mid - half).rem_euclid(tau), 2.0 * half);
                    lower(&mut ranges, &mut reach, span, behind, |k| {
                        ray_disc(dirs[k], rel, disc.radius)
                    });
                }
            }
        }
        let (lo, hi) = (self.laser.range_min, self.laser.range_max);
        if let Some(grid) = march {
            grid.lower(origin, &dirs, &mut ranges, hi.min(limit));
        }
        rep_117(&mut ranges, lo, hi);
        Scan {
            origin,
            angle_min: theta0,
            angle_increment: self.inc,
            ranges,
            range_min: lo,
            directions: dirs,
        }
    }

    /// Adds the seeded Gaussian noise to every valid range (clamped to the valid range,
    /// as Gazebo's ray sensor does). One draw per beam, valid or not, so that the draws
    /// do not depend on what the beams met (a scan cast only to a horizon,
    /// [`LaserModel::scan_within`], draws the same).
    pub fn add_noise<R: Rng + ?Sized>(&self, scan: &mut Scan, rng: &mut R) {
        if let Some(draws) = self.draws(scan.ranges.len(), rng) {
            self.apply_noise(&mut scan.ranges, &draws);
        }
    }

    /// One noise draw per beam of a scan of `n` beams; none without noise.
    fn draws<R: Rng + ?Sized>(&self, n: usize, rng: &mut R) -> Option<Vec<f64>> {
        let noise = self.noise.as_ref()?;
        Some((0..n).map(|_| noise.sample(rng)).collect())
    }

    /// Adds `draws` to the valid ranges, clamped to the valid range.
    fn apply_noise(&self, ranges: &mut [f64], draws: &[f64]) {
        let (lo, hi) = (self.laser.range_min, self.laser.range_max);
        for (r, d) in ranges.iter_mut().zip(draws) {
            if r.is_finite() {
                *r = (*r + d).clamp(lo, hi);
            }
        }
    }

    /// The scan [`cast`](Self::cast) then [`add_noise`](Self::add_noise) would give,
    /// drawing the same noise, except that a beam whose noisy range is beyond `need` may
    /// read `INFINITY`: for readers that use nothing farther (the map update, the
    /// costmap, the tracker), at the cost of the obstacles within `need` (and a margin)
    /// only. The walls come from `near`, [`NearSegments`] of the same world (with
    /// another world's, the whole scan is cast).
    ///
    /// With `whole`, the beams beyond the horizon are cast to the end as well (for a
    /// reader of whole scans), and the beams within it keep the values they have
    /// without: so a run reads the same numbers whether or not someone also wants the
    /// whole scan. A beam is the same as [`cast`](Self::cast)'s to rounding (on a
    /// loaded map the horizon's few walls may be swept where the whole cast marches
    /// over the cells: both are exact to rounding).
    ///
    /// ```
    /// use hyplan_core::Point2;
    /// use rand::SeedableRng;
    /// use sim::{Laser, LaserModel, NearSegments, Shape, StaticWorld};
    /// let mut world = StaticWorld::default();
    /// for center in [(2.5, 0.0), (20.5, 0.0)] {
    ///     world.add_shape(&Shape::Box { center, size: (1.0, 12.0), angle_deg: 0.0 });
    /// }
    /// let laser = LaserModel::new(Laser::default());
    /// let mut near = NearSegments::new(&world);
    /// let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    /// let o = Point2::new(0.0, 0.0);
    /// let scan = laser.scan_within(&world, &[], o, 0.0, 5.0, false, &mut near, &mut rng);
    /// let ahead = scan.beam_toward(0.0).unwrap();
    /// assert!((scan.ranges[ahead] - 2.0).abs() < 0.1); // the near wall, measured
    /// let side = scan.beam_toward(1.45).unwrap();
    /// assert_eq!(scan.ranges[side], f64::INFINITY); // the near wall's end, beyond 5 m
    /// ```
    #[allow(clippy::too_many_arguments)]
    pub fn scan_within<R: Rng + ?Sized>(
        &self,
        world: &StaticWorld,
        people: &[Disc],
        origin: Point2,
        heading: f64,
        need: f64,
        whole: bool,
        near: &mut NearSegments,
        rng: &mut R,
    ) -> Scan {
        let margin = 0.05 + 20.0 * self.laser.noise_sd;
        self.scan_within_margin(
            world,
            people,
            origin,
            heading,
            (need, margin),
            whole,
            near,
            rng,
        )
    }

    /// [`scan_within`](Self::scan_within) with the margin past `need` that the cast goes:
    /// a beam cast that far without a hit reads beyond `need` unless its noise draw is
    /// below minus half of it (ten deviations for the public one); then the beams
    /// beyond the horizon are cast to the end.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn scan_within_margin<R: Rng + ?Sized>(
        &self,
        world: &StaticWorld,
        people: &[Disc],
        origin: Point2,
        heading: f64,
        (need, margin): (f64, f64),
        whole: bool,
        near: &mut NearSegments,
        rng: &mut R,
    ) -> Scan {
        let limit = need + margin;
        // (A NaN `need` casts the whole scan too.)
        if limit.partial_cmp(&self.laser.range_max) != Some(std::cmp::Ordering::Less)
            || near.len() != world.segments.len() + world.grid_segments.len()
        {
            let mut scan = self.cast(world, people, origin, heading);
            self.add_noise(&mut scan, rng);
            return scan;
        }
        let mut scan = self.cast_to(world, people, origin, heading, limit, Some(near));
        let draws = self.draws(scan.ranges.len(), rng);
        // A beam that met nothing before `limit` has a true range of at least `limit`
        // (to rounding): with a draw above `-margin / 2` its noisy range is beyond `need`.
        let beyond = |r: f64| r >= limit && r.is_finite();
        let unsure = draws.as_ref().is_some_and(|draws| {
            scan.ranges
                .iter()
                .zip(draws)
                .any(|(&r, &d)| beyond(r) && d <= -0.5 * margin)
        });
        if whole || unsure {
            let all = self.cast(world, people, origin, heading);
            for (r, a) in scan.ranges.iter_mut().zip(all.ranges) {
                if beyond(*r) {
                    *r = a;
                }
            }
        } else {
            for r in &mut scan.ranges {
                if beyond(*r) {
                    *r = f64::INFINITY;
                }
            }
        }
        if let Some(draws) = draws {
            self.apply_noise(&mut scan.ranges, &draws);
        }
        scan
    }
}

/// The walls of a world (its shapes' segments, then its loaded map's) in buckets, for
/// casts to a horizon ([`LaserModel::scan_within`]): only the segments within it are
/// swept, where a whole cast sweeps them all.
///
/// ```
/// use sim::{NearSegments, Shape, StaticWorld};
/// let mut world = StaticWorld::default();
/// world.add_shape(&Shape::Box { center: (2.5, 0.0), size: (1.0, 2.0), angle_deg: 0.0 });
/// assert_eq!(NearSegments::new(&world).len(), 4);
/// ```
#[derive(Debug, Clone, Default)]
pub struct NearSegments {
    grid: BoxGrid,
    marks: Marks,
    picked: Vec<u32>,
}

/// Side of [`NearSegments`]' buckets, m: about a quarter of the horizon the runs cast to.
const NEAR_BUCKET: f64 = 1.0;

impl NearSegments {
    /// `world`'s segments in buckets.
    #[must_use]
    pub fn new(world: &StaticWorld) -> Self {
        let boxes = world
            .segments
            .iter()
            .chain(&world.grid_segments)
            .map(|s| {
                (
                    Point2::new(s.a.x.min(s.b.x), s.a.y.min(s.b.y)),
                    Point2::new(s.a.x.max(s.b.x), s.a.y.max(s.b.y)),
                )
            })
            .collect();
        Self {
            grid: BoxGrid::new(boxes, NEAR_BUCKET),
            ..Self::default()
        }
    }

    /// Number of segments held.
    #[must_use]
    pub fn len(&self) -> usize {
        self.grid.len()
    }

    /// Whether it holds no segment.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.grid.len() == 0
    }

    /// The indices of the segments within `reach` of `p` (a superset: their boxes are),
    /// in the buckets' order (a cast's ranges are minima: the order does not change them).
    fn within(&mut self, p: Point2, reach: f64) -> &[u32] {
        self.picked.clear();
        let picked = &mut self.picked;
        self.grid
            .near(p, reach, &mut self.marks, |k| picked.push(k));
        &self.picked
    }
}

/// Ranges outside `[lo, hi]` as REP 117 writes them: `NEG_INFINITY` below (something at
/// the scanner), `INFINITY` above (no return).
fn rep_117(ranges: &mut [f64], lo: f64, hi: f64) {
    // Two selects, not a chain of branches: they compile to masks, so the beams that
    // leave the range cost no mispredicted branch.
    for r in ranges {
        let v = if *r > hi { f64::INFINITY } else { *r };
        *r = if v < lo { f64::NEG_INFINITY } else { v };
    }
}

/// Lowers each range of the beams in `spans` to the obstacle's hit `hit(k)` where that is
/// nearer; a beam already shorter than `behind` (the obstacle's distance) is skipped, a
/// block of them at once when `reach` says its longest range is.
fn lower(
    ranges: &mut [f64],
    reach: &mut Reach,
    spans: [std::ops::Range<usize>; 2],
    behind: f64,
    hit: impl Fn(usize) -> Option<f64>,
) {
    for range in spans {
        if range.is_empty() {
            continue;
        }
        for b in range.start / BLOCK..=(range.end - 1) / BLOCK {
            if reach.block[b] < behind {
                continue;
            }
            let beams = range.start.max(b * BLOCK)..range.end.min((b + 1) * BLOCK);
            let mut lowered = false;
            for k in beams {
                if ranges[k] < behind {
                    continue;
                }
                if let Some(t) = hit(k)
                    && t < ranges[k]
                {
                    ranges[k] = t;
                    lowered = true;
                }
            }
            if lowered {
                reach.refresh(ranges, b);
            }
        }
    }
}

/// Beams per block of [`Reach`].
const BLOCK: usize = 16;

/// The longest range of each block of [`BLOCK`] beams of a cast under way: most of a
/// building's walls are hidden behind nearer ones, and their spans are then skipped a
/// block at a time instead of beam by beam.
struct Reach {
    block: Vec<f64>,
    /// The longest of all, or more: ranges only fall, so it is brought down only when
    /// an obstacle is beyond it.
    all: f64,
}

impl Reach {
    fn new(ranges: &[f64]) -> Self {
        let mut reach = Self {
            block: vec![f64::INFINITY; ranges.len().div_ceil(BLOCK)],
            all: f64::INFINITY,
        };
        for b in 0..reach.block.len() {
            reach.refresh(ranges, b);
        }
        reach
    }

    fn refresh(&mut self, ranges: &[f64], b: usize) {
        let end = ranges.len().min((b + 1) * BLOCK);
        self.block[b] = ranges[b * BLOCK..end]
            .iter()
            .fold(f64::NEG_INFINITY, |m, &r| m.max(r));
    }

    /// The longest range (`all` brought down to it).
    fn longest(&mut self) -> f64 {
        self.all = self.block.iter().fold(f64::NEG_INFINITY, |m, &r| m.max(r));
        self.all
    }
}

/// Bound on `|fast_atan2(y, x) - y.atan2(x)|`, rad (the polynomial's 1e-5 of Abramowitz
/// and Stegun 4.4.49, with room for rounding; a test sweeps it).
const FAST_ATAN2_ERROR: f64 = 2e-5;

/// The angle of `(x, y)` within [`FAST_ATAN2_ERROR`], in `[-pi, pi]`: the odd polynomial of
/// Abramowitz and Stegun 4.4.49 on `[0, 1]`, unfolded by octant. Five multiplications where
/// libm's exact `atan2` costs several times more; the cast only needs beam spans from it.
fn fast_atan2(y: f64, x: f64) -> f64 {
    use std::f64::consts::{FRAC_PI_2, PI};
    let (ax, ay) = (x.abs(), y.abs());
    let (lo, hi) = if ax < ay { (ax, ay) } else { (ay, ax) };
    if hi == 0.0 {
        return 0.0;
    }
    let z = lo / hi;
    let z2 = z * z;
    let mut a = z
        * (0.999_866_0
            + z2 * (-0.330_299_5 + z2 * (0.180_141_0 + z2 * (-0.085_133_0 + z2 * 0.020_835_1))));
    if ay > ax {
        a = FRAC_PI_2 - a;
    }
    if x < 0.0 {
        a = PI - a;
    }
    if y < 0.0 { -a } else { a }
}

/// An obstacle of a cast, by index: a segment of `segments` then `grid_segments`, a disc of
/// `discs` then the people.
#[derive(Debug, Clone, Copy)]
enum Obstacle {
    Segment(usize),
    Disc(usize),
}

/// Width of the distance bins in which [`nearest_first`] orders a cast's obstacles, m.
const BIN: f64 = 0.25;

/// Bins of [`nearest_first`] ([`BIN`] wide, the last one open-ended).
const BINS: usize = 256;

/// Below this many obstacles [`nearest_first`] sorts them exactly (distances are never
/// negative nor NaN: their bits sort as they do).
const SORTED_BELOW: usize = 64;

/// `order` by distance, in bins of [`BIN`] (a counting sort: O(n), where a sort is
/// O(n log n) for the hundreds of segments of a building); sorted when there are few.
///
/// The cast's ranges do not depend on the order (each is the minimum of its hits): the
/// order only lets the obstacles behind nearer hits be skipped a block of beams at a
/// time, which a quarter-metre order does about as well as an exact one.
fn nearest_first(mut order: Vec<(f64, Obstacle)>) -> Vec<(f64, Obstacle)> {
    if order.len() < SORTED_BELOW {
        // A few shapes: sorting them costs less than the bins' counts.
        order.sort_unstable_by_key(|o| o.0.to_bits());
        return order;
    }
    let mut starts = [0usize; BINS + 1];
    for &(d, _) in &order {
        starts[bin(d) + 1] += 1;
    }
    for b in 0..BINS {
        starts[b + 1] += starts[b];
    }
    let mut sorted = vec![(0.0, Obstacle::Disc(0)); order.len()];
    for o in order {
        let at = &mut starts[bin(o.0)];
        sorted[*at] = o;
        *at += 1;
    }
    sorted
}

/// The bin of distance `d` (never negative nor NaN; `as` saturates: the far ones go to the
/// last bin). `1 / BIN` is a power of two, so the product is exact.
fn bin(d: f64) -> usize {
    ((d * (1.0 / BIN)) as usize).min(BINS - 1)
}

/// The nearest distance bin `bin(d)` holds.
fn bin_start(d: f64) -> f64 {
    bin(d) as f64 * BIN
}

/// Distance from the origin to segment `p + s e`, `s` in `[0, 1]`.
fn segment_distance(p: Vector2<f64>, e: Vector2<f64>) -> f64 {
    let len2 = e.norm_squared();
    let s = if len2 > 0.0 {
        (-p.dot(&e) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p + e * s).norm()
}

/// Distance along unit ray `d` from the origin to segment `p + s e`, `s` in `[0, 1]`.
#[must_use]
pub fn ray_segment(d: Vector2<f64>, p: Vector2<f64>, e: Vector2<f64>) -> Option<f64> {
    let denom = d.perp(&e);
    let (num_t, num_s) = (p.perp(&e), p.perp(&d));
    // t = num_t / denom >= 0 and s = num_s / denom in [0, 1], decided on the numerators
    // (turned to denom's sign, which is exact) so that only a hit pays a division.
    let sign = 1.0f64.copysign(denom);
    let (nt, ns) = (num_t * sign, num_s * sign);
    (denom != 0.0 && nt >= 0.0 && ns >= 0.0 && ns <= denom.abs()).then(|| num_t / denom)
}

/// Distance along unit ray `d` from the origin to the circle of radius `r` centred at
/// `c` (origin outside the circle).
#[must_use]
pub fn ray_disc(d: Vector2<f64>, c: Vector2<f64>, r: f64) -> Option<f64> {
    let b = d.dot(&c);
    let disc = b * b - (c.norm_squared() - r * r);
    if disc < 0.0 {
        return None;
    }
    let t = b - disc.sqrt();
    (t >= 0.0).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::{BIN, FAST_ATAN2_ERROR, Obstacle, bin, bin_start, fast_atan2, nearest_first};

    /// A horizon just short of a wall's nearest point with a margin of 2 mm: the beams
    /// near the wall's normal are cast to the horizon without a hit, and their noise
    /// (1 cm) often brings them back within `need`. The scan must then cast those beams
    /// to the end, and read as the whole noisy scan within `need`.
    #[test]
    fn beams_that_noise_may_bring_within_the_horizon_are_cast_to_the_end() {
        use super::{Laser, LaserModel, NearSegments};
        use crate::{Shape, StaticWorld};
        use hyplan_core::Point2;
        use rand::SeedableRng;
        let mut world = StaticWorld::default();
        world.add_shape(&Shape::Box {
            center: (3.5, 0.0),
            size: (1.0, 10.0),
            angle_deg: 0.0,
        });
        let model = LaserModel::new(Laser::default());
        let mut near = NearSegments::new(&world);
        let (margin, o) = (0.002, Point2::new(0.0, 0.0));
        let need = 3.0 - margin - 1e-6;
        let mut within_need = 0;
        for seed in 0..200 {
            let rng = || rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let mut all = model.cast(&world, &[], o, 0.0);
            model.add_noise(&mut all, &mut rng());
            let got = model.scan_within_margin(
                &world,
                &[],
                o,
                0.0,
                (need, margin),
                false,
                &mut near,
                &mut rng(),
            );
            for (k, (&a, &g)) in all.ranges.iter().zip(&got.ranges).enumerate() {
                assert!(
                    a == g || (g == f64::INFINITY && a > need),
                    "seed {seed} beam {k}: whole {a}, to the horizon {g}"
                );
                within_need += usize::from(a <= need);
            }
        }
        // The case is met: noise brought beams within `need`.
        assert!(within_need > 100, "{within_need}");
    }

    /// What the cast's early stop relies on: the obstacles come out by bin, each bin's
    /// start at or below every distance in it and after, and none is lost.
    #[test]
    fn obstacles_come_nearest_bin_first() {
        // Distances from a fixed sequence over 0-80 m, bin edges and the far bin included.
        let mut x: u64 = 7;
        let mut order: Vec<(f64, Obstacle)> = (0..2000)
            .map(|i| {
                x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                let d = (x >> 11) as f64 / (1u64 << 53) as f64 * 80.0;
                (
                    if i % 7 == 0 {
                        (d / BIN).floor() * BIN
                    } else {
                        d
                    },
                    Obstacle::Segment(i),
                )
            })
            .collect();
        order.push((0.0, Obstacle::Disc(0)));
        let few = nearest_first(order[..40].to_vec());
        assert!(few.windows(2).all(|w| w[0].0 <= w[1].0));
        let sorted = nearest_first(order.clone());
        assert_eq!(sorted.len(), order.len());
        for w in sorted.windows(2) {
            assert!(bin(w[0].0) <= bin(w[1].0));
        }
        for (k, &(d, _)) in sorted.iter().enumerate() {
            assert!(sorted[k..].iter().all(|&(e, _)| bin_start(d) <= e));
        }
        let mut before: Vec<u64> = order.iter().map(|o| o.0.to_bits()).collect();
        let mut after: Vec<u64> = sorted.iter().map(|o| o.0.to_bits()).collect();
        before.sort_unstable();
        after.sort_unstable();
        assert_eq!(before, after);
    }

    /// The error bound the beam spans rely on, over a dense sweep of directions and
    /// lengths (both axes, every octant, the axes themselves).
    #[test]
    fn fast_atan2_stays_within_its_bound() {
        let mut worst = 0.0f64;
        for k in 0..=200_000 {
            let a = -std::f64::consts::PI + k as f64 * std::f64::consts::TAU / 200_000.0;
            for len in [1e-6, 0.3, 7.0, 1e4] {
                let (y, x) = (len * a.sin(), len * a.cos());
                let err = (fast_atan2(y, x) - y.atan2(x)).abs();
                // +pi and -pi are the same direction.
                let err = err.min((err - std::f64::consts::TAU).abs());
                worst = worst.max(err);
            }
        }
        assert!(worst < FAST_ATAN2_ERROR, "worst error {worst}");
        assert!(
            worst > FAST_ATAN2_ERROR / 10.0,
            "bound far too loose: {worst}"
        );
        assert_eq!(fast_atan2(0.0, 0.0), 0.0);
    }
}
