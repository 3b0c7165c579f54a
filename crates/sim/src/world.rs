//! The simulated world: static geometry in metres and people walking scripted routes.
//!
//! Static geometry is kept as what a laser and a contact test need: line segments (the
//! edges of walls, boxes, polygons and of the occupied cells of a loaded map) and discs.
//! People are discs whose position is a pure function of time ([`Person::position`]).

use envmap::GridMap;
use hyplan_core::{Bounds, Point2, Zone};
use serde::{Deserialize, Serialize};

use crate::grid_cast::GridRays;

/// A static obstacle, in metres (scenario syntax): the workspace's one shape type.
pub use envmap::Shape;

/// A point from a scenario pair.
#[must_use]
pub fn pt(p: (f64, f64)) -> Point2 {
    Point2::new(p.0, p.1)
}

/// How a person walks their way-points.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum Walk {
    /// First to last way-point, then stands still there.
    #[default]
    Once,
    /// Around and around, back from the last way-point to the first.
    Loop,
    /// First to last, then back to the first, and again.
    BackAndForth,
    /// Appears at the first way-point at `start`, walks to the last and leaves the world
    /// there (a person coming in at a door and going out at another): before and after,
    /// the person is off stage, at [`OFFSTAGE`], where nothing meets them.
    Through,
}

/// Where a person not in the world stands ([`Walk::Through`] before setting off and after
/// arriving): a point a thousand kilometres from any world, m.
pub const OFFSTAGE: (f64, f64) = (-1.0e6, -1.0e6);

/// A person: a disc with a route of way-points and a walking speed. The scenario's
/// `people_model` says how they move: along the route blind to everything ([`crate::Scripted`],
/// the default, as the paper's Gazebo 7 actors did), or toward each way-point in turn
/// under social forces ([`crate::SocialForce`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Person {
    /// Way-points, m (at least two).
    pub path: Vec<(f64, f64)>,
    /// Walking speed, m/s.
    pub speed: f64,
    /// When the person sets off, s (standing at the first way-point before).
    #[serde(default)]
    pub start: f64,
    /// Body radius, m (default 0.25).
    #[serde(default = "default_person_radius")]
    pub radius: f64,
    /// Once, loop, back-and-forth or through (default once).
    #[serde(default)]
    pub walk: Walk,
    /// The group the person walks with (default none): under social forces, members of
    /// one group keep together ([`crate::SocialForceParams::group_strength`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub group: Option<u32>,
}

fn default_person_radius() -> f64 {
    0.25
}

impl Person {
    /// Where the person is at time `t` seconds: a pure function of `t` ([`OFFSTAGE`]
    /// when a [`Walk::Through`] person is not in the world).
    #[must_use]
    pub fn position(&self, t: f64) -> Point2 {
        let n = self.path.len();
        if n == 0 {
            return Point2::origin();
        }
        if self.walk == Walk::Through && t < self.start {
            return pt(OFFSTAGE);
        }
        let p = |k: usize| pt(self.path[k]);
        // Legs in walking order: 0..n-1 forward, then (loop) the closing leg, or
        // (back-and-forth) the forward legs reversed.
        let legs = match self.walk {
            Walk::Once | Walk::Through => n - 1,
            Walk::Loop => n,
            Walk::BackAndForth => 2 * (n - 1),
        };
        let leg = |k: usize| -> (Point2, Point2) {
            if k < n - 1 {
                (p(k), p(k + 1))
            } else if self.walk == Walk::Loop {
                (p(n - 1), p(0))
            } else {
                let r = k - (n - 1);
                (p(n - 1 - r), p(n - 2 - r))
            }
        };
        let total: f64 = (0..legs)
            .map(|k| {
                let (a, b) = leg(k);
                (b - a).norm()
            })
            .sum();
        let mut s = (t - self.start).max(0.0) * self.speed;
        if total <= 0.0 {
            return p(0);
        }
        if matches!(self.walk, Walk::Once | Walk::Through) {
            if s >= total {
                return if self.walk == Walk::Through {
                    pt(OFFSTAGE)
                } else {
                    p(n - 1)
                };
            }
        } else {
            s = s.rem_euclid(total);
        }
        for k in 0..legs {
            let (a, b) = leg(k);
            let len = (b - a).norm();
            if s <= len {
                return if len > 0.0 {
                    a + (b - a) * (s / len)
                } else {
                    a
                };
            }
            s -= len;
        }
        leg(legs - 1).1
    }
}

/// A line segment of the static world.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// One end.
    pub a: Point2,
    /// The other end.
    pub b: Point2,
    /// For an edge of a closed outline, its outward normal (the laser skips edges seen
    /// from behind); for an edge of a loaded map's occupied cells, the normal toward its
    /// free side when all its occupied cells are on one side; `None` for loose edges.
    pub outward: Option<nalgebra::Vector2<f64>>,
}

/// A round static obstacle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Disc {
    /// Centre.
    pub center: Point2,
    /// Radius, m.
    pub radius: f64,
}

impl Disc {
    /// Whether the disc is in the world: false for a person at [`OFFSTAGE`].
    ///
    /// ```
    /// let (x, y) = sim::OFFSTAGE;
    /// let away = sim::Disc { center: hyplan_core::Point2::new(x, y), radius: 0.25 };
    /// assert!(!away.on_stage());
    /// ```
    #[must_use]
    pub fn on_stage(&self) -> bool {
        self.center.x > 0.5 * OFFSTAGE.0
    }
}

/// The static world as the laser and the contact test see it.
#[derive(Debug, Clone, Default)]
pub struct StaticWorld {
    /// Edges of every polygonal obstacle.
    pub segments: Vec<Segment>,
    /// Edges of the occupied cells of a loaded map, merged into straight runs.
    pub grid_segments: Vec<Segment>,
    /// Round obstacles.
    pub discs: Vec<Disc>,
    /// Closed outlines, for inside tests.
    pub polygons: Vec<Vec<Point2>>,
    /// A loaded map's grid (its forbidden cells are obstacles). Set it with
    /// [`add_grid`](Self::add_grid): the laser's table of it is made once, on first use,
    /// and cached with the grid.
    pub grid: Option<GridMap>,
}

impl StaticWorld {
    /// Adds a shape.
    pub fn add_shape(&mut self, shape: &Shape) {
        if let Some((center, radius)) = shape.disc() {
            self.discs.push(Disc { center, radius });
            return;
        }
        if let Some(poly) = shape.outline() {
            // Shoelace: positive for counter-clockwise outlines.
            let n = poly.len();
            let area2: f64 = (0..n)
                .map(|k| {
                    let (a, b) = (poly[k], poly[(k + 1) % n]);
                    a.x * b.y - b.x * a.y
                })
                .sum();
            for k in 0..n {
                let (a, b) = (poly[k], poly[(k + 1) % n]);
                let e = b - a;
                // Counter-clockwise: the outside is to the right of each edge.
                let right = nalgebra::Vector2::new(e.y, -e.x);
                let outward = if area2 > 0.0 {
                    Some(right)
                } else if area2 < 0.0 {
                    Some(-right)
                } else {
                    None
                };
                self.segments.push(Segment { a, b, outward });
            }
            self.polygons.push(poly);
        }
    }

    /// Adds the occupied (forbidden) cells of a grid map: the boundary between occupied
    /// and other cells, merged into maximal straight runs.
    pub fn add_grid(&mut self, map: GridMap) {
        let (w, h) = (map.width(), map.height());
        let occ = |i: isize, j: isize| {
            i >= 0
                && j >= 0
                && (i as usize) < w
                && (j as usize) < h
                && map.cell_zone(i as usize, j as usize) == Zone::Forbidden
        };
        let (o, r) = (map.origin(), map.resolution());
        let at = |i: usize, j: usize| Point2::new(o.x + i as f64 * r, o.y + j as f64 * r);
        let segments = &mut self.grid_segments;
        let mut push = |a, b, outward| segments.push(Segment { a, b, outward });
        // A run whose occupied cells are all on one side faces the other (the laser skips
        // it seen from behind); a run with occupied cells on both sides faces neither.
        let side = |occupied_before: &mut dyn Iterator<Item = bool>,
                    normal: nalgebra::Vector2<f64>| {
            let mut all = (true, true);
            for o in occupied_before {
                all = (all.0 && o, all.1 && !o);
            }
            match all {
                (true, _) => Some(normal),
                (_, true) => Some(-normal),
                _ => None,
            }
        };
        // Horizontal edges: between rows j-1 and j, for j in 0..=h; then vertical ones.
        edge_runs(
            h + 1,
            w,
            |j, i| occ(i, j - 1) != occ(i, j),
            |j, s, e| {
                let below = &mut (s..e).map(|i| occ(i as isize, j as isize - 1));
                push(
                    at(s, j),
                    at(e, j),
                    side(below, nalgebra::Vector2::new(0.0, 1.0)),
                );
            },
        );
        edge_runs(
            w + 1,
            h,
            |i, j| occ(i - 1, j) != occ(i, j),
            |i, s, e| {
                let left = &mut (s..e).map(|j| occ(i as isize - 1, j as isize));
                push(
                    at(i, s),
                    at(i, e),
                    side(left, nalgebra::Vector2::new(1.0, 0.0)),
                );
            },
        );
        self.grid = Some(map);
    }

    /// The loaded map's cells as rays and nearest-point queries see them.
    pub(crate) fn grid_rays(&self) -> Option<GridRays<'_>> {
        let grid = self.grid.as_ref()?;
        GridRays::new(grid, grid.strides_from(Zone::Forbidden)?)
    }

    /// Whether `p` lies inside (or on) an obstacle.
    #[must_use]
    pub fn inside(&self, p: Point2) -> bool {
        if self.discs.iter().any(|d| (p - d.center).norm() <= d.radius) {
            return true;
        }
        if self.polygons.iter().any(|poly| point_in_polygon(p, poly)) {
            return true;
        }
        self.in_occupied_cell(p)
    }

    /// Whether `p` lies in an occupied cell of the loaded map (if any).
    pub(crate) fn in_occupied_cell(&self, p: Point2) -> bool {
        self.grid.as_ref().is_some_and(|g| {
            g.world_to_cell(p)
                .is_some_and(|(i, j)| g.cell_zone(i, j) == Zone::Forbidden)
        })
    }

    /// Distance from `p` to the nearest obstacle boundary and the nearest boundary point
    /// (`(inf, p)` in an empty world). Inside an obstacle it is still the distance to the
    /// boundary: use [`inside`](Self::inside) to tell.
    ///
    /// A loaded map's part is found from its cells (a ring of the distance transform
    /// around `p`) rather than by sweeping its segments, unless `p` lies in a forbidden
    /// cell or off the map.
    #[must_use]
    pub fn nearest(&self, p: Point2) -> (f64, Point2) {
        let best = nearest_on_segments(p, &self.segments);
        self.nearer_disc(p, self.nearer_on_grid(p, best))
    }

    /// `best`, or the nearest point of the loaded map's part if nearer.
    fn nearer_on_grid(&self, p: Point2, best: (f64, Point2)) -> (f64, Point2) {
        let from_grid = self
            .grid_rays()
            .and_then(|g| g.nearest(p))
            .unwrap_or_else(|| nearest_on_segments(p, &self.grid_segments));
        if from_grid.0 < best.0 {
            from_grid
        } else {
            best
        }
    }

    /// `best`, or the nearest point of a round obstacle if nearer.
    fn nearer_disc(&self, p: Point2, mut best: (f64, Point2)) -> (f64, Point2) {
        for d in &self.discs {
            let v = p - d.center;
            let n = v.norm();
            let dist = (n - d.radius).abs();
            if dist < best.0 {
                let q = if n > 0.0 {
                    d.center + v * (d.radius / n)
                } else {
                    d.center + nalgebra::Vector2::new(d.radius, 0.0)
                };
                best = (dist, q);
            }
        }
        best
    }
}

/// The static world's boundary within a fixed reach of any point: the segments sorted into
/// square cells, each cell listing the segments within `reach` of any point of it, so that
/// a query sweeps the few segments near it instead of all (a loaded map's cells, when it
/// has them, and the round obstacles are looked up as [`StaticWorld::nearest`] does).
#[derive(Debug, Clone)]
pub(crate) struct NearIndex {
    origin: Point2,
    cell: f64,
    cols: usize,
    rows: usize,
    /// Per cell, the indices of its segments into `segments`.
    lists: Vec<Vec<u32>>,
    segments: Vec<Segment>,
    reach: f64,
}

impl NearIndex {
    /// The segments of `world` within `reach` of any point (its loaded map's edges too,
    /// unless the map's cells answer for them).
    pub(crate) fn new(world: &StaticWorld, reach: f64) -> Self {
        let mut segments = world.segments.clone();
        if world.grid.is_none() {
            segments.extend_from_slice(&world.grid_segments);
        }
        let reach = if reach.is_finite() {
            reach.max(0.0)
        } else {
            0.0
        };
        let mut lo = Point2::new(f64::INFINITY, f64::INFINITY);
        let mut hi = Point2::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
        for s in &segments {
            for q in [s.a, s.b] {
                lo = lo.inf(&q);
                hi = hi.sup(&q);
            }
        }
        let cell = reach.max(0.25);
        // Cells cover the segments' box grown by the reach; at most 1024 a side (a
        // larger world gets larger cells).
        let span = (hi - lo).map(|v| v.max(0.0)) + nalgebra::Vector2::repeat(2.0 * reach);
        let cell = cell.max(span.x.max(span.y) / 1024.0);
        let origin = lo - nalgebra::Vector2::repeat(reach);
        let (cols, rows) = if segments.is_empty() {
            (0, 0)
        } else {
            (
                (span.x / cell).ceil().max(1.0) as usize,
                (span.y / cell).ceil().max(1.0) as usize,
            )
        };
        let mut lists = vec![Vec::new(); cols * rows];
        let half_diagonal = cell * std::f64::consts::FRAC_1_SQRT_2;
        for (k, s) in segments.iter().enumerate() {
            let grow = reach + cell;
            let c0 = (((s.a.x.min(s.b.x) - grow - origin.x) / cell)
                .floor()
                .max(0.0)) as usize;
            let c1 = (((s.a.x.max(s.b.x) + grow - origin.x) / cell).ceil() as usize).min(cols);
            let r0 = (((s.a.y.min(s.b.y) - grow - origin.y) / cell)
                .floor()
                .max(0.0)) as usize;
            let r1 = (((s.a.y.max(s.b.y) + grow - origin.y) / cell).ceil() as usize).min(rows);
            for r in r0..r1 {
                for c in c0..c1 {
                    let centre =
                        origin + nalgebra::Vector2::new(c as f64 + 0.5, r as f64 + 0.5) * cell;
                    let q = closest_on_segment(centre, s.a, s.b);
                    if (centre - q).norm() <= reach + half_diagonal {
                        lists[r * cols + c].push(k as u32);
                    }
                }
            }
        }
        Self {
            origin,
            cell,
            cols,
            rows,
            lists,
            segments,
            reach,
        }
    }

    /// [`StaticWorld::nearest`] for a `p` whose nearest boundary point is within the
    /// reach: the same distance; `(inf, p)` when nothing is within reach. `world` is the
    /// world the index was made of.
    pub(crate) fn nearest(&self, world: &StaticWorld, p: Point2) -> (f64, Point2) {
        let rel = (p - self.origin) / self.cell;
        let inside_grid = rel.x >= 0.0
            && rel.y >= 0.0
            && (rel.x as usize) < self.cols
            && (rel.y as usize) < self.rows;
        // Off the index every segment is farther than the reach.
        let mut best = (f64::INFINITY, p);
        if inside_grid {
            for &k in &self.lists[rel.y as usize * self.cols + rel.x as usize] {
                let s = &self.segments[k as usize];
                let q = closest_on_segment(p, s.a, s.b);
                let d = (p - q).norm();
                if d < best.0 {
                    best = (d, q);
                }
            }
        }
        if world.grid.is_some() {
            best = world.nearer_on_grid(p, best);
        }
        best = world.nearer_disc(p, best);
        if best.0 > self.reach {
            (f64::INFINITY, p)
        } else {
            best
        }
    }
}

/// The point of segment `ab` closest to `p`.
#[must_use]
pub fn closest_on_segment(p: Point2, a: Point2, b: Point2) -> Point2 {
    let ab = b - a;
    let len_sq = ab.norm_squared();
    if len_sq == 0.0 {
        return a;
    }
    let t = ((p - a).dot(&ab) / len_sq).clamp(0.0, 1.0);
    a + ab * t
}

/// The nearest point of `segments` to `p` and its distance (`(INFINITY, p)` for none),
/// the first of equals kept.
fn nearest_on_segments(p: Point2, segments: &[Segment]) -> (f64, Point2) {
    let mut best = (f64::INFINITY, p);
    for s in segments {
        let q = closest_on_segment(p, s.a, s.b);
        let d = (p - q).norm();
        if d < best.0 {
            best = (d, q);
        }
    }
    best
}

/// The maximal runs of cell edges along each of `lines` grid lines of `len` edges:
/// `emit(line, first, past_last)` for each run of edges where `edge(line, k)` holds
/// (coordinates as `isize`, so that `edge` may look one cell before the grid).
fn edge_runs(
    lines: usize,
    len: usize,
    edge: impl Fn(isize, isize) -> bool,
    mut emit: impl FnMut(usize, usize, usize),
) {
    for line in 0..lines {
        let mut run: Option<usize> = None;
        for k in 0..=len {
            let on = k < len && edge(line as isize, k as isize);
            match (on, run) {
                (true, None) => run = Some(k),
                (false, Some(first)) => {
                    emit(line, first, k);
                    run = None;
                }
                _ => {}
            }
        }
    }
}

/// Even-odd rule; points on the boundary may go either way.
#[must_use]
pub fn point_in_polygon(p: Point2, poly: &[Point2]) -> bool {
    let mut inside = false;
    let n = poly.len();
    for k in 0..n {
        let (a, b) = (poly[k], poly[(k + n - 1) % n]);
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if p.x < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// The whole world: bounds, static geometry (all of it, and the part on the robot's
/// prior map) and people.
#[derive(Debug, Clone)]
pub struct World {
    /// The box the robot must stay in.
    pub bounds: Bounds,
    /// Everything static the laser sees and the robot can touch.
    pub statics: StaticWorld,
    /// The static part the robot knows in advance (its prior map); items placed after the
    /// map was made are in `statics` only.
    pub mapped: StaticWorld,
    /// People.
    pub people: Vec<Person>,
}

impl World {
    /// People's positions and radii at time `t`, s.
    #[must_use]
    pub fn people_at(&self, t: f64) -> Vec<Disc> {
        use crate::people::PeopleModel;
        crate::people::Scripted::new(&self.people).people(t, crate::kinematics::Pose::default())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The index finds the same nearest distance as the sweep of every segment
        /// whenever that distance is within its reach, and nothing otherwise.
        #[test]
        fn near_index_matches_the_sweep(
            walls in prop::collection::vec(((0.0..20.0f64, 0.0..12.0f64), (0.0..20.0f64, 0.0..12.0f64)), 1..12),
            discs in prop::collection::vec((0.0..20.0f64, 0.0..12.0f64, 0.1..1.0f64), 0..3),
            points in prop::collection::vec((-3.0..23.0f64, -3.0..15.0f64), 1..40),
            reach in 0.3..4.0f64,
        ) {
            let mut world = StaticWorld::default();
            for (a, b) in walls {
                world.add_shape(&Shape::Wall { from: a, to: b, thickness: 0.1 });
            }
            for (x, y, r) in discs {
                world.add_shape(&Shape::Disc { center: (x, y), radius: r });
            }
            let index = NearIndex::new(&world, reach);
            for (x, y) in points {
                let p = Point2::new(x, y);
                let (full, _) = world.nearest(p);
                let (near, _) = index.nearest(&world, p);
                if full <= reach {
                    prop_assert_eq!(near, full, "at {:?}", p);
                } else {
                    prop_assert!(near.is_infinite(), "at {:?}: {} beyond {}", p, near, reach);
                }
            }
        }
    }

    #[test]
    fn person_modes() {
        let mut p = Person {
            path: vec![(0.0, 0.0), (2.0, 0.0)],
            speed: 1.0,
            start: 1.0,
            radius: 0.25,
            walk: Walk::Once,
            group: None,
        };
        assert_eq!(p.position(0.5), Point2::new(0.0, 0.0));
        assert_eq!(p.position(2.0), Point2::new(1.0, 0.0));
        assert_eq!(p.position(9.0), Point2::new(2.0, 0.0));
        p.walk = Walk::BackAndForth;
        assert_eq!(p.position(4.0), Point2::new(1.0, 0.0));
        p.walk = Walk::Loop;
        assert_eq!(p.position(4.0), Point2::new(1.0, 0.0));
    }

    #[test]
    fn grid_edges_merge() {
        let map = GridMap::from_ascii("...\n.##\n...").unwrap();
        let mut w = StaticWorld::default();
        w.add_grid(map);
        assert_eq!(w.grid_segments.len(), 4);
        assert!(w.inside(Point2::new(1.5, 1.5)));
        // Each edge faces away from the occupied cells: its normal points from its middle
        // into a free cell.
        for s in &w.grid_segments {
            let n = s.outward.expect("occupied cells on one side");
            let middle = nalgebra::center(&s.a, &s.b);
            assert!(
                !w.inside(middle + n * 0.25) && w.inside(middle - n * 0.25),
                "{s:?}"
            );
        }
        // Occupied cells on both sides of a run: it faces neither way.
        let mut w = StaticWorld::default();
        w.add_grid(GridMap::from_ascii("#.\n.#").unwrap());
        assert!(w.grid_segments.iter().any(|s| s.outward.is_none()));
    }
}
