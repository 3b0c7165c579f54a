//! People who avoid each other by optimal reciprocal collision avoidance ([`Orca`]), the
//! velocity-obstacle model of RVO2, with its half-planes and linear program
//! (`half_planes`).

use envmap::GridMap;
use hyplan_core::{Point2, Zone};
use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use crate::boxgrid::{self, BoxGrid, Marks};
use crate::grid_cast::GridRays;
use crate::half_planes::{self, Body, HalfPlane, agent_half_plane, edge_half_plane};
use crate::people::{Stepped, Stepper, discs_ahead, on_stage};
use crate::social_force::{KEEP_RIGHT, heading};
use crate::world::{Disc, Person, Segment, StaticWorld, pt};

/// ORCA's parameters (scenario syntax). The defaults are CrowdNav's ORCA people
/// (`crowd_sim/envs/policy/orca.py`: neighbour distance 10 m, 10 neighbours, time
/// horizons 5 s for people and walls, no safety space, people walking at most their
/// preferred speed), the parameters of the people most robot crowd-navigation papers
/// are measured among; RVO2's own examples use the same structure with other numbers
/// (its `Circle`: 15 m, 10 neighbours, 10 s horizons).
///
/// ```ron
/// people_model: Orca((sees_robot: false)),
/// ```
///
/// ```
/// let p = sim::OrcaParams::default();
/// assert_eq!((p.time_horizon, p.neighbour_distance, p.max_neighbours), (5.0, 10.0, 10));
/// assert!(p.problem().is_none());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct OrcaParams {
    /// Whether people see the robot (default true): it is then one of their neighbours,
    /// a disc of the robot's body radius moving at its velocity, of which they take the
    /// whole avoidance (the robot does not reciprocate ORCA); when false they walk into
    /// it (the hard case for the robot).
    pub sees_robot: bool,
    /// How far ahead collisions with other people (and the robot) are avoided, s (5,
    /// CrowdNav's `time_horizon`; ORCA's `tau`).
    pub time_horizon: f64,
    /// How far ahead collisions with walls are avoided, s (5, CrowdNav's
    /// `time_horizon_obst`). Walls within `obstacle_time_horizon` times the person's
    /// largest speed, plus their radius, are considered (RVO2's obstacle range).
    pub obstacle_time_horizon: f64,
    /// Centre distance within which another person (or the robot) is a neighbour, m (10,
    /// CrowdNav's `neighbor_dist`).
    pub neighbour_distance: f64,
    /// How many of the nearest neighbours each person avoids (10, CrowdNav's
    /// `max_neighbors`).
    pub max_neighbours: usize,
    /// Speed cap as a multiple of the person's speed (1: CrowdNav's people walk at most
    /// their preferred speed; RVO2's `maxSpeed` over the preferred speed).
    pub max_speed_ratio: f64,
    /// Distance from a way-point at which a person heads for the next one, m (0.5, as
    /// [`crate::SocialForceParams::switch_distance`]).
    pub switch_distance: f64,
    /// Toward the last way-point of a `Once` route the preferred speed is
    /// `min(speed, distance / arrival_time)`, s (1: RVO2's examples, whose preferred
    /// velocity is the vector to the goal, normalised only beyond 1 m).
    pub arrival_time: f64,
    /// Padding added to every body radius (people's and the robot's, and people's margin
    /// from walls), m (0.01: CrowdNav gives RVO2 each radius plus 0.01 m plus its
    /// `safety_space`, 0), so that bodies on the edge of a velocity obstacle stay apart
    /// rather than graze.
    pub safety_space: f64,
    /// How much further to their left each person sees the others (and the robot), m
    /// (ours, [`crate::KEEP_RIGHT`], 1 mm; 0 for none): the side preference that breaks
    /// exactly symmetric encounters toward passing on the right, where ORCA alone only
    /// slows down (see [`Orca`]).
    pub keep_right: f64,
    /// How often people choose a new velocity, s (0.04: 25 Hz, as [`crate::STEP`] for social
    /// forces). Between steps people walk on at their velocities. From 0.005 (the engine's
    /// tick) to 1. Coarser steps are cheaper but let people who see the robot walk into it:
    /// at 0.1 s (ir-sim's `step_time`; CrowdNav and RVO2's examples step ORCA every 0.25 s)
    /// a quarter of the crowd table's runs in the doors hall and the crossing flow had a
    /// contact that none had at 0.04 s (none of them the robot's fault).
    pub step: f64,
}

impl Default for OrcaParams {
    fn default() -> Self {
        Self {
            sees_robot: true,
            time_horizon: 5.0,
            obstacle_time_horizon: 5.0,
            neighbour_distance: 10.0,
            max_neighbours: 10,
            max_speed_ratio: 1.0,
            switch_distance: 0.5,
            arrival_time: 1.0,
            safety_space: 0.01,
            keep_right: KEEP_RIGHT,
            step: crate::STEP,
        }
    }
}

impl OrcaParams {
    /// The first value out of range, as (field, value, what it must be); `None` when all
    /// are valid.
    ///
    /// ```
    /// let p = sim::OrcaParams { time_horizon: 0.0, ..Default::default() };
    /// assert_eq!(p.problem(), Some(("time_horizon", 0.0, "must be finite and > 0")));
    /// ```
    #[must_use]
    pub fn problem(&self) -> Option<(&'static str, f64, &'static str)> {
        let positive = [
            ("time_horizon", self.time_horizon),
            ("obstacle_time_horizon", self.obstacle_time_horizon),
            ("max_speed_ratio", self.max_speed_ratio),
            ("arrival_time", self.arrival_time),
        ];
        let non_negative = [
            ("neighbour_distance", self.neighbour_distance),
            ("switch_distance", self.switch_distance),
            ("safety_space", self.safety_space),
            ("keep_right", self.keep_right),
        ];
        crate::validate::first_out_of_range(&positive, &non_negative).or_else(|| {
            (!(MIN_STEP..=MAX_STEP).contains(&self.step)).then_some((
                "step",
                self.step,
                "must be from 0.005 to 1",
            ))
        })
    }
}

/// The range of [`OrcaParams::step`], s: not below the engine's tick (finer steps are
/// never taken), and a step a second at most.
const MIN_STEP: f64 = 0.005;
const MAX_STEP: f64 = 1.0;

/// One person's state.
#[derive(Debug, Clone, Copy)]
struct Walker {
    pos: Point2,
    vel: Vector2<f64>,
    /// The leg walked, in walking order (its end is the goal).
    leg: usize,
    /// In the world (false for a [`crate::Walk::Through`] person before setting off and
    /// after arriving: nobody's neighbour).
    on_stage: bool,
}

/// The walls as ORCA obstacles, a coarse grid of buckets to find the drawn ones near a
/// person without sweeping them all, and a loaded map's cell edges by the grid line they
/// lie on, to find those a person sees.
#[derive(Debug, Clone, Default)]
struct Walls {
    obstacles: Vec<Wall>,
    /// The bounding box of each obstacle, (min, max).
    bounds: Vec<(Point2, Point2)>,
    /// The bounding box of each obstacle that is not a loaded map's cell edge, in buckets.
    grid: BoxGrid,
    /// The obstacle of each box of `grid`.
    boxed: Vec<u32>,
    /// The bounding box of each of a loaded map's cell edges, in buckets.
    cell_grid: BoxGrid,
    /// The obstacle of each box of `cell_grid`.
    cell_boxed: Vec<u32>,
    /// A loaded map's cell edges.
    cell_edges: CellEdges,
}

/// Within this distance of a person every cell edge of a loaded map is theirs to avoid,
/// seen or not, m: rays a few degrees apart miss the one-cell steps of a slanted wall's
/// outline at a few decimetres, and those are the edges a step may reach.
const CELL_EDGES_ALL_WITHIN: f64 = 1.5;

/// Rays a person casts to find the loaded map's cell edges they see: one every 5 degrees.
const WALL_RAYS: usize = 72;

/// Steps between a person's looks for the loaded map's cell edges they see (0.4 s at the
/// default step: they walk at most 0.72 m in it, inside the [`CELL_EDGES_ALL_WITHIN`] they
/// always avoid). The looks of different people fall on different steps. On a building's
/// map the looks are the people's largest cost (0.2 s apart, 12 % of the instructions of
/// the bench's 20-person run on MIT building 31); people looking every 0.2 s and every
/// 0.4 s came as near the AWS house's walls (their radius and 1 cm) and walked as far.
const LOOK_EVERY: u64 = 10;

/// A loaded map's cell edges (its boundary runs between forbidden and other cells), by
/// the grid line each lies on, so that the edge a ray hits is found from the hit point.
#[derive(Debug, Clone, Default)]
struct CellEdges {
    origin: Point2,
    resolution: f64,
    /// The runs on each horizontal grid line `y = origin.y + j resolution`, by their
    /// lowest x.
    rows: Vec<Vec<Run>>,
    /// The runs on each vertical grid line `x = origin.x + i resolution`, by their lowest y.
    cols: Vec<Vec<Run>>,
    /// The rays' unit directions.
    rays: Vec<Vector2<f64>>,
}

/// A run of cell edges on a grid line: from `lo` to `hi` along it, m, and its obstacles
/// (`count` of them from `first`: one per solid side).
#[derive(Debug, Clone, Copy)]
struct Run {
    lo: f64,
    hi: f64,
    first: u32,
    count: u32,
}

impl CellEdges {
    /// Calls `f` with the obstacles of each run that `h`, a point on a grid line, lies on.
    fn at(&self, h: Point2, mut f: impl FnMut(u32)) {
        // A hit is computed on the line it crosses: on it to rounding.
        const ON_LINE: f64 = 1e-6;
        let mut on = |lines: &[Vec<Run>], across: f64, along: f64| {
            let u = across / self.resolution;
            let k = u.round();
            if (u - k).abs() > ON_LINE || k < 0.0 || k as usize >= lines.len() {
                return;
            }
            let runs = &lines[k as usize];
            let slack = ON_LINE * self.resolution;
            let from = runs.partition_point(|r| r.hi < along - slack);
            for r in runs[from..].iter().take_while(|r| r.lo <= along + slack) {
                (r.first..r.first + r.count).for_each(&mut f);
            }
        };
        on(&self.rows, h.y - self.origin.y, h.x);
        on(&self.cols, h.x - self.origin.x, h.y);
    }
}

/// A wall as ORCA sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Wall {
    /// An edge, solid on its left (from `a` to `b`) and open on its right.
    Edge { a: Point2, b: Point2 },
    /// A round obstacle.
    Disc { center: Point2, radius: f64 },
}

impl Wall {
    /// The bounding box, (min, max).
    fn bounds(&self) -> (Point2, Point2) {
        match *self {
            Self::Edge { a, b } => (
                Point2::new(a.x.min(b.x), a.y.min(b.y)),
                Point2::new(a.x.max(b.x), a.y.max(b.y)),
            ),
            Self::Disc { center, radius } => (
                center - Vector2::new(radius, radius),
                center + Vector2::new(radius, radius),
            ),
        }
    }

    /// Whether this is an edge with `p` strictly on its solid side, for which ORCA draws no
    /// half-plane (as RVO2 leaves such edges out of an agent's obstacle neighbours).
    fn back_facing(&self, p: Point2) -> bool {
        match *self {
            Self::Edge { a, b } => (b - a).perp(&(p - a)) > 0.0,
            Self::Disc { .. } => false,
        }
    }

    /// The squared distance from `p` to the wall (non-negative, so its bits sort as the
    /// value).
    fn distance_sq(&self, p: Point2) -> f64 {
        match *self {
            Self::Edge { a, b } => {
                let ab = b - a;
                let t = if ab.norm_squared() > 0.0 {
                    ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                (a + ab * t - p).norm_squared()
            }
            Self::Disc { center, radius } => {
                let gap = ((p - center).norm() - radius).max(0.0);
                gap * gap
            }
        }
    }
}

impl Walls {
    /// `statics` as ORCA obstacles: each outline edge one-sided (solid on its inward
    /// side), each loose edge two-sided, each edge of a loaded map's cells one-sided
    /// (solid on its occupied cell's side), each disc a round obstacle; bucketed in
    /// cells of about `cell` m.
    fn new(statics: &StaticWorld, cell: f64) -> Self {
        let mut obstacles = Vec::new();
        let open = |a: Point2, b: Point2| Wall::Edge { a, b };
        let push_edge = |obstacles: &mut Vec<Wall>, s: &Segment, solid_left: Option<bool>| {
            if s.a == s.b {
                return;
            }
            match solid_left {
                Some(true) => obstacles.push(open(s.a, s.b)),
                Some(false) => obstacles.push(open(s.b, s.a)),
                None => {
                    obstacles.push(open(s.a, s.b));
                    obstacles.push(open(s.b, s.a));
                }
            }
        };
        for s in &statics.segments {
            let e = s.b - s.a;
            let left = Vector2::new(-e.y, e.x);
            push_edge(&mut obstacles, s, s.outward.map(|n| left.dot(&n) < 0.0));
        }
        let shapes_end = obstacles.len();
        let mut cell_runs = Vec::with_capacity(statics.grid_segments.len());
        for s in &statics.grid_segments {
            let solid_left = statics.grid.as_ref().map(|g| {
                let e = s.b - s.a;
                let left = Vector2::new(-e.y, e.x) / e.norm().max(f64::MIN_POSITIVE);
                let probe = nalgebra::center(&s.a, &s.b) + left * (0.5 * g.resolution());
                g.world_to_cell(probe)
                    .is_some_and(|(i, j)| g.cell_zone(i, j) == Zone::Forbidden)
            });
            let first = obstacles.len();
            push_edge(&mut obstacles, s, solid_left);
            cell_runs.push((s, first as u32, (obstacles.len() - first) as u32));
        }
        let cells_end = obstacles.len();
        obstacles.extend(statics.discs.iter().map(|d| Wall::Disc {
            center: d.center,
            radius: d.radius,
        }));
        let cell_edges = statics
            .grid
            .as_ref()
            .map(|g| CellEdges::new(g, &cell_runs))
            .unwrap_or_default();
        let (cell_boxed, boxed): (Vec<u32>, Vec<u32>) = (0..obstacles.len() as u32)
            .partition(|&k| (shapes_end..cells_end).contains(&(k as usize)));
        let bounds: Vec<(Point2, Point2)> = obstacles.iter().map(Wall::bounds).collect();
        let boxes = |of: &[u32]| of.iter().map(|&k| bounds[k as usize]).collect();
        Self {
            grid: BoxGrid::new(boxes(&boxed), cell),
            cell_grid: BoxGrid::new(boxes(&cell_boxed), CELL_EDGES_ALL_WITHIN),
            obstacles,
            bounds,
            boxed,
            cell_boxed,
            cell_edges,
        }
    }

    /// The obstacles near `p`, nearest first (ties to the lower index), into
    /// `out.indices`, but for edges that `p` is behind ([`Wall::back_facing`]): those
    /// whose bounding box comes within `reach`; of a loaded map's cell edges, those within
    /// [`CELL_EDGES_ALL_WITHIN`] and those of `seen` ([`Walls::seen`]) within `reach`.
    /// `nearby`: the candidates of the person at `p` (found again when they have moved
    /// [`Nearby::MOVED`] since, or their reach changed).
    fn near(&self, p: Point2, reach: f64, seen: &[u32], nearby: &mut Nearby, out: &mut Near) {
        out.indices.clear();
        out.keyed.clear();
        let cell_reach = reach.min(CELL_EDGES_ALL_WITHIN);
        if nearby.stale(p, reach) {
            self.candidates(p, reach, nearby, out);
        }
        let (obstacles, keyed) = (&self.obstacles, &mut out.keyed);
        let reach_sq = reach * reach;
        let mut take = |k: u32| {
            let obstacle = &obstacles[k as usize];
            if !obstacle.back_facing(p) {
                keyed.push(u128::from(obstacle.distance_sq(p).to_bits()) << 32 | u128::from(k));
            }
        };
        // The buckets' own test, on the same bounds: the same obstacles as a query of
        // the buckets from `p` would give.
        for &k in &nearby.drawn {
            if boxgrid::within(self.bounds[k as usize], p, reach) {
                take(k);
            }
        }
        for &k in &nearby.cells {
            if boxgrid::within(self.bounds[k as usize], p, cell_reach) {
                take(k);
            }
        }
        for &k in seen {
            let obstacle = &obstacles[k as usize];
            let d = obstacle.distance_sq(p);
            if d <= reach_sq && !obstacle.back_facing(p) {
                keyed.push(u128::from(d.to_bits()) << 32 | u128::from(k));
            }
        }
        // Nearest first, as RVO2 orders obstacle neighbours: an edge hidden behind a
        // nearer one's half-plane is then skipped. An edge may be both near and seen.
        out.hint
            .sort(&mut out.keyed, &mut nearby.order, self.obstacles.len());
        out.indices.extend(out.keyed.iter().map(|&key| key as u32));
    }

    /// `nearby` found from `p`: the obstacles whose bounding box comes within `reach` +
    /// [`Nearby::SLACK`] of `p` (a loaded map's cell edges within
    /// [`CELL_EDGES_ALL_WITHIN`] + [`Nearby::SLACK`]), but for single edges that `p` is
    /// behind by more than [`Nearby::SLACK`]: every obstacle [`Walls::near`] may take from
    /// a point [`Nearby::MOVED`] from `p`.
    fn candidates(&self, p: Point2, reach: f64, nearby: &mut Nearby, out: &mut Near) {
        let slack = Nearby::SLACK;
        let behind = |k: u32| match self.obstacles[k as usize] {
            Wall::Edge { a, b } => {
                // On the solid (left) side of the edge's line, by more than the slack.
                let e = b - a;
                e.perp(&(p - a)) > slack * e.norm()
            }
            Wall::Disc { .. } => false,
        };
        nearby.drawn.clear();
        nearby.cells.clear();
        let (drawn, cells) = (&mut nearby.drawn, &mut nearby.cells);
        self.grid.near(p, reach + slack, &mut out.marks, |b| {
            let k = self.boxed[b as usize];
            if !behind(k) {
                drawn.push(k);
            }
        });
        self.cell_grid.near(
            p,
            reach.min(CELL_EDGES_ALL_WITHIN) + slack,
            &mut out.cell_marks,
            |b| {
                let k = self.cell_boxed[b as usize];
                if !behind(k) {
                    cells.push(k);
                }
            },
        );
        nearby.at = Some(p);
        nearby.reach = reach;
    }

    /// The loaded map's cell edges that one of [`WALL_RAYS`] rays from `p`, cast on
    /// `cells` (the map's), hits within `reach`, into `out` (in no order, each once).
    fn seen(
        &self,
        p: Point2,
        reach: f64,
        cells: &GridRays<'_>,
        ranges: &mut Vec<f64>,
        out: &mut Vec<u32>,
    ) {
        out.clear();
        let rays = &self.cell_edges.rays;
        if rays.is_empty() {
            return;
        }
        ranges.clear();
        ranges.resize(rays.len(), reach);
        cells.lower(p, rays, ranges, reach);
        for (d, &t) in rays.iter().zip(ranges.iter()) {
            if t < reach {
                self.cell_edges.at(p + d * t, |k| out.push(k));
            }
        }
        out.sort_unstable();
        out.dedup();
    }
}

impl CellEdges {
    /// The runs of `map`'s cell edges, each with its obstacles: `(segment, first,
    /// count)`.
    fn new(map: &GridMap, runs: &[(&Segment, u32, u32)]) -> Self {
        let (o, res) = (map.origin(), map.resolution());
        let mut rows = vec![Vec::new(); map.height() + 1];
        let mut cols = vec![Vec::new(); map.width() + 1];
        for &(s, first, count) in runs {
            let (lines, across, lo, hi) = if s.a.y == s.b.y {
                (&mut rows, s.a.y - o.y, s.a.x.min(s.b.x), s.a.x.max(s.b.x))
            } else {
                (&mut cols, s.a.x - o.x, s.a.y.min(s.b.y), s.a.y.max(s.b.y))
            };
            let k = (across / res).round();
            if k >= 0.0 && (k as usize) < lines.len() {
                lines[k as usize].push(Run {
                    lo,
                    hi,
                    first,
                    count,
                });
            }
        }
        for line in rows.iter_mut().chain(&mut cols) {
            line.sort_by(|a, b| a.lo.total_cmp(&b.lo));
        }
        let rays = (0..WALL_RAYS)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / WALL_RAYS as f64;
                Vector2::new(a.cos(), a.sin())
            })
            .collect();
        Self {
            origin: o,
            resolution: res,
            rows,
            cols,
            rays,
        }
    }
}

/// One person's candidate obstacles for [`Walls::near`], kept between steps: people
/// move a few centimetres a step, so the buckets are searched again only every
/// [`Nearby::MOVED`] metres, with a margin. The result does not depend on it.
#[derive(Debug, Clone, Default)]
struct Nearby {
    /// Where the candidates were found (none yet: found at the next query).
    at: Option<Point2>,
    /// The reach they were found for.
    reach: f64,
    /// The obstacles that are not a loaded map's cell edges.
    drawn: Vec<u32>,
    /// A loaded map's cell edges.
    cells: Vec<u32>,
    /// The obstacles [`Walls::near`] gave last, in their order: the hint of its sort.
    order: Vec<u32>,
}

impl Nearby {
    /// How much farther than the reach the candidates are taken, m (and how far behind a
    /// single edge a person must be for it to be left out).
    const SLACK: f64 = 1.0;
    /// How far the person may move before the candidates are found again, m: half the
    /// slack, so that the rounding of the tests never decides (a test of which
    /// side of an edge a point is on errs by far less than 0.5 m within 10^5 m of the
    /// origin).
    const MOVED: f64 = 0.5 * Self::SLACK;

    /// Whether the candidates must be found again for a person at `p` with `reach` (always
    /// at a position that is not finite, where the buckets decide as before).
    fn stale(&self, p: Point2, reach: f64) -> bool {
        self.at.is_none_or(|at| {
            let moved = (p - at).norm_squared();
            reach != self.reach || moved > Self::MOVED * Self::MOVED || moved.is_nan()
        })
    }
}

/// Scratch of [`Walls::near`], kept between queries: its result and what finding it
/// takes.
#[derive(Debug, Clone, Default)]
struct Near {
    /// The obstacles near the query point, nearest first.
    indices: Vec<u32>,
    /// (squared distance's bits, index) of each, packed so that they order as the pair
    /// (one comparison of integers, where a pair's takes a branch per field), before
    /// sorting.
    keyed: Vec<u128>,
    /// Their sort's own.
    hint: OrderHint,
    /// The bucket queries' own.
    marks: Marks,
    cell_marks: Marks,
    /// The rays' ranges to the loaded map's cells.
    ranges: Vec<f64>,
}

/// People who avoid each other by optimal reciprocal collision avoidance, ORCA (J. van
/// den Berg, S. J. Guy, M. Lin, D. Manocha, "Reciprocal n-body collision avoidance",
/// ISRR 2009; RVO2): each walks their route at their speed, and at every step takes the
/// velocity nearest their preferred one that collides with none of their neighbours
/// within [`OrcaParams::time_horizon`], nor with a wall within
/// [`OrcaParams::obstacle_time_horizon`], if [`OrcaParams::sees_robot`] the robot among
/// the neighbours.
///
/// For two people A and B, the velocity obstacle `VO(A|B)` is the set of A's velocities
/// relative to B that bring their bodies into contact within the time horizon `T` (a
/// cone cut off by a disc of radius `(r_A + r_B) / T`). With `u` the smallest change of
/// the relative velocity that leaves it, and `n` the outward normal there, A keeps to the
/// half-plane `ORCA(A|B) = { v : (v - (v_A + u / 2)) . n >= 0 }`: each of the two takes
/// half of the avoidance, and their choices together avoid the contact. Walls give
/// half-planes of their own, taken whole. The new velocity is the point of the
/// intersection of the half-planes, within the speed cap, nearest to the preferred
/// velocity (a 2-D linear program; when it is empty, the velocity that violates the
/// people's half-planes least, keeping the walls'). The velocity obstacles, the
/// half-planes and the linear program are computed as the paper and RVO2 do, in `f64`
/// and in buffers kept between steps; a property test checks the velocities against
/// `dodgy_2d`, an independent port of RVO2, on random people and walls.
///
/// Each person walks their [`Person`] route: the way-points are successive goals, the
/// preferred velocity is `speed` toward the next one (on a `Walk::Once` route,
/// `min(speed, distance / arrival_time)` toward the last way-point, so that they stop
/// there).
///
/// Where this model departs from RVO2, and why:
///
/// - **Symmetry.** A person walking straight at another (or at the robot) along the line
///   of their centres gets half-planes square to that line: ORCA slows them down and
///   never turns them, and two people head-on stop face to face (RVO2's examples perturb
///   the preferred velocities at random). Instead each person sees the others
///   `keep_right` ([`crate::KEEP_RIGHT`], 1 mm) further to their left than they are, so
///   that an exact tie is broken toward passing on the right, as
///   [`crate::SocialForce`] does.
/// - **Bodies.** Every radius is padded by `safety_space` (1 cm), as CrowdNav does: on
///   the edge of a velocity obstacle, unpadded bodies graze, a fraction of a millimetre
///   inside each other after rounding.
/// - **The robot.** When people see it, the robot is a neighbour of avoidance
///   responsibility 0: people take the whole avoidance (`u`, not `u / 2`), since the
///   robot does not run ORCA. When they do not see it, it is nobody's neighbour.
/// - **Walls.** The static world's edges are one-sided open obstacles (solid on the side
///   of their outline's inside, or of a loaded map's occupied cell); loose edges are
///   obstacles on both sides; discs are standing round bodies (their own velocity
///   obstacle, avoided whole, within the walls' horizon). Each person is given only
///   the obstacles within RVO2's obstacle range (`obstacle_time_horizon x max speed +
///   radius`), nearest first as in RVO2: drawn ones whose bounding box is in range,
///   found in a coarse grid built once; of a loaded map's cell edges, those within 1.5 m
///   and those one of 72 rays from the person (one every 5 degrees, cast on the map's
///   cells every 0.4 s) hits in range. As in RVO2, an edge whose ends are both deep past
///   a nearer wall's half-plane is left out; still, a real building's map puts hundreds
///   of edges in range (about 400 front-facing within 7 m of a place of MIT building 31,
///   `cell_edges_on_the_building_maps`), most behind other walls, each tested against
///   the half-planes before it: the rays keep those a person sees (about 40).
/// - **Ties.** Two people whose centres coincide exactly (where no direction parts
///   them) are seen 1 mm apart along x, the lower index on the left, so that positions
///   stay a deterministic function of the scenario and of the robot's poses.
/// - **Local only.** Like RVO2, ORCA looks one time horizon ahead and knows no route. A
///   wall at a slant across a leg is slid along and walked around; a wall square across
///   it, wherever its ends, holds the person in front of it (its half-plane is square to
///   their way, and the side preference is for people only). Routes should go around
///   walls with way-points.
///
/// # Cost
///
/// One step with `n` people sorts each person's `n` candidate neighbours (O(n^2 log n))
/// and solves `n` linear programs of `max_neighbours` + (nearby obstacle edges)
/// half-planes (incremental, at most quadratic in the half-planes), without allocating,
/// after sorting the obstacles in reach by distance, and on a loaded map 72 rays a
/// person. Walls dominate where they are dense: measured with 20 people
/// (`cost_of_twenty_people`, release), a call costs on average about 1.3 us a 5 ms tick
/// in an open room (0.6x [`crate::SocialForce`]) and about 10-13 us among a loaded map's
/// 3,600 cell edges of pillars (0.8-1.0x). The new velocities are chosen once per
/// [`OrcaParams::step`] of simulated time (25 Hz by default); a call between steps
/// extrapolates the positions.
///
/// # Use
///
/// The state (positions, velocities, legs) advances by the time between successive
/// calls: every new velocity from the current state, then the positions. A call at an
/// earlier time than the last one starts over from the people's first way-points (a
/// restarted episode). The robot's velocity is its displacement between calls over their
/// interval. People wait at their first way-point until their `start` (they still step
/// aside) and never go faster than `max_speed_ratio` times their `speed` (so a person of
/// speed 0 stands like a post).
///
/// ```
/// use sim::{Orca, OrcaParams, PeopleModel, Person, Pose, StaticWorld, Walk};
/// let walker = Person { path: vec![(0.0, 0.0), (10.0, 0.0)], speed: 1.0, start: 0.0,
///     radius: 0.25, walk: Walk::Once, group: None };
/// let people = [walker];
/// let world = StaticWorld::default();
/// let mut model = Orca::new(&people, &world, 0.2, OrcaParams::default());
/// let mut now = Vec::new();
/// for tick in 0..=800 {
///     now = model.people(tick as f64 * 0.005, Pose { x: 5.0, y: 5.0, phi: 0.0 });
/// }
/// // 4 s at 1 m/s: ORCA changes velocity at once.
/// assert!((now[0].center.x - 4.0).abs() < 0.02, "{}", now[0].center.x);
/// ```
#[derive(Debug, Clone)]
pub struct Orca<'w> {
    params: OrcaParams,
    people: &'w [Person],
    statics: &'w StaticWorld,
    walls: Walls,
    robot_radius: f64,
    walkers: Vec<Walker>,
    /// The velocities of the step being taken.
    next: Vec<Vector2<f64>>,
    /// The walls near the person being stepped (scratch).
    near: Near,
    /// The half-planes of the person being stepped, and the linear program's own
    /// (scratch).
    planes: Vec<HalfPlane>,
    lp_scratch: Vec<HalfPlane>,
    /// Each person's candidate walls.
    nearby: Vec<Nearby>,
    /// The loaded map's cell edges each person's rays hit at their last look
    /// ([`LOOK_EVERY`] steps apart, staggered), and the steps taken.
    seen: Vec<Vec<u32>>,
    steps: u64,
    /// Each person's candidate neighbours in the order of the last step, nearest first
    /// (a row of agent indices per person, when the crowd is at most [`ORDER_CAP`]
    /// agents): a hint that makes their sort nearly free, since people move a few
    /// centimetres a step. The result does not depend on it.
    order: Vec<u32>,
    clock: Stepper,
}

/// The largest crowd (people and the robot) whose neighbour orders are kept between
/// steps: 1,024 agents, 4 MB.
const ORDER_CAP: usize = 1024;

/// The key of an agent who is not a neighbour: after every squared distance's bits
/// (below 2^63), in index order.
const OUT_OF_REACH: u128 = 1 << 127;

/// Sorts `keys` by insertion: linear on keys already nearly in order, as a person's
/// neighbours are from one step to the next (where `sort_unstable` sorts from scratch).
fn sort_nearly_sorted(keys: &mut [u128]) {
    for i in 1..keys.len() {
        let key = keys[i];
        let mut j = i;
        while j > 0 && keys[j - 1] > key {
            keys[j] = keys[j - 1];
            j -= 1;
        }
        keys[j] = key;
    }
}

/// The sort of a person's obstacles, nearest first, from the order of the step before:
/// people move a few centimetres a step, so the obstacles near them keep their order
/// but for a few, and an insertion sort from the old order is nearly linear where
/// `sort_unstable` sorts from scratch. The result does not depend on the hint.
#[derive(Debug, Clone, Default)]
struct OrderHint {
    /// Per obstacle: the generation at which it was last among the keys, and where (or
    /// [`OrderHint::TAKEN`] once placed).
    slots: Vec<(u32, u32)>,
    generation: u32,
    /// The keys in the hint's order, then sorted.
    sorted: Vec<u128>,
}

impl OrderHint {
    /// A slot's position once its obstacle is placed.
    const TAKEN: u32 = u32::MAX;

    /// Sorts `keys` (each an obstacle's key: its squared distance's bits above its index
    /// in the low 32 bits, so that the copies of one obstacle are equal) ascending and
    /// without copies, starting from the obstacles of `last` in their order; then sets
    /// `last` to the result's indices. `obstacles`: how many there are.
    fn sort(&mut self, keys: &mut Vec<u128>, last: &mut Vec<u32>, obstacles: usize) {
        if self.slots.len() < obstacles {
            self.slots.resize(obstacles, (0, 0));
        }
        self.generation = self.generation.wrapping_add(1);
        if self.generation == 0 {
            self.slots.fill((0, 0));
            self.generation = 1;
        }
        let g = self.generation;
        for (at, &key) in keys.iter().enumerate() {
            let slot = &mut self.slots[key as u32 as usize];
            if slot.0 != g {
                *slot = (g, at as u32);
            }
        }
        self.sorted.clear();
        for &k in last.iter() {
            let slot = &mut self.slots[k as usize];
            if slot.0 == g && slot.1 != Self::TAKEN {
                self.sorted.push(keys[slot.1 as usize]);
                slot.1 = Self::TAKEN;
            }
        }
        for (at, &key) in keys.iter().enumerate() {
            let slot = &mut self.slots[key as u32 as usize];
            if slot.1 == at as u32 {
                self.sorted.push(key);
                slot.1 = Self::TAKEN;
            }
        }
        sort_nearly_sorted(&mut self.sorted);
        std::mem::swap(keys, &mut self.sorted);
        last.clear();
        last.extend(keys.iter().map(|&key| key as u32));
    }
}

impl<'w> Orca<'w> {
    /// `people` at their first way-points, standing, among `statics`, with a robot of body
    /// radius `robot_radius`, m. The walls become ORCA obstacles here, once.
    #[must_use]
    pub fn new(
        people: &'w [Person],
        statics: &'w StaticWorld,
        robot_radius: f64,
        params: OrcaParams,
    ) -> Self {
        let mut model = Self {
            params,
            people,
            statics,
            walls: Walls::default(),
            robot_radius,
            walkers: Vec::with_capacity(people.len()),
            next: vec![Vector2::zeros(); people.len()],
            near: Near::default(),
            planes: Vec::new(),
            lp_scratch: Vec::new(),
            nearby: vec![Nearby::default(); people.len()],
            order: Vec::new(),
            seen: vec![Vec::new(); people.len()],
            steps: 0,
            clock: Stepper::default(),
        };
        let widest = (0..people.len())
            .map(|k| model.reach(k))
            .fold(1.0, f64::max);
        model.walls = Walls::new(statics, widest);
        model.reset();
        model
    }

    /// Person `k`'s speed cap, m/s.
    fn max_speed(&self, k: usize) -> f64 {
        self.params.max_speed_ratio * self.people[k].speed.max(0.0)
    }

    /// How far from person `k` walls are considered, m (RVO2's obstacle range).
    fn reach(&self, k: usize) -> f64 {
        let r = self.params.obstacle_time_horizon * self.max_speed(k) + self.people[k].radius;
        if r.is_finite() { r } else { 0.0 }
    }
}

/// Neighbour `other` as agent `me` is to see it: moved by `shift` (the side preference),
/// and, when their centres then coincide and they do not move apart (where no direction
/// parts them), 1 mm further along x (`other_after`: the other has the higher index, so
/// it is seen to the right; else to the left).
fn seen(me: &Body, other: &Body, shift: Vector2<f64>, other_after: bool, time_step: f64) -> Body {
    let mut moved = *other;
    moved.position += shift;
    let to_other = moved.position - me.position;
    // (The drift only where it is needed: a division is dear in a loop this hot.)
    let apart = |to_other: Vector2<f64>| {
        let drift = (me.velocity - other.velocity) - to_other / time_step;
        drift.norm_squared() > 1e-12
    };
    if to_other.norm_squared() <= 1e-12 && !apart(to_other) {
        moved.position.x += if other_after { 1e-3 } else { -1e-3 };
    }
    moved
}

impl Stepped for Orca<'_> {
    /// Everyone back at their first way-point, standing.
    fn reset(&mut self) {
        self.steps = 0;
        self.seen.iter_mut().for_each(Vec::clear);
        self.nearby.iter_mut().for_each(|n| n.at = None);
        self.walkers.clear();
        self.walkers.extend(self.people.iter().map(|p| {
            let on_stage = p.walk != crate::Walk::Through;
            Walker {
                pos: if on_stage {
                    p.path.first().map_or(Point2::origin(), |&q| pt(q))
                } else {
                    pt(crate::world::OFFSTAGE)
                },
                vel: Vector2::zeros(),
                leg: 0,
                on_stage,
            }
        }));
    }

    /// One step of `h` seconds from time `t`, the robot at `robot` moving at
    /// `robot_velocity`: every new velocity from the current state, then the positions.
    fn step(&mut self, t: f64, h: f64, robot: Point2, robot_velocity: Vector2<f64>) {
        let near = self.params.switch_distance;
        for (w, p) in self.walkers.iter_mut().zip(self.people) {
            on_stage(
                p,
                t,
                near,
                (&mut w.pos, &mut w.vel, &mut w.leg, &mut w.on_stage),
            );
        }
        let n = self.walkers.len();
        let mut agents: Vec<Body> = self
            .walkers
            .iter()
            .zip(self.people)
            .map(|(w, p)| Body {
                position: w.pos.coords,
                velocity: w.vel,
                radius: p.radius + self.params.safety_space,
            })
            .collect();
        if self.params.sees_robot {
            agents.push(Body {
                position: robot.coords,
                velocity: robot_velocity,
                radius: self.robot_radius + self.params.safety_space,
            });
        }
        // Whether each agent is anyone's neighbour.
        let eligible: Vec<bool> = (0..agents.len())
            .map(|j| self.walkers.get(j).is_none_or(|w| w.on_stage))
            .collect();
        // Nearest first, ties to the lower index: a squared distance is not negative, so
        // its bits order as it does, and (bits, index) packed in a `u128` order as both.
        let mut candidates: Vec<u128> = Vec::with_capacity(agents.len());
        let mut planes = std::mem::take(&mut self.planes);
        let mut scratch = std::mem::take(&mut self.lp_scratch);
        let mut near = std::mem::take(&mut self.near);
        let cells = self.statics.grid_rays();
        let reach_sq = self.params.neighbour_distance * self.params.neighbour_distance;
        for k in 0..n {
            if !self.walkers[k].on_stage {
                self.next[k] = Vector2::zeros();
                continue;
            }
            let p = &self.people[k];
            let max_speed = self.max_speed(k);
            let (preferred, facing) = {
                let w = &mut self.walkers[k];
                match heading(p, &mut w.leg, w.pos, t, self.params.switch_distance) {
                    Some(g) => (
                        g.direction * g.speed(p.speed, self.params.arrival_time),
                        g.direction,
                    ),
                    None => (
                        Vector2::zeros(),
                        w.vel.try_normalize(0.0).unwrap_or_default(),
                    ),
                }
            };
            if !(max_speed > 0.0 && max_speed.is_finite()) {
                self.next[k] = Vector2::zeros();
                continue;
            }
            let me = agents[k];
            let at = self.walkers[k].pos;
            let shift = Vector2::new(-facing.y, facing.x) * self.params.keep_right;
            // The nearest neighbours, ties to the lower index (the robot last): every agent
            // keyed, those out of reach past the others, in last step's order.
            let m = agents.len();
            let row = (m <= ORDER_CAP).then(|| {
                if self.order.len() != n * m {
                    self.order = (0..n).flat_map(|_| 0..m as u32).collect();
                }
                &mut self.order[k * m..(k + 1) * m]
            });
            let key = |j: usize| {
                let d_sq = (agents[j].position - at.coords).norm_squared();
                if j != k && eligible[j] && d_sq <= reach_sq {
                    u128::from(d_sq.to_bits()) << 64 | j as u128
                } else {
                    OUT_OF_REACH | j as u128
                }
            };
            candidates.clear();
            match row {
                Some(row) => {
                    candidates.extend(row.iter().map(|&j| key(j as usize)));
                    sort_nearly_sorted(&mut candidates);
                    for (slot, &c) in row.iter_mut().zip(&candidates) {
                        *slot = c as u32;
                    }
                }
                None => {
                    candidates.extend((0..m).map(key));
                    candidates.sort_unstable();
                }
            }
            let reach = self.reach(k);
            if let Some(cells) = &cells
                && (self.steps + k as u64).is_multiple_of(LOOK_EVERY)
            {
                let (ranges, seen) = (&mut near.ranges, &mut self.seen[k]);
                self.walls.seen(at, reach, cells, ranges, seen);
            }
            self.walls
                .near(at, reach, &self.seen[k], &mut self.nearby[k], &mut near);
            // The walls' half-planes first, nearest first (an edge deep past a nearer
            // one's half-plane is left out), then the neighbours'.
            let margin = p.radius + self.params.safety_space;
            let horizon = self.params.obstacle_time_horizon;
            planes.clear();
            for &i in &near.indices {
                let plane = match self.walls.obstacles[i as usize] {
                    Wall::Edge { a, b } => edge_half_plane(
                        me.position,
                        me.velocity,
                        margin,
                        (a.coords, b.coords),
                        horizon,
                        &planes,
                    ),
                    Wall::Disc { center, radius } => {
                        let disc = Body {
                            position: center.coords,
                            velocity: Vector2::zeros(),
                            radius,
                        };
                        agent_half_plane(&me, &disc, 1.0, horizon, h)
                    }
                };
                planes.extend(plane);
            }
            let hard = planes.len();
            for &c in candidates
                .iter()
                .take_while(|&&c| c < OUT_OF_REACH)
                .take(self.params.max_neighbours)
            {
                let j = c as u64 as usize;
                let other = seen(&me, &agents[j], shift, j > k, h);
                // People share the avoidance; of the robot, who does not run ORCA, they
                // take it all.
                let share = if j < n { 0.5 } else { 1.0 };
                planes.extend(agent_half_plane(
                    &me,
                    &other,
                    share,
                    self.params.time_horizon,
                    h,
                ));
            }
            let v = half_planes::solve(&planes, hard, max_speed, preferred, &mut scratch);
            self.next[k] = if v.iter().all(|c| c.is_finite()) {
                v
            } else {
                Vector2::zeros()
            };
        }
        self.planes = planes;
        self.lp_scratch = scratch;
        self.near = near;
        self.steps += 1;
        for (w, v) in self.walkers.iter_mut().zip(&self.next) {
            if w.on_stage {
                w.vel = *v;
                w.pos += w.vel * h;
            }
        }
    }

    fn clock(&mut self) -> &mut Stepper {
        &mut self.clock
    }

    fn step_length(&self) -> f64 {
        self.params.step
    }

    fn discs(&self, ahead: f64) -> Vec<Disc> {
        discs_ahead(
            self.people,
            self.walkers.iter().map(|w| (w.pos, w.vel, w.on_stage)),
            ahead,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::PeopleModel;

    #[test]
    fn parameters_are_checked() {
        let bad = |p: OrcaParams| p.problem().map(|(f, _, _)| f);
        let d = OrcaParams::default();
        assert_eq!(bad(d), None);
        let p = OrcaParams {
            time_horizon: f64::NAN,
            ..d
        };
        assert_eq!(bad(p), Some("time_horizon"));
        let p = OrcaParams {
            obstacle_time_horizon: 0.0,
            ..d
        };
        assert_eq!(bad(p), Some("obstacle_time_horizon"));
        let p = OrcaParams {
            neighbour_distance: -1.0,
            ..d
        };
        assert_eq!(bad(p), Some("neighbour_distance"));
        let p = OrcaParams {
            max_speed_ratio: f64::INFINITY,
            ..d
        };
        assert_eq!(bad(p), Some("max_speed_ratio"));
        let p = OrcaParams {
            arrival_time: -0.5,
            ..d
        };
        assert_eq!(bad(p), Some("arrival_time"));
        // 0 is allowed where it means "none".
        let p = OrcaParams {
            neighbour_distance: 0.0,
            switch_distance: 0.0,
            max_neighbours: 0,
            ..d
        };
        assert_eq!(bad(p), None);
    }

    /// Outline edges are solid on their inside, a loaded map's edges on their occupied
    /// cell's side, loose edges on both; the buckets find what is near and only that.
    #[test]
    fn walls_become_obstacles() {
        let mut statics = StaticWorld::default();
        statics.add_shape(&crate::Shape::Box {
            center: (6.0, 6.0),
            size: (1.0, 1.0),
            angle_deg: 0.0,
        });
        let map = envmap::GridMap::from_ascii("....\n.#..\n....").unwrap();
        statics.add_grid(map);
        statics.segments.push(Segment {
            a: Point2::new(20.0, 0.0),
            b: Point2::new(20.0, 1.0),
            outward: None,
        });
        let walls = Walls::new(&statics, 1.0);
        // 4 box edges, 2 sides of the loose edge, 4 cell edges.
        assert_eq!(walls.obstacles.len(), 10);
        let solid_left_at = |k: usize, inside: Point2| {
            let Wall::Edge { a, b } = walls.obstacles[k] else {
                panic!("{:?}", walls.obstacles[k])
            };
            (b - a).perp(&(inside - a)) > 0.0
        };
        for k in 0..4 {
            assert!(solid_left_at(k, Point2::new(6.0, 6.0)), "box edge {k}");
        }
        for k in 6..10 {
            assert!(solid_left_at(k, Point2::new(1.5, 1.5)), "cell edge {k}");
        }
        assert_ne!(
            solid_left_at(4, Point2::new(21.0, 0.5)),
            solid_left_at(5, Point2::new(21.0, 0.5))
        );
        // The walls near `p` within `reach`, found afresh.
        let near = |p: Point2, reach: f64| {
            let mut out = Near::default();
            walls.near(p, reach, &[], &mut Nearby::default(), &mut out);
            out.indices
        };
        // From inside the box and the cell every edge is seen from its solid side.
        assert_eq!(near(Point2::new(6.0, 6.0), 0.6), Vec::<u32>::new());
        assert_eq!(near(Point2::new(1.5, 1.5), 0.6), Vec::<u32>::new());
        // Below the box: its bottom edge; its sides are within reach but seen from behind.
        let below = near(Point2::new(6.0, 5.2), 0.6);
        assert_eq!(below.len(), 1);
        let Wall::Edge { a, b } = walls.obstacles[below[0] as usize] else {
            panic!()
        };
        assert!(a.y == 5.5 && b.y == 5.5, "{a} {b}");
        // One side of the loose edge, the one facing the point.
        let beside = near(Point2::new(20.5, 0.5), 0.6);
        assert_eq!(beside.len(), 1);
        assert!(!solid_left_at(beside[0] as usize, Point2::new(20.5, 0.5)));
        assert_eq!(near(Point2::new(10.0, 10.0), 1.0), Vec::<u32>::new());
    }

    proptest::proptest! {
        /// The neighbours' insertion sort gives `sort_unstable`'s order, from any start.
        #[test]
        fn nearly_sorted_keys_sort_as_any_keys(mut keys in proptest::collection::vec(proptest::prelude::any::<u128>(), 0..40)) {
            let mut expected = keys.clone();
            expected.sort_unstable();
            sort_nearly_sorted(&mut keys);
            proptest::prop_assert_eq!(keys, expected);
        }

        /// The obstacles' sort from the last order gives `sort_unstable` then `dedup`'s
        /// keys, whatever that order holds (obstacles gone, new ones, copies), and leaves
        /// their indices as the next hint; over three sorts with one scratch.
        #[test]
        fn hinted_sorts_sort_as_from_scratch(
            rounds in proptest::collection::vec(
                (
                    proptest::collection::vec(0..60_u32, 0..50),
                    proptest::collection::vec(0..60_u32, 0..30),
                ),
                1..4,
            )
        ) {
            let mut hint = OrderHint::default();
            for (picked, last) in rounds {
                // One key per obstacle, from its index (so its copies are equal), in an
                // order that is not the indices'.
                let key = |k: u32| u128::from(u64::from(k * 7 % 5)) << 32 | u128::from(k);
                let mut keys: Vec<u128> = picked.iter().map(|&k| key(k)).collect();
                let mut expected = keys.clone();
                expected.sort_unstable();
                expected.dedup();
                let mut order = last.clone();
                hint.sort(&mut keys, &mut order, 60);
                proptest::prop_assert_eq!(&keys, &expected);
                let indices: Vec<u32> = expected.iter().map(|&k| k as u32).collect();
                proptest::prop_assert_eq!(order, indices);
            }
        }

        /// A person's candidate walls kept between steps change nothing: along a walk
        /// among boxes, loose edges and a loaded map's cells, the walls near each place
        /// are those found with no candidates kept.
        #[test]
        fn kept_candidates_give_the_walls_near(
            boxes in proptest::collection::vec((0.0..12.0_f64, 0.0..12.0_f64, 0.2..3.0_f64, 0.2..3.0_f64, 0.0..90.0_f64), 0..6),
            loose in proptest::collection::vec((0.0..12.0_f64, 0.0..12.0_f64, 0.0..12.0_f64, 0.0..12.0_f64), 0..4),
            cells in proptest::collection::vec(proptest::prelude::any::<bool>(), 64),
            walk in proptest::collection::vec((0.0..std::f64::consts::TAU, 0.0..0.4_f64), 1..120),
            reach in 0.5..6.0_f64,
        ) {
            let mut statics = StaticWorld::default();
            for &(x, y, w, h, angle_deg) in &boxes {
                statics.add_shape(&crate::Shape::Box { center: (x, y), size: (w, h), angle_deg });
            }
            for &(ax, ay, bx, by) in &loose {
                statics.segments.push(Segment { a: Point2::new(ax, ay), b: Point2::new(bx, by), outward: None });
            }
            let text: String = cells
                .chunks(8)
                .map(|row| row.iter().map(|&b| if b { '#' } else { '.' }).collect::<String>() + "\n")
                .collect();
            statics.add_grid(envmap::GridMap::from_ascii(&text).unwrap());
            let walls = Walls::new(&statics, reach);
            let (mut kept, mut near, mut fresh) = (Nearby::default(), Near::default(), Near::default());
            let mut p = Point2::new(6.0, 6.0);
            for &(heading, length) in &walk {
                p += Vector2::new(heading.cos(), heading.sin()) * length;
                walls.near(p, reach, &[], &mut kept, &mut near);
                walls.near(p, reach, &[], &mut Nearby::default(), &mut fresh);
                proptest::prop_assert_eq!(&near.indices, &fresh.indices, "at {}", p);
            }
        }
    }

    /// The neighbour orders kept between steps are a hint only: a crowd whose orders are
    /// forgotten before every step walks exactly the same.
    #[test]
    fn kept_neighbour_orders_change_nothing() {
        let people: Vec<Person> = (0..14)
            .map(|k| {
                let y = 0.6 * k as f64;
                let (from, to) = if k % 2 == 0 {
                    ((0.0, y), (8.0, 7.8 - y))
                } else {
                    ((8.0, y), (0.0, 7.8 - y))
                };
                Person {
                    path: vec![from, to, from],
                    speed: 1.0 + 0.05 * k as f64,
                    start: 0.1 * k as f64,
                    radius: 0.25,
                    walk: crate::Walk::Loop,
                    group: None,
                }
            })
            .collect();
        let world = StaticWorld::default();
        let params = OrcaParams {
            neighbour_distance: 3.0,
            max_neighbours: 4,
            ..Default::default()
        };
        let mut kept = Orca::new(&people, &world, 0.2, params);
        let mut forgotten = Orca::new(&people, &world, 0.2, params);
        let robot = |t: f64| crate::Pose {
            x: 4.0 + 0.3 * t,
            y: 4.0,
            phi: 0.0,
        };
        for tick in 0..2000 {
            let t = tick as f64 * 0.005;
            forgotten.order.clear();
            let (a, b) = (kept.people(t, robot(t)), forgotten.people(t, robot(t)));
            assert_eq!(a, b, "at {t} s");
        }
        assert_eq!(kept.order.len(), 14 * 15);
        // The hint was used: some person's order is no longer the agents' own.
        assert!(
            kept.order
                .chunks(15)
                .any(|row| row.windows(2).any(|w| w[0] > w[1]))
        );
    }

    /// Over the free places of the world of `scenario` (every 7th cell each way, 0.3 m from
    /// obstacles, a reach of 7 m: a person at 1.34 m/s): how many places, how many wall
    /// edges a person there is handed, and how many front-facing ones are in reach.
    /// Checks on the way that every front-facing edge within [`CELL_EDGES_ALL_WITHIN`] is
    /// handed, nearest first.
    fn edges_handed(scenario: &str) -> (usize, usize, usize) {
        const REACH: f64 = 7.0;
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../scenarios/sim")
            .join(scenario);
        let (_, world) = crate::Scenario::load(&path).unwrap();
        let statics = &world.statics;
        let walls = Walls::new(statics, REACH);
        let rays = statics.grid_rays().unwrap();
        let grid = statics.grid.as_ref().unwrap();
        let mut near = Near::default();
        let (mut ranges, mut seen) = (Vec::new(), Vec::new());
        let (mut handed, mut in_reach, mut places) = (0, 0, 0);
        for j in (0..grid.height()).step_by(7) {
            for i in (0..grid.width()).step_by(7) {
                let p = grid.cell_center(i, j);
                if grid.cell_zone(i, j) == Zone::Forbidden || statics.nearest(p).0 < 0.3 {
                    continue;
                }
                places += 1;
                walls.seen(p, REACH, &rays, &mut ranges, &mut seen);
                walls.near(p, REACH, &seen, &mut Nearby::default(), &mut near);
                let mut last = 0.0;
                for &k in &near.indices {
                    let d = walls.obstacles[k as usize].distance_sq(p);
                    assert!(d >= last, "nearest first");
                    last = d;
                }
                handed += near.indices.len();
                for (k, o) in walls.obstacles.iter().enumerate() {
                    let d = o.distance_sq(p).sqrt();
                    if o.back_facing(p) || d > REACH {
                        continue;
                    }
                    in_reach += 1;
                    if d <= CELL_EDGES_ALL_WITHIN - 0.01 {
                        assert!(near.indices.contains(&(k as u32)), "{p}: {o:?} at {d:.3} m");
                    }
                }
            }
        }
        (places, handed, in_reach)
    }

    /// On a real house's map, a person is handed every front-facing cell edge within
    /// [`CELL_EDGES_ALL_WITHIN`], and of the farther ones within reach only those their
    /// rays hit: a fraction of them, the rest being hidden behind nearer walls.
    #[test]
    fn people_on_a_map_avoid_the_cell_edges_near_and_seen() {
        let (places, handed, in_reach) = edges_handed("nav-aws_small_house.ron");
        assert!(places > 500, "{places}");
        // Measured: about 28 of 117 edges a place.
        assert!(handed * 3 < in_reach, "{handed} of {in_reach}");
    }

    /// The same count on the building maps of `data/ros_maps/`. Run it with `cargo test
    /// -p sim --release --lib -- --ignored --nocapture orca::tests::cell_edges_on`.
    #[test]
    #[ignore = "a measurement, not a check"]
    fn cell_edges_on_the_building_maps() {
        for scenario in [
            "explore-tb3.ron",
            "nav-aws_small_house.ron",
            "explore-yujin_rnd_hokuyo.ron",
            "explore-uos_avz5floor_open.ron",
            "explore-mit_building_31.ron",
            "explore-mit_stata_basement.ron",
        ] {
            let (places, handed, in_reach) = edges_handed(scenario);
            println!(
                "{scenario}: {places} places, wall edges a person is handed {:.1}, front-facing in reach {:.1}",
                handed as f64 / places as f64,
                in_reach as f64 / places as f64
            );
        }
    }
}
